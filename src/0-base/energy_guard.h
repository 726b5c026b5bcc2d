/**
 * @file energy_guard.h
 * @brief The energy guard: a run whose energy grows past run.energy_limit
 *        times the energy put in stops as unstable.
 *
 * The kinetic + strain energy of a run cannot exceed what was put in:
 * contact, damping and cracks take energy out, nothing makes it. On a
 * closed scene (no gravity, loads, moving boundaries or held points
 * moving) what was put in is the start's energy; where gravity or loads
 * work, it is the start's plus their work, which a stage may count
 * through SEAM_ENERGY_IN (chapter 5's energy account does). A scheme's
 * drift is a few per cent on the benchmarks; a run whose energy has
 * doubled has blown up, whether or not a value is infinite yet (the
 * program appendix, "The energy guard").
 */
#ifndef MPM_ENERGY_GUARD_H
#define MPM_ENERGY_GUARD_H

#include <stddef.h>

#include "scene_read.h"
#include "sim.h"

/** @brief run.energy_limit when the scene leaves it out. */
#define ENERGY_LIMIT_DEFAULT 2.0

/** What the guard compares a run's energy with. */
typedef struct EnergyGuard {
    double limit;       /**< run.energy_limit; 0: no guard */
    double e_start;     /**< kinetic + strain energy at the start */
    int counted;        /**< 1: the energy put in comes from SEAM_ENERGY_IN */
} EnergyGuard;

/**
 * @brief Moving boundaries and held point sets that move (a velocity or a
 *        table): their reactions do work that no stage counts. The first
 *        is named into @p first (NULL: not asked).
 * @return how many.
 */
int energy_guard_moving(const Scene *sc, char *first, size_t len);

/**
 * @brief What does work on the scene (gravity, a load, a moving boundary,
 *        held points moving), named into @p why.
 * @return 0 (closed), 1 (gravity or a load: work a stage may count) or
 *         2 (a moving boundary or held points: work nothing counts).
 */
int energy_guard_open(const Scene *sc, char *why, size_t len);

/**
 * @brief After the stages prepared: refuse run.energy_limit, given in the
 *        scene, where the guard has nothing to compare with (an open
 *        scene whose work no stage counts). @return 0, or -1 with the
 *        file, line and value in the reader's message.
 */
int energy_guard_check(const Sim *sim, const config_t *cfg, SceneReader *r);

/**
 * @brief The guard of a run, from the state the scene starts from (call
 *        it before a restart's state is read): off (limit 0) where it
 *        has nothing to compare with.
 */
EnergyGuard energy_guard_start(const Sim *sim);

/**
 * @brief Has the energy @p stored passed the guard's level now? Then the
 *        failure is recorded in Sim::fail (step_fail(): the ratio to the
 *        energy put in) and 1 is returned; else 0.
 */
int energy_guard_passed(Sim *sim, const EnergyGuard *g, double stored);

#endif
