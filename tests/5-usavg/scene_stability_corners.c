/**
 * @file scene_stability_corners.c
 * @brief Corners of the stability map (figures/fig-stability) on the beam
 *        impact with contact between bodies (figures/fig6/beam_supports.cfg),
 *        reduced to 1.5 ms, 2 x 2 points per cell.
 *
 * - USL at cfl 0.1 stops: sim_advance() reports the step, a point and the
 *   quantity, before the bodies can touch (their point domains 1.5 mm
 *   apart at 2.43 m/s: 0.62 ms). The impactor translates rigidly (no
 *   stress in exact arithmetic), and where its edge gives a node a small
 *   share of its mass, USL's update v + dt f / m_i (eq. 20) amplifies
 *   round-off until a point leaves the grid, long before any value
 *   overflows: the points' state is finite. Such a node appears when the
 *   impactor's rows of points cross node lines (every 0.21 ms at 2 x 2 per
 *   cell, first at 0.10 ms): the stop comes within a tenth of that after a
 *   crossing (0.6 % measured, at the second crossing; the first cost 3.7 %
 *   of the energy).
 * - the program on the same run, the energy guard off: exit status 3,
 *   the message names that step, point and quantity, history.csv holds
 *   only finite numbers, and particles_final.csv is not written (only a
 *   run that ends writes it). With the guard (the scene is closed: no
 *   gravity, loads or moving holds) it stops no later, at the first
 *   history row whose energy passes twice the first row's, the row
 *   before it within twice.
 * - USAVG at cfl 0.1 runs the reduced time with max |E/E0 - 1| <= 1 %, the
 *   map's bound between stable and drifting, checked every step.
 * - cfl 1.2 is refused at input, naming the key and allow_cfl_above_one;
 *   the program exits 1 and writes nothing. With allow_cfl_above_one = true
 *   the step is 12 times the cfl 0.1 step, and USL stops within it.
 */
#include "testkit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "stages.h"

static const char *const SCENE = "figures/fig6/beam_supports.cfg";
#define TIME "1.5"
#define BOUND 0.01      /* the map's drift bound on |E/E0 - 1| */

/** Load the scene with @p scheme at @p cfl, 2 x 2 points per cell (the
 *  scene's), to TIME ms; @p extra: one more override or NULL. */
static Sim *load(const char *scheme, const char *cfl, const char *extra)
{
    char u[64], c[64];
    snprintf(u, sizeof u, "run.update=%s", scheme);
    snprintf(c, sizeof c, "run.cfl=%s", cfl);
    const char *const over[] = {u, c, "run.time=" TIME, extra, NULL};
    Sim *sim = tk_load_file(SCENE, over);
    for (int b = 0; b < sim->scene.nbodies; b++)
        assert_int_equal(sim->scene.bodies[b].ppc, 2);
    return sim;
}

static int points_finite(const Sim *sim)
{
    const Particles *P = &sim->pts;
    for (int p = 0; p < P->n; p++)
        if (!isfinite(P->x[p] + P->y[p] + P->vx[p] + P->vy[p] + P->sxx[p] +
                      P->syy[p] + P->sxy[p] + P->exx[p] + P->eyy[p] + P->exy[p]))
            return 0;
    return 1;
}

/** From the layout: when the impactor's and the beam's point domains (each
 *  point fills h/ppc x h/ppc) would touch, and when the impactor's rows of
 *  points cross horizontal node lines (first at @p first, then every
 *  @p every ms: rows h/ppc apart, moving at its speed). */
static double layout_times(const char *scene, double *first, double *every)
{
    const char *const over[] = {"run.time=1e-9", NULL};
    Sim *sim = tk_load_file(scene, over);
    const Particles *P = &sim->pts;
    const double h = sim->grid.dy;
    double top = -INFINITY, bottom = INFINITY, v = 0, row = 0, lowest = INFINITY;
    for (int p = 0; p < P->n; p++) {
        const char *name = sim->scene.bodies[P->body[p]].name;
        double half = 0.5 * h / sim->scene.bodies[P->body[p]].ppc;
        if (strcmp(name, "beam") == 0)
            top = fmax(top, P->y[p] + half);
        else if (strcmp(name, "impactor") == 0) {
            bottom = fmin(bottom, P->y[p] - half);
            v = P->vy[p];
            row = 2 * half;
            lowest = fmin(lowest, P->y[p]);
        }
    }
    double oy = sim->grid.oy;
    tk_free(sim);
    assert_true(v < 0 && bottom > top);
    *every = row / -v;
    *first = fmod(lowest - oy, row) / -v;
    return (bottom - top) / -v;
}

/** Run to the end or the first failure; returns sim_advance()'s status. */
static int run_out(Sim *sim)
{
    int rc = 0;
    while (sim->step < sim->nsteps && (rc = sim_advance(sim)) == 0)
        ;
    return rc;
}

