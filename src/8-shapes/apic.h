/**
 * @file apic.h
 * @brief The affine particle-in-cell transfer (APIC; Jiang, Schroeder,
 *        Selle, Teran & Stomakhin 2015, and Jiang, Schroeder & Teran 2017,
 *        J. Comput. Phys. 338): each point carries, besides its velocity,
 *        the affine part of the velocity field around it, and gives the
 *        nodes m_p S_ip (v_p + C_p (x_i - x_p)) instead of m_p S_ip v_p.
 */
#ifndef MPM_APIC_H
#define MPM_APIC_H

#include <stddef.h>

#include "sim.h"
#include "stencil.h"
#include "strip_scatter.h"
#include "transfer.h"

/** The name under which the APIC state is attached (sim_state()). */
#define APIC_STATE "apic"

/** The APIC state of a run: its row of run.transfer (first, so that
 *  RunSettings::transfer leads to it) and each point's B_p. */
typedef struct Apic {
    Transfer row;  /**< the row, with the functions of apic.c */
    double *B;     /**< 4 per point: B_xx, B_xy, B_yx, B_yy (B = C D) */
    int n;         /**< points */
} Apic;

/** The row "apic" of run.transfer, as the scene reader finds it (set-up
 *  copies it into the run's own Apic::row, which RunSettings::transfer
 *  then points to). */
extern const Transfer transfer_apic;
/** The row "flip", today's transfer: eq. 26 and 30, no state. */
extern const Transfer transfer_flip;

/**
 * @brief D_p = sum_i S_ip (x_i - x_p)(x_i - x_p)^T over stencil @p st of a
 *        point at Task 0's position of point @p p: (xx, xy, yy).
 */
void apic_inertia(const Grid *g, const Particles *P, int p, const Stencil *st,
                  double D[3]);

/** @brief Tasks 1 and 6 (Transfer::scatter): the nodes get
 *         m_p S_ip C_p (x_i - x_p) more, C_p = B_p D_p^+ ; those of
 *         @p own only (a thread's strip; NULL: all, strip_scatter.h). */
void apic_scatter(const Sim *sim, int p, const Stencil *st, Grid *g,
                  const Owned *own);

/** @brief Task 5 (Transfer::gather): v_p = sum_i S_ip v_i and
 *         B_p = sum_i S_ip v_i (x_i - x_p)^T, at Task 0's position. */
void apic_gather(struct Sim *sim, int p, const Stencil *st);

/** @brief Set point @p p's affine part to the velocity gradient @p L
 *         (xx, xy, yx, yy): B_p = L D_p at Task 0's position. */
void apic_set_gradient(Sim *sim, int p, const double L[4]);

/** @brief The angular momentum about the origin of a run with
 *         run.transfer = "apic", per thickness as the masses are:
 *         sum_p m_p (x_p x v_p + B_p,yx - B_p,xy), which APIC conserves
 *         (Jiang et al. 2017). */
double apic_angular_momentum(const Sim *sim);

/**
 * @brief SEAM_PREPARE for run.transfer = "apic": refuse another method and
 *        keyed velocity fields; the linear shape through a stencil
 *        function; B_p from each body's initial velocity gradient; a
 *        checkpoint subscriber. @return 0, or -1 with a message.
 */
int apic_prepare(Sim *sim, void *state, char *err, size_t errlen);

/** @brief Register the key run.transfer and its rows "flip" and "apic". */
void apic_install(Hooks *h);

#endif
