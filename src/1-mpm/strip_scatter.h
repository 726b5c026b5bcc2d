/**
 * @file strip_scatter.h
 * @brief A scatter on threads by strips of node rows (strips.h, issue 29):
 *        which nodes a thread owns, and a loop that hands each strip's
 *        points, in increasing index, to a per-point function.
 *
 * The scatters of Tasks 1 and 3 (extrapolate.c) and the later stages'
 * scatters to the grid (contact's sums, chapter 4; APIC's affine term,
 * chapter 8) add to a node only through the ownership test owns(), so
 * every node sums the same products in the same order on any number of
 * threads.
 */
#ifndef MPM_STRIP_SCATTER_H
#define MPM_STRIP_SCATTER_H

#include "grid.h"

struct Sim;

/// [owns]
/** The nodes [lo, hi) that a thread owns (strips.h). */
typedef struct Owned {
    int lo;           /**< first node */
    int hi;           /**< one past the last */
} Owned;

/** Does a pair that adds to slot @p s write a node of @p own? Always when
 *  @p own is NULL (one thread: a constant that the compiler folds). */
static inline int owns(const Grid *g, const Owned *own, int s)
{
    if (!own)
        return 1;
    int node = grid_slot_node(g, s);
    return node >= own->lo && node < own->hi;
}
/// [owns]

/** One point's share of a scatter: point @p p adds to the nodes of
 *  @p own only (NULL: to all of its nodes); @p ctx is the caller's. */
typedef void (*StripPointFn)(struct Sim *sim, void *ctx, int p,
                             const Owned *own);

/**
 * @brief A scatter on the strips of Task 0 (Strips::n > 0): strip t's
 *        thread calls @p fn for the points that reach its nodes, in
 *        increasing index, with its nodes as @p own for a point at the
 *        strip's edge (NULL for one inside). On one thread (Strips::n 0)
 *        the caller loops over the points itself, with @p own NULL.
 */
void strip_scatter(struct Sim *sim, StripPointFn fn, void *ctx);

#endif
