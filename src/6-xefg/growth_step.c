/**
 * @file growth_step.c
 * @brief After each step, the tips that reach the criterion grow, one
 *        segment per tip per step: when by Rankine's sigma_1 >= f_t,
 *        where normal to sigma_1 or (direction = "hoop") by the largest
 *        hoop stress of K_I, K_II at the tip.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cohesive.h"
#include "growth.h"
#include "step.h"

/// [growth_after_step]
int growth_after_step(Sim *sim, Xefg *x, Growth *g)
{
    for (int k = 0; k < g->ncrack && k < x->ncrack; k++) {
        if (!g->set[k].on)
            continue;
        const CohesiveLaw *L = &x->coh->set[k].law;
        for (int e = 0; e < 2; e++) {        /* at most one segment a tip */
            if (!x->crack[k].tip[e])
                continue;
            double s[3], tip[2], ahead[2], dir[2];
            if (growth_tip_stress(x, k, e, g->radius, s) == 0)
                continue;
            crack_line_tip(&x->crack[k], e, tip, ahead);
            double s1 = growth_criterion(s, ahead, dir), K[2] = {0.0, 0.0};
            if (g->set[k].tip)                /* when: the cohesive zone's tip */
                s1 = growth_tip_zone(g, x, k, e, L);
            if (!(s1 >= L->f_t))
                continue;                            /* when: Rankine */
            if (g->set[k].hoop &&                    /* where: hoop stress */
                growth_hoop_direction(sim, g, k, e, ahead, K, dir)) {
                snprintf(g->msg, sizeof g->msg, "K_I, K_II at a tip (no "
                         "Gauss point in the ring of r_d = %g to %g about "
                         "it, or two materials), direction = \"hoop\" of "
                         "crack", g->k_radius, 2.0 * g->k_radius);
                return step_fail(sim, -1, g->msg, (double)k);
            }
            double len = g->set[k].length;
            double px = tip[0] + len * dir[0], py = tip[1] + len * dir[1];
            if (growth_insert(sim, x, g, k, e, px, py, g->msg,
                              sizeof g->msg - 16)) {
                strcat(g->msg, "; the crack");    /* " = k" follows */
                return step_fail(sim, -1, g->msg, (double)k);
            }
            if (g->nevent < g->event_cap)
                g->event[g->nevent++] = (GrowthEvent){k, e, sim->step, sim->t,
                                                      s1, K[0], K[1], tip[0],
                                                      tip[1], px, py};
        }
    }
    return 0;
}
/// [growth_after_step]
