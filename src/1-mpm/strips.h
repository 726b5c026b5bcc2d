/**
 * @file strips.h
 * @brief Who writes which grid nodes when the scatters run on threads
 *        (issue 29): strips of whole node rows, one per thread, and the
 *        points that reach each strip, in increasing index.
 *
 * The scatter on one thread adds point p's share to a node in increasing
 * p. A thread that owns a strip visits the points that reach its nodes in
 * increasing p and adds only to its own nodes, so every node receives the
 * same products in the same order, starting from the same zero: the same
 * bits on any number of threads, without atomics or locks. The points are
 * binned in Task 0 by a stable counting sort; every array is allocated at
 * set-up (strips_init()), none in a step.
 */
#ifndef MPM_STRIPS_H
#define MPM_STRIPS_H

struct Sim;

/// [strips]
/** Strips of node rows and the points of each (structure of arrays). */
typedef struct Strips {
    int n;            /**< strips this step; 0: scatter on one thread */
    int cap;          /**< strips allocated: the run's threads */
    int npoints;      /**< points the arrays have room for */
    int reach;        /**< cell rows a stencil reaches beyond its point's
                           own: 0 linear, 1 for 3 x 3 nodes (chapter 8) */
    int *first_node;  /**< cap + 1: strip t owns nodes [first_node[t],
                           first_node[t + 1]) */
    int *start;       /**< cap + 1: strip t's points are list[start[t]]
                           .. list[start[t + 1] - 1] */
    int *list;        /**< 2 per point: point indices, strip by strip,
                           increasing within each */
    int *code;        /**< per point: its cell row this step */
    int *rows;        /**< cap per cell row: points of each chunk there */
    int *count;       /**< per chunk (a cache line apart), per strip: the
                           next place of the chunk's points in list */
    int *row_strips;  /**< per cell row: 2 x the first strip its points
                           reach, + 1 when they reach the next one too */
} Strips;
/// [strips]

/**
 * @brief Set-up: room for the strips of Sim::threads threads over the
 *        grid and the points of @p sim (nothing when one thread).
 * @return 0, or -1 when memory is exhausted.
 */
int strips_init(struct Sim *sim);

/**
 * @brief Task 0, after the cells: cut the node rows into strips of about
 *        equal points and list each strip's points in increasing index
 *        (Strips::n = 0, one thread, when the run has one thread or the
 *        grid too few rows).
 */
void strips_bin(struct Sim *sim);

/** @brief Release the arrays. */
void strips_free(Strips *S);

#endif
