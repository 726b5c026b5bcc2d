/**
 * @file crack_fields.c
 * @brief Task 1 with cracks: the crack side of every particle-node pair
 *        that crosses a crack, as stage 2's part of the field key (eq. 2).
 */
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "cracks.h"
#include "step.h"

/** Hand the crossing @p hit of pair (@p p, @p a) to every subscriber. */
static int cracks_tell_crossed(Sim *sim, const Cracks *C, int p, int a,
                               const CrackHit *hit)
{
    for (int k = 0; k < C->ncrossed; k++)
        if (C->crossed[k].fn(sim, C, p, a, hit, C->crossed[k].state))
            return -1;
    return 0;
}

/// [cracks_key_fields]
/** The fields of point @p p's pairs into Cracks::pair_field (and the
 *  crossings into Cracks::pair_hit), through run.shape's stencil function
 *  @p wide, or NULL for the cell's four nodes, in rows of @p w pairs.
 *  @return nonzero when a pair is not in field 0. */
static inline __attribute__((always_inline)) int
point_fields(const Sim *sim, const Cracks *C, StencilFn wide, int w, int p)
{
    const Grid *g = &sim->grid;
    int cell = sim->pts.cell[p], any = 0, node[STENCIL_MAX];
    double px = sim->pts.x[p], py = sim->pts.y[p];
    signed char *field = &C->pair_field[w * p];
    CrackHit *hit = C->pair_hit ? &C->pair_hit[w * p] : NULL;
    if (!wide) {          /* the cell's corners, as grid_node_x() gives them */
        int i = cell % g->nnx, j = cell / g->nnx;
        double x0 = g->ox + i * g->dx, x1 = g->ox + (i + 1) * g->dx;
        double y0 = g->oy + j * g->dy, y1 = g->oy + (j + 1) * g->dy;
        double nx[STENCIL_NODES] = {x0, x1, x0, x1};
        double ny[STENCIL_NODES] = {y0, y0, y1, y1};   /* shape_cell_nodes() */
        if (C->search->visit_lines) {    /* the four lines in one visit */
            Crossings x[STENCIL_NODES];
            for (int a = 0; a < STENCIL_NODES; a++)
                x[a].n = x[a].lost = 0;
            C->search->visit_lines(C, cell, px, py, STENCIL_NODES, nx, ny, x);
            for (int a = 0; a < STENCIL_NODES; a++) {
                int f = crossings_field(&x[a], hit ? &hit[a] : NULL);
                field[a] = (signed char)f;
                any |= f;
            }
            return any;
        }
        for (int a = 0; a < STENCIL_NODES; a++) {
            int f = crack_field(C, cell, px, py, nx[a], ny[a], hit ? &hit[a] : NULL);
            field[a] = (signed char)f;
            any |= f;
        }
        return any;
    }
    int n = stencil_node_list(sim, wide, p, node);
    for (int a = 0; a < w; a++) {
        int f = a < n ? crack_field(C, cell, px, py, grid_node_x(g, node[a]),
                                    grid_node_y(g, node[a]), hit ? &hit[a] : NULL) : 0;
        field[a] = (signed char)f;
        any |= f;
    }
    return any;
}

/** point_fields() of the points @p from to @p to of @p list (or of the
 *  points of those indices, @p list NULL), keeping those that key a pair
 *  in @p keyed, in place from @p from. @return one past the last kept. */
static inline __attribute__((always_inline)) int
fields_range(const Sim *sim, const Cracks *C, StencilFn wide, int w,
             const int *list, int from, int to, int *keyed)
{
    int k = from;
    for (int i = from; i < to; i++) {
        int p = list ? list[i] : i;
        if (point_fields(sim, C, wide, w, p))
            keyed[k++] = p;
    }
    return k;
}

/** fields_range() through the cell's four nodes, compiled on its own (an
 *  OpenMP region's body does not see a constant NULL stencil function). */
static __attribute__((noinline)) int
fields_range_linear(const Sim *sim, const Cracks *C, const int *list, int from,
                    int to, int *keyed)
{
    return fields_range(sim, C, NULL, STENCIL_NODES, list, from, to, keyed);
}

/** fields_range() through run.shape's stencil function (chapter 8). */
static __attribute__((noinline)) int
fields_range_wide(const Sim *sim, const Cracks *C, const int *list, int from,
                  int to, int *keyed)
{
    return fields_range(sim, C, sim->scene.run.stencil, sim->fields.width,
                        list, from, to, keyed);
}

/** Task 1 over the pairs of every point near a crack, through run.shape's
 *  stencil function @p wide, or NULL for the cell's four nodes, in rows of
 *  @p w pairs (a constant STENCIL_NODES when linear). On threads: the
 *  points near a crack (Cracks::near_cell; all of them when the search
 *  keeps none), listed in point order; then their pairs' fields, the list
 *  cut evenly among the threads (a crack's points may be few, and all in
 *  one thread's share of the points), each thread keeping in place those
 *  that key a pair. On one thread, in point order: their rows (so that
 *  rows and slots come in the order they have on one thread); then the
 *  keys on threads, a row being its point's alone; then, on one thread in
 *  point order, the subscribers. */