/** USL's stop, for the program test. */
static Failure usl_fail;
static char usl_quantity[128];

static void usl_stops_with_diagnostic(void **state)
{
    (void)state;
    Sim *sim = load("usl", "0.1", NULL);
    long n = sim->nsteps;
    int rc = run_out(sim);
    const Failure *f = &sim->fail;
    assert_int_not_equal(rc, 0);
    print_message("usl, cfl 0.1: stopped at step %ld of %ld (t = %g ms): particle %d "
                  "(body %s) %s = %g\n", f->step, n, f->time, f->particle,
                  sim->scene.bodies[sim->pts.body[f->particle]].name, f->quantity,
                  f->value);
    assert_true(f->step >= 1 && f->step < n);
    assert_int_equal(f->step, sim->step);
    assert_close(f->time, sim->t, 0.0);
    assert_true(f->particle >= 0 && f->particle < sim->pts.n);
    assert_non_null(f->quantity);
    assert_true(strstr(f->quantity, "velocity") || strstr(f->quantity, "position") ||
                strstr(f->quantity, "stress"));
    assert_true(points_finite(sim));
    /* before the bodies can touch: the blow-up began in the free impactor */
    double first, every, t_touch = layout_times(SCENE, &first, &every);
    /* and just after its rows of points crossed node lines: a node beyond
     * gets a sliver of their mass */
    double crossed = first + floor((f->time - first) / every) * every;
    print_message("the point domains touch at %.4f ms at the earliest; the impactor's "
                  "rows crossed node lines at %.4f ms, %.1f %% of the %.4f ms between "
                  "crossings before the stop\n", t_touch, crossed,
                  100 * (f->time - crossed) / every, every);
    assert_true(f->time < t_touch);
    assert_true(f->time >= crossed && f->time - crossed < 0.1 * every);
    usl_fail = *f;
    snprintf(usl_quantity, sizeof usl_quantity, "%s", f->quantity);
    tk_free(sim);
}

/** Every data row of @p path: numbers only, finite; returns the rows. */
static long finite_rows(const char *path, long *last_step)
{
    char *text = tk_slurp(path, NULL);
    char *save = NULL, *line = strtok_r(text, "\n", &save);
    assert_non_null(line);                       /* the header */
    long rows = 0;
    while ((line = strtok_r(NULL, "\n", &save)) != NULL) {
        for (char *c = line;;) {
            char *end;
            double v = strtod(c, &end);
            if (end == c || !isfinite(v))
                fail_msg("%s row %ld: \"%.40s\" is not a finite number", path,
                         rows + 1, c);
            if (c == line)
                *last_step = (long)v;
            if (*end != ',') {
                assert_int_equal(*end, '\0');
                break;
            }
            c = end + 1;
        }
        rows++;
    }
    free(text);
    return rows;
}

/** The total energy (column 5) of history.csv's first, last but one and
 *  last rows; @return the last row's step. */
static long history_energies(const char *path, double *first, double *before,
                             double *last)
{
    char *text = tk_slurp(path, NULL), *save = NULL;
    char *line = strtok_r(text, "\n", &save);          /* the header */
    assert_non_null(line);
    assert_true(strncmp(line, "step,time,kinetic,strain,total,", 31) == 0);
    long rows = 0, step = -1;
    *first = *before = *last = NAN;
    while ((line = strtok_r(NULL, "\n", &save)) != NULL) {
        double v[5];
        char *c = line;
        for (int k = 0; k < 5; k++, c++)
            v[k] = strtod(c, &c);
        step = (long)v[0];
        *before = *last;
        *last = v[4];
        if (rows++ == 0)
            *first = v[4];
    }
    free(text);
    assert_true(rows >= 2);
    return step;
}

