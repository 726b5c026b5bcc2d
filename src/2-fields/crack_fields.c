/**
 * @file crack_fields.c
 * @brief Task 1 with cracks: the crack side of every particle-node pair
 *        that crosses a crack, as stage 2's part of the field key (eq. 2).
 */
#include <omp.h>
#include <stdlib.h>

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
/** Task 1 over the pairs of every point near a crack, through run.shape's
 *  stencil function @p wide, or NULL for the cell's four nodes, in rows of
 *  @p w pairs (a constant STENCIL_NODES when linear): each pair's field on
 *  threads (a point writes its own Cracks::pair_field; a thread lists the
 *  points of its share that key a pair), then the keys and the
 *  subscribers on one thread, share after share: in point order, so that
 *  the rows and slots come in the order they have on one thread. */
static inline __attribute__((always_inline)) int
key_fields(Sim *sim, const Cracks *C, StencilFn wide, int w)
{
    const Grid *g = &sim->grid;
    const Particles *P = &sim->pts;
    int np = P->n, shares = 1;
#pragma omp parallel num_threads(sim->threads)
    {
        int t = omp_get_thread_num(), nt = omp_get_num_threads();
        int k = (int)((long)np * t / nt), end = (int)((long)np * (t + 1) / nt);
        for (int p = k; p < end; p++) {
            int node[STENCIL_MAX], cell = P->cell[p], any = 0;
            if (C->near_cell && C->near_cell[cell] < 0)
                continue;                    /* no crack near: field 0 */
            int n = stencil_node_list(sim, wide, p, node);
            for (int a = 0; a < w; a++) {
                CrackHit hit;
                int f = a < n ? crack_field(C, cell, P->x[p], P->y[p],
                                            grid_node_x(g, node[a]),
                                            grid_node_y(g, node[a]), &hit) : 0;
                C->pair_field[w * p + a] = (signed char)f;
                if (f > 0 && C->pair_hit)
                    C->pair_hit[w * p + a] = hit;
                any |= f;
            }
            if (any)
                C->keyed[k++] = p;
        }
        C->keyed_end[t] = k;
        if (t == 0)
            shares = nt;
    }
    for (int t = 0; t < shares; t++)
        for (int k = (int)((long)np * t / shares); k < C->keyed_end[t]; k++) {
            int p = C->keyed[k];
            for (int a = 0; a < w; a++) {
                int f = C->pair_field[w * p + a];
                if (!f)
                    continue;                /* field 0: nothing to key */
                if (f < 0) {
                    int node[STENCIL_MAX];
                    stencil_node_list(sim, wide, p, node);
                    return step_fail(sim, p, "crack crossings of one line (more "
                                     "than CROSSINGS_MAX)", node[a]);
                }
                unsigned key = (unsigned)f << C->side_shift;
                if (wide ? fields_key_wide(sim, p, a, key) : fields_key(sim, p, a, key))
                    return -1;
                if (C->ncrossed && cracks_tell_crossed(sim, C, p, a, &C->pair_hit[w * p + a]))
                    return -1;               /* later stages' subscribers */
            }
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
