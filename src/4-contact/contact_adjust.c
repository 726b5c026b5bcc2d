/**
 * @file contact_adjust.c
 * @brief The momentum change of two fields in contact at a node, for every
 *        law (eq. 13-19): shared by crack contact and contact between
 *        bodies.
 */
#include "contact_law.h"
#include "contact_settings.h"

/// [contact_adjust]
int contact_adjust(Grid *g, int a, int b, const double n[2],
                   const ContactLaw *law, double dp[2])
{
    double ma = g->m[a], mb = g->m[b];
    double pa[2] = {g->px[a], g->py[a]}, pb[2] = {g->px[b], g->py[b]};
    double s[2];
    contact_stick(ma, pa, mb, pb, s);        /* stick, bonded */
    int slides = 0;
    if (law->kind == CONTACT_FRICTION) {
        contact_friction(ma, pa, mb, pb, n, law->mu, dp);
        slides = dp[0] != s[0] || dp[1] != s[1];  /* not stopped */
    } else {
        dp[0] = s[0];
        dp[1] = s[1];
    }
    g->px[a] += dp[0];                       /* momentum exact: b gets -dp */
    g->py[a] += dp[1];
    g->px[b] -= dp[0];
    g->py[b] -= dp[1];
    return slides;
}
/// [contact_adjust]

/// [contact_friction_work]
double contact_friction_work(const Grid *g, int a, int b, const double n[2],
                             const double dp[2], double dt)
{
    double dn = dp[0] * n[0] + dp[1] * n[1];
    double tx = dp[0] - dn * n[0], ty = dp[1] - dn * n[1];  /* friction */
    /* the relative velocity the step started from, (q - dt f) / m: what
       Task 5 adds the impulse to, a mass average of the points' velocities */
    double vx = (g->qx[a] - dt * g->fx[a]) / g->m[a] -
                (g->qx[b] - dt * g->fx[b]) / g->m[b];
    double vy = (g->qy[a] - dt * g->fy[a]) / g->m[a] -
                (g->qy[b] - dt * g->fy[b]) / g->m[b];
    return tx * vx + ty * vy;
}
/// [contact_friction_work]
