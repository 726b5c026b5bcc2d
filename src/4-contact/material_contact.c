/**
 * @file material_contact.c
 * @brief Contact between bodies at the nodes (Bardenhagen et al. 2001, the
 *        paper's Fig. 4): one field per contact group where groups meet,
 *        the normal from the fields' mass gradients, detection by approach
 *        (and relative volume when the pair asks), the shared adjustment.
 */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact_law.h"
#include "contact_regression.h"
#include "checkpoint.h"
#include "contact_stencil.h"
#include "material_contact.h"
#include "output.h"
#include "step.h"
#include "strip_scatter.h"
#include "strips.h"

/** The scatters of Task 2 over the points near the nodes with several
 *  fields (near_scatter()). */
typedef enum NearPass {
    PASS_GRADIENT,        /**< mass_gradients() */
    PASS_FIT,             /**< a pass of regression_fit() */
    PASS_REACH            /**< interface_reach() */
} NearPass;

static void near_scatter(Sim *sim, MaterialContact *M, NearPass pass);

int material_contact_prepare(Sim *sim, void *state, char *err, size_t errlen)
{
    MaterialContact *M = state;
    const Hooks *h = &sim->hooks;
    const FieldKey *group = hooks_find_field_key(h, "contact group");
    const FieldKey *side = hooks_find_field_key(h, "crack side");
    int nn = sim->grid.nnodes;
    M->shift = group ? group->shift : -1;
    M->group_mask = group ? (1u << group->bits) - 1u : 0u;
    M->side_mask = side ? ((1u << side->bits) - 1u) << side->shift : 0u;
    M->cell_groups = calloc((size_t)nn, sizeof(unsigned));
    M->mixed = calloc((size_t)nn, 1);
    M->mixed_cell = calloc((size_t)nn, 1);
    M->near = calloc((size_t)nn, 1);
    M->keyed = calloc((size_t)sim->pts.n + 1, 1);
    M->keyed_list = calloc((size_t)sim->pts.n + 1, sizeof(int));
    M->keyed_end = calloc((size_t)sim->threads, sizeof(int));
    M->near_list = calloc(2 * (size_t)sim->pts.n + 1, sizeof(int));
    M->near_end = calloc((size_t)sim->threads + 1, sizeof(int));
    M->node_work = calloc((size_t)nn, sizeof(double));
    M->area = calloc((size_t)nn, sizeof(double));
    M->cx = calloc((size_t)nn * CONTACT_AXES, sizeof(double));
    M->cy = calloc((size_t)nn * CONTACT_AXES, sizeof(double));
    M->geometry_step = -1;
    if (M->shift < 0 || fields_enable(sim) || !M->cell_groups || !M->mixed ||
        !M->mixed_cell ||
        !M->near || !M->keyed || !M->keyed_list || !M->keyed_end || !M->near_list || !M->near_end || !M->node_work || !M->area || !M->cx || !M->cy ||
        contact_decision_alloc(&M->decision, nn) ||
        (M->normal == NORMAL_REGRESSION &&
         (!(M->fit = calloc((size_t)nn * REGRESSION_DOUBLES, sizeof(double))) ||
          !(M->fit_pair = calloc((size_t)nn * 2, sizeof(int)))))) {
        snprintf(err, errlen, "%s: out of memory (or field-key bits) for "
                 "contact between bodies", sim->scene.file);
        return -1;
    }
    return 0;
}

/// [material_key_fields_wide]
/** material_key_fields() through run.shape's stencil function (chapter 8),
 *  compiled on its own: a node is mixed when the stencils of points of
 *  several groups reach it (M->cell_groups holds per node the groups
 *  whose points reach it), and a point keys every pair of its stencil at
 *  a mixed node, in its stencil's order (the pairs Task 1 keys). */
static __attribute__((noinline)) int key_fields_wide(Sim *sim, MaterialContact *M)
{
    const Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    StencilFn wide = sim->scene.run.stencil;
    memset(M->cell_groups, 0, sizeof(unsigned) * (size_t)g->nnodes);
    for (int p = 0; p < P->n; p++) {            /* the groups at each node */
        int node[STENCIL_MAX], n = stencil_node_list(sim, wide, p, node);
        for (int a = 0; a < n; a++)
            M->cell_groups[node[a]] |= 1u << M->group_of_body[P->body[p]];
    }
    for (int n = 0; n < g->nnodes; n++) {
        unsigned seen = M->cell_groups[n];
        M->mixed[n] = (seen & (seen - 1)) != 0;  /* more than one group */
    }
    for (int p = 0; p < P->n; p++) {
        int node[STENCIL_MAX], group = M->group_of_body[P->body[p]];
        if (group == 0)
            continue;                           /* field 0 */
        int n = stencil_node_list(sim, wide, p, node);
        for (int a = 0; a < n; a++)
            if (M->mixed[node[a]] &&
                fields_key_wide(sim, p, a, (unsigned)group << M->shift))
                return -1;
    }
    return 0;
}
/// [material_key_fields_wide]

