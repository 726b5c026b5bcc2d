/**
 * @file run.c
 * @brief The run loop: steps, history, snapshots, progress, and the stop
 *        on instability.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

#include "output.h"
#include "sim.h"

static double wall_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static void progress_line(const Sim *sim, double start, double *last)
{
    double now = wall_seconds();
    if (now - *last < 0.5 && sim->step < sim->nsteps)
        return;
    *last = now;
    double frac = (double)sim->step / (double)sim->nsteps;
    double left = frac > 0 ? (now - start) * (1 - frac) / frac : 0;
    fprintf(stderr, "\r  step %ld/%ld  t = %.4g %s  %3.0f%%  about %.0f s left   ",
            sim->step, sim->nsteps, sim->t, sim->scene.run.units->time, 100 * frac, left);
    fflush(stderr);
}

/** The step whose time is nearest snapshot @p k's asked time, k T / K for
 *  K snapshots over the run's time T (a whole step at least, at most the
 *  last). */
static long snapshot_step(const Sim *sim, int k)
{
    const RunSettings *run = &sim->scene.run;
    long n = lround(k * run->time / (run->snapshots * sim->dt));
    return n < 1 ? 1 : n > sim->nsteps ? sim->nsteps : n;
}

/// [sim_run]
int sim_run(Sim *sim, const char *outdir, int progress)
{
    char path[1200];
    const RunSettings *run = &sim->scene.run;
    if (output_make_dir(outdir)) {
        fprintf(stderr, "mpm: cannot create output directory %s\n", outdir);
        return 2;
    }
    snprintf(path, sizeof path, "%s/history.csv", outdir);
    FILE *hist = fopen(path, "w");
    double *times = malloc(sizeof(double) * (size_t)(run->snapshots + 2));
    if (!hist || !times) {
        fprintf(stderr, "mpm: cannot write %s\n", path);
        if (hist)
            fclose(hist);
        free(times);
        return 2;
    }
    long hist_every = run->history_every > 0 ? run->history_every
                                             : (sim->nsteps + 999) / 1000;
    int nsnap = 0, asked = 1, rc = 0;             /* asked: the next snapshot k */
    long snap_at = run->snapshots > 0 ? snapshot_step(sim, 1) : -1;
    progress = progress && isatty(STDERR_FILENO);
    double start = wall_seconds(), last = 0;

    output_history_header(sim, hist);
    output_history_row(sim, hist);
    if (run->snapshots > 0) {
        times[nsnap] = sim->t;
        if (output_snapshot(sim, outdir, nsnap++, times))
            rc = 2;
    }
    while (rc == 0 && sim->step < sim->nsteps) {
        if (sim_advance(sim)) {
            const Failure *f = &sim->fail;
            if (progress)
                fputc('\n', stderr);
            fprintf(stderr, "mpm: unstable at step %ld (t = %.6g %s): particle %d "
                    "%s = %g; stopping, output so far is in %s\n", f->step,
                    f->time, run->units->time, f->particle, f->quantity, f->value,
                    outdir);
            rc = 3;
            break;
        }
        if (sim->step % hist_every == 0 || sim->step == sim->nsteps) {
            output_history_row(sim, hist);
            fflush(hist);                          /* whole rows on disk */
        }
        if (sim->step == snap_at) {                /* the step nearest k T / K */
            times[nsnap] = sim->t;
            if (output_snapshot(sim, outdir, nsnap++, times))
                rc = 2;
            while (asked <= run->snapshots && snapshot_step(sim, asked) <= sim->step)
                asked++;                           /* two asked times, one step */
            snap_at = asked <= run->snapshots ? snapshot_step(sim, asked) : -1;
        }
        if (progress)
            progress_line(sim, start, &last);
    }
    sim->loop_seconds = wall_seconds() - start;
    if (progress && rc != 3)
        fputc('\n', stderr);
    if (fclose(hist) != 0 && rc == 0)
        rc = 2;
    if (rc == 0) {
        snprintf(path, sizeof path, "%s/particles_final.csv", outdir);
        if (output_points_csv(sim, path))
            rc = 2;
    }
    if (rc == 2)
        fprintf(stderr, "mpm: cannot write output into %s\n", outdir);
    free(times);
    return rc;
}
/// [sim_run]