static void usl_program_writes_no_nan(void **state)
{
    (void)state;
    if (!usl_fail.quantity)
        skip();
    char dir[] = "/tmp/mpm_stability_XXXXXX", args[1024], out[4096], path[512];
    assert_non_null(mkdtemp(dir));
    snprintf(args, sizeof args, "%s -q -o %s/out run.update=usl run.cfl=0.1 "
             "run.time=" TIME " run.energy_limit=0", SCENE, dir);
    int rc = tk_run_mpm(args, out, sizeof out);
    print_message("mpm said: %s", out);
    assert_int_equal(rc, 3);
    char expect[256];
    snprintf(expect, sizeof expect, "unstable at step %ld (t = ", usl_fail.step);
    assert_non_null(strstr(out, expect));
    snprintf(expect, sizeof expect, "particle %d %s = ", usl_fail.particle, usl_quantity);
    assert_non_null(strstr(out, expect));
    snprintf(path, sizeof path, "%s/out/history.csv", dir);
    long last = -1, rows = finite_rows(path, &last);
    print_message("history.csv: %ld rows, all finite, to step %ld\n", rows, last);
    assert_true(rows >= 2 && last < usl_fail.step);
    struct stat st;
    snprintf(path, sizeof path, "%s/out/particles_final.csv", dir);
    assert_int_not_equal(stat(path, &st), 0);

    snprintf(args, sizeof args, "%s -q -o %s/guard run.update=usl run.cfl=0.1 "
             "run.time=" TIME, SCENE, dir);
    assert_int_equal(tk_run_mpm(args, out, sizeof out), 3);
    print_message("mpm said (the guard on): %s", out);
    assert_non_null(strstr(out, "run.energy_limit"));
    snprintf(path, sizeof path, "%s/guard/history.csv", dir);
    double e_first, e_before, e_last;
    last = history_energies(path, &e_first, &e_before, &e_last);
    print_message("guard: stopped at the row of step %ld, E/E0 = %g (the row "
                  "before: %g); the point check stops at step %ld\n", last,
                  e_last / e_first, e_before / e_first, usl_fail.step);
    snprintf(expect, sizeof expect, "unstable at step %ld (t = ", last);
    assert_non_null(strstr(out, expect));
    assert_true(last <= usl_fail.step);
    assert_true(e_last > 2.0 * e_first && e_before <= 2.0 * e_first);
    snprintf(args, sizeof args, "rm -rf '%s'", dir);
    assert_int_equal(system(args), 0);
}

static void usavg_stable(void **state)
{
    (void)state;
    Sim *sim = load("usavg", "0.1", NULL);
    Totals t0 = sim_totals(sim);
    const double E0 = t0.kinetic + t0.strain;
    double drift = 0, at = 0;
    while (sim->step < sim->nsteps) {
        tk_steps(sim, 1);
        Totals t = sim_totals(sim);
        double d = fabs((t.kinetic + t.strain) / E0 - 1);
        if (d > drift) {
            drift = d;
            at = sim->t;
        }
    }
    print_message("usavg, cfl 0.1: %ld steps to %g ms, max |E/E0 - 1| = %.3f %% at "
                  "%.3f ms (bound %g %%)\n", sim->nsteps, sim->t, 100 * drift, at,
                  100 * BOUND);
    assert_true(drift <= BOUND);
    tk_free(sim);
}

static void cfl_above_one_refused(void **state)
{
    (void)state;
    Sim sim;
    sim_init(&sim);
    mpm_install_stages(&sim.hooks);
    char *over[] = {"run.cfl=1.2"};
    char err[1024] = "";
    int rc = sim_load_file(&sim, SCENE, 1, over, err, sizeof err);
    sim_free(&sim);
    print_message("refused: %s\n", err);
    assert_int_not_equal(rc, 0);
    assert_non_null(strstr(err, "cfl"));
    assert_non_null(strstr(err, "1.2 exceeds 1"));
    assert_non_null(strstr(err, "allow_cfl_above_one = true"));

    char dir[] = "/tmp/mpm_stability_XXXXXX", args[1024], out[4096], path[512];
    assert_non_null(mkdtemp(dir));
    snprintf(args, sizeof args, "%s -q -o %s/out run.cfl=1.2", SCENE, dir);
    assert_int_equal(tk_run_mpm(args, out, sizeof out), 1);
    assert_non_null(strstr(out, err));
    struct stat st;
    snprintf(path, sizeof path, "%s/out", dir);
    assert_int_not_equal(stat(path, &st), 0);    /* nothing written */
    assert_int_equal(rmdir(dir), 0);
}

static void cfl_above_one_insisted(void **state)
{
    (void)state;
    Sim *slow = load("usl", "0.1", NULL);
    Sim *sim = load("usl", "1.2", "run.allow_cfl_above_one=true");
    assert_close(sim->dt / slow->dt, 12.0, 1e-12);
    tk_free(slow);
    int rc = run_out(sim);
    print_message("usl, cfl 1.2 insisted: stopped at step %ld of %ld (t = %g ms): "
                  "particle %d %s = %g\n", sim->fail.step, sim->nsteps, sim->fail.time,
                  sim->fail.particle, sim->fail.quantity, sim->fail.value);
    assert_int_not_equal(rc, 0);
    assert_true(sim->fail.step >= 1 && sim->fail.step < sim->nsteps);
    assert_true(points_finite(sim));
    tk_free(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(usl_stops_with_diagnostic),
        cmocka_unit_test(usl_program_writes_no_nan),
        cmocka_unit_test(usavg_stable),
        cmocka_unit_test(cfl_above_one_refused),
        cmocka_unit_test(cfl_above_one_insisted),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