/// [material_key_fields]
/** The groups in each cell (by its lower-left node), M->cell_groups:
 *  on threads over the strips' points (strips.h), each strip's thread
 *  writing the cells of its own nodes only; an OR, the same in any order. */
static void cell_groups(Sim *sim, MaterialContact *M)
{
    const Particles *P = &sim->pts;
    const Strips *S = &sim->strips;
    memset(M->cell_groups, 0, sizeof(unsigned) * (size_t)sim->grid.nnodes);
    if (S->n == 0) {
        for (int p = 0; p < P->n; p++)
            M->cell_groups[P->cell[p]] |= 1u << M->group_of_body[P->body[p]];
        return;
    }
#pragma omp parallel for num_threads(sim->threads) schedule(static, 1)
    for (int t = 0; t < S->n; t++) {
        int lo = S->first_node[t], hi = S->first_node[t + 1];
        for (int k = S->start[t]; k < S->start[t + 1]; k++) {
            int p = S->list[k], c = P->cell[p];
            if (c >= lo && c < hi)
                M->cell_groups[c] |= 1u << M->group_of_body[P->body[p]];
        }
    }
}

int material_key_fields(Sim *sim, void *state, Seam seam)
{
    MaterialContact *M = state;
    const Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    int nx = g->nnx;
    (void)seam;
    if (sim->scene.run.stencil)                 /* another row of run.shape */
        return key_fields_wide(sim, M);
    cell_groups(sim, M);                        /* the groups in each cell */
#pragma omp parallel for num_threads(sim->threads) schedule(static)
    for (int j = 0; j < g->nny; j++) {          /* a node: its four cells */
        const unsigned *row = &M->cell_groups[j * nx];
        const unsigned *below = j > 0 ? row - nx : row;  /* row 0: itself */
        unsigned char *mixed = &M->mixed[j * nx];
        unsigned seen = row[0] | below[0];
        mixed[0] = (seen & (seen - 1)) != 0;    /* more than one group */
#pragma omp simd
        for (int i = 1; i < nx; i++) {          /* integers: any lanes */
            unsigned s = row[i] | row[i - 1] | below[i] | below[i - 1];
            mixed[i] = (s & (s - 1)) != 0;
        }
    }
#pragma omp parallel for num_threads(sim->threads) schedule(static)
    for (int j = 0; j < g->nny - 1; j++) {      /* a cell: its four corners */
        const unsigned char *lo = &M->mixed[j * nx], *up = lo + nx;
        unsigned char *cell = &M->mixed_cell[j * nx];
#pragma omp simd
        for (int i = 0; i < nx - 1; i++)
            cell[i] = lo[i] | lo[i + 1] | up[i] | up[i + 1];
    }
    int np = P->n, shares = 1;
#pragma omp parallel num_threads(sim->threads)
    {                                           /* which corners to key */
        int t = omp_get_thread_num(), nt = omp_get_num_threads();
        int k = (int)((long)np * t / nt), end = (int)((long)np * (t + 1) / nt);
        for (int p = k; p < end; p++) {
            int node[STENCIL_NODES];
            unsigned bits = 0;
            if (!M->mixed_cell[P->cell[p]] || M->group_of_body[P->body[p]] == 0)
                continue;                       /* one group, or field 0 */
            stencil_nodes(sim, p, node);
            for (int a = 0; a < STENCIL_NODES; a++)
                bits |= (unsigned)M->mixed[node[a]] << a;
            M->keyed[p] = (unsigned char)bits;
            M->keyed_list[k++] = p;
        }
        M->keyed_end[t] = k;
        if (t == 0)
            shares = nt;
    }
    for (int t = 0; t < shares; t++)            /* the rows, in point order */
        for (int k = (int)((long)np * t / shares); k < M->keyed_end[t]; k++) {
            int p = M->keyed_list[k];
            unsigned key = (unsigned)M->group_of_body[P->body[p]] << M->shift;
            for (int a = 0; a < STENCIL_NODES; a++)
                if ((M->keyed[p] >> a & 1u) && fields_key(sim, p, a, key))
                    return -1;
        }
    return 0;
}
/// [material_key_fields]

