/*
 * Exercise "the frictional adjustment" (chapter 4): the change of field a's
 * momentum at a node where two crack faces touch, with Coulomb friction mu.
 * Copy this file, fill in the function, and run
 *     make exercise EX=4-contact/frictional-adjustment SOLUTION=your_copy.c
 * The contract is in src/4-contact/contact_law.h; README.md says what is
 * checked.
 */
#include <math.h>

#include "contact_law.h"

void contact_friction(double ma, const double pa[2], double mb,
                      const double pb[2], const double n[2], double mu,
                      double dp[2])
{
    /* TODO: derive dp from the properties in README.md (you may call
     * contact_stick() for the change that stick would make). */
    (void)ma;
    (void)pa;
    (void)mb;
    (void)pb;
    (void)n;
    (void)mu;
    dp[0] = dp[1] = 0.0;
}
