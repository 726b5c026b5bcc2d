/**
 * @file footprint.h
 * @brief The memory a run will take, estimated from the scene before any
 *        point or node is allocated, and the limit it must stay under.
 */
#ifndef MPM_FOOTPRINT_H
#define MPM_FOOTPRINT_H

#include <stddef.h>

#include "scene.h"

/** Bytes a point may take, at most: its arrays twice over (they grow by
 *  doubling), a row of the field table (4 keys, slots, normals and tags),
 *  the stages' per-point state and its stencil stored at Task 0 (256, the
 *  widest: chapter 8's; a linear one takes 112). An upper bound, not a
 *  measurement. */
#define FOOTPRINT_POINT_BYTES (2.0 * (14 * 8 + 3 * 4) + 160.0 + 256.0)

/** Bytes a node may take, at most: two slots of the grid's twelve
 *  arrays (field 0 and one extra field), the fixed flags, set-up scratch,
 *  the field table's lists and the contact stages' per-node arrays. */
#define FOOTPRINT_NODE_BYTES 256.0

/** What a scene will allocate, estimated. */
typedef struct Footprint {
    double points;  /**< material points, an upper estimate */
    double nodes;   /**< grid nodes */
    double bytes;   /**< points and nodes at their bytes above */
    int body;       /**< the body with the most points, -1 when none */
} Footprint;

/** @brief Estimate the points of every body (its shape's area over a
 *         point's, plus a band along its edge, at most its bounding box's
 *         count) and the nodes of the grid, in a time that does not grow
 *         with either. */
Footprint footprint_estimate(const Scene *sc);

/** @brief The memory this machine has available now, in bytes
 *         (MemAvailable of /proc/meminfo, else the physical memory). */
double footprint_available(void);

/**
 * @brief Refuse a scene whose estimate exceeds @p limit bytes (0: the
 *        machine's available memory).
 * @param sc        the scene, read but not set up
 * @param limit     bytes the run may take; 0 for footprint_available()
 * @param grid_line the scene-file line of the grid, named when the nodes
 *                  take more than the points (0: none)
 * @param err       message "file:line: needs about ..." when refused
 * @param errlen    its size
 * @return 0, or -1 when refused.
 */
int footprint_check(const Scene *sc, size_t limit, int grid_line, char *err,
                    size_t errlen);

#endif