/** Room for the per-slot sums (grown with the grid's slots). */
static int reserve_slots(Sim *sim, MaterialContact *M)
{
    int cap = sim->grid.capacity;
    if (cap <= M->cap)
        return 0;
    double **arr[5] = {&M->gx, &M->gy, &M->va, &M->lo, &M->hi};
    for (int k = 0; k < 5; k++) {
        size_t n = (size_t)cap * (k < 3 ? 1u : CONTACT_AXES);
        double *x = realloc(*arr[k], sizeof(double) * n);
        if (!x)
            return step_fail(sim, 0, "memory for contact normals", cap);
        *arr[k] = x;
    }
    M->cap = cap;
    return 0;
}

/** Set @p flag in the cells (by lower-left node) of which a touched node
 *  is a corner. */
static void mark_cells_around(unsigned char *cells, const FieldTable *F,
                              int nx, unsigned char flag)
{
    for (int k = 0; k < F->ntouched; k++) {
        int n = F->touched[k];
        cells[n] = flag;
        if (n >= 1)
            cells[n - 1] = flag;
        if (n >= nx)
            cells[n - nx] = flag;
        if (n >= nx + 1)
            cells[n - nx - 1] = flag;
    }
}

/** A point's current area (volume / thickness) and its half sizes along
 *  x and y (k x k points filled a cell: dx / k by dy / k, stretched). */
static double point_size(const Sim *sim, int p, double half[2])
{
    const Particles *P = &sim->pts;
    const Body *b = &sim->scene.bodies[P->body[p]];
    double sx = 1.0 + P->exx[p], sy = 1.0 + P->eyy[p];
    half[0] = 0.5 * sim->grid.dx / b->ppc * sx;
    half[1] = 0.5 * sim->grid.dy / b->ppc * sy;
    return sx * sy * P->vol[p] / b->thickness;
}

/** The nodes, stencil, half sizes and area of point @p p, a point near a
 *  node with several fields (out of line: most points are not near). */
static __attribute__((noinline)) void
point_near_stencil(const Sim *sim, int p, int node[STENCIL_NODES], Stencil *buf,
                   StencilRow *st, double half[2], double *area)
{
    *area = point_size(sim, p, half);
    stencil_nodes(sim, p, node);
    *st = contact_stencil_linear(sim, p, buf);
}

/** Is point @p p in a cell beside a node with several fields? If so, its
 *  nodes, stencil (in @p st; @p buf holds it when none is stored), half
 *  sizes and area. */
static inline __attribute__((always_inline)) int
point_near(const Sim *sim, const MaterialContact *M, int p,
           int node[STENCIL_NODES], Stencil *buf, StencilRow *st,
           double half[2], double *area)
{
    if (!M->near[sim->pts.cell[p]])
        return 0;
    point_near_stencil(sim, p, node, buf, st, half, area);
    return 1;
}

/** As point_near() through @p wide, run.shape's stencil function: a wider
 *  point reaches beyond its cell's corners (MaterialContact::near), so
 *  its own nodes tell. @return its stencil's nodes, or 0 when not near. */
static int point_near_wide(const Sim *sim, StencilFn wide, int p,
                           int node[STENCIL_MAX], Stencil *buf, StencilRow *st,
                           double half[2], double *area)
{
    int n = contact_stencil(sim, wide, p, node, buf, st);
    if (n)
        *area = point_size(sim, p, half);
    return n;
}

/** point_near() through @p wide, or NULL for the cell's four nodes.
 *  @return the nodes of the point's stencil, or 0 when it is not near. */
static inline __attribute__((always_inline)) int
point_nodes(const Sim *sim, const MaterialContact *M, StencilFn wide, int p,
            int node[STENCIL_MAX], Stencil *buf, StencilRow *st, double half[2],
            double *area)
{
    if (wide)                                   /* another row of run.shape */
        return point_near_wide(sim, wide, p, node, buf, st, half, area);
    return point_near(sim, M, p, node, buf, st, half, area) ? STENCIL_NODES : 0;
}

