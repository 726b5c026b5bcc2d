/**
 * @file quadrature.h
 * @brief Background-cell Gauss quadrature of the weak form (eq. 22-30),
 *        with cells cut by a crack split on each side (xefg.md 2.6).
 */
#ifndef MPM_QUADRATURE_H
#define MPM_QUADRATURE_H

#include "crack_line.h"

/** One quadrature point: where, and its weight (an area). */
typedef struct QuadPoint {
    double x;   /**< position x */
    double y;   /**< position y */
    double w;   /**< weight */
} QuadPoint;

/** Most Gauss points per direction. */
#define GAUSS_MAX 10

/**
 * @brief The @p n-point Gauss-Legendre rule on [-1, 1] (n = 1 .. GAUSS_MAX):
 *        exact for polynomials of degree 2n - 1.
 * @return 0, or -1 for an n out of range
 */
int gauss_legendre(int n, double *xi, double *w);

/**
 * @brief Quadrature points of the rectangle [x0, x1] x [y0, y1]: n x n
 *        Gauss points when no crack meets it. When cracks meet it, it is cut
 *        along the line of each segment that meets it into convex pieces,
 *        and each piece is fanned into triangles carrying n x n collapsed
 *        (Duffy) Gauss points; a piece that has a tip on its boundary is
 *        fanned from the tip, so that no point sits on a tip and the
 *        1/sqrt(r) gradients of eq. 5 are integrated well. Every point
 *        lies strictly inside a piece, off the crack.
 * @return the number of points, written to @p out; when more than @p cap,
 *         the number needed (nothing written beyond cap); -1 for a bad n
 *         (or out of memory)
 */
int quad_cell(const CrackLine *cracks, int ncracks, double x0, double y0,
              double x1, double y1, int n, QuadPoint *out, int cap);

/** The room quad_cell_in() works in (opaque). */
typedef struct QuadWork QuadWork;

/** @brief Room for cells met by at most @p max_cuts cuts (segments and
 *         tips). @return it, or NULL out of memory. */
QuadWork *quad_work_new(int max_cuts);

/** @brief Release the room (NULL: nothing). */
void quad_work_free(QuadWork *w);

/**
 * @brief quad_cell() in the room @p w (made once, at set-up), allocating
 *        nothing unless a piece needs more vertices than the room foresees
 *        (rounding). @return as quad_cell(); -2 when the cell has more
 *        cuts than @p w has room for.
 */
int quad_cell_in(QuadWork *w, const CrackLine *cracks, int ncracks, double x0,
                 double y0, double x1, double y1, int n, QuadPoint *out,
                 int cap);

#endif
