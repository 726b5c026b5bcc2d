/**
 * @file gimp.h
 * @brief uGIMP shape functions (Bardenhagen & Kober 2004): the linear hat
 *        of each node averaged over the point's undeformed domain, a
 *        rectangle of the point's initial spacing centred on the point.
 */
#ifndef MPM_GIMP_H
#define MPM_GIMP_H

#include "shape.h"
#include "stencil.h"

/// [gimp_weight]
/**
 * @brief The 1D uGIMP weight of one node and its derivative, in cell units.
 * @param d  point minus node, in cells
 * @param l  half the point's domain, in cells (0 < l <= 1/2)
 * @param G  out: dS/dd (per cell; divide by the cell size for per length)
 * @return S, the average of the node's hat function over [d - l, d + l]
 */
double gimp_weight(double d, double l, double *G);
/// [gimp_weight]

/**
 * @brief The uGIMP stencil of a point in cell @p cell (lower-left node) at
 *        local coordinates (@p xi, @p eta), half sizes @p lx, @p ly in
 *        cells: the 4, 6 or 9 nodes its domain reaches, row by row.
 *
 * A node off the grid is left out (its weight is lost: shapes_check.c keeps
 * every domain inside the grid). Slots are the nodes (one field).
 */
void gimp_stencil_cell(const Grid *g, int cell, double xi, double eta,
                       double lx, double ly, Stencil *st);

/** @brief The uGIMP stencil of point @p p from Task 0's cell and local
 *         coordinates, its half sizes those of its body's points. */
void gimp_stencil(const struct Sim *sim, int p, Stencil *st);

/** @brief Half the domain of point @p p along x and y, in cells (its body
 *         has k x k points per cell: 1 / (2k)). */
static inline double gimp_half(const Sim *sim, int p)
{
    return 0.5 / sim->scene.bodies[sim->pts.body[p]].ppc;
}

/** The row "gimp" of run.shape's table. */
extern const ShapeFunctions shape_gimp;

#endif