/// [mass_gradients]
/** Point @p p's share of mass_gradients(), to the nodes of @p own (NULL:
 *  all), through @p wide (NULL: the cell's four nodes). */
static inline __attribute__((always_inline)) void
gradient_at(Sim *sim, MaterialContact *M, int p, const Owned *own, StencilFn wide)
{
    const FieldTable *F = &sim->fields;
    int node[STENCIL_MAX];
    Stencil buf;
    StencilRow st;
    double half[2], area;
    int n = point_nodes(sim, M, wide, p, node, &buf, &st, half, &area);
    if (!n)
        return;
    double mp = sim->pts.m[p];
    for (int a = 0; a < n; a++)
        if (F->first[node[a]] >= 0 && owns(&sim->grid, own, node[a])) {
            M->gx[st.slot[a]] += mp * st.Gx[a];
            M->gy[st.slot[a]] += mp * st.Gy[a];
            M->va[st.slot[a]] += area * st.S[a];
        }
}

/** gradient_at() through the cell's four nodes. Inlined in the one-thread
 *  loop, where @p own is a constant NULL. */
static inline __attribute__((always_inline)) void
gradient_point(Sim *sim, void *state, int p, const Owned *own)
{
    gradient_at(sim, state, p, own, NULL);
}

/** gradient_at() through run.shape's stencil function (chapter 8). */
static inline __attribute__((always_inline)) void
gradient_point_wide(Sim *sim, void *state, int p, const Owned *own)
{
    gradient_at(sim, state, p, own, sim->scene.run.stencil);
}

/** The wide stencils' gradients, compiled on their own (chapter 8). */
static __attribute__((noinline)) void gradients_wide(Sim *sim, MaterialContact *M)
{
    contact_scatter_wide(sim, gradient_point_wide, M);
}

/** Task 2, first pass: at the nodes with several fields, each field's mass
 *  gradient sum_p m_p grad S_ip and area sum_p A_p S_ip. A point in a cell
 *  none of whose corners has several fields costs one test. On threads by
 *  strips, each node summing in point order as on one (strip_scatter.h). */
static void mass_gradients(Sim *sim, MaterialContact *M)
{
    if (sim->scene.run.stencil)                 /* another row of run.shape */
        gradients_wide(sim, M);
    else
        near_scatter(sim, M, PASS_GRADIENT);
}
/// [mass_gradients]

/** The candidate directions of node @p n (CONTACT_AXES; zero when a
 *  field gives none): from its two fields of largest area, a and b, the
 *  unit g_a, -g_b and the average of contact_interface_normal(). */
static void candidate_axes(Sim *sim, MaterialContact *M, int n)
{
    const FieldTable *F = &sim->fields;
    const Grid *g = &sim->grid;
    int a = -1, b = -1;
    for (int s = n; s >= 0; s = field_next(F, g, s)) {
        if (a < 0 || M->va[s] > M->va[a]) {
            b = a;
            a = s;
        } else if (b < 0 || M->va[s] > M->va[b]) {
            b = s;
        }
    }
    if (b < 0)
        b = a;                                  /* one field: no pair to use it */
    double *cx = &M->cx[CONTACT_AXES * n], *cy = &M->cy[CONTACT_AXES * n];
    double ga[2] = {M->gx[a], M->gy[a]}, gb[2] = {M->gx[b], M->gy[b]}, c[2];
    double la = hypot(ga[0], ga[1]), lb = hypot(gb[0], gb[1]);
    cx[0] = la > 0 ? ga[0] / la : 0.0;
    cy[0] = la > 0 ? ga[1] / la : 0.0;
    cx[1] = lb > 0 ? -gb[0] / lb : 0.0;
    cy[1] = lb > 0 ? -gb[1] / lb : 0.0;
    int ok = contact_interface_normal(ga, gb, c);
    cx[2] = ok ? c[0] : 0.0;
    cy[2] = ok ? c[1] : 0.0;
    if (M->fit) {                               /* the pair to fit, from w = 0 */
        M->fit_pair[2 * n] = a;
        M->fit_pair[2 * n + 1] = b;
        memset(&M->fit[REGRESSION_DOUBLES * n], 0, sizeof(double) * 3);
    }
}

/// [regression_fit]
/** Point @p p's share of a pass of regression_fit(), at the nodes of
 *  @p own (NULL: all): a point of a node's first fitted field adds with
 *  the label 0, one of its second with 1, weighted by S_ip, at its
 *  position from the node in units of h = sqrt(dx dy). */
