/**
 * @file sim.h
 * @brief A simulation: the scene, its material points, the grid, the hooks
 *        of the build, and the clock.
 */
#ifndef MPM_SIM_H
#define MPM_SIM_H

#include <stddef.h>
#include <stdint.h>

#include "field_table.h"
#include "grid.h"
#include "hooks.h"
#include "particles.h"
#include "scene.h"
#include "stencils.h"
#include "strips.h"

/** Most pieces of stage state a simulation carries. */
#define SIM_MAX_EXT 8

/** A piece of state a stage attached to the simulation, found by name. */
typedef struct SimExt {
    const char *name;            /**< "cracks", ... */
    void *state;                 /**< owned by the stage */
    void (*release)(void *state); /**< frees it (sim_free, in reverse order) */
} SimExt;

/** Why a run stopped early: the step, the point and the quantity. */
typedef struct Failure {
    long step;          /**< step at which it was detected */
    double time;        /**< time at the start of that step */
    int particle;       /**< point index */
    const char *quantity; /**< "velocity", "position", "stress", ... */
    double value;       /**< offending value */
    int stop;           /**< 1: a rule ended the run (step_stop()), not an
                             instability */
} Failure;

/** One simulation. */
typedef struct Sim {
    Scene scene;        /**< what the scene file said */
    Particles pts;      /**< material points */
    Grid grid;          /**< background grid */
    Hooks hooks;        /**< behaviour added by the stages of this build */
    FieldTable fields;  /**< velocity fields of the nodes (Task 1) */
    Strips strips;      /**< the nodes each thread writes, the points of
                             each (Task 0, strips.h) */
    Stencils stencils;  /**< every point's stencil of this step (Task 0,
                             stencils.h) */
    SimExt ext[SIM_MAX_EXT]; /**< the stages' state, by name */
    int next;           /**< how many */
    double t;           /**< current time (ms) */
    double dt;          /**< time step (ms) */
    long step;          /**< steps taken */
    long nsteps;        /**< steps the run will take */
    Failure fail;       /**< filled when sim_step() reports instability */
    double *bodyke;     /**< scratch: kinetic energy per body */
    int nmoving;        /**< nodes held at a prescribed velocity */
    int *moving;        /**< those nodes */
    int *moving_bc;     /**< the boundary (Scene::bc) that holds each */
    double loop_seconds; /**< wall time of sim_run()'s time loop, output included */
    long loop_steps;    /**< steps that loop took (fewer after a restart) */
    const char *source; /**< the scene file as given (a checkpoint names it) */
    int noverrides;     /**< its command-line overrides */
    char *const *overrides; /**< "key.path=value", the caller's strings */
    uint64_t scene_hash; /**< fingerprint of the settings (checkpoint.h) */
    size_t memory_limit; /**< bytes a scene may need (footprint.h), set
                              before loading; 0: the memory available */
    int threads;        /**< threads the parallel loops use: run.threads,
                             else OpenMP's default (OMP_NUM_THREADS, or
                             every core); set when a scene is loaded */
} Sim;

/** Quantities that history.csv records at one instant. */
typedef struct Totals {
    double kinetic;     /**< sum 1/2 m v^2 (mJ) */
    double strain;      /**< sum V0 * 1/2 sigma : eps (mJ) */
    double px;          /**< total x momentum (g mm/ms) */
    double py;          /**< total y momentum */
} Totals;

/** @brief Zero a simulation; the caller then installs the stages' hooks. */
void sim_init(Sim *sim);

/** @brief Attach a stage's @p state under @p name; @p release frees it
 *         with the simulation. @return 0, or -1 when full (nothing kept). */
int sim_attach(Sim *sim, const char *name, void *state,
               void (*release)(void *state));

/** @brief The state attached under @p name, or NULL. */
void *sim_state(const Sim *sim, const char *name);

/**
 * @brief Recompute the time step from the current point velocities and
 *        the scene's CFL factor (call after changing velocities by hand).
 */
void sim_set_time_step(Sim *sim);

/**
 * @brief Is the time step of sim_set_time_step() usable: positive and
 *        finite, and the run's time at least one and at most a countable
 *        number of steps? @return 0, or -1 with a message naming the
 *        settings that give it in @p err.
 */
int sim_check_time_step(const Sim *sim, char *err, size_t errlen);

/**
 * @brief Take one MPM time step (Tasks 0-8): the "mpm" row of the method
 *        table.
 * @return 0, or non-zero when the run went unstable (see Sim::fail).
 */
int sim_step(Sim *sim);

/** @brief Take one step with the scene's method (run.method). */
int sim_advance(Sim *sim);

/** @brief Energies and momentum of the points now. */
Totals sim_totals(const Sim *sim);

/** @brief Release everything the simulation holds. */
void sim_free(Sim *sim);

#endif
