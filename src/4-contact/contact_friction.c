/**
 * @file contact_friction.c
 * @brief Frictional sliding (eq. 14-19). Chapter 4's exercise "the
 *        frictional adjustment" replaces this file.
 */
#include <math.h>

#include "contact_law.h"

/// [contact_friction]
void contact_friction(double ma, const double pa[2], double mb,
                      const double pb[2], const double n[2], double mu,
                      double dp[2])
{
    double s[2];
    contact_stick(ma, pa, mb, pb, s);          /* what stick would do */
    double sn = s[0] * n[0] + s[1] * n[1];     /* normal part: always */
    double tx = s[0] - sn * n[0], ty = s[1] - sn * n[1];
    double st = sqrt(tx * tx + ty * ty);       /* tangential part needed */
    double limit = mu * fabs(sn);              /* Coulomb: |dp_t| <= mu |dp_n| */
    if (st <= limit) {                         /* friction stops the sliding */
        dp[0] = s[0];
        dp[1] = s[1];
        return;
    }
    double f = limit / st;                     /* slides: friction at its limit */
    dp[0] = sn * n[0] + f * tx;
    dp[1] = sn * n[1] + f * ty;
}
/// [contact_friction]
