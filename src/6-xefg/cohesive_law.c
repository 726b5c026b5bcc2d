/**
 * @file cohesive_law.c
 * @brief The traction-separation law (xefg.md 2.3; our choice, the paper's
 *        law is beyond our transcript): a penalty branch, then linear or
 *        exponential softening whose whole area is G_f; secant unloading.
 */
#include <math.h>

#include "cohesive_law.h"

double cohesive_delta0(const CohesiveLaw *L)
{
    return L->f_t / L->K;
}

/// [cohesive_envelope]
double cohesive_delta_c(const CohesiveLaw *L)
{
    return L->kind == COHESIVE_LINEAR ? 2.0 * L->G_f / L->f_t : INFINITY;
}

/** The area the softening branch must have: G_f less the elastic
 *  triangle f_t delta_0 / 2 (the exponential's decay energy G_s). */
static double softening_energy(const CohesiveLaw *L)
{
    return L->G_f - 0.5 * L->f_t * cohesive_delta0(L);
}

double cohesive_envelope(const CohesiveLaw *L, double delta)
{
    double d0 = cohesive_delta0(L);
    if (delta <= d0)
        return L->K * fmax(delta, 0.0);                /* penalty branch */
    if (L->kind == COHESIVE_LINEAR) {
        double dc = cohesive_delta_c(L);               /* 2 G_f / f_t */
        return delta >= dc ? 0.0 : L->f_t * (dc - delta) / (dc - d0);
    }
    return L->f_t * exp(-L->f_t * (delta - d0) / softening_energy(L));
}
/// [cohesive_envelope]

double cohesive_softening_slope(const CohesiveLaw *L)
{
    if (L->kind == COHESIVE_LINEAR)
        return -L->f_t / (cohesive_delta_c(L) - cohesive_delta0(L));
    return -L->f_t * L->f_t / softening_energy(L);
}

double cohesive_envelope_work(const CohesiveLaw *L, double delta)
{
    double d0 = cohesive_delta0(L);
    if (delta <= d0)
        return 0.5 * L->K * delta * delta;
    double w = delta - d0, e0 = 0.5 * L->f_t * d0;
    if (L->kind == COHESIVE_LINEAR) {
        double dc = cohesive_delta_c(L);
        if (delta >= dc)
            return L->G_f;
        return e0 + L->f_t * (w - 0.5 * w * w / (dc - d0));
    }
    double gs = softening_energy(L);
    return e0 + gs * -expm1(-L->f_t * w / gs);
}

double cohesive_dissipated(const CohesiveLaw *L, double dmax)
{
    if (dmax <= cohesive_delta0(L))
        return 0.0;
    return cohesive_envelope_work(L, dmax) -
           0.5 * cohesive_envelope(L, dmax) * dmax;
}

/// [cohesive_traction]
CohesiveState cohesive_traction(const CohesiveLaw *L, double dn, double ds,
                                double *dmax, int commit)
{
    double open = fmax(dn, 0.0), shut = fmin(dn, 0.0);
    double b2 = L->beta * L->beta;
    double d = sqrt(open * open + b2 * ds * ds);      /* effective opening */
    double m = fmax(*dmax, d);                        /* history */
    if (commit)
        *dmax = m;
    /* secant stiffness: unloading and reloading run along the line from
     * the origin to (dmax, t(dmax)) */
    double k = m > cohesive_delta0(L) ? cohesive_envelope(L, m) / m : L->K;
    CohesiveState s;
    s.tn = k * open + L->K * shut;                    /* penalty contact */
    s.ts = b2 * k * ds;
    s.stored = 0.5 * k * d * d + 0.5 * L->K * shut * shut;
    return s;
}
/// [cohesive_traction]
