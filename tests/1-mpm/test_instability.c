/**
 * @file test_instability.c
 * @brief USL made unstable on purpose (tests/1-mpm/scenes/usl_unstable.cfg):
 *        the stop names step, particle and quantity, the program exits 3 and
 *        leaves readable output; MUSL and USF stay stable on the same set-up.
 *
 * The set-up is the single-particle oscillator of test_oscillator.c with the
 * point at x_p = 1/32 of the cell, far from the cell's free nodes.  Those
 * nodes get mass m x_p (S -> 0) but the full force V sigma / L (G finite), so
 * USL's updated nodal velocity v + dt f / (m x_p) overshoots; its step map on
 * (v, eps L) has trace 2 - h/x_p and determinant 1 - h (1/x_p - 1), with
 * h = (omega dt)^2 = cfl^2 = 0.25 here: eigenvalues
 * lambda = (tr -+ sqrt(tr^2 - 4 det)) / 2 = -6.97 and 0.97.  The strain grows
 * by |lambda| a step until the point is thrown out of the grid.
 *
 * MUSL (v' = v - dt k u, u' = u + dt v') and USF (u' = u + dt v,
 * v' = v - dt k u') are symplectic Euler steps whatever x_p: they conserve
 * H = E -+ (1/2) dt k u v exactly, and |dt k u v| <= sqrt(h) E, so with
 * u(0) = 0 the energy E = K + U stays within E0 / (1 +- sqrt(h) / 2).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run.h"
#include "testkit.h"

static const char *const SCENE = "tests/1-mpm/scenes/usl_unstable.cfg";
static const double XP = 1.0 / 32.0;
static const double PI = 3.14159265358979323846;

static Sim *load_at(const char *scheme, const char *cfl)
{
    char ov[64];
    snprintf(ov, sizeof ov, "run.update=%s", scheme);
    const char *const overrides[] = {ov, cfl, NULL};
    Sim *sim = tk_load_file(SCENE, overrides);
    assert_int_equal(sim->pts.n, 1);
    assert_close(sim->pts.x[0], XP, 1e-15);
    return sim;
}

static Sim *load(const char *scheme) { return load_at(scheme, NULL); }

/** sim_step() reports the failure with step, particle and quantity. */
static void usl_stops(void **state)
{
    (void)state;
    Sim *sim = load("usl");
    long n = sim->nsteps;
    int rc = 0;
    while (sim->step < n && (rc = sim_step(sim)) == 0)
        ;
    assert_int_not_equal(rc, 0);
    print_message("usl: stopped at step %ld of %ld (t = %g ms): particle %d, %s = %g\n",
                  sim->fail.step, n, sim->fail.time, sim->fail.particle,
                  sim->fail.quantity, sim->fail.value);
    assert_true(sim->fail.step >= 1 && sim->fail.step < n);
    assert_int_equal(sim->fail.step, sim->step);       /* the step that failed */
    assert_close(sim->fail.time, sim->t, 0.0);
    assert_int_equal(sim->fail.particle, 0);
    assert_non_null(sim->fail.quantity);
    assert_true(strstr(sim->fail.quantity, "velocity") ||
                strstr(sim->fail.quantity, "position") ||
                strstr(sim->fail.quantity, "stress"));
    tk_free(sim);
}

/** The growth rate is USL's eigenvalue: |eps| x 6.97 a step. */
static void usl_growth_rate(void **state)
{
    (void)state;
    Sim *sim = load("usl");
    sim->pts.vx[0] = 1e-20;   /* eps ~ 1e-21 x 7^15: the point stays put */
    sim_set_time_step(sim);
    double h = 4.0 * PI * PI * sim->dt * sim->dt;
    double tr = 2.0 - h / XP, det = 1.0 - h * (1.0 / XP - 1.0);
    double lambda = 0.5 * (tr - sqrt(tr * tr - 4.0 * det));
    tk_steps(sim, 10);                       /* the other mode (0.97) is gone */
    double e10 = fabs(sim->pts.exx[0]);
    for (int k = 0; k < 5; k++) {            /* lambda < 0: eps flips sign */
        double before = sim->pts.exx[0];
        tk_steps(sim, 1);
        assert_true(before * sim->pts.exx[0] < 0);
    }
    double rate = pow(fabs(sim->pts.exx[0]) / e10, 1.0 / 5.0);
    print_message("usl: |eps| grows by %.6f a step; step map eigenvalue %.6f "
                  "(relative difference %.1e)\n", rate, lambda,
                  rate / fabs(lambda) - 1);
    /* the 0.97 mode decays relative to this one by 7^-10 ~ 3e-9 */
    assert_close(rate, fabs(lambda), 1e-6 * fabs(lambda));
    tk_free(sim);
}

