/*
 * Exercise "line crossing" (chapter 2): which side of a crack is a
 * particle on, seen from a node?  Copy this file, fill in the two
 * functions, and run
 *     make exercise EX=2-fields/line-crossing SOLUTION=your_copy.c
 * The contract is in src/2-fields/cracks.h; README.md says what is checked.
 */
#include "cracks.h"

int crack_segment_side(const Crack *c, int k, double px, double py, double nx,
                       double ny)
{
    /* TODO: signed areas A(123), A(124), A(341), A(342) with 1 = particle,
     * 2 = node, 3 -> 4 = segment k of the crack (eq. 33), and the sign
     * patterns of subtask 3.  +1 above, -1 below, 0 not crossed. */
    (void)c;
    (void)k;
    (void)px;
    (void)py;
    (void)nx;
    (void)ny;
    return 0;
}

int crack_crossing(const Crack *c, double px, double py, double nx, double ny)
{
    /* TODO: over all segments of the crack: an odd number of crossings
     * crosses (subtask 4), with the sign of the sum of their sides. */
    (void)c;
    (void)px;
    (void)py;
    (void)nx;
    (void)ny;
    return 0;
}
