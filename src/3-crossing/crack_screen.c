/**
 * @file crack_screen.c
 * @brief Extent screening (Appendix, subtask 1): a crack whose bounding
 *        box misses the box of the particle-node line is not tested.
 */
#include <math.h>
#include <stdlib.h>

#include "searches.h"

/** Make the search's copy of the grid (once). */
static int screened_update(Cracks *C, const Grid *g)
{
    if (!C->search_state && !(C->search_state = malloc(sizeof(SearchGrid))))
        return -1;
    search_grid_of(C->search_state, g);
    return 0;
}

static void screened_release(Cracks *C)
{
    free(C->search_state);
    C->search_state = NULL;
}

/// [screened]
/** Every segment of the cracks whose box meets the line's box. */
static void screened_visit(const Cracks *C, int cell, double px, double py,
                           double nx, double ny, Crossings *x)
{
    const SearchGrid *sg = C->search_state;
    double x0 = fmin(px, nx), x1 = fmax(px, nx);
    double y0 = fmin(py, ny), y1 = fmax(py, ny);
    (void)cell;
    for (int k = 0; k < C->ncracks; k++) {
        const Crack *c = &C->crack[k];
        if (!boxes_meet(x0, x1, y0, y1, c->xmin, c->xmax, c->ymin, c->ymax,
                        sg->eps))
            continue;                           /* subtask 1 */
        for (int j = 0; j + 1 < c->n; j++)
            crossings_test(C, k, j, px, py, nx, ny, x);
    }
}

const CrossingSearch crossing_screened = {
    "screened", screened_visit, screened_update, screened_release, NULL,
};
/// [screened]
