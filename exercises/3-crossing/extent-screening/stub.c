/*
 * Exercise "extent screening" (chapter 3): test a crack's segments only
 * when its bounding box meets the box of the particle-node line.  Copy this
 * file, fill in the three functions, and run
 *     make exercise EX=3-crossing/extent-screening SOLUTION=your_copy.c
 * The contract is CrossingSearch in src/2-fields/cracks.h and the helpers
 * in src/3-crossing/searches.h; README.md says what is checked.
 */
#include <stdlib.h>

#include "searches.h"

static int screened_update(Cracks *C, const Grid *g)
{
    /* TODO: keep what the search needs to know of the grid (a SearchGrid,
     * made by search_grid_of(), in C->search_state); 0, or -1 when memory
     * is short.  Called before the first step and after the cracks move. */
    (void)C;
    (void)g;
    return 0;
}

static void screened_release(Cracks *C)
{
    /* TODO: free what screened_update() kept. */
    (void)C;
}

static void screened_visit(const Cracks *C, int cell, double px, double py,
                           double nx, double ny, Crossings *x)
{
    /* TODO: for every crack whose box (Crack::xmin ... ymax) meets the box
     * of the line from (px, py) to (nx, ny), test each of its segments
     * with crossings_test().  Mind round-off: see boxes_meet(). */
    (void)C;
    (void)cell;
    (void)px;
    (void)py;
    (void)nx;
    (void)ny;
    (void)x;
}

const CrossingSearch crossing_screened = {
    "screened", screened_visit, screened_update, screened_release, NULL,
};
