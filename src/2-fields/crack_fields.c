/**
 * @file crack_fields.c
 * @brief Task 1 with cracks: the crack side of every particle-node pair
 *        that crosses a crack, as stage 2's part of the field key (eq. 2).
 */
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
 *  stencil function @p wide, or NULL for the cell's four nodes. */
static inline __attribute__((always_inline)) int
key_fields(Sim *sim, const Cracks *C, StencilFn wide)
{
    const Grid *g = &sim->grid;
    const Particles *P = &sim->pts;
    for (int p = 0; p < P->n; p++) {
        int node[STENCIL_MAX], cell = P->cell[p];
        if (C->near_cell && C->near_cell[cell] < 0)
            continue;                        /* no crack near: field 0 */
        int n = stencil_node_list(sim, wide, p, node);
        for (int a = 0; a < n; a++) {
            CrackHit hit;
            int f = crack_field(C, cell, P->x[p], P->y[p], grid_node_x(g, node[a]),
                                grid_node_y(g, node[a]), &hit);
            if (f < 0)
                return step_fail(sim, p, "crack crossings of one line (more "
                                 "than CROSSINGS_MAX)", node[a]);
            if (!f)
                continue;                    /* field 0: nothing to key */
            unsigned key = (unsigned)f << C->side_shift;
            if (wide ? fields_key_wide(sim, p, a, key) : fields_key(sim, p, a, key))
                return -1;
            if (C->ncrossed && cracks_tell_crossed(sim, C, p, a, &hit))
                return -1;                   /* later stages' subscribers */
        }
    }
    return 0;
}

/** Task 1 through the cell's four nodes (the paper's), compiled on its
 *  own so that a scene without a wider stencil runs the code it ran
 *  before chapter 8. */
static __attribute__((noinline)) int key_fields_linear(Sim *sim, const Cracks *C)
{
    return key_fields(sim, C, NULL);
}

/** Task 1 through run.shape's stencil function (chapter 8). */
static __attribute__((noinline)) int key_fields_wide(Sim *sim, const Cracks *C)
{
    return key_fields(sim, C, sim->scene.run.stencil);
}

int cracks_key_fields(Sim *sim, void *state, Seam seam)
{
    (void)seam;
    if (sim->scene.run.stencil)              /* another row of run.shape */
        return key_fields_wide(sim, state);
    return key_fields_linear(sim, state);    /* the paper's four nodes */
}
/// [cracks_key_fields]

int cracks_on_crossed(Cracks *C, CrossedHook fn, void *state)
{
    if (C->ncrossed >= CRACKS_CROSSED_MAX)
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
