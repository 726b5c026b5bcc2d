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

/// [stencil_wide]
/** @brief The field slots Task 1 gave the pairs of point @p p, over the
 *         Stencil::n nodes of a stencil of run.shape's table, in the order
 *         its function gives them (the order Task 1 keyed them in). */
static inline void stencil_fields(const Sim *sim, int p, Stencil *st)
{
    const FieldTable *F = &sim->fields;
    if (F->row_of) {                       /* a keyed pair uses its slot */
        int r = F->row_of[p];
        if (r >= 0)
            for (int a = 0; a < st->n; a++)
                st->slot[a] = F->row_slot[F->width * r + a];
    }
}

/** @brief The stencil of point @p p through @p wide, a row of run.shape's
 *         table (chapter 8): its nodes, S_ip and G_ip, then the field
 *         slots of its pairs. */
static inline void stencil_wide(const Sim *sim, StencilFn wide, int p,
                                Stencil *st)
{
    wide(sim, p, st);
    stencil_fields(sim, p, st);
}
/// [stencil_wide]

/** @brief The stencil of point @p p: run.shape's (linear unless the scene
 *         chose another row). @return the nodes in use, Stencil::n */
static inline int stencil_of_point(const Sim *sim, int p, Stencil *st)
{
    if (sim->scene.run.stencil) {         /* another row of run.shape */
        stencil_wide(sim, sim->scene.run.stencil, p, st);
        return st->n;
    }
    stencil_linear(sim, p, st);
    return st->n = STENCIL_NODES;
}

/// [stencil_row]
/** A point's stencil as the passes of a step read it: the arrays of a
 *  Stencil, here pointers, into the stencils stored at Task 0
 *  (stencils.h) or into a Stencil (stencil_row()). */
typedef struct StencilRow {
    int n;                /**< nodes in use */
    const int *slot;      /**< the field slot of each pair */
    const double *S;      /**< shape function values S_ip */
    const double *Gx;     /**< gradients dS/dx */
    const double *Gy;     /**< gradients dS/dy */
} StencilRow;

/** @brief The row of a computed stencil @p st. */
static inline StencilRow stencil_row(const Stencil *st)
{
    return (StencilRow){st->n, st->slot, st->S, st->Gx, st->Gy};
}

/** @brief Point @p p's bilinear stencil of this step, stored at Task 0
 *         with Task 1's fields (run.shape linear, no stencil function). */
static inline StencilRow stencil_stored(const Sim *sim, int p)
{
    const Stencil4 *r = &sim->stencils.linear[p];
    return (StencilRow){STENCIL_NODES, r->slot, r->S, r->Gx, r->Gy};
}

/** @brief Point @p p's stencil of this step through run.shape's stencil
 *         function, stored at Task 0 with Task 1's fields. */
static inline const Stencil *stencil_stored_wide(const Sim *sim, int p)
{
    return &sim->stencils.wide[p];
}
/// [stencil_row]

/// [stencil_velocity_gradient]
/** @brief The velocity gradient at a point, L_p = sum_i v_i (x) G_ip over
 *         the first @p n pairs of its stencil @p st (eq. 34), into @p L as
 *         (du/dx, du/dy, dv/dx, dv/dy). */
static inline __attribute__((always_inline)) void
row_velocity_gradient(const Grid *g, const StencilRow *st, int n, double L[4])
{
    double xx = 0.0, xy = 0.0, yx = 0.0, yy = 0.0;  /* sums in registers */
#pragma GCC unroll 4
    for (int a = 0; a < n; a++) {
        int s = st->slot[a];
        xx += g->vx[s] * st->Gx[a];
        xy += g->vx[s] * st->Gy[a];
        yx += g->vy[s] * st->Gx[a];
        yy += g->vy[s] * st->Gy[a];
    }
    L[0] = xx;
    L[1] = xy;
    L[2] = yx;
    L[3] = yy;
}

/** @brief row_velocity_gradient() of a computed stencil @p st. */
static inline void stencil_velocity_gradient(const Grid *g, const Stencil *st,
                                             int n, double L[4])
{
    StencilRow row = stencil_row(st);
    row_velocity_gradient(g, &row, n, L);
}
/// [stencil_velocity_gradient]

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

/** @brief The nodes of point @p p's linear stencil, its cell's four
 *         (stage 4's contact runs with linear shape functions only). */
static inline void stencil_nodes(const Sim *sim, int p, int node[STENCIL_NODES])
{
    shape_cell_nodes(&sim->grid, sim->pts.cell[p], node);
}

/// [stencil_node_list]
/** @brief The nodes of point @p p's stencil, in its order: the pairs Task 1
 *         keys. @p wide is run.shape's stencil function (up to STENCIL_MAX
 *         nodes with uGIMP, chapter 8), or NULL for the cell's four (a
 *         constant NULL compiles to the linear loop alone). @return how
 *         many */
static inline __attribute__((always_inline)) int
stencil_node_list(const Sim *sim, StencilFn wide, int p, int node[STENCIL_MAX])
{
    if (wide) {                            /* another row of run.shape */
        Stencil st;
        wide(sim, p, &st);
        for (int a = 0; a < st.n; a++)
            node[a] = st.slot[a];          /* field 0: the nodes */
        return st.n;
    }
    stencil_nodes(sim, p, node);
    return STENCIL_NODES;
}
/// [stencil_node_list]

#endif
