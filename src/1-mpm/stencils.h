/**
 * @file stencils.h
 * @brief Every point's stencil of one step, computed once at Task 0 and
 *        read by every pass of the step (issue 29).
 *
 * All passes of a step (Tasks 1, 3, 5, 6 and the stress update) use the
 * shape functions of the points' positions at Task 0: update_points()
 * moves a point but not its cell, so the later passes read the old S_ip
 * and G_ip (eq. 31: "the stored shape data"). Computing them once per step
 * and storing them costs 112 bytes per point for the bilinear functions
 * (a Stencil4), a whole Stencil for a wider row of run.shape (chapter 8);
 * the arrays are allocated when a scene is loaded, none in a step.
 */
#ifndef MPM_STENCILS_H
#define MPM_STENCILS_H

#include "shape.h"

struct Sim;
struct Stencil;

/// [stencils]
/** A point's stored bilinear stencil: its cell's four nodes (as field
 *  slots), S_ip, dS/dx and dS/dy. */
typedef struct Stencil4 {
    int slot[STENCIL_NODES];     /**< the field slot of each pair */
    double S[STENCIL_NODES];     /**< shape function values S_ip */
    double Gx[STENCIL_NODES];    /**< gradients dS/dx */
    double Gy[STENCIL_NODES];    /**< gradients dS/dy */
} Stencil4;

/** The stencils of this step, one per point: linear ones when run.shape
 *  has no stencil function, whole Stencils (up to STENCIL_MAX nodes) when
 *  it has one. */
typedef struct Stencils {
    int npoints;             /**< points they hold; 0: none (set-up, or a
                                  method with a step of its own) */
    Stencil4 *linear;        /**< per point, or NULL */
    struct Stencil *wide;    /**< per point through run.stencil, or NULL */
} Stencils;
/// [stencils]

/**
 * @brief Set-up, after the stages prepared (they may choose run.stencil):
 *        room for one stencil per point of the "mpm" method's runs.
 * @return 0, or -1 when memory is exhausted.
 */
int stencils_init(struct Sim *sim);

/** @brief Task 0, after the cells: every point's stencil, every pair in
 *         field 0 (nothing before stencils_init()). */
void stencils_fill(struct Sim *sim);

/** @brief Task 1 ends: the pairs it keyed take their slots (FieldTable::
 *         row_slot), as stencil_fields() gives them. */
void stencils_fields(struct Sim *sim);

/** @brief Release the arrays. */
void stencils_free(Stencils *T);

#endif
