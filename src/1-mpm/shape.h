/**
 * @file shape.h
 * @brief Linear (bilinear in 2D) grid shape functions N_i(x) and their
 *        gradients, the S_ip and G_ip of the paper's Appendix.
 */
#ifndef MPM_SHAPE_H
#define MPM_SHAPE_H

#include "grid.h"

/** Nodes a point's shape functions reach (bilinear: the cell's four). */
#define STENCIL_NODES 4
/** Most nodes any row of the shape-function table reaches: 3 x 3 for a
 *  point whose domain is at most a cell wide (uGIMP, chapter 8). A
 *  stencil holds this many; its count Stencil::n says how many are used. */
#define STENCIL_MAX 9

struct Sim;
struct Stencil;

/** A stencil function: the nodes, S_ip, G_ip and Stencil::n of point
 *  @p p (ShapeFunctions::stencil, RunSettings::stencil). */
typedef void (*StencilFn)(const struct Sim *sim, int p, struct Stencil *st);

/// [shape_functions]
/** A row of the shape-function table, chosen by run.shape ("linear" is
 *  stage 1's; later stages add rows). */
typedef struct ShapeFunctions {
    const char *name;   /**< the value of run.shape */
    int nodes;          /**< most nodes one point reaches (<= STENCIL_MAX) */
    /** Fill the stencil of point @p p (nodes, S_ip, G_ip and Stencil::n)
     *  from Task 0's cell and local coordinates; NULL: the bilinear
     *  functions, inline in stencil_of_point(). */
    StencilFn stencil;
} ShapeFunctions;
/// [shape_functions]

/// [shape_linear]
/**
 * @brief Values and gradients of the four shape functions of one cell.
 *
 * Corners are numbered 0 (xi=0, eta=0), 1 (1, 0), 2 (0, 1), 3 (1, 1), where
 * (xi, eta) in [0, 1]^2 are the local coordinates of the point in the cell.
 * @param xi   local x coordinate in the cell, 0 at the left edge
 * @param eta  local y coordinate in the cell, 0 at the bottom edge
 * @param idx  1 / cell width
 * @param idy  1 / cell height
 * @param S    out: S[k] = N_k
 * @param Gx   out: Gx[k] = dN_k/dx
 * @param Gy   out: Gy[k] = dN_k/dy
 */
void shape_linear(double xi, double eta, double idx, double idy,
                  double S[4], double Gx[4], double Gy[4]);
/// [shape_linear]

/**
 * @brief Cell that holds (x, y) and the point's local coordinates in it.
 *
 * The caller guarantees that the point lies inside the grid; a point on the
 * grid's far edge belongs to the last cell.
 * @return index of the cell's lower-left node
 */
static inline int shape_locate(const Grid *g, double x, double y,
                               double *xi, double *eta)
{
    double gx = (x - g->ox) * g->idx;
    double gy = (y - g->oy) * g->idy;
    int i = (int)gx;
    int j = (int)gy;
    if (i > g->ncx - 1)
        i = g->ncx - 1;
    if (j > g->ncy - 1)
        j = g->ncy - 1;
    *xi = gx - i;
    *eta = gy - j;
    return j * g->nnx + i;
}

/** @brief The four nodes of the cell whose lower-left node is @p cell. */
static inline void shape_cell_nodes(const Grid *g, int cell,
                                    int node[STENCIL_NODES])
{
    node[0] = cell;
    node[1] = cell + 1;
    node[2] = cell + g->nnx;
    node[3] = cell + g->nnx + 1;
}

#endif