/** MUSL and USF run the same scene to its end with bounded energy. */
static void stable(const char *scheme)
{
    Sim *sim = load(scheme);
    Totals t0 = sim_totals(sim);
    const double E0 = t0.kinetic + t0.strain;
    const double h = 4.0 * PI * PI * sim->dt * sim->dt;
    double lo = 1, hi = 1;
    long n = sim->nsteps;
    while (sim->step < n) {
        tk_steps(sim, 1);
        Totals t = sim_totals(sim);
        double E = (t.kinetic + t.strain) / E0;
        lo = fmin(lo, E);
        hi = fmax(hi, E);
    }
    print_message("%-4s: %ld steps, E/E0 in [%.6f, %.6f]; bounds [%.6f, %.6f]\n",
                  scheme, n, lo, hi, 1 / (1 + sqrt(h) / 2), 1 / (1 - sqrt(h) / 2));
    assert_true(hi <= (1 + 1e-9) / (1 - sqrt(h) / 2));
    assert_true(lo >= (1 - 1e-9) / (1 + sqrt(h) / 2));
    tk_free(sim);
}

static void musl_stable(void **state) { (void)state; stable("musl"); }
static void usf_stable(void **state) { (void)state; stable("usf"); }

static int ends_with(const char *s, const char *tail)
{
    size_t a = strlen(s), b = strlen(tail);
    return a >= b && strcmp(s + a - b, tail) == 0;
}

/** history.csv: a header and complete rows of numbers; returns the last
 *  row's step. */
static long check_history(const char *path)
{
    char *text = tk_slurp(path, NULL);
    assert_true(ends_with(text, "\n"));
    char *save = NULL, *line = strtok_r(text, "\n", &save);
    assert_non_null(line);
    assert_true(strncmp(line, "step,time,kinetic,strain,total", 30) == 0);
    int fields = 1;
    for (const char *c = line; *c; c++)
        fields += *c == ',';
    long rows = 0, last = -1;
    while ((line = strtok_r(NULL, "\n", &save)) != NULL) {
        int k = 0;
        for (char *c = line;; k++) {
            char *end;
            double v = strtod(c, &end);
            assert_true(end != c && isfinite(v));
            if (k == 0)
                last = (long)v;
            if (*end != ',') {
                assert_int_equal(*end, '\0');
                break;
            }
            c = end + 1;
        }
        assert_int_equal(k + 1, fields);
        rows++;
    }
    assert_int_equal(rows, last + 1);        /* one row a step, from step 0 */
    free(text);
    return last;
}

/** particles.pvd: a closed collection of closed .vtu files. */
static int check_pvd(const char *dir)
{
    char path[1024];
    int w = snprintf(path, sizeof path, "%s/particles.pvd", dir);
    assert_true(w > 0 && w < (int)sizeof path);
    char *text = tk_slurp(path, NULL);
    assert_true(ends_with(text, "</VTKFile>\n"));
    int files = 0;
    for (char *c = strstr(text, "file=\""); c; c = strstr(c, "file=\"")) {
        c += 6;
        char *q = strchr(c, '"');
        assert_non_null(q);
        w = snprintf(path, sizeof path, "%s/%.*s", dir, (int)(q - c), c);
        assert_true(w > 0 && w < (int)sizeof path);
        char *vtu = tk_slurp(path, NULL);
        assert_true(ends_with(vtu, "</VTKFile>\n"));
        free(vtu);
        files++;
    }
    free(text);
    return files;
}

/** The program: exit 3, a message naming step, particle and quantity, and
 *  the output written so far readable. The energy guard is off here
 *  (run.energy_limit=0): it would stop the run earlier, at the step of
 *  energy_guard_stops_first() below. */
