/**
 * @file crack_contact.c
 * @brief Crack-surface contact at the nodes (section 2.2, eq. 8-19): the
 *        fields of a node on the two sides of a crack, their normal, the
 *        relative volume, detection, and the momentum change.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "checkpoint.h"
#include "contact_stencil.h"
#include "crack_contact.h"
#include "output.h"
#include "step.h"
#include "strip_scatter.h"

int crack_contact_prepare(Sim *sim, void *state, char *err, size_t errlen)
{
    ContactState *S = state;
    Cracks *C = cracks_of(sim);
    const Scene *sc = &sim->scene;
    S->vnode = calloc((size_t)sim->grid.nnodes, sizeof(double));
    S->node_work = calloc((size_t)sim->grid.nnodes, sizeof(double));
    S->volumes_step = -1;
    if (cracks_on_crossed(sim, C, sc->run.stencil ? crack_normals_crossed_wide
                                                  : crack_normals_crossed,
                          &S->normals)) {
        snprintf(err, errlen, "%s: crack contact: more than %d subscribers to "
                 "the crack crossings, or out of memory", sc->file,
                 CRACKS_CROSSED_MAX);
        return -1;
    }
    if (crack_normals_alloc(&S->normals, sim) || !S->vnode || !S->node_work ||
        contact_decision_alloc(&S->decision, sim->grid.nnodes)) {
        snprintf(err, errlen, "%s: out of memory for crack contact", sc->file);
        return -1;
    }
    for (int k = 0; k < S->ncracks; k++)
        S->opening |= S->crack[k].law.kind != CONTACT_NONE &&
                      S->crack[k].law.detect == DETECT_OPENING;
    if (S->opening) {                        /* the faces start closed */
        size_t n = (size_t)(sim->pts.n > 0 ? sim->pts.n : 1);
        S->x0 = malloc(n * sizeof(double));
        S->y0 = malloc(n * sizeof(double));
        if (!S->x0 || !S->y0) {
            snprintf(err, errlen, "%s: out of memory for crack contact", sc->file);
            return -1;
        }
        memcpy(S->x0, sim->pts.x, (size_t)sim->pts.n * sizeof(double));
        memcpy(S->y0, sim->pts.y, (size_t)sim->pts.n * sizeof(double));
    }
    /* eq. 10: the undeformed cell volume, with the thickness of the body
       the crack lies in (cracks_prepare found one holding a crack point) */
    for (int k = 0; k < S->ncracks; k++) {
        const Crack *c = &C->crack[k];
        double t = 0;
        for (int j = 0; j < c->n && t == 0; j++)
            for (int b = 0; b < sc->nbodies && t == 0; b++)
                if (shape_contains(&sc->bodies[b].shape, c->x[j], c->y[j]))
                    t = sc->bodies[b].thickness;
        S->crack[k].vcell = sim->grid.dx * sim->grid.dy * t;
    }
    return 0;
}

/** The normal of extra slot @p s (the sum of its pairs' unit normals,
 *  above to below) added to (nx, ny). */
static void add_slot_normal(const Sim *sim, const ContactState *S, int s,
                            double *nx, double *ny)
{
    int e = s - sim->grid.nnodes;
    *nx += S->normals.nx[e];
    *ny += S->normals.ny[e];
}

/** Room for the per-slot displacement sums (grown with the grid's slots). */
static int reserve_slots(Sim *sim, ContactState *S)
{
    int cap = sim->grid.capacity;
    if (cap <= S->cap)
        return 0;
    double *x = realloc(S->ux, sizeof(double) * (size_t)cap);
    if (x)
        S->ux = x;
    double *y = realloc(S->uy, sizeof(double) * (size_t)cap);
    if (y)
        S->uy = y;
    if (!x || !y)
        return step_fail(sim, 0, "memory for crack openings", cap);
    S->cap = cap;
    return 0;
}

/// [node_volumes]
/** Point @p p's share of node_volumes(), to the nodes of @p own (NULL:
 *  all), through @p wide, run.shape's stencil function, or NULL for the
 *  cell's four nodes (contact_stencil.h). */
static inline __attribute__((always_inline)) void
volume_at(Sim *sim, ContactState *S, int p, const Owned *own, StencilFn wide)
{
    const FieldTable *F = &sim->fields;
    const Particles *P = &sim->pts;
    int node[STENCIL_MAX];
    Stencil buf;
    StencilRow st;
    int n = contact_stencil(sim, wide, p, node, &buf, &st);
    if (!n)
        return;
    double v = (1.0 + P->exx[p]) * (1.0 + P->eyy[p]) * P->vol[p];
    double mux = S->opening ? P->m[p] * (P->x[p] - S->x0[p]) : 0.0;
    double muy = S->opening ? P->m[p] * (P->y[p] - S->y0[p]) : 0.0;
    for (int a = 0; a < n; a++)
        if (F->first[node[a]] >= 0 && owns(&sim->grid, own, node[a])) {
            S->vnode[node[a]] += v * st.S[a];
            if (S->opening) {
                S->ux[st.slot[a]] += mux * st.S[a];
                S->uy[st.slot[a]] += muy * st.S[a];
            }
        }
}

