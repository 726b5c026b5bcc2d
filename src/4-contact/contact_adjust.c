/**
 * @file contact_adjust.c
 * @brief The momentum change of two fields in contact at a node, for every
 *        law (eq. 13-19): shared by crack contact and contact between
 *        bodies.
 */
#include "contact_law.h"
#include "contact_settings.h"

/// [contact_adjust]
double contact_adjust(Grid *g, int a, int b, const double n[2],
                      const ContactLaw *law)
{
    double ma = g->m[a], mb = g->m[b];
    double pa[2] = {g->px[a], g->py[a]}, pb[2] = {g->px[b], g->py[b]};
    double dp[2];
    if (law->kind == CONTACT_FRICTION)
        contact_friction(ma, pa, mb, pb, n, law->mu, dp);
    else
        contact_stick(ma, pa, mb, pb, dp);   /* stick, bonded */
    g->px[a] += dp[0];                       /* momentum exact: b gets -dp */
    g->py[a] += dp[1];
    g->px[b] -= dp[0];
    g->py[b] -= dp[1];
    /* work of the impulse on the adjusted relative velocity: zero for stick
       and frictionless, the friction's dissipation otherwise */
    return dp[0] * (g->px[a] / ma - g->px[b] / mb) +
           dp[1] * (g->py[a] / ma - g->py[b] / mb);
}
/// [contact_adjust]