static inline __attribute__((always_inline)) void
fit_point(Sim *sim, void *state, int p, const Owned *own)
{
    MaterialContact *M = state;
    const FieldTable *F = &sim->fields;
    const Grid *g = &sim->grid;
    int node[STENCIL_NODES];
    Stencil buf;
    StencilRow st;
    double half[2], area, h = sqrt(g->dx * g->dy);
    if (!point_near(sim, M, p, node, &buf, &st, half, &area))
        return;
    for (int a = 0; a < STENCIL_NODES; a++) {
        int n = node[a], s = st.slot[a];
        if (F->first[n] < 0 || st.S[a] <= 0.0 || !owns(g, own, n))
            continue;
        const int *pair = &M->fit_pair[2 * n];
        if (pair[0] == pair[1] || (s != pair[0] && s != pair[1]))
            continue;                           /* one field, or a third */
        regression_add(&M->fit[REGRESSION_DOUBLES * n],
                       (sim->pts.x[p] - grid_node_x(g, n)) / h,
                       (sim->pts.y[p] - grid_node_y(g, n)) / h, st.S[a],
                       s == pair[1]);
    }
}

/** Task 2, NORMAL_REGRESSION: REGRESSION_NEWTON Newton steps of each
 *  node's fit, each from one pass over the points near the nodes (on
 *  threads by strips); the fitted normal then takes the place of the
 *  gradients' average among the node's candidates (pair_axis() keeps the
 *  one along which the pair lies farthest apart). */
static void regression_fit(Sim *sim, MaterialContact *M)
{
    const FieldTable *F = &sim->fields;
    for (int it = 0; it < REGRESSION_NEWTON; it++) {
#pragma omp parallel for num_threads(sim->threads) schedule(static)
        for (int k = 0; k < F->ntouched; k++)
            regression_clear(&M->fit[REGRESSION_DOUBLES * F->touched[k]]);
        near_scatter(sim, M, PASS_FIT);
#pragma omp parallel for num_threads(sim->threads) schedule(static)
        for (int k = 0; k < F->ntouched; k++)
            regression_newton(&M->fit[REGRESSION_DOUBLES * F->touched[k]]);
    }
#pragma omp parallel for num_threads(sim->threads) schedule(static)
    for (int k = 0; k < F->ntouched; k++) {
        int n = F->touched[k];
        double c[2];
        if (M->fit_pair[2 * n] == M->fit_pair[2 * n + 1] ||
            !regression_normal(&M->fit[REGRESSION_DOUBLES * n], c))
            continue;                           /* keep the gradients' */
        M->cx[CONTACT_AXES * n + 2] = c[0];    /* in place of the average */
        M->cy[CONTACT_AXES * n + 2] = c[1];
    }
}
/// [regression_fit]

/// [interface_reach]
/** Point @p p's share of interface_reach(), at the nodes of @p own (NULL:
 *  all), through @p wide (NULL: the cell's four nodes): a point covers
 *  x_p . c -/+ r_p along each candidate direction c of a node, r_p =
 *  |c_x| half_x + |c_y| half_y (its rectangle's half width). */
static inline __attribute__((always_inline)) void
reach_at(Sim *sim, MaterialContact *M, int p, const Owned *own, StencilFn wide)
{
    const FieldTable *F = &sim->fields;
    const Particles *P = &sim->pts;
    int node[STENCIL_MAX];
    Stencil buf;
    StencilRow st;
    double half[2], area;
    int nodes = point_nodes(sim, M, wide, p, node, &buf, &st, half, &area);
    for (int a = 0; a < nodes; a++) {
        int n = node[a], s = st.slot[a];
        if (F->first[n] < 0 || st.S[a] <= 0.0 || !owns(&sim->grid, own, n))
            continue;
        for (int k = 0; k < CONTACT_AXES; k++) {
            double cx = M->cx[CONTACT_AXES * n + k], cy = M->cy[CONTACT_AXES * n + k];
            double at = P->x[p] * cx + P->y[p] * cy;
            double r = fabs(cx) * half[0] + fabs(cy) * half[1];
            double *lo = &M->lo[CONTACT_AXES * s + k], *hi = &M->hi[CONTACT_AXES * s + k];
            *lo = fmin(*lo, at - r);
            *hi = fmax(*hi, at + r);
        }
    }
}

/** reach_at() through the cell's four nodes. Inlined in the one-thread
 *  loop, where @p own is a constant NULL. */
