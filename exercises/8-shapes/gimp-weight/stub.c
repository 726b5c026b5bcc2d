/*
 * Exercise "GIMP weight" (chapter 8): the weight of one node for a point
 * that is a domain, not a point.
 * Copy this file, fill in gimp_weight(), and run
 *     make exercise EX=8-shapes/gimp-weight SOLUTION=your_copy.c
 * The contract is in src/8-shapes/gimp.h; README.md says what is checked.
 */
#include "gimp.h"

double gimp_weight(double d, double l, double *G)
{
    /* TODO: the average of the hat 1 - |x| (zero beyond |x| = 1) over
     * [d - l, d + l], and its derivative in d. This stub returns the hat
     * at the point itself (chapter 1's linear weight, l ignored) and no
     * slope: the weights still sum to one, the gradients do not. */
    double r = d < 0 ? -d : d;
    (void)l;
    *G = 0.0;
    return r < 1.0 ? 1.0 - r : 0.0;
}
