/**
 * @file scene_growth_dcb.c
 * @brief Chapter 7's growth on the DCB (tests/7-fracture/scenes/
 *        dcb_growth.cfg): its end nodes open the arms slowly, and the tip
 *        grows by half a cell whenever the mean J of its contours reaches
 *        G_c.
 *
 * Bounds, fixed before the first run:
 * - the crack grows (at least 20 segments in 600 ms), by exactly one
 *   segment per event, and the crack has 1 + events segments;
 * - an event happens exactly when a block of evaluations spanning
 *   growth.average (2 ms) ends with the mean J (over the contours and the
 *   block) >= G_c, and at no other evaluation (so none while J < G_c);
 * - the tip stays on the crack line: |y| <= 0.05 cell (the beam is
 *   symmetric: K_II is round-off, the kink angle with it);
 * - the crack length against the opening: where the tip first reaches a
 *   = 52, 56, ..., 68 mm, the opening is within 5 % of the opening at
 *   which a Q4 finite element analysis gives G(a) = G_c (G = Delta^2 C' /
 *   (2 B C^2), C(a) the opening compliance of end shear, C' by central
 *   differences of 1 mm, elements of 0.5 mm);
 * - a run stopped after some events and restarted writes the same bytes
 *   as one that never stopped; a crack that fills max_segments stops the
 *   run, naming the key.
 */
#include "testkit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "crack_growth.h"
#include "cracks.h"
#include "q4.h"

#define SCENE "tests/7-fracture/scenes/dcb_growth.cfg"
#define OUT "build/test-growth"
#define ARM 18.0          /* arm depth, mm */
#define LENGTH 100.0      /* beam length, mm */
#define V_END 4e-3        /* the end nodes' speed, mm/ms */
#define RAMP 50.0         /* over which they reach it, ms */
#define NA 5              /* crack lengths compared with the FEA */

static const double A_AT[NA] = {52.0, 56.0, 60.0, 64.0, 68.0};

/** The opening (both arms) the end nodes have imposed at time @p t. */
static double opening(double t)
{
    double d = t <= RAMP ? V_END * t * t / (2.0 * RAMP) : V_END * (t - 0.5 * RAMP);
    return 2.0 * d;
}

/** Opening compliance of the DCB with crack length @p a (plane stress,
 *  thickness 1): the upper arm and the ligament's symmetry, a uniform
 *  shear on its end; C = 2 delta / P, delta the force-weighted mean of
 *  the end's displacement. Mesh x = beam y, mesh y = beam x. */
static double compliance(double a, double h, double E, double nu)
{
    Q4Model q;
    int nx = (int)lround(ARM / h), ny = (int)lround(LENGTH / h);
    assert_int_equal(q4_init(&q, nx, ny, 0.0, 0.0, h, h, 1.0, E, nu), 0);
    for (int j = 0; j <= ny; j++)
        if (j * h >= a - 1e-9)                      /* ligament: symmetry */
            q.fix[2 * q4_node(&q, 0, j)] = 1;
    q.fix[2 * q4_node(&q, 0, ny) + 1] = 1;           /* no rigid beam-x motion */
    double P = 1e-3, f = P / nx;                     /* end nodes above y = 0 */
    for (int i = 1; i <= nx; i++)
        q.f[2 * q4_node(&q, i, 0)] += i == nx ? 0.5 * f : f;
    q.f[2 * q4_node(&q, 1, 0)] += 0.5 * f;           /* sum P: the lost half */
    assert_int_equal(q4_solve(&q), 0);
    double work = 0.0;
    for (int i = 1; i <= nx; i++)
        work += q.f[2 * q4_node(&q, i, 0)] * q.u[2 * q4_node(&q, i, 0)];
    q4_free(&q);
    return 2.0 * work / (P * P);
}

/** The FEA's opening at which G(a) = G_c. */
static double fea_opening(double a, double Gc, double E, double nu)
{
    const double h = 0.5, da = 1.0;
    double c = compliance(a, h, E, nu);
    double dc = (compliance(a + da, h, E, nu) - compliance(a - da, h, E, nu)) /
                (2.0 * da);
    return c * sqrt(2.0 * Gc / dc);
}

