/**
 * @file branch.h
 * @brief The branch functions of the tip enrichment: the LEFM set (eq. 5)
 *        and the cohesive r^m sin(theta/2) (eq. 6), with their gradients.
 */
#ifndef MPM_BRANCH_H
#define MPM_BRANCH_H

/** Which branch functions enrich a tip. */
typedef enum {
    BRANCH_LEFM = 0,     /**< sqrt(r) {sin, cos} (theta/2) {1, sin theta} (eq. 5) */
    BRANCH_COHESIVE = 1  /**< r^m sin(theta/2) (eq. 6): closes the crack at the tip */
} BranchKind;

/** Most branch functions of one tip. */
#define BRANCH_MAX 4

/// [branch_functions]
/**
 * @brief The branch functions at (x, y) about the tip at @p tip with unit
 *        direction @p dir (crack_line_tip()), and their gradients in
 *        global coordinates.
 *
 * (r, theta) are polar coordinates about the tip in its frame (x' along
 * dir), with theta = side * acos(x'/r), so that theta = +-pi on the two
 * faces of the crack and the jump follows the crack even where it bends.
 * @param kind  the set: eq. 5 or eq. 6
 * @param m     exponent of eq. 6 (BRANCH_COHESIVE), m >= 1
 * @param tip   the tip's point
 * @param dir   the unit vector ahead of the tip
 * @param side  the point's side of the crack (crack_line_side(), +1 or -1)
 * @param x     the point's x
 * @param y     the point's y
 * @param B     the values (BRANCH_MAX room)
 * @param dBx   d/dx of each (NULL: not wanted; then dBy too)
 * @param dBy   d/dy of each
 * @return how many functions: 4 (LEFM) or 1 (cohesive); 0 at r = 0, where
 *         they are not defined (no quadrature point may sit on a tip)
 */
int branch_functions(BranchKind kind, double m, const double tip[2],
                     const double dir[2], int side, double x, double y,
                     double *B, double *dBx, double *dBy);
/// [branch_functions]

#endif