static inline __attribute__((always_inline)) void
reach_point(Sim *sim, void *state, int p, const Owned *own)
{
    reach_at(sim, state, p, own, NULL);
}

/** reach_at() through run.shape's stencil function (chapter 8). */
static inline __attribute__((always_inline)) void
reach_point_wide(Sim *sim, void *state, int p, const Owned *own)
{
    reach_at(sim, state, p, own, sim->scene.run.stencil);
}

/** The wide stencils' reaches, compiled on their own (chapter 8). */
static __attribute__((noinline)) void reaches_wide(Sim *sim, MaterialContact *M)
{
    contact_scatter_wide(sim, reach_point_wide, M);
}

/** Task 2, second pass: how far each field's points reach along each
 *  candidate direction of the node; on threads by strips, a thread writing
 *  its own nodes only (strip_scatter.h). */
static void interface_reach(Sim *sim, MaterialContact *M)
{
    if (sim->scene.run.stencil)                 /* another row of run.shape */
        reaches_wide(sim, M);
    else
        near_scatter(sim, M, PASS_REACH);
}
/// [interface_reach]

/// [near_points]
/** Task 2, before its scatters (linear stencils): the points in a cell
 *  beside a node with several fields (MaterialContact::near), in
 *  increasing index; on one thread from near_list[0] to near_end[0], on
 *  threads each strip's from its first place in Strips::list on, a point
 *  at the strip's edge as ~p. One pass over the points serves the two or
 *  three scatters that follow. */
static void near_points(Sim *sim, MaterialContact *M)
{
    const Strips *S = &sim->strips;
    const int *cell = sim->pts.cell;
    if (S->n == 0) {
        int m = 0;
        for (int p = 0, np = sim->pts.n; p < np; p++)
            if (M->near[cell[p]])
                M->near_list[m++] = p;
        M->near_end[0] = m;
        return;
    }
#pragma omp parallel for num_threads(sim->threads) schedule(static, 1)
    for (int t = 0; t < S->n; t++) {            /* strip_scatter()'s points */
        int m = S->start[t];
        for (int k = S->start[t]; k < S->start[t + 1]; k++) {
            int p = S->list[k];
            if (M->near[cell[p]])
                M->near_list[m++] = S->row_strips[S->code[p]] & 1 ? ~p : p;
        }
        M->near_end[t] = m;
    }
}

/** A near point's share of @p pass, to the nodes of @p own (NULL: all). */
static inline __attribute__((always_inline)) void
near_point(Sim *sim, MaterialContact *M, NearPass pass, int p, const Owned *own)
{
    if (pass == PASS_GRADIENT)
        gradient_point(sim, M, p, own);
    else if (pass == PASS_FIT)
        fit_point(sim, M, p, own);
    else
        reach_point(sim, M, p, own);
}

/** @p pass over the points of near_points(), as strip_scatter() would
 *  hand them (the others add nothing): each node sums in point order on
 *  any number of threads. */
static void near_scatter(Sim *sim, MaterialContact *M, NearPass pass)
{
    const Strips *S = &sim->strips;
    if (S->n == 0) {
        for (int k = 0; k < M->near_end[0]; k++)
            near_point(sim, M, pass, M->near_list[k], NULL);
        return;
    }
#pragma omp parallel for num_threads(sim->threads) schedule(static, 1)
    for (int t = 0; t < S->n; t++) {
        Owned own = {S->first_node[t], S->first_node[t + 1]};
        for (int k = S->start[t]; k < M->near_end[t]; k++) {
            int e = M->near_list[k];
            if (e < 0)                          /* at the strip's edge */
                near_point(sim, M, pass, ~e, &own);
            else
                near_point(sim, M, pass, e, NULL);
        }
    }
}
/// [near_points]

/** Task 2: the per-slot sums, the candidate directions and the reaches of
 *  this step. */