/** volume_at() through the cell's four nodes. Inlined in the one-thread
 *  loop, where @p own is a constant NULL. */
static inline __attribute__((always_inline)) void
volume_point(Sim *sim, void *state, int p, const Owned *own)
{
    volume_at(sim, state, p, own, NULL);
}

/** volume_at() through run.shape's stencil function (chapter 8). */
static inline __attribute__((always_inline)) void
volume_point_wide(Sim *sim, void *state, int p, const Owned *own)
{
    volume_at(sim, state, p, own, sim->scene.run.stencil);
}

/** The wide stencils' scatter, compiled on its own (chapter 8). */
static __attribute__((noinline)) void volumes_wide(Sim *sim, ContactState *S)
{
    contact_scatter_wide(sim, volume_point_wide, S);
}

/** Eq. 8-9 at the nodes that carry extra fields this step (the only ones
 *  where contact is possible): V_i = sum_p V_p S_ip with the current point
 *  volume V_p = (1 + e_xx)(1 + e_yy) m_p / rho_p; and, for the opening
 *  rule, each field's sum_p m_p S_ip u_p of the points' displacements. A
 *  point none of whose nodes has extra fields costs four integer tests (a
 *  wider stencil's: the stencil and a test per node).
 *  On threads by strips, each node summing in point order as on one
 *  (strip_scatter.h). */
static int node_volumes(Sim *sim, ContactState *S)
{
    const FieldTable *F = &sim->fields;
    const Grid *g = &sim->grid;
    if (S->opening && reserve_slots(sim, S))
        return -1;
#pragma omp parallel for num_threads(sim->threads) schedule(static)
    for (int k = 0; k < F->ntouched; k++) {  /* a node clears its own */
        S->vnode[F->touched[k]] = 0.0;
        for (int s = F->touched[k]; s >= 0 && S->opening; s = field_next(F, g, s))
            S->ux[s] = S->uy[s] = 0.0;
    }
    if (sim->scene.run.stencil)              /* another row of run.shape */
        volumes_wide(sim, S);
    else if (sim->strips.n > 0)
        strip_scatter(sim, volume_point, S);
    else
        for (int p = 0, np = sim->pts.n; p < np; p++)
            volume_point(sim, S, p, NULL);
    return 0;
}
/// [node_volumes]

/** A node's visit at a task: what its pairs share (one per node, so that
 *  nodes run on threads). */
typedef struct NodeVisit {
    Seam seam;            /**< the task being done */
    int node;             /**< the node */
    int pair;             /**< pairs of fields met at the node so far */
    int adjusted;         /**< a pair was adjusted */
    double work;          /**< its pairs' work at Task 4, in their order */
} NodeVisit;

/// [contact_pair]
/** Contact between field @p a (above the crack) and field @p b (below) at
 *  a node of volume @p vnode, across crack @p tag whose normal is the
 *  direction of (nx, ny): detect (eq. 10-12), adjust (eq. 13-19). */
static void contact_pair(Sim *sim, ContactState *S, NodeVisit *v, int a,
                         int b, double nx, double ny, int tag, double vnode)
{
    Grid *g = &sim->grid;
    const CrackContact *cc = tag >= 0 && tag < S->ncracks ? &S->crack[tag] : NULL;
    double len = sqrt(nx * nx + ny * ny);
    if (!cc || cc->law.kind == CONTACT_NONE || !(len > 0))
        return;
    double n[2] = {nx / len, ny / len};
    double opening = 0.0;                    /* b's displacement less a's, along n */
    if (cc->law.detect == DETECT_OPENING)
        opening = (S->ux[b] / g->m[b] - S->ux[a] / g->m[a]) * n[0] +
                  (S->uy[b] / g->m[b] - S->uy[a] / g->m[a]) * n[1];
    unsigned bit = v->pair < 32 ? 1u << v->pair : 0u;
    v->pair++;
    if (v->seam == SEAM_TASK6_CONTACT) {     /* the step's decision */
        if (!contact_decision_held(&S->decision, v->node, bit, sim->step))
            return;
    } else if (v->seam == SEAM_TASK2_HELD &&
               cc->law.kind != CONTACT_BONDED) {   /* the last step's */
        if (!contact_decision_held(&S->decision, v->node, bit, sim->step - 1) ||
            !contact_pair_detected(g, a, b, n, vnode / cc->vcell, opening, sim->dt,
                                   &cc->law))
            return;
    } else if (!contact_pair_detected(g, a, b, n, vnode / cc->vcell, opening,
                                       sim->dt, &cc->law)) {  /* at the step's end */
        return;
    } else if (v->seam == SEAM_TASK4_CONTACT) {
        contact_decision_hold(&S->decision, v->node, bit);
    }
    double dp[2];
    int slides = contact_adjust(g, a, b, n, &cc->law, dp);
    if (v->seam == SEAM_TASK4_CONTACT && slides)       /* the change the points get */
        v->work += contact_friction_work(g, a, b, n, dp, sim->dt);
    v->adjusted = 1;
}
/// [contact_pair]

