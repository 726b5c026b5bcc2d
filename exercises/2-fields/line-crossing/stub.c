/*
 * Exercise "line crossing" (chapter 2): which velocity field does the pair
 * (particle, node) use?  Copy this file, fill in the two functions, and run
 *     make exercise EX=2-fields/line-crossing SOLUTION=your_copy.c
 * The contract is in src/2-fields/cracks.h; README.md says what is checked.
 */
#include "cracks.h"

int crack_crossing(const Crack *c, double px, double py, double nx, double ny)
{
    /* TODO: signed areas A(123), A(124), A(341), A(342) for each segment
     * 3 -> 4 of the crack (eq. 33), the sign patterns of subtask 3, and an
     * odd number of crossings (subtask 4).  +1 above, -1 below, 0 none. */
    (void)c;
    (void)px;
    (void)py;
    (void)nx;
    (void)ny;
    return 0;
}

int crack_field(const Cracks *C, double px, double py, double nx, double ny)
{
    /* TODO: 0 when no crack is crossed, 1 above the first crack crossed,
     * 2 below it (eq. 2). */
    (void)C;
    (void)px;
    (void)py;
    (void)nx;
    (void)ny;
    return 0;
}