static void program_exit_status(void **state)
{
    (void)state;
    Sim *sim = load("usl");
    while (sim_step(sim) == 0)
        ;
    char expect_step[64], expect_particle[64];
    snprintf(expect_step, sizeof expect_step, "step %ld", sim->fail.step);
    snprintf(expect_particle, sizeof expect_particle, "particle %d", sim->fail.particle);
    char quantity[128];
    snprintf(quantity, sizeof quantity, "%s", sim->fail.quantity);
    long fail_step = sim->fail.step;
    tk_free(sim);

    char dir[] = "/tmp/mpm_instability_XXXXXX";
    assert_non_null(mkdtemp(dir));
    char args[1024], out[4096];
    snprintf(args, sizeof args, "%s -o %s/out run.energy_limit=0", SCENE, dir);
    int rc = tk_run_mpm(args, out, sizeof out);
    print_message("mpm said: %s", out);
    assert_int_equal(rc, 3);
    assert_non_null(strstr(out, expect_step));
    assert_non_null(strstr(out, expect_particle));
    assert_non_null(strstr(out, quantity));

    char path[512];
    snprintf(path, sizeof path, "%s/out/history.csv", dir);
    assert_int_equal(check_history(path), fail_step);  /* every step before */
    snprintf(path, sizeof path, "%s/out", dir);
    int snaps = check_pvd(path);
    print_message("history.csv complete to step %ld; particles.pvd lists %d "
                  "closed .vtu files\n", fail_step, snaps);
    assert_true(snaps >= 2);                 /* t = 0 and at least one more */

    snprintf(args, sizeof args, "rm -rf '%s'", dir);
    assert_int_equal(system(args), 0);
}

/** Sums that overflow while every point is finite (masses of 1e300 at
 *  1e5 m/s: each point's m v^2 / 2 is 5e309) stop the run at its first
 *  history row with status 3, naming the sum, instead of writing inf. */
static void overflowing_totals_stop_the_run(void **state)
{
    (void)state;
    Sim *sim = tk_load_file("tests/1-mpm/scenes/disks.cfg", NULL);
    Particles *P = &sim->pts;
    for (int p = 0; p < P->n; p++) {
        P->m[p] = 1e300;
        P->vx[p] = P->vx[p] > 0 ? 1e5 : -1e5;
    }
    sim_set_time_step(sim);                 /* a step that keeps them in the grid */
    RunOptions opt = {0, 0, 0, NULL};
    int rc = sim_run(sim, "build/test-instability-totals", &opt);
    assert_int_equal(rc, 3);
    assert_non_null(sim->fail.quantity);
    assert_string_equal(sim->fail.quantity, "total kinetic energy");
    assert_int_equal(sim->fail.step, 0);       /* the first row, at t = 0 */
    tk_free(sim);
}

/** The guard's runs: cfl 0.27, h = 0.0729, USL's eigenvalue
 *  (tr - sqrt(tr^2 - 4 det)) / 2 = -1.30, so that its energy grows about
 *  1.7-fold a step and a restart's energy differs from the start's. */
#define GUARD_CFL "run.cfl=0.27"

/** The first step after which USL's energy (kinetic + strain) passes
 *  twice its start, stepping with sim_step() alone (no guard); @p ratio
 *  gets E / E0 there, @p fail_step the step the point check stops at,
 *  and @p high the step before it of the highest energy, @p e_high that
 *  energy / E0. */
static long doubling_step(const char *scheme, double *ratio, long *fail_step,
                          long *high, double *e_high)
{
    Sim *sim = load_at(scheme, GUARD_CFL);
    Totals t = sim_totals(sim);
    double e0 = t.kinetic + t.strain;
    long at = -1;
    *fail_step = -1;
    *high = 0;
    *e_high = 1.0;
    while (sim->step < sim->nsteps) {
        if (sim_step(sim)) {
            *fail_step = sim->fail.step;
            break;
        }
        t = sim_totals(sim);
        double e = (t.kinetic + t.strain) / e0;
        if (at < 0 && e > 2.0) {
            at = sim->step;
            *ratio = e;
        } else if (at < 0 && e > *e_high) {
            *high = sim->step;
            *e_high = e;
        }
    }
    tk_free(sim);
    return at;
}

