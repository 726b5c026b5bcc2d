/*
 * Exercise "hoop angle" (chapter 7b): where a crack kinks.
 * Copy this file, fill in hoop_angle(), and run
 *     make exercise EX=7-fracture/hoop-angle SOLUTION=your_copy.c
 * The contract is in src/6-xefg/hoop_angle.h; README.md says what
 * is checked.
 */
#include "hoop_angle.h"

double hoop_angle(double KI, double KII)
{
    /* TODO: the angle theta_c (radians, from the direction ahead of the
     * tip towards its left normal) at which the hoop stress of the
     * near-tip field is largest. This stub says "straight ahead" always:
     * right for pure mode I only, so the mixed-mode tests fail. */
    (void)KI;
    (void)KII;
    return 0.0;
}
