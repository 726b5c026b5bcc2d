/**
 * @file search_grid.c
 * @brief The grid as the crossing searches see it, and the margin by which
 *        their boxes grow so that round-off never drops a crossing.
 */
#include <float.h>
#include <math.h>

#include "searches.h"

void search_grid_of(SearchGrid *sg, const Grid *g)
{
    sg->ox = g->ox;
    sg->oy = g->oy;
    sg->dx = g->dx;
    sg->dy = g->dy;
    sg->ncx = g->ncx;
    sg->ncy = g->ncy;
    sg->nnx = g->nnx;
    /* a point within a few ulps of the largest coordinate from a line can
       be classified on it; 1024 ulps of that coordinate is a safe margin */
    double m = fmax(fmax(fabs(g->ox), fabs(g->ox + g->ncx * g->dx)),
                    fmax(fabs(g->oy), fabs(g->oy + g->ncy * g->dy)));
    sg->eps = 1024 * DBL_EPSILON * (m + fmax(g->dx, g->dy));
}
