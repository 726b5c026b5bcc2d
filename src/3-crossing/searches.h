/**
 * @file searches.h
 * @brief Chapter 3's crossing searches: extent screening (the paper's
 *        subtask 1) and an index of crack segments by grid cell. Both are
 *        rows of stage 2's crossing-search table and must give exactly the
 *        fields of the plain search. And curved cracks given as arcs.
 */
#ifndef MPM_SEARCHES_H
#define MPM_SEARCHES_H

#include "cracks.h"

/// [search_box]
/** The grid as a search sees it, and the margin of its boxes. */
typedef struct SearchGrid {
    double ox;      /**< grid origin x */
    double oy;      /**< grid origin y */
    double dx;      /**< cell width */
    double dy;      /**< cell height */
    int ncx;        /**< cells along x */
    int ncy;        /**< cells along y */
    int nnx;        /**< nodes along x */
    /** Boxes grow by eps on every side: more than the distance below which
     *  the signed areas of eq. 33 can round to a crossing, so screening
     *  never drops a segment that the plain search would count. */
    double eps;
} SearchGrid;

/** @brief The grid's geometry and margin for the searches. */
void search_grid_of(SearchGrid *sg, const Grid *g);

/** @brief Do the boxes [ax0, ax1] x [ay0, ay1] and [bx0, bx1] x [by0, by1]
 *         meet once both grow by eps? */
static inline int boxes_meet(double ax0, double ax1, double ay0, double ay1,
                             double bx0, double bx1, double by0, double by1,
                             double eps)
{
    return ax0 <= bx1 + 2 * eps && bx0 <= ax1 + 2 * eps &&
           ay0 <= by1 + 2 * eps && by0 <= ay1 + 2 * eps;
}
/// [search_box]

/** @brief Extent screening: skip a crack whose box the line's box misses. */
extern const CrossingSearch crossing_screened;

/** @brief The segment index: test only the segments that reach the cell. */
extern const CrossingSearch crossing_indexed;

/** The keys of cracks[i].arc (NULL-ended). */
extern const char *const crack_arc_keys[];

/**
 * @brief Read cracks[i].arc = { center = [x, y]; radius = r;
 *        angles = [from, to]; segments = n; }: the crack runs on the circle
 *        from angle @e from to angle @e to (degrees, counter-clockwise when
 *        to > from), as n equal segments (by default about half a cell
 *        long each); the points are checked as a list of points would be.
 */
int crack_read_arc(Sim *sim, const config_setting_t *s, int index,
                   struct SceneReader *r);

#endif