static inline __attribute__((always_inline)) int
key_fields(Sim *sim, const Cracks *C, StencilFn wide, int w)
{
    const int *near_cell = C->near_cell, *cell = sim->pts.cell;
    int np = sim->pts.n, nnear = np, shares = 1, *list = C->keyed, *end = C->keyed_end;
    if (near_cell) {
#pragma omp parallel num_threads(sim->threads)
        {                   /* a share's near points, from its first index */
            int t = omp_get_thread_num(), nt = omp_get_num_threads();
            int k = (int)((long)np * t / nt), last = (int)((long)np * (t + 1) / nt);
            for (int p = k; p < last; p++)
                if (near_cell[cell[p]] >= 0)
                    list[k++] = p;
            end[t] = k;
            if (t == 0)
                shares = nt;
        }
        nnear = 0;
        for (int t = 0; t < shares; t++) {   /* one list, in point order */
            int from = (int)((long)np * t / shares);
            memmove(&list[nnear], &list[from], sizeof(int) * (size_t)(end[t] - from));
            nnear += end[t] - from;
        }
    }
#pragma omp parallel num_threads(sim->threads)
    {                       /* fields; the points that key, in place */
        int t = omp_get_thread_num(), nt = omp_get_num_threads();
        int from = (int)((long)nnear * t / nt), to = (int)((long)nnear * (t + 1) / nt);
        const int *near = near_cell ? list : NULL;
        end[t] = wide ? fields_range_wide(sim, C, near, from, to, list)
                      : fields_range_linear(sim, C, near, from, to, list);
        if (t == 0)
            shares = nt;
    }
    for (int t = 0; t < shares; t++)        /* rows, in point order */
        for (int k = (int)((long)nnear * t / shares); k < end[t]; k++) {
            int p = list[k];
            for (int a = 0; a < w; a++)
                if (C->pair_field[w * p + a] < 0) {
                    int node[STENCIL_MAX];
                    stencil_node_list(sim, wide, p, node);
                    return step_fail(sim, p, "crack crossings of one line (more "
                                     "than CROSSINGS_MAX)", node[a]);
                }
            if (fields_row(sim, p) < 0)
                return -1;
        }
#pragma omp parallel for num_threads(sim->threads) schedule(static, 1)
    for (int t = 0; t < shares; t++)        /* keys: a row is its point's */
        for (int k = (int)((long)nnear * t / shares); k < end[t]; k++) {
            int p = list[k], r = sim->fields.row_of[p];
            for (int a = 0; a < w; a++)
                if (C->pair_field[w * p + a] > 0)
                    fields_row_key(&sim->fields, r, a, (unsigned)C->pair_field[w * p + a]
                                                           << C->side_shift);
        }
    for (int t = 0; C->ncrossed && t < shares; t++)   /* later stages' */
        for (int k = (int)((long)nnear * t / shares); k < end[t]; k++) {
            int p = list[k];
            for (int a = 0; a < w; a++)
                if (C->pair_field[w * p + a] > 0 &&
                    cracks_tell_crossed(sim, C, p, a, &C->pair_hit[w * p + a]))
                    return -1;               /* subscribers, in point order */
        }
    return 0;
}

/** Task 1 through the cell's four nodes (the paper's), compiled on its
 *  own so that a scene without a wider stencil runs the code it ran
 *  before chapter 8. */
static __attribute__((noinline)) int key_fields_linear(Sim *sim, const Cracks *C)
{
    return key_fields(sim, C, NULL, STENCIL_NODES);
}

/** Task 1 through run.shape's stencil function (chapter 8). */
static __attribute__((noinline)) int key_fields_wide(Sim *sim, const Cracks *C)
{
    return key_fields(sim, C, sim->scene.run.stencil, sim->fields.width);
}

int cracks_key_fields(Sim *sim, void *state, Seam seam)
{
    (void)seam;
    if (sim->scene.run.stencil)              /* another row of run.shape */
        return key_fields_wide(sim, state);
    return key_fields_linear(sim, state);    /* the paper's four nodes */
}
/// [cracks_key_fields]

int cracks_on_crossed(const Sim *sim, Cracks *C, CrossedHook fn, void *state)
{
    if (C->ncrossed >= CRACKS_CROSSED_MAX)
        return -1;
    if (!C->pair_hit &&
        !(C->pair_hit = malloc(sizeof(CrackHit) * (size_t)sim->fields.width *
                               (size_t)(sim->pts.n + 1))))
        return -1;
    C->crossed[C->ncrossed].fn = fn;
    C->crossed[C->ncrossed].state = state;
    C->ncrossed++;
    return 0;
}

int cracks_multi_field_nodes(const Sim *sim)
{
    return fields_multi_field_nodes(sim);
}
