/*
 * Exercise "crack motion" (chapter 2): Task 7, moving the crack points.
 * Copy this file, fill in cracks_move(), and run
 *     make exercise EX=2-fields/crack-motion SOLUTION=your_copy.c
 * The contract is in src/2-fields/cracks.h; README.md says what is checked.
 */
#include "cracks.h"

int cracks_move(Sim *sim)
{
    /* TODO: for every point of every crack, interpolate the centre-of-mass
     * velocity of the nodes of its cell (eq. 32: all fields of a node
     * together) with the shape functions, move the point by dt times it,
     * refuse a point that leaves the grid, and update each crack's extent.
     * This stub leaves the cracks where they are. */
    (void)sim;
    return 0;
}