/** The energy guard (run.energy_limit, default 2; the scene is closed:
 *  its nodes are held at rest, nothing loads it): USL's energy grows
 *  about 1.7-fold a step (GUARD_CFL), and the program stops at the
 *  first history row (one a step here) whose energy passes twice the
 *  start, with status 3, a message naming that step and the ratio, and
 *  that row written; before the point check would (it needs the point
 *  off the grid). A restart from a checkpoint taken before it stops at
 *  the same step: the level is the start's, not the restart's. MUSL's
 *  energy stays within E0 / (1 - sqrt(h) / 2) = 1.16 E0 (above): the
 *  guard lets it run to the end. */
static void energy_guard_stops_first(void **state)
{
    (void)state;
    double ratio = 0, e_high;
    long fail_step, high, at = doubling_step("usl", &ratio, &fail_step, &high, &e_high);
    print_message("usl: energy passes 2 E0 after step %ld (E/E0 = %g); the "
                  "point check stops at step %ld; restart after step %ld "
                  "(E/E0 = %g)\n", at, ratio, fail_step, high, e_high);
    assert_true(at >= 1 && at < fail_step);
    assert_true(ratio > 2.0);
    assert_true(high >= 1 && 2.0 * e_high > ratio);  /* a level of twice the
                           restart's energy would let step `at` pass */

    char dir[] = "/tmp/mpm_guard_XXXXXX";
    assert_non_null(mkdtemp(dir));
    char args[1024], out[4096], expect[64];
    snprintf(args, sizeof args, "%s -q -o %s/out run.snapshots=0 " GUARD_CFL, SCENE, dir);
    assert_int_equal(tk_run_mpm(args, out, sizeof out), 3);
    print_message("mpm said: %s", out);
    snprintf(expect, sizeof expect, "unstable at step %ld ", at);
    assert_non_null(strstr(out, expect));
    assert_non_null(strstr(out, "run.energy_limit"));
    const char *eq = strstr(out, "grow) = ");
    assert_non_null(eq);
    assert_close(strtod(eq + 8, NULL), ratio, 1e-5 * ratio);   /* %g: 6 digits */
    char path[512];
    snprintf(path, sizeof path, "%s/out/history.csv", dir);
    assert_int_equal(check_history(path), at);      /* its row, then the stop */

    snprintf(args, sizeof args, "%s -q -o %s/re run.snapshots=0 " GUARD_CFL " --stop-at %ld",
             SCENE, dir, high);
    tk_run_mpm_ok(args, out, sizeof out);
    snprintf(args, sizeof args, "-q --restart %s/re", dir);
    assert_int_equal(tk_run_mpm(args, out, sizeof out), 3);
    assert_non_null(strstr(out, expect));

    snprintf(args, sizeof args, "%s -q -o %s/musl run.snapshots=0 run.update=musl " GUARD_CFL,
             SCENE, dir);
    tk_run_mpm_ok(args, out, sizeof out);
    snprintf(args, sizeof args, "rm -rf '%s'", dir);
    assert_int_equal(system(args), 0);
}

/** Where gravity works and nothing counts its work (stage 1 has no energy
 *  account), the guard has nothing to compare with: off by default (the
 *  run ends), and run.energy_limit given is refused with file and line. */
static void energy_guard_needs_the_work_counted(void **state)
{
    (void)state;
    char out[4096];
    const char *args = "tests/1-mpm/scenes/disks.cfg -q -o build/test-guard-gravity "
                       "run.time=0.1 run.snapshots=0 run.gravity=[0.0,-1.0]";
    tk_run_mpm_ok(args, out, sizeof out);
    char more[512];
    snprintf(more, sizeof more, "%s run.energy_limit=3", args);
    assert_int_equal(tk_run_mpm(more, out, sizeof out), 1);
    print_message("mpm said: %s", out);
    assert_non_null(strstr(out, "energy_limit: 3: gravity does work on this "
                                "scene that this run does not count"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(usl_stops),
        cmocka_unit_test(usl_growth_rate),
        cmocka_unit_test(musl_stable),
        cmocka_unit_test(usf_stable),
        cmocka_unit_test(program_exit_status),
        cmocka_unit_test(overflowing_totals_stop_the_run),
        cmocka_unit_test(energy_guard_stops_first),
        cmocka_unit_test(energy_guard_needs_the_work_counted),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
