/**
 * @file run.c
 * @brief The run loop: steps, history, snapshots, progress, and the stop
 *        on instability.
 */
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "checkpoint.h"
#include "energy_guard.h"
#include "outfile.h"
#include "output.h"
#include "run.h"
#include "sim.h"
#include "step.h"

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
 *  last). @p dt0 is the step the run started with: once the step has
 *  been shortened (an XEFG crack grew, chapter 6b), the step is counted
 *  from now at the new step. */
static long snapshot_step(const Sim *sim, int k, double dt0)
{
    const RunSettings *run = &sim->scene.run;
    long n = sim->dt == dt0
                 ? lround(k * run->time / (run->snapshots * sim->dt))
                 : sim->step + lround((k * run->time / run->snapshots - sim->t) /
                                      sim->dt);
    return n < 1 ? 1 : n > sim->nsteps ? sim->nsteps : n;
}

/** history.csv: appended a row at a time, each row flushed, so the file
 *  holds whole rows after an interrupt; a row that cannot be written
 *  whole is cut off again. */
typedef struct History {
    FILE *f;            /**< the open file */
    char *path;         /**< its name, for messages */
    long bytes;         /**< its length up to the last whole row */
    EnergyGuard guard;  /**< the energy guard (energy_guard.h) */
} History;

static int history_flush(History *h)
{
    errno = 0;
    if (fflush(h->f) == 0 && !ferror(h->f)) {
        h->bytes = ftell(h->f);
        return 0;
    }
    outfile_report(h->path, errno ? errno : EIO);
    if (ftruncate(fileno(h->f), h->bytes) == 0)   /* no cut row on disk */
        clearerr(h->f);
    return -1;
}

/** Append a row; -1 when it cannot be written, -3 when the totals it
 *  holds are not finite though every point is (sums that overflow), or
 *  when the energy passed the guard's level (its row is written first:
 *  the file shows the growth). */
static int history_row(Sim *sim, History *h)
{
    Totals t = output_history_row(sim, h->f);
    if (history_flush(h))
        return -1;
    const char *what = !isfinite(t.kinetic) ? "total kinetic energy" :
                       !isfinite(t.strain) ? "total strain energy" :
                       !isfinite(t.px) ? "total momentum x" :
                       !isfinite(t.py) ? "total momentum y" : NULL;
    if (!what && energy_guard_passed(sim, &h->guard, t.kinetic + t.strain))
        return -3;
    if (!what)
        return 0;
    double v = !isfinite(t.kinetic) ? t.kinetic : !isfinite(t.strain) ? t.strain :
               !isfinite(t.px) ? t.px : t.py;
    step_fail(sim, -1, what, v);
    return -3;
}

/** Open history.csv: new with its header and first row, or, to restart,
 *  cut back to the checkpoint's last row. @return 0 or -1. */
static int history_open(Sim *sim, History *h, const char *dir, int restart)
{
    h->bytes = 0;
    h->path = outfile_path(dir, "history.csv");
    h->f = h->path ? fopen(h->path, restart ? "r+" : "w") : NULL;
    if (!h->f) {
        outfile_report(h->path ? h->path : dir, h->path ? errno : ENOMEM);
        return -1;
    }
    if (restart)
        return 0;
    output_history_header(sim, h->f);
    return history_row(sim, h);
}

/** Cut a restarted history.csv back to @p bytes and write after it. */
static int history_resume(History *h, long bytes)
{
    h->bytes = bytes;
    if (ftruncate(fileno(h->f), bytes) || fseek(h->f, bytes, SEEK_SET)) {
        outfile_report(h->path, errno);
        return -1;
    }
    return 0;
}

static int history_close(History *h)
{
    int rc = 0;
    if (h->f && fclose(h->f) != 0) {
        outfile_report(h->path, errno);
        rc = -1;
    }
    free(h->path);
    return rc;
}

/** Snapshot number rp->nsnap now, and the step of the next one. */
static int snapshot_now(Sim *sim, RunProgress *rp, const char *dir,
                        double dt0)
{
    const RunSettings *run = &sim->scene.run;
    int asked = rp->asked;
    rp->times[rp->nsnap] = sim->t;
    if (output_snapshot(sim, dir, rp->nsnap++, rp->times))
        return -1;
    while (rp->asked <= run->snapshots && snapshot_step(sim, rp->asked, dt0) <= sim->step)
        rp->asked++;                               /* two asked times, one step */
    if (sim->step > 0 && rp->asked == asked)       /* one snapshot an asked time */
        rp->asked++;
    rp->snap_at = rp->asked <= run->snapshots ? snapshot_step(sim, rp->asked, dt0) : -1;
    return 0;
}

/** Start a run: a new one (history header, snapshot 0), or one that goes
 *  on from the checkpoint in @p dir. @return 0, 1 (checkpoint refused),
 *  2 (output error) or 3 (sums not finite at the start). */
static int run_start(Sim *sim, RunProgress *rp, History *h, const char *dir,
                     int restart)
{
    if (restart) {
        char err[2048];
        if (checkpoint_read(sim, rp, dir, err, sizeof err)) {
            fprintf(stderr, "mpm: %s\n", err);
            return 1;
        }
        if (history_open(sim, h, dir, 1) || history_resume(h, rp->history_bytes))
            return 2;
        return 0;
    }
    char *old = outfile_path(dir, "%s", CHECKPOINT_FILE);
    if (old && unlink(old) && errno != ENOENT) {    /* not another run's */
        outfile_report(old, errno);
        free(old);
        return 2;
    }
    free(old);
    int hr = history_open(sim, h, dir, 0);
    if (hr)
        return hr == -3 ? 3 : 2;
    rp->asked = 1;
    rp->snap_at = sim->scene.run.snapshots > 0 ? snapshot_step(sim, 1, sim->dt) : -1;
    if (sim->scene.run.snapshots > 0 && snapshot_now(sim, rp, dir, sim->dt))
        return 2;
    return 0;
}

