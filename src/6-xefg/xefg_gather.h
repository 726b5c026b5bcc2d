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
    double *ws;      /**< scratch, 3 per Gauss point (2 per parameter if
                          more): w sigma of each Gauss point for
                          xefg_gather_force(), the terms of an energy's
                          sum */
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
 * @brief Internal forces of the weighted stresses XefgGather::ws (w sigma,
 *        3 per Gauss point) into @p f (2 per parameter), each parameter
 *        summing its Gauss points in ascending order: the bits of
 *        xefg_internal_force(). An `omp for`: called inside a parallel
 *        region (xefg_update_and_force()), whose threads share it.
 */
void xefg_gather_force(const Xefg *x, double *f);

/** @brief Node @p I's cell average of stress and strain into @p P, its
 *         Gauss points summed in ascending order: the bits of the
 *         scatter in xefg_to_points(). */
void xefg_gather_cell(const Xefg *x, int I, Particles *P);

/** @brief Release the gather. */
void xefg_gather_free(XefgGather *G);

#endif