static int interface_geometry(Sim *sim, MaterialContact *M)
{
    const FieldTable *F = &sim->fields;
    const Grid *g = &sim->grid;
    if (reserve_slots(sim, M))
        return -1;
    /* on threads, the node loops too: a node writes its own slots */
#pragma omp parallel for num_threads(sim->threads) schedule(static)
    for (int k = 0; k < F->ntouched; k++)       /* the nodes with several fields */
        for (int s = F->touched[k]; s >= 0; s = field_next(F, g, s)) {
            M->gx[s] = M->gy[s] = M->va[s] = 0.0;
            for (int c = 0; c < CONTACT_AXES; c++) {
                M->lo[CONTACT_AXES * s + c] = HUGE_VAL;
                M->hi[CONTACT_AXES * s + c] = -HUGE_VAL;
            }
        }
    if (F->ntouched == 0)
        return 0;                               /* no node, no point near */
    mark_cells_around(M->near, F, g->nnx, 1);   /* and the cells around them */
    if (!sim->scene.run.stencil)               /* the linear scatters' */
        near_points(sim, M);
    mass_gradients(sim, M);
#pragma omp parallel for num_threads(sim->threads) schedule(static)
    for (int k = 0; k < F->ntouched; k++) {     /* eq. 8-10: the node's area */
        int n = F->touched[k];
        M->area[n] = 0.0;
        for (int s = n; s >= 0; s = field_next(F, g, s))
            M->area[n] += M->va[s];
        if (M->reach)
            candidate_axes(sim, M, n);
    }
    if (M->fit)
        regression_fit(sim, M);
    if (M->reach)
        interface_reach(sim, M);
    mark_cells_around(M->near, F, g->nnx, 0);   /* clean for the next step */
    return 0;
}

/// [pair_axis]
/** The normal @p n (from a to b) and the gap of fields @p a and @p b at
 *  node @p node: for a pair that detects by a gap, of the candidate
 *  directions, each turned to point from a to b (as g_a - g_b does), the
 *  one along which the two fields' points lie farthest apart (for convex
 *  bodies the separation is the largest gap over all directions, the
 *  separating-axis theorem); for the other rules, the average of
 *  contact_interface_normal(). @return 0 when no direction exists. */
static int pair_axis(const MaterialContact *M, int node, int a, int b,
                     const ContactLaw *law, double n[2], double *gap)
{
    double ga[2] = {M->gx[a], M->gy[a]}, gb[2] = {M->gx[b], M->gy[b]}, ab[2];
    if (!contact_interface_normal(ga, gb, ab))
        return 0;                               /* which side is which: unknown */
    if (law->detect != DETECT_GAP) {            /* the average, and no gap */
        n[0] = ab[0];
        n[1] = ab[1];
        *gap = 0.0;
        return 1;
    }
    int found = 0;
    for (int k = 0; k < CONTACT_AXES; k++) {
        double cx = M->cx[CONTACT_AXES * node + k], cy = M->cy[CONTACT_AXES * node + k];
        double along = cx * ab[0] + cy * ab[1];
        if (along == 0.0)
            continue;                           /* none, or across the pair */
        double sign = along > 0 ? 1.0 : -1.0;
        const double *lo = &M->lo[CONTACT_AXES * (sign > 0 ? b : a)];
        const double *hi = &M->hi[CONTACT_AXES * (sign > 0 ? a : b)];
        double g = lo[k] - hi[k];               /* the far one's near reach less
                                                   the near one's far reach */
        if (!found || g > *gap) {
            *gap = g;
            n[0] = sign * cx;
            n[1] = sign * cy;
            found = 1;
        }
    }
    return found;
}
/// [pair_axis]

/// [material_contact_task]
/** Tasks 2, 4 and 6 at the @p k-th touched node: its pairs of fields, in
 *  their order; the work of its sliding pairs (Task 4) summed in that
 *  order into MaterialContact::node_work[k]. Writes its own slots and
 *  decision only. @return 1 when it adjusted a pair that is not bonded. */