/** Contact across the crack between the fields @p f (sides 0, 1, 2; -1
 *  when absent) of one body at a node of volume @p vnode. */
static void crack_contact_fields(Sim *sim, ContactState *S, NodeVisit *v,
                                 const int f[3], double vnode)
{
    const int *tag = S->normals.tag;
    int nn = sim->grid.nnodes;
    if (f[0] < 0 && f[1] >= 0 && f[2] >= 0) {     /* both sides crossed */
        double nx = 0, ny = 0;
        add_slot_normal(sim, S, f[1], &nx, &ny);
        add_slot_normal(sim, S, f[2], &nx, &ny);
        int t1 = tag[f[1] - nn], t2 = tag[f[2] - nn];
        contact_pair(sim, S, v, f[1], f[2], nx, ny, t1 < t2 ? t1 : t2, vnode);
        return;
    }
    for (int side = 1; side <= 2; side++) {       /* field 0 against 1, 2 */
        if (f[0] < 0 || f[side] < 0)
            continue;
        double nx = 0, ny = 0;
        add_slot_normal(sim, S, f[side], &nx, &ny);
        int t = tag[f[side] - nn];
        if (side == 1)                   /* above the crack: field 1 */
            contact_pair(sim, S, v, f[1], f[0], nx, ny, t, vnode);
        else                             /* the node's side is above */
            contact_pair(sim, S, v, f[0], f[2], nx, ny, t, vnode);
    }
}

/// [crack_contact_task]
/** The @p k-th touched node at task @p seam: its bodies' fields across the
 *  crack (the side at bit @p side_shift of the key); writes its own slots,
 *  decision and S->node_work[k] only. @return 1 when a pair was adjusted. */
static int crack_contact_node(Sim *sim, ContactState *S, Seam seam, int k,
                              int side_shift)
{
    const FieldTable *F = &sim->fields;
    const Grid *g = &sim->grid;
    unsigned side_mask = 3u << side_shift;
    NodeVisit v = {seam, F->touched[k], 0, 0, 0.0};
    double vnode = S->vnode[v.node];         /* eq. 8: the node's total volume */
    if (seam == SEAM_TASK4_CONTACT)
        contact_decision_begin(&S->decision, v.node, sim->step);
    /* a node's slots are sorted by key: those of one body (the key's
       bits beyond the crack side) come together, sides 0, 1, 2 */
    for (int s = v.node; s >= 0;) {
        unsigned body = field_key(F, g, s) & ~side_mask;
        int f[3] = {-1, -1, -1};
        for (; s >= 0 && (field_key(F, g, s) & ~side_mask) == body;
             s = field_next(F, g, s))
            if (g->m[s] > 0)
                f[(field_key(F, g, s) & side_mask) >> side_shift] = s;
        crack_contact_fields(sim, S, &v, f, vnode);
    }
    S->node_work[k] = v.work;
    return v.adjusted;
}

int crack_contact_task(Sim *sim, void *state, Seam seam)
{
    ContactState *S = state;
    const FieldTable *F = &sim->fields;
    int nodes = 0, side_shift = cracks_of(sim)->side_shift;
    if (S->volumes_step != sim->step) {      /* the step's first contact */
        if (crack_normals_sum(sim, &S->normals) || node_volumes(sim, S))
            return -1;
        S->volumes_step = sim->step;
    }
    /* on threads: a node writes its own slots, decision and work only */
#pragma omp parallel for num_threads(sim->threads) schedule(static) \
    reduction(+ : nodes)
    for (int k = 0; k < F->ntouched; k++)
        nodes += crack_contact_node(sim, S, seam, k, side_shift);
    S->task_nodes = nodes;
    if (seam == SEAM_TASK4_CONTACT) {        /* the step's decision */
        for (int k = 0; k < F->ntouched; k++)    /* in node order, any threads */
            S->work += S->node_work[k];
        S->nodes = S->task_nodes;
    }
    return 0;
}
/// [crack_contact_task]

int crack_contact_history(const Sim *sim, void *state, FILE *f, int header)
{
    const ContactState *S = state;
    if (header)
        return fprintf(f, ",contact_nodes,contact_work") < 0 ? -1 : 0;
    return fprintf(f, ",%d,%.*g", S->nodes, output_digits(sim, 10), S->work) < 0
               ? -1 : 0;
}

double crack_contact_energy(const Sim *sim, void *state, const char **name)
{
    (void)sim;
    *name = "crack contact";
    return -((const ContactState *)state)->work;   /* work <= 0: dissipated */
}

int crack_contact_checkpoint(Sim *sim, void *state, FILE *f, int save)
{
    ContactState *S = state;
    size_t n = (size_t)sim->pts.n * sizeof(double);
    return checkpoint_io(f, &S->work, sizeof S->work, save) ||
           checkpoint_io(f, &S->nodes, sizeof S->nodes, save) ||
           contact_decision_checkpoint(&S->decision, f, save) ||
           (S->opening && (checkpoint_io(f, S->x0, n, save) ||
                           checkpoint_io(f, S->y0, n, save))) ? -1 : 0;
}
