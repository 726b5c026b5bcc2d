/*
 * Exercise "the stick limit" (chapter 4): stick contact (eq. 13), the
 * change of field a's momentum that gives both fields at a node the
 * centre-of-mass velocity.  Copy this file, fill in the function, and run
 *     make exercise EX=4-contact/stick-limit SOLUTION=your_copy.c
 * The contract is in src/4-contact/contact_law.h; README.md says what is
 * checked.
 */
#include "contact_law.h"

void contact_stick(double ma, const double pa[2], double mb, const double pb[2],
                   double dp[2])
{
    /* TODO: eq. 13, written in momenta (no division by a mass alone). */
    (void)ma;
    (void)pa;
    (void)mb;
    (void)pb;
    dp[0] = dp[1] = 0.0;
}
