/**
 * @file fields.c
 * @brief Task 1 with cracks: the field v(p,i) of every particle-node pair
 *        and the extra grid slots of fields 1 and 2 (eq. 2, 26).
 */
#include <string.h>

#include "cracks.h"
#include "shape.h"
#include "step.h"

/** Slot of field @p f (1 or 2) at node @p n, created on first use;
 *  -1 when the reserved slots are used up. */
static int field_slot(Sim *sim, Cracks *C, int n, int f)
{
    Grid *g = &sim->grid;
    int *slot = &C->node_field[2 * n + f - 1];
    if (*slot >= 0)
        return *slot;
    if (g->nslots == g->capacity)
        return -1;
    if (C->node_field[2 * n] < 0 && C->node_field[2 * n + 1] < 0)
        C->touched[C->ntouched++] = n;
    int s = g->nslots++;
    g->slot_node[s - g->nnodes] = n;
    g->m[s] = g->px[s] = g->py[s] = g->fx[s] = g->fy[s] = 0.0;
    *slot = s;
    return s;
}

/// [cracks_assign_fields]
int cracks_assign_fields(Sim *sim)
{
    Cracks *C = cracks_of(sim);
    Grid *g = &sim->grid;
    const Particles *P = &sim->pts;
    for (int k = 0; k < C->ntouched; k++) {      /* Task 8: forget last step's */
        C->node_field[2 * C->touched[k]] = -1;
        C->node_field[2 * C->touched[k] + 1] = -1;
    }
    C->ntouched = 0;
    g->nslots = g->nnodes;
    for (int p = 0; p < P->n; p++) {
        int node[4];
        unsigned bits = 0;
        shape_cell_nodes(g, P->cell[p], node);
        for (int a = 0; a < 4; a++) {
            int f = crack_field(C, P->x[p], P->y[p], grid_node_x(g, node[a]),
                                grid_node_y(g, node[a]));
            if (!f)
                continue;
            if (field_slot(sim, C, node[a], f) < 0)
                return step_fail(sim, p, "crack velocity fields (more nodes "
                                 "near cracks than reserved)", node[a]);
            bits |= (unsigned)f << (2 * a);
        }
        C->pair[p] = (unsigned char)bits;
    }
    return 0;
}
/// [cracks_assign_fields]

/// [cracks_pair_slots]
void cracks_pair_slots(const Sim *sim, int p, int slot[4])
{
    const Cracks *C = cracks_of(sim);
    unsigned bits = C->pair[p];
    if (!bits)
        return;                                  /* all four pairs in field 0 */
    for (int a = 0; a < 4; a++) {
        unsigned f = (bits >> (2 * a)) & 3u;
        if (f)
            slot[a] = C->node_field[2 * slot[a] + (int)f - 1];
    }
}
/// [cracks_pair_slots]

int cracks_multi_field_nodes(const Sim *sim)
{
    const Cracks *C = cracks_of(sim);
    const Grid *g = &sim->grid;
    int count = 0;
    for (int k = 0; k < C->ntouched; k++) {
        int n = C->touched[k], fields = g->m[n] > 0;
        for (int f = 0; f < 2; f++) {
            int s = C->node_field[2 * n + f];
            fields += s >= 0 && g->m[s] > 0;
        }
        count += fields > 1;
    }
    return count;
}
