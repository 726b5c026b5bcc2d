/**
 * @file crack_fields.c
 * @brief Task 1 with cracks: the crack side of every particle-node pair
 *        that crosses a crack, as stage 2's part of the field key (eq. 2).
 */
#include "cracks.h"
#include "step.h"

/// [cracks_key_fields]
int cracks_key_fields(Sim *sim, void *state, Seam seam)
{
    const Cracks *C = state;
    const Grid *g = &sim->grid;
    const Particles *P = &sim->pts;
    (void)seam;
    for (int p = 0; p < P->n; p++) {
        int node[STENCIL_NODES], cell = P->cell[p];
        if (C->near_cell && C->near_cell[cell] < 0)
            continue;                        /* no crack near: field 0 */
        stencil_nodes(sim, p, node);
        for (int a = 0; a < STENCIL_NODES; a++) {
            CrackHit hit;
            int f = crack_field(C, cell, P->x[p], P->y[p], grid_node_x(g, node[a]),
                                grid_node_y(g, node[a]), &hit);
            if (f < 0)
                return step_fail(sim, p, "crack crossings of one line (more "
                                 "than CROSSINGS_MAX)", node[a]);
            if (!f)
                continue;                    /* field 0: nothing to key */
            if (fields_key(sim, p, a, (unsigned)f << C->side_shift))
                return -1;
            if (C->crossed && C->crossed(sim, C, p, a, &hit))
                return -1;                   /* a later stage's subscriber */
        }
    }
    return 0;
}
/// [cracks_key_fields]

int cracks_multi_field_nodes(const Sim *sim)
{
    return fields_multi_field_nodes(sim);
}
