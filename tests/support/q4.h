/**
 * @file q4.h
 * @brief A static plane-stress finite element analysis on a regular grid of
 *        4-node elements: the reference the paper compares CRAMP with in
 *        Fig. 2.  A verification tool, solved by LAPACKE's banded Cholesky.
 */
#ifndef MPM_Q4_H
#define MPM_Q4_H

/** A rectangular mesh of nx x ny bilinear elements and its solution. */
typedef struct Q4Model {
    int nx;             /**< elements along x */
    int ny;             /**< elements along y */
    double x0;          /**< lower-left corner x */
    double y0;          /**< lower-left corner y */
    double dx;          /**< element width */
    double dy;          /**< element height */
    double t;           /**< thickness */
    double E;           /**< Young's modulus */
    double nu;          /**< Poisson's ratio */
    double *f;          /**< nodal forces, 2 per node (x, y) */
    unsigned char *fix; /**< fixed degrees of freedom, 2 per node */
    double *u;          /**< nodal displacements after q4_solve() */
} Q4Model;

/** @brief Set up the mesh. @return 0, or -1 when memory is short. */
int q4_init(Q4Model *q, int nx, int ny, double x0, double y0, double dx,
            double dy, double t, double E, double nu);

/** @brief Node index of mesh point (i, j). */
static inline int q4_node(const Q4Model *q, int i, int j)
{
    return j * (q->nx + 1) + i;
}

/** @brief Add the force (fx, fy) at (x, y), shared among the four nodes of
 *         its element with the bilinear shape functions. */
void q4_point_force(Q4Model *q, double x, double y, double fx, double fy);

/** @brief Assemble K, impose the fixed dofs and solve K u = f (dpbsv).
 *  @return 0, or LAPACK's non-zero info. */
int q4_solve(Q4Model *q);

/** @brief Plane-stress stress (xx, yy, xy) at (x, y) from the solution. */
void q4_stress(const Q4Model *q, double x, double y, double s[3]);

/** @brief Displacement (ux, uy) at (x, y) from the solution. */
void q4_displacement(const Q4Model *q, double x, double y, double u[2]);

/** @brief Release the arrays. */
void q4_free(Q4Model *q);

#endif
