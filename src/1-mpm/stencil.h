/**
 * @file stencil.h
 * @brief The stencil of one point: the nodes its shape functions reach,
 *        the values S_ip and gradients G_ip there, and the field slot of
 *        each pair (Task 0 and Task 1's v(p,i)).
 *
 * Every loop between points and grid reads a point's stencil and nothing
 * else of the shape functions, and runs over its Stencil::n nodes, so a
 * chapter that brings other shape functions (GIMP, chapter 8) adds a row
 * to the table of run.shape (shape.h) and changes no loop.
 */
#ifndef MPM_STENCIL_H
#define MPM_STENCIL_H

#include "shape.h"
#include "sim.h"

/// [stencil]
/** One point's view of the grid. slot[a] is the a-th node's own slot (its
 *  index, field 0) unless Task 1 gave the pair another field; the node of
 *  any slot is grid_slot_node(). */
typedef struct Stencil {
    int n;                    /**< nodes in use (STENCIL_NODES when linear) */
    int slot[STENCIL_MAX];    /**< the nodes, as the field slot of each pair */
    double S[STENCIL_MAX];    /**< shape function values S_ip */
    double Gx[STENCIL_MAX];   /**< gradients dS/dx */
    double Gy[STENCIL_MAX];   /**< gradients dS/dy */
} Stencil;

/** @brief The bilinear stencil of point @p p from its cell found in Task
 *         0, with the field slots Task 1 gave its pairs; Stencil::n is
 *         left to the caller (it is STENCIL_NODES). */
static inline void stencil_linear(const Sim *sim, int p, Stencil *st)
{
    const Grid *g = &sim->grid;
    const FieldTable *F = &sim->fields;
    shape_linear(sim->pts.xi[p], sim->pts.eta[p], g->idx, g->idy, st->S,
                 st->Gx, st->Gy);
    shape_cell_nodes(g, sim->pts.cell[p], st->slot);
    if (F->row_of) {                       /* a keyed pair uses its slot */
        int r = F->row_of[p];
        if (r >= 0)
            for (int a = 0; a < STENCIL_NODES; a++)
                st->slot[a] = F->row_slot[STENCIL_NODES * r + a];
    }
}

/// [stencil]

/** @brief The stencil of point @p p: run.shape's (linear unless the scene
 *         chose another row). @return the nodes in use, Stencil::n */
static inline int stencil_of_point(const Sim *sim, int p, Stencil *st)
{
    if (sim->scene.run.stencil) {
        sim->scene.run.stencil(sim, p, st); /* another row of run.shape */
        return st->n;
    }
    stencil_linear(sim, p, st);
    return st->n = STENCIL_NODES;
}

/** @brief The stencil of a position: nodes and shape functions; every
 *         pair in field 0 (crack points, output). */
static inline void stencil_at(const Grid *g, double x, double y, Stencil *st)
{
    double xi, eta;
    int cell = shape_locate(g, x, y, &xi, &eta);
    st->n = STENCIL_NODES;
    shape_linear(xi, eta, g->idx, g->idy, st->S, st->Gx, st->Gy);
    shape_cell_nodes(g, cell, st->slot);
}

/** @brief The nodes of point @p p's linear stencil, its cell's four (Task
 *         1 needs no more: the stages that key fields run with linear
 *         shape functions only, chapter 8). */
static inline void stencil_nodes(const Sim *sim, int p, int node[STENCIL_NODES])
{
    shape_cell_nodes(&sim->grid, sim->pts.cell[p], node);
}

#endif
