/**
 * @file run.h
 * @brief The run loop: steps, snapshots, history, checkpoints and stops.
 */
#ifndef MPM_RUN_H
#define MPM_RUN_H

#include <signal.h>

#include "sim.h"

/** How sim_run() runs: what it prints, and when it stops before the end. */
typedef struct RunOptions {
    int progress;       /**< print a progress line on standard error */
    int restart;        /**< go on from the output directory's checkpoint */
    long stop_at;       /**< stop after this step as if interrupted (0: no) */
    /** set to a signal's number by the caller's handler (NULL: none):
     *  the run stops after the step it is in */
    const volatile sig_atomic_t *interrupt;
} RunOptions;

/**
 * @brief Run to the scene's end time writing output into @p outdir.
 *
 * A stop before the end (an interrupt, RunOptions::stop_at) writes the
 * points (particles_final.csv) and a checkpoint, from which a run with
 * RunOptions::restart goes on to the same bytes an unbroken run writes.
 * @param sim    a loaded simulation
 * @param outdir output directory, created if missing
 * @param opt    what to print and when to stop or save
 * @return 0 (also after a stop at RunOptions::stop_at), 1 when the
 *         checkpoint to restart from is refused, 2 on an output error,
 *         3 when the run went unstable, 128 + the signal's number when
 *         interrupted.
 */
int sim_run(Sim *sim, const char *outdir, const RunOptions *opt);

#endif
