/**
 * @file grid.h
 * @brief The background grid: a regular array of rectangular cells whose
 *        nodes carry the nodal masses, momenta and forces of one time step.
 *
 * A node owns one *slot* (its field 0).  Extra velocity fields (field_table.h)
 * append slots after the first @c nnodes; @c slot_node says to which node
 * each extra slot belongs.  Conventional MPM uses only the first @c nnodes
 * slots.  Arrays a stage asks for (the momentum before contact)
 * stay NULL otherwise.
 */
#ifndef MPM_GRID_H
#define MPM_GRID_H

/** Bit set in Grid::fixed when a node's x velocity is held at zero. */
#define GRID_FIX_X 1u
/** Bit set in Grid::fixed when a node's y velocity is held at zero. */
#define GRID_FIX_Y 2u

/// [grid]
/** Regular background grid and its nodal data (structure of arrays). */
typedef struct Grid {
    double ox;        /**< x of the lower-left grid corner */
    double oy;        /**< y of the lower-left grid corner */
    double dx;        /**< cell width */
    double dy;        /**< cell height */
    double idx;       /**< 1 / dx */
    double idy;       /**< 1 / dy */
    int ncx;          /**< cells along x */
    int ncy;          /**< cells along y */
    int nnx;          /**< nodes along x (ncx + 1) */
    int nny;          /**< nodes along y (ncy + 1) */
    int nnodes;       /**< nnx * nny */
    int nslots;       /**< slots in use: nnodes plus extra field slots */
    int capacity;     /**< slots allocated */
    int *slot_node;   /**< node of extra slot s is slot_node[s - nnodes] */
    double *m;        /**< nodal mass per slot (eq. 26) */
    double *px;       /**< nodal x momentum per slot (eq. 26) */
    double *py;       /**< nodal y momentum per slot */
    double *fx;       /**< total nodal x force per slot (eq. 28) */
    double *fy;       /**< total nodal y force per slot */
    double *vx;       /**< nodal x velocity p/m per slot (eq. 34) */
    double *vy;       /**< nodal y velocity per slot */
    double *ax;       /**< nodal x acceleration f/m per slot */
    double *ay;       /**< nodal y acceleration per slot */
    double *qx;       /**< x momentum before Task 4's contact, when asked */
    double *qy;       /**< y momentum before Task 4's contact, when asked */
    unsigned char *fixed; /**< per node: GRID_FIX_X | GRID_FIX_Y */
} Grid;
/// [grid]

/**
 * @brief Allocate a grid of ncx x ncy cells of size dx x dy from (ox, oy).
 * @param g   the grid to fill
 * @param ox  x of the lower-left corner
 * @param oy  y of the lower-left corner
 * @param dx  cell width
 * @param dy  cell height
 * @param ncx cells along x
 * @param ncy cells along y
 * @return 0 on success, -1 when memory is exhausted.
 */
int grid_init(Grid *g, double ox, double oy, double dx, double dy,
              int ncx, int ncy);

/** @brief Make room for @p capacity slots (never shrinks). @return 0 or -1. */
int grid_reserve(Grid *g, int capacity);

/** @brief Allocate the optional per-slot array @p which (&g->qx or
 *        &g->qy), zeroed; it grows with the grid. @return 0 or -1. */
int grid_want(Grid *g, double **which);

/** @brief Release the grid's arrays. */
void grid_free(Grid *g);

/** @brief Zero slots 0 .. nslots-1 of the @p narrays arrays @p arrays,
 *         in blocks shared among @p threads threads (on one thread the
 *         grid's `memset` was the largest serial part of a step, issue 29). */
void grid_zero(const Grid *g, double *const *arrays, int narrays, int threads);

/** @brief Task 0/8: zero masses, momenta, forces (and volumes) of every
 *         slot in use. */
void grid_clear(Grid *g, int threads);

/** @brief Node that owns slot @p s. */
static inline int grid_slot_node(const Grid *g, int s)
{
    return s < g->nnodes ? s : g->slot_node[s - g->nnodes];
}

/** @brief x coordinate of node @p n. */
static inline double grid_node_x(const Grid *g, int n)
{
    return g->ox + (n % g->nnx) * g->dx;
}

/** @brief y coordinate of node @p n. */
static inline double grid_node_y(const Grid *g, int n)
{
    return g->oy + (n / g->nnx) * g->dy;
}

/** @brief Bytes held by the grid's arrays. */
double grid_bytes(const Grid *g);

#endif
