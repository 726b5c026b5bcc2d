/**
 * @file usavg_scheme.h
 * @brief The paper's averaged stress update, USAVG, as a row of the table
 *        of update schemes, and the energy argument that picks its shares:
 *        what a row's step conserves on chapter 1's one-point oscillator.
 */
#ifndef MPM_USAVG_SCHEME_H
#define MPM_USAVG_SCHEME_H

#include "scene.h"

/// [usavg_scheme]
/** @brief USAVG: which shares of the strain increment are taken at Task 2
 *         and at Task 6, and whether Task 6 re-extrapolates first. */
UpdateScheme usavg_scheme(void);
/// [usavg_scheme]

/// [scheme_modified_energy]
/**
 * @brief The modified energy of a scheme row on the one-point oscillator:
 *        the quadratic form that one step of the row conserves exactly.
 *
 * The row takes the share @p a of the strain increment at Task 2 (from the
 * velocity at the start of the step) and 1 - a at Task 6 (from the new
 * velocity, re-extrapolated): a = 0 is MUSL, 1 is USF. On the oscillator
 * (tests/1-mpm/test_oscillator.c: angular frequency omega, state v, the
 * point's velocity, and u, the stretch of its cell) one step of size dt is
 *
 *     u += a dt v,   v -= dt omega^2 u,   u += (1 - a) dt v.
 *
 * The energy is (m/2) (v^2 + (omega u)^2); the form is normalised so that
 * it is v^2 + (omega u)^2 at dt = 0.
 * @param a     the share of the step at Task 2, in [0, 1]
 * @param theta omega dt, in [0, 2)
 * @param v     the velocity
 * @param wu    omega times the stretch u
 * @return the form at (v, wu); one step of the row leaves it unchanged.
 */
double scheme_modified_energy(double a, double theta, double v, double wu);

/**
 * @brief The largest departure of the oscillator's energy from its start,
 *        max over the orbit of |E/E0 - 1|, under the row of share @p a
 *        started with all its energy kinetic (u = 0).
 *
 * The orbit lies on the level set of scheme_modified_energy() through
 * (v0, 0); a long run's largest |E/E0 - 1| comes as close to this bound as
 * its steps sample the orbit.
 * @param a     the share of the step at Task 2, in [0, 1]
 * @param theta omega dt, in (0, 2)
 * @return max |E/E0 - 1| over the orbit.
 */
double scheme_energy_departure(double a, double theta);
/// [scheme_modified_energy]

#endif