static void grows_straight_when_J_reaches_G_c(void **state)
{
    (void)state;
    Sim *sim = tk_load_file(SCENE, NULL);
    const Cracks *C = cracks_of(sim);
    const JState *S = sim_state(sim, "j-integral");
    const CrackGrowth *G = sim_state(sim, "crack-growth");
    assert_non_null(S);
    assert_non_null(G);
    assert_int_equal(S->ntips, 1);
    const Crack *c = &C->crack[0];
    const GrowthEnd *e = &G->end[1];                /* the last point's */
    double Gc = G->set[0].G_c, dy = sim->grid.dy, avg = G->set[0].average;
    long events = 0, evaluations = 0, wrong = 0, blocks = 0, nblock = 0;
    double Jblock = 0.0;
    double ymax = 0.0, Jmax_below = 0.0, Jmin_at = 1e300, first_t = -1.0;
    double open_at[NA];
    int next = 0;
    for (long n = 0; n < sim->nsteps; n++) {
        tk_steps(sim, 1);
        if (S->at_step == sim->step) {               /* J evaluated now */
            double J = 0.0;
            int m = S->set[0].ncontours;
            for (int k = 0; k < m; k++)
                J += S->tip[0].J[k] / m;
            int grew = e->events > events, decide = 1;
            evaluations++;
            Jblock += J;                             /* the block's mean */
            nblock++;
            if (nblock * S->every * sim->dt < avg)
                decide = 0;
            else {
                J = Jblock / nblock;
                Jblock = 0.0;
                nblock = 0;
                blocks++;
            }
            if (grew != (decide && J >= Gc)) {
                if (wrong++ < 5)
                    printf("  step %ld: J %.6g, G_c %.6g, decides %d, grew %d\n",
                           sim->step, J, Gc, decide, grew);
            }
            if (!decide)
                J = 0.0;                             /* not a decision */
            if (grew) {
                Jmin_at = fmin(Jmin_at, J);
                if (first_t < 0)
                    first_t = sim->t;
            } else {
                Jmax_below = fmax(Jmax_below, J);
            }
            assert_true(e->events - events <= 1);   /* one event a step */
            events = e->events;
            while (next < NA && S->tip[0].x >= A_AT[next])
                open_at[next++] = opening(sim->t);
        }
        ymax = fmax(ymax, fabs(S->tip[0].y));
        assert_int_equal(c->n - 2, e->events);       /* 1 + events segments */
    }
    printf("  %ld evaluations of J in %ld blocks of %g ms, %ld events (segments "
           "now %d), tip at (%.4f, %.3g) mm\n", evaluations, blocks, avg, events,
           c->n - 1, S->tip[0].x, S->tip[0].y);
    printf("  first event at t = %.2f ms, opening %.4f mm; block J at events "
           ">= %.6g, without an event <= %.6g (G_c %g)\n", first_t,
           opening(first_t), Jmin_at, Jmax_below, Gc);
    printf("  largest |tip y| %.3g mm (%.3g cell)\n", ymax, ymax / dy);
    assert_int_equal(wrong, 0);
    assert_true(events >= 20);
    assert_true(ymax <= 0.05 * dy);
    /* the crack length against the opening: G(a) = G_c by the FEA */
    double E = sim->scene.mat[0].E, nu = sim->scene.mat[0].nu;
    printf("  crack length a against the opening Delta (both arms), FEA "
           "G(a) = G_c (Q4, 0.5 mm):\n     a (mm)   Delta MPM   Delta FEA   "
           "MPM/FEA - 1\n");
    TkBounds b = {0, 0};
    assert_int_equal(next, NA);
    for (int k = 0; k < NA; k++) {
        double fea = fea_opening(A_AT[k], Gc, E, nu);
        double err = open_at[k] / fea - 1.0;
        printf("     %5.1f    %8.5f    %8.5f    %+7.3f %%\n", A_AT[k],
               open_at[k], fea, 100.0 * err);
        tk_bound(&b, 4, fabs(err) <= 0.05, "a = %g mm: opening %+.2f %% from "
                 "the FEA's (bound 5 %%)", A_AT[k], 100.0 * err);
    }
    tk_bounds_finish(&b);
    tk_free(sim);
}

static char out[16384];

/** $MPM_BIN with @p args; the test fails unless it exits 0. */
static void run_ok(const char *args)
{
    tk_run_mpm_ok(args, out, sizeof out);
}

/** The last row's events_crack0_last of history.csv at @p path. */
static long last_events(const char *path)
{
    char *text = tk_slurp(path, NULL);
    char *head = strstr(text, "events_crack0_last");
    assert_non_null(head);
    int col = 0;
    for (char *p = text; p < head; p++)
        col += *p == ',';
    size_t len = strlen(text);
    while (len > 0 && text[len - 1] == '\n')
        text[--len] = '\0';
    char *row = strrchr(text, '\n') + 1;
    for (int k = 0; k < col; k++)
        row = strchr(row, ',') + 1;
    long n = atol(row);
    free(text);
    return n;
}

/** Stopped after some events and restarted: the same bytes. */
static void restart_gives_the_same_bytes(void **state)
{
    (void)state;
    system("rm -rf " OUT "/full " OUT "/split");
    run_ok(SCENE " -q -o " OUT "/full run.time=420 run.history_every=20");
    assert_non_null(strstr(out, "segments of"));
    run_ok(SCENE " -q -o " OUT "/split run.time=420 run.history_every=20 "
           "--stop-at 6700");
    long before = last_events(OUT "/split/history.csv");
    run_ok("--restart " OUT "/split -q");
    long after = last_events(OUT "/split/history.csv");
    printf("  events by the stop at step 6700: %ld; at the end: %ld\n",
           before, after);
    assert_true(before > 0 && after > before);
    tk_assert_same_outputs(OUT "/full", OUT "/split", "checkpoint.mpm");
}

/** A crack that fills its room stops the run and names the key. */
static void full_crack_stops_the_run(void **state)
{
    (void)state;
    int rc = tk_run_mpm(SCENE " -q -o " OUT "/full-room run.time=200 "
                        "cracks.[0].growth.G_c=2e-6 "
                        "cracks.[0].growth.max_segments=3", out, sizeof out);
    printf("  exit %d: %s", rc, out);
    assert_true(rc != 0);
    assert_non_null(strstr(out, "segments of crack 0, all the room reserved "
                            "(cracks.[0].growth.max_segments, " SCENE ":"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(grows_straight_when_J_reaches_G_c),
        cmocka_unit_test(restart_gives_the_same_bytes),
        cmocka_unit_test(full_crack_stops_the_run),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
