/**
 * @file balance.h
 * @brief The stage-6 growth tests' energy balance of an XEFG run with
 *        cohesive cracks (chapter 6b, "Energy"): start + held work =
 *        kinetic + strain + cohesive stored + dissipated + what the
 *        damping took out (Xefg::w_damped, as cohesive_energy_terms()
 *        counts it).
 */
#ifndef MPM_TEST_BALANCE_H
#define MPM_TEST_BALANCE_H

#include <math.h>

#include "cohesive.h"
#include "xefg.h"

/** @brief The balance's error (in - the rest), the energy in to @p in. */
static inline double xefg_balance_error(const Sim *s, double *in)
{
    const Xefg *x = xefg_of(s);
    *in = x->e0 + x->w_held;
    return *in - xefg_kinetic_energy(x) - xefg_strain_energy(x, s) -
           cohesive_stored_energy(x->coh) -
           cohesive_dissipated_energy(x->coh) - x->w_damped;
}

/** @brief |the balance's error| over the energy in. */
static inline double xefg_balance(const Sim *s)
{
    double in;
    double err = xefg_balance_error(s, &in);
    return fabs(err) / in;
}

#endif
