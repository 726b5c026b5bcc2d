/**
 * @file growth_tip_zone.c
 * @brief When a tip grows under criterion = "tip" (our choice; chapter
 *        6b, "Petersson's beam"): when the cohesive zone's own tip, where
 *        the traction reaches f_t, has come into the crack's last segment
 *        (one of its cohesive points leaves the elastic branch), not when
 *        the stress averaged ahead of the crack's end reaches f_t: ahead
 *        of a cohesive zone the stress is bounded by f_t, so that average
 *        stays below it and the crack stalls.
 */
#include <math.h>

#include "cohesive.h"
#include "growth.h"

/// [growth_tip_zone]
double growth_tip_zone(const Growth *g, const Xefg *x, int c, int end,
                       const CohesiveLaw *L)
{
    const CrackLine *l = &x->crack[c];
    int i = end ? l->n - 1 : 0, j = end ? l->n - 2 : 1;
    double tip[2] = {l->x[i], l->y[i]}, prev[2] = {l->x[j], l->y[j]};
    double seg = hypot(tip[0] - prev[0], tip[1] - prev[1]), most = -1.0;
    const Cohesive *C = x->coh;
    for (int p = 0; C && p < C->npt; p++)   /* the last segment's points */
        if (C->crack[p] == c &&
            growth_segment_distance(prev, tip, C->px[p], C->py[p]) <=
                1e-9 * seg)
            most = fmax(most, C->dmax[p]);
    if (most >= 0.0)            /* K dmax: f_t where softening begins */
        return L->f_t * most / cohesive_delta0(L);
    double s[3], ahead[2], dir[2];  /* a notch: the Gauss points nearest */
    if (growth_tip_stress(x, c, end, 0.5 * g->h, s) == 0)
        return NAN;
    crack_line_tip(l, end, tip, ahead);
    return growth_criterion(s, ahead, dir);
}
/// [growth_tip_zone]
