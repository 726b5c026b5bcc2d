/**
 * @file energy_guard.h
 * @brief The energy guard: a closed scene whose energy grows past
 *        run.energy_limit times its start is stopped as unstable.
 *
 * Nothing does work on a closed scene (no gravity, loads, moving
 * boundaries or held points moving), so its energy (kinetic + strain)
 * can only stay or fall: contact, damping and cracks take energy out.
 * A scheme's drift is a few per cent on the benchmarks; a run whose
 * energy has doubled has blown up, whether or not a value is infinite
 * yet (chapter 5, "An energy guard").
 */
#ifndef MPM_ENERGY_GUARD_H
#define MPM_ENERGY_GUARD_H

#include <stddef.h>

#include "sim.h"

/** @brief run.energy_limit when the scene leaves it out. */
#define ENERGY_LIMIT_DEFAULT 2.0

/**
 * @brief What does work on the scene that the guard cannot count: into
 *        @p why ("gravity", "load 0", ...) when something does.
 * @return 1 (open, @p why filled) or 0 (closed).
 */
int energy_guard_open(const Scene *sc, char *why, size_t len);

/**
 * @brief The energy above which sim_run() stops: run.energy_limit times
 *        the kinetic + strain energy now, for a closed scene whose energy
 *        now is positive; INFINITY otherwise (no guard). Call it on the
 *        state the scene starts from; @p e_start gets the energy now.
 */
double energy_guard_level(const Sim *sim, double *e_start);

#endif
