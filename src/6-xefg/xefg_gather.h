/**
 * @file xefg_gather.h
 * @brief XEFG's sums on threads in a fixed order: the Gauss rows turned
 *        round, so that each parameter gathers its internal force and each
 *        node its cell average in the order the one-thread scatter adds
 *        them (appendix "Running in parallel"): the same bits on any
 *        number of threads.
 */
#ifndef MPM_XEFG_GATHER_H
#define MPM_XEFG_GATHER_H

#include "xefg.h"

/** The Gauss rows by parameter and the Gauss points by node, built at
 *  set-up in the room a growing crack may need, rebuilt after it grows. */
typedef struct XefgGather {
    long version;    /**< Xefg::rows_version it was built for */
    int *col_start;  /**< per parameter: its entries (ndof + 1 offsets) */
    double *col_grad; /**< each entry's Nx, Ny (2 per), copied from the
                           Gauss rows: read in a stream */
    int *col_point;  /**< the Gauss point of each entry, ascending */
    int *cell_start; /**< per node: its Gauss points (nnode + 1 offsets) */
    int *cell_point; /**< the Gauss points of each node's cell, ascending */
    double *ws;      /**< w sigma of each Gauss point (3 per) */
} XefgGather;

/**
 * @brief Allocate and build the gather of @p x when @p sim runs on more
 *        than one thread (one thread keeps the scatter: nothing built).
 * @return 0, or -1 when memory ran out.
 */
int xefg_gather_build(Xefg *x, const Sim *sim);

/** @brief Rebuild the gather after a crack grew (no allocation). */
void xefg_gather_refresh(Xefg *x);

/** @brief 1 when @p x has a gather of its current rows. */
int xefg_gather_current(const Xefg *x);

/**
 * @brief Internal forces of the stresses Xefg::gs into @p f (2 per
 *        parameter) on the threads, each parameter summing its Gauss
 *        points in ascending order: the bits of xefg_internal_force().
 */
void xefg_gather_force(const Xefg *x, const Sim *sim, double *f);

/** @brief The cell averages of stress and strain of xefg_to_points(),
 *         each node summing its Gauss points in ascending order, on the
 *         threads. */
void xefg_gather_cells(const Xefg *x, Sim *sim);

/** @brief Release the gather. */
void xefg_gather_free(XefgGather *G);

#endif
