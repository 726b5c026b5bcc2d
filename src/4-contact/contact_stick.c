/**
 * @file contact_stick.c
 * @brief Stick contact (eq. 13). Chapter 4's exercise "the stick limit"
 *        replaces this file.
 */
#include "contact_law.h"

/// [contact_stick]
void contact_stick(double ma, const double pa[2], double mb, const double pb[2],
                   double dp[2])
{
    double m = ma + mb;                  /* dp_a = m_a v_cm - p_a */
    dp[0] = (ma * pb[0] - mb * pa[0]) / m;
    dp[1] = (ma * pb[1] - mb * pa[1]) / m;
}
/// [contact_stick]
