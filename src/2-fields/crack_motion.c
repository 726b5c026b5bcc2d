/**
 * @file crack_motion.c
 * @brief Task 7: crack points move as massless material points with the
 *        centre-of-mass velocity of the nodes (eq. 7 and 32).
 */
#include "cracks.h"
#include "step.h"

/// [node_cm_velocity]
/** Centre-of-mass velocity of node @p n over all its fields (eq. 32). */
static void node_cm_velocity(const Sim *sim, int n, double *vx, double *vy)
{
    const Grid *g = &sim->grid;
    double m = g->m[n], px = g->px[n], py = g->py[n];
    for (int s = field_next(&sim->fields, g, n); s >= 0;
         s = field_next(&sim->fields, g, s)) {
        m += g->m[s];
        px += g->px[s];
        py += g->py[s];
    }
    *vx = m > 0 ? px / m : 0.0;
    *vy = m > 0 ? py / m : 0.0;
}
/// [node_cm_velocity]

/// [cracks_move]
int cracks_move(Sim *sim)
{
    Cracks *C = cracks_of(sim);
    const Grid *g = &sim->grid;
    double xmax = g->ox + g->ncx * g->dx, ymax = g->oy + g->ncy * g->dy;
    for (int k = 0; k < C->ncracks; k++) {
        Crack *c = &C->crack[k];
        for (int j = 0; j < c->n; j++) {
            Stencil st;
            double vx = 0, vy = 0;
            stencil_at(g, c->x[j], c->y[j], &st);
            for (int a = 0; a < STENCIL_NODES; a++) {
                double nvx, nvy;
                node_cm_velocity(sim, st.slot[a], &nvx, &nvy);
                vx += st.S[a] * nvx;
                vy += st.S[a] * nvy;
            }
            c->x[j] += sim->dt * vx;
            c->y[j] += sim->dt * vy;
            if (!(c->x[j] >= g->ox && c->x[j] < xmax && c->y[j] >= g->oy &&
                  c->y[j] < ymax))
                return step_fail(sim, -1, "crack point (left the grid)", c->x[j]);
        }
        crack_extent(c);
    }
    return 0;
}
/// [cracks_move]
