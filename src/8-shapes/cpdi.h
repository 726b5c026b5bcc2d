/**
 * @file cpdi.h
 * @brief CPDI shape functions (Sadeghirad, Brannon & Burghardt 2011, the
 *        first variant, "CPDI1"): the point's domain is a parallelogram
 *        that its deformation gradient carries, and the weights average
 *        the nodes' hat functions over it through its four corners.
 */
#ifndef MPM_CPDI_H
#define MPM_CPDI_H

#include <stdio.h>

#include "shape.h"
#include "stencil.h"

/** The name under which the deformation gradients are attached to a
 *  simulation (sim_state()). */
#define CPDI_STATE "cpdi"

/** The per-point deformation gradients that carry the domains. */
typedef struct Cpdi {
    double *F;   /**< 4 per point: F_xx, F_xy, F_yx, F_yy */
    int n;       /**< points */
} Cpdi;

/**
 * @brief The CPDI stencil of a parallelogram domain centred at (@p x,
 *        @p y) with half-side vectors @p r1 and @p r2 (lengths): the nodes
 *        of the cells its corners lie in, at most 3 x 3 (a wider domain is
 *        cut: cpdi_update() stops a run before that happens).
 *
 * S_ip = 1/4 sum_k N_i(x_k) over the corners x_k = x -+ r1 -+ r2, and
 * G_ip = 1/V closed integral of N_i n ds with N_i linear along each side.
 */
void cpdi_stencil_domain(const Grid *g, double x, double y, const double r1[2],
                         const double r2[2], Stencil *st);

/** @brief The CPDI stencil of point @p p: Task 0's position, and its body's
 *         initial half spacing carried by the point's F. */
void cpdi_stencil(const struct Sim *sim, int p, Stencil *st);

/** @brief The half-side vectors of point @p p's domain now (F times the
 *         initial half spacing along x and along y). */
void cpdi_vectors(const struct Sim *sim, const Cpdi *C, int p, double r1[2],
                  double r2[2]);

/**
 * @brief Set-up for run.shape = "cpdi": F = I for every point, a Task-7
 *        subscriber that advances F, a checkpoint subscriber that keeps it.
 * @return 0, or -1 with a message in @p err.
 */
int cpdi_prepare(struct Sim *sim, char *err, size_t errlen);

/** The row "cpdi" of run.shape's table. */
extern const ShapeFunctions shape_cpdi;

#endif
