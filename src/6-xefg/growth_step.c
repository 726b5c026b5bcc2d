/**
 * @file growth_step.c
 * @brief After each step, the tips that reach the criterion grow, one
 *        segment per tip per step: when by Rankine's sigma_1 >= f_t,
 *        where normal to sigma_1 or (direction = "hoop") by the largest
 *        hoop stress of K_I, K_II at the tip; with max_speed, not
 *        sooner than length / max_speed after the tip's last segment; a
 *        segment that would meet a crack stops the run (growth_meets()).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cohesive.h"
#include "growth.h"
#include "step.h"

/** Has the tip at end @p e of crack @p k grown less than @p wait ago
 *  (its last event in the list, which holds every event)? */
static int grew_within(const Growth *g, int k, int e, double t, double wait)
{
    for (int i = g->nevent - 1; i >= 0; i--)
        if (g->event[i].crack == k && g->event[i].end == e)
            return t - g->event[i].t < wait;
    return 0;                                     /* its first segment */
}

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
            if (growth_tip_stress(x, k, e, g->set[k].tip_radius[e], s) == 0)
                continue;
            crack_line_tip(&x->crack[k], e, tip, ahead);
            /* where: normal to sigma_1, the critical normal of the
             * acoustic tensor below, in closed form (det Q is flat to
             * fourth order there: acoustic_critical() finds it to 1e-4) */
            double s1 = growth_criterion(s, ahead, dir), K[2] = {0.0, 0.0};
            AcousticCritical ac;
            if (g->set[k].tip) {              /* when: the cohesive zone's tip */
                s1 = growth_tip_zone(g, x, k, e, L);
                if (!(s1 >= L->f_t))
                    continue;
            } else if (!growth_stability_lost(s, L->f_t, g->set[k].tangent[e],
                                              g->set[k].softening, &ac)) {
                continue;          /* when: the bulk's loss of stability */
            }
            if (g->set[k].max_speed > 0.0 &&       /* at most max_speed */
                grew_within(g, k, e, sim->t,
                            g->set[k].length / g->set[k].max_speed)) {
                g->waits++;
                continue;
            }
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
            int seg, met = growth_meets(x, g->h, k, e, tip,
                                        (double[2]){px, py}, &seg);
            if (met >= 0) {                  /* two tips meeting: stop */
                snprintf(g->msg, sizeof g->msg, "growth of crack %d "
                         "stopped: its new segment from (%g, %g) to (%g, %g) "
                         "meets crack %d (its segment %d); a crack that ends "
                         "on another needs a junction enrichment (Rabczuk and "
                         "Zi eq. 10), which XEFG here lacks; the crack met",
                         k, tip[0], tip[1], px, py, met, seg);
                return step_stop(sim, -1, g->msg, (double)met);
            }
            if (growth_insert(sim, x, g, k, e, px, py, g->msg,
                              sizeof g->msg - 16)) {
                strcat(g->msg, "; the crack");    /* " = k" follows */
                return step_stop(sim, -1, g->msg, (double)k);
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