static int node_contact(Sim *sim, MaterialContact *M, Seam seam, int k)
{
    const FieldTable *F = &sim->fields;
    Grid *g = &sim->grid;
    unsigned gmask = M->group_mask;
    int n = F->touched[k], adjusted = 0, pair = 0;
    double vrel = M->area[n] / (g->dx * g->dy);  /* eq. 10, per unit thickness */
    double work = 0.0;
    if (seam == SEAM_TASK4_CONTACT)
        contact_decision_begin(&M->decision, n, sim->step);
    for (int a = n; a >= 0; a = field_next(F, g, a)) {
        unsigned ka = field_key(F, g, a);
        for (int b = field_next(F, g, a); b >= 0 && g->m[a] > 0;
             b = field_next(F, g, b)) {
            unsigned kb = field_key(F, g, b);
            int ga = (int)((ka >> M->shift) & gmask);
            int gb = (int)((kb >> M->shift) & gmask);
            if (g->m[b] <= 0 || ga == gb || (ka & M->side_mask) != (kb & M->side_mask))
                continue;                       /* same body, or across a crack */
            unsigned bit = pair < 32 ? 1u << pair : 0u;
            pair++;
            const ContactLaw *law = material_law(M, ga, gb);
            double nrm[2] = {0.0, 0.0}, gap = 0.0;
            if (law->kind != CONTACT_BONDED && !pair_axis(M, n, a, b, law, nrm, &gap))
                continue;
            if (seam == SEAM_TASK6_CONTACT) {   /* the step's decision */
                if (!contact_decision_held(&M->decision, n, bit, sim->step))
                    continue;
            } else if (seam == SEAM_TASK2_HELD &&
                       law->kind != CONTACT_BONDED) {   /* the last step's */
                if (!contact_decision_held(&M->decision, n, bit, sim->step - 1) ||
                    !contact_pair_detected(g, a, b, nrm, vrel, gap, sim->dt, law))
                    continue;
            } else if (!contact_pair_detected(g, a, b, nrm, vrel, gap, sim->dt,
                                              law)) {   /* at the step's end */
                continue;
            } else if (seam == SEAM_TASK4_CONTACT) {
                contact_decision_hold(&M->decision, n, bit);
            }
            double dp[2];
            int slides = contact_adjust(g, a, b, nrm, law, dp);
            if (seam == SEAM_TASK4_CONTACT && slides)  /* the change the points get */
                work += contact_friction_work(g, a, b, nrm, dp, sim->dt);
            adjusted |= law->kind != CONTACT_BONDED;
        }
    }
    M->node_work[k] = work;
    return adjusted;
}

int material_contact_task(Sim *sim, void *state, Seam seam)
{
    MaterialContact *M = state;
    const FieldTable *F = &sim->fields;
    int nodes = 0;
    if (M->geometry_step != sim->step) {        /* the step's first contact */
        if (interface_geometry(sim, M))
            return -1;
        M->geometry_step = sim->step;
    }
    /* on threads: a node writes its own slots, decision and work only */
#pragma omp parallel for num_threads(sim->threads) schedule(static) \
    reduction(+ : nodes)
    for (int k = 0; k < F->ntouched; k++)
        nodes += node_contact(sim, M, seam, k);
    M->task_nodes = nodes;
    if (seam == SEAM_TASK4_CONTACT) {           /* the step's decision */
        for (int k = 0; k < F->ntouched; k++)   /* in node order, any threads */
            M->work += M->node_work[k];
        M->nodes = M->task_nodes;
    }
    return 0;
}
/// [material_contact_task]

/// [material_contact_history]
int material_contact_history(const Sim *sim, void *state, FILE *f, int header)
{
    const MaterialContact *M = state;
    const Particles *P = &sim->pts;
    const Scene *sc = &sim->scene;
    if (header) {
        if (fprintf(f, ",material_contact_nodes,material_contact_work") < 0)
            return -1;
        for (int b = 0; b < sc->nbodies; b++)
            if (fprintf(f, ",momentum_x_%s,momentum_y_%s", sc->bodies[b].name,
                        sc->bodies[b].name) < 0)
                return -1;
        return 0;
    }
    if (fprintf(f, ",%d,%.*g", M->nodes, output_digits(sim, 10), M->work) < 0)
        return -1;
    for (int b = 0; b < sc->nbodies; b++) {    /* each body's momentum */
        double px = 0.0, py = 0.0;
        for (int p = 0; p < P->n; p++)
            if (P->body[p] == b) {
                px += P->m[p] * P->vx[p];
                py += P->m[p] * P->vy[p];
            }
        if (fprintf(f, ",%.*g,%.*g", output_digits(sim, 10), px,
                    output_digits(sim, 10), py) < 0)
            return -1;
    }
    return 0;
}
/// [material_contact_history]

double material_contact_energy(const Sim *sim, void *state, const char **name)
{
    (void)sim;
    *name = "contact between bodies";
    return -((const MaterialContact *)state)->work;  /* work <= 0: dissipated */
}

int material_contact_checkpoint(Sim *sim, void *state, FILE *f, int save)
{
    (void)sim;
    MaterialContact *M = state;
    return checkpoint_io(f, &M->work, sizeof M->work, save) ||
           checkpoint_io(f, &M->nodes, sizeof M->nodes, save) ||
           contact_decision_checkpoint(&M->decision, f, save) ? -1 : 0;
}