static int save_checkpoint(Sim *sim, RunProgress *rp, const History *h,
                           const char *dir)
{
    rp->history_bytes = h->bytes;
    return checkpoint_write(sim, rp, dir);
}

/** A stop before the end: the points and a checkpoint, and a message
 *  saying where the run stopped and how to go on. @return the status. */
static int run_stopped(Sim *sim, RunProgress *rp, const History *h,
                       const char *dir, int signo)
{
    int bad = output_points_final(sim, dir) ||
              save_checkpoint(sim, rp, h, dir);
    fprintf(stderr, "mpm: %s after step %ld of %ld (t = %.6g %s)%s\n",
            signo == SIGINT ? "interrupted (SIGINT)" :
            signo == SIGTERM ? "terminated (SIGTERM)" :
            signo ? "stopped by a signal" : "stopped as asked (--stop-at)",
            sim->step, sim->nsteps, sim->t, sim->scene.run.units->time,
            bad ? "; the state could not be saved" : "");
    if (bad)
        return 2;
    fprintf(stderr, "mpm: points in %s/particles_final.%s; go on with: "
            "mpm --restart %s\n", dir, sim->scene.run.binary ? "vtu" : "csv", dir);
    return signo ? 128 + signo : 0;
}

/** The stop's message: unstable (or stopped by a rule: Failure::stop),
 *  step, time, point (if one) and quantity. */
static void report_unstable(const Sim *sim, const char *outdir, int progress)
{
    const Failure *f = &sim->fail;
    const char *unit = sim->scene.run.units->time;
    if (progress)
        fputc('\n', stderr);
    const char *what = f->stop ? "stopped" : "unstable";
    if (f->particle >= 0)
        fprintf(stderr, "mpm: %s at step %ld (t = %.6g %s): particle %d "
                "%s = %g; stopping, output so far is in %s\n", what, f->step,
                f->time, unit, f->particle, f->quantity, f->value, outdir);
    else                                           /* a crack point, a sum */
        fprintf(stderr, "mpm: %s at step %ld (t = %.6g %s): %s = %g; "
                "stopping, output so far is in %s\n", what, f->step, f->time,
                unit, f->quantity, f->value, outdir);
}

/// [sim_run]
int sim_run(Sim *sim, const char *outdir, const RunOptions *opt)
{
    const RunSettings *run = &sim->scene.run;
    RunProgress rp = {0, 1, -1, NULL, run->snapshots + 2, 0};
    History h = {NULL, NULL, 0, energy_guard_start(sim)};  /* before a
                                                   restart's state is read */
    rp.times = malloc(sizeof(double) * (size_t)rp.cap);
    if (!rp.times || output_make_dir(outdir)) {
        free(rp.times);
        return 2;
    }
    int rc = run_start(sim, &rp, &h, outdir, opt->restart);
    if (rc == 3)
        report_unstable(sim, outdir, 0);
    long hist_every = run->history_every > 0 ? run->history_every
                                             : (sim->nsteps + 999) / 1000;
    int progress = opt->progress && isatty(STDERR_FILENO), signo = 0;
    double start = wall_seconds(), last = 0;
    long first = sim->step;
    double dt0 = sim->dt, dt_seen = sim->dt;      /* the step, as it started */
    while (rc == 0 && sim->step < sim->nsteps) {
        int hrc = 0;
        if (sim_advance(sim) ||
            ((sim->step % hist_every == 0 || sim->step == sim->nsteps) &&
             (hrc = history_row(sim, &h)) == -3)) {
            report_unstable(sim, outdir, progress);
            rc = 3;
            break;
        }
        if (hrc)
            rc = 2;
        if (sim->dt != dt_seen && rp.snap_at >= 0) {   /* shortened: again */
            dt_seen = sim->dt;
            rp.snap_at = snapshot_step(sim, rp.asked, dt0);
        }
        if (rc == 0 && rp.snap_at >= 0 && sim->step >= rp.snap_at &&
            snapshot_now(sim, &rp, outdir, dt0))
            rc = 2;                                /* the step nearest k T / K */
        if (rc == 0 && run->checkpoint_every > 0 && sim->step < sim->nsteps &&
            sim->step % run->checkpoint_every == 0 && save_checkpoint(sim, &rp, &h, outdir))
            rc = 2;
        if (progress)
            progress_line(sim, start, &last);
        signo = opt->interrupt ? *opt->interrupt : 0;
        if (rc == 0 && sim->step < sim->nsteps &&
            (signo || sim->step == opt->stop_at)) {
            if (progress)
                fputc('\n', stderr);
            rc = run_stopped(sim, &rp, &h, outdir, signo);
            progress = 0;
            if (rc == 0)
                rc = -1;                           /* stopped as asked */
            break;
        }
    }
    sim->loop_seconds = wall_seconds() - start;
    sim->loop_steps = sim->step - first;
    if (progress && rc != 3)
        fputc('\n', stderr);
    if (history_close(&h) && (rc == 0 || rc == -1))
        rc = 2;
    if (rc == 0 && output_points_final(sim, outdir))
        rc = 2;
    if (rc == 2)
        fprintf(stderr, "mpm: stopped: output in %s is incomplete\n", outdir);
    free(rp.times);
    return rc == -1 ? 0 : rc;
}
/// [sim_run]
