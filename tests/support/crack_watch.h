/**
 * @file crack_watch.h
 * @brief Test helper: watch the points beside a crack, by the crack's own
 *        geometry, for crossings of its line and for its opening.
 *
 * A point's side of a crack is the sign of the cross product of the
 * nearest segment (among those its projection falls on) with the vector
 * from the segment's start to the point: +1 left of the crack's direction
 * (above), -1 right (below), exact in floating point up to the product's
 * rounding. A point crosses when its side, while its projection falls on
 * the crack, differs from the last side it had there. Nothing here is a
 * tolerance: a point that reaches the far side, by any distance, counts.
 */
#ifndef MPM_CRACK_WATCH_H
#define MPM_CRACK_WATCH_H

#include "sim.h"

/** The watched points of one crack. */
typedef struct CrackWatch {
    int body;            /**< the body whose points are watched (-1: all) */
    signed char *last;   /**< per point: last side on the crack, 0 unknown */
    int *face;           /**< points of the faces (for the opening) */
    signed char *face_side; /**< their sides at the start */
    int nface;           /**< how many */
    double open0;        /**< mean gap of the faces at the start */
    long crossings;      /**< crossings seen so far */
    int first_p;         /**< first point seen crossing, -1 */
    long first_step;     /**< at which step */
} CrackWatch;

/** @brief Side of (x, y) against the polyline (cx, cy) of @p n points:
 *         +1 above, -1 below, 0 on it; *within = 0 when its projection
 *         falls on no segment (then the side is 0); *dist the distance. */
int watch_side(const double *cx, const double *cy, int n, double x, double y,
               int *within, double *dist);

/**
 * @brief Start watching the points of body @p body beside the crack
 *        (cx, cy, n): every point's side; the faces are the points within
 *        @p band of the crack whose projection falls in its middle
 *        @p middle fraction (by arc length, e.g. 0.6).
 */
void watch_start(CrackWatch *w, const Sim *sim, int body, const double *cx,
                 const double *cy, int n, double band, double middle);

/** @brief Check every watched point now; @return crossings found now. */
int watch_check(CrackWatch *w, const Sim *sim, const double *cx,
                const double *cy, int n);

/** @brief Opening of the crack now: the mean signed distance of the faces'
 *         points above less that of those below, less its start value. */
double watch_opening(const CrackWatch *w, const Sim *sim, const double *cx,
                     const double *cy, int n);

/** @brief Release the watch. */
void watch_free(CrackWatch *w);

#endif
