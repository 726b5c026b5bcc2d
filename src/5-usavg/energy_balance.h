/**
 * @file energy_balance.h
 * @brief The energy bookkeeping of a run (stage 5): what came in (the
 *        initial energy and the work of gravity and point loads), what is
 *        stored (kinetic + strain) and what was dissipated (damping, and
 *        what each stage reports through SEAM_ENERGY: contact friction);
 *        what is left over is the scheme's error.
 */
#ifndef MPM_ENERGY_BALANCE_H
#define MPM_ENERGY_BALANCE_H

#include <stdio.h>

#include "sim.h"

/// [energy_balance_state]
/** Stage 5's energy account of one run (mJ). */
typedef struct EnergyBalance {
    double e0;       /**< kinetic + strain energy at the start */
    double w_ext;    /**< work of gravity and point loads so far */
    double w_damp;   /**< energy taken out by damping so far (>= 0) */
    double *x;       /**< per point: position x at the start of the step
                          (only when gravity or loads act; without
                          gravity, kept for the loaded points only) */
    double *y;       /**< per point: position y at the start of the step */
} EnergyBalance;
/// [energy_balance_state]

/** The balance at one instant (mJ). */
typedef struct EnergyTerms {
    double in;          /**< e0 + w_ext */
    double stored;      /**< kinetic + strain now */
    double damping;     /**< dissipated by damping */
    double dissipated;  /**< taken out by the stages (SEAM_ENERGY: contact
                             friction), >= 0 */
    double error;       /**< in - stored - damping - dissipated */
} EnergyTerms;

/** @brief Attach the account to @p sim and subscribe its hooks (the
 *         start, the report; per step only when the scene has gravity,
 *         point loads or damping). @return 0, or -1 out of memory. */
int energy_balance_prepare(Sim *sim, void *state, char *err, size_t errlen);

/** @brief The terms of the balance now. */
EnergyTerms energy_balance_terms(const Sim *sim, const EnergyBalance *B);

/** @brief Task 7, each step: the work of gravity and point loads on the
 *         points over the step, each force times its point's displacement
 *         (the force the step applied, the motion the step made). */
int energy_balance_step(Sim *sim, void *state, Seam seam);

/** @brief Task 4, each step when the scene has damping: the energy the
 *         damping force -kappa p takes out of the nodes over the step. */
int energy_balance_damping(Sim *sim, void *state, Seam seam);

/** @brief Print the balance line at the end of a run. */
int energy_balance_report(const Sim *sim, void *state, FILE *f);

/** @brief What the stages report through SEAM_ENERGY, summed (>= 0). */
double energy_seam_dissipated(const Sim *sim);

/** @brief Print the balance line of terms @p e, @p e0 the energy at the
 *         start (the rest of EnergyTerms::in is external work), each
 *         SEAM_ENERGY term by name; with @p moving > 0 moving holds whose
 *         work the terms lack, and no balance. A method with its own
 *         account (XEFG) prints its terms with it. @return 0 or -1. */
int energy_terms_print(const Sim *sim, const EnergyTerms *e, double e0,
                       int moving, FILE *f);

/** @brief Save or restore the account's sums (SEAM_CHECKPOINT). */
int energy_balance_checkpoint(Sim *sim, void *state, FILE *f, int save);

/** @brief Subscribe the account's set-up (stage 5's installer). */
int energy_balance_install(Hooks *h);

#endif
