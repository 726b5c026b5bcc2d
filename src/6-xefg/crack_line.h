/**
 * @file crack_line.h
 * @brief A crack as the meshfree method sees it: a polyline whose ends
 *        inside the body are tips; the side of a point (eq. 3-4) and how
 *        a node's support meets the crack (eq. 1-2: W_b, W_s).
 */
#ifndef MPM_CRACK_LINE_H
#define MPM_CRACK_LINE_H

/** A crack of n points; segment k joins points k and k + 1. */
typedef struct CrackLine {
    int n;              /**< points (segments + 1), at least 2 */
    const double *x;    /**< point x (stage 2's Crack::x) */
    const double *y;    /**< point y */
    int tip[2];         /**< 1 when end 0 / end n - 1 is a tip (lies in the
                             body); 0 when it lies outside (a crack mouth) */
} CrackLine;

/** How a support (a disk) meets a crack. */
typedef enum {
    SUPPORT_UNCUT = 0,  /**< no segment comes within the radius */
    SUPPORT_CUT = 1,    /**< cut through: W_b, step enrichment (eq. 1) */
    SUPPORT_TIP = 2     /**< holds a tip: W_s, branch enrichment (eq. 1) */
} SupportCut;

/**
 * @brief The side of (x, y): +1 left of the crack (walking from point 0 to
 *        point n - 1), -1 right, 0 on it; the closest segment decides
 *        (eq. 3-4: H = sign f, f the signed distance). Where the closest
 *        point is a vertex shared by two segments, the sum of their unit
 *        normals decides (right also where the crack folds back sharply).
 * @param c    the crack
 * @param x    the point's x
 * @param y    the point's y
 * @param dist distance to the crack (NULL: not wanted)
 */
int crack_line_side(const CrackLine *c, double x, double y, double *dist);

/**
 * @brief How the disk of centre (x, y) and radius @p r meets the crack: a
 *        tip closer than r makes it SUPPORT_TIP (that end in *end), else
 *        any segment closer than r makes it SUPPORT_CUT.
 * @param c   the crack
 * @param x   the disk's centre x
 * @param y   the disk's centre y
 * @param r   its radius
 * @param end the end (0 or 1) of the tip it holds, the nearer of two; -1
 *            when it holds none (may be NULL)
 */
SupportCut crack_line_cut(const CrackLine *c, double x, double y, double r,
                          int *end);

/**
 * @brief The tip at end @p end (0 or 1): its point and the unit vector
 *        along its last segment, pointing ahead of the crack.
 */
void crack_line_tip(const CrackLine *c, int end, double tip[2], double dir[2]);

#endif
