/**
 * @file test_modified_energy.c
 * @brief Exercise 5.1 (exercises/5-usavg/averaged-update): the energy error
 *        of a stress-update row, derived on chapter 1's one-point
 *        oscillator (src/5-usavg/usavg_scheme.c) and measured on it and on
 *        a free vibrating bar.
 *
 * The oscillator of tests/1-mpm/test_oscillator.c (one point in one cell,
 * period 1, omega = 2 pi) under five rows of the scheme table: MUSL (Task-2
 * share a = 0), USF (1), USAVG (1/2), and two rows this test registers,
 * a = 1/4 and 3/4 (the rest after re-extrapolation). Measured before the
 * bounds were fixed:
 * - over 10 periods at theta = omega dt = 0.2, scheme_modified_energy()
 *   stays within |H/H0 - 1| <= 1.1e-14 (asserted: 1e-10); the energy
 *   itself does not (the stub, which returns it, fails);
 * - over 50 periods at theta = 0.4, 0.2, 0.1, the run's max |E/E0 - 1| is
 *   scheme_energy_departure() to within a relative 2e-5 (asserted: 1e-3),
 *   e.g. at theta = 0.1: 5.263157e-02 (MUSL, USF), 2.499999e-03 (USAVG),
 *   2.534476e-02 (a = 1/4 and 3/4).
 *
 * The orders: scheme_energy_departure() falls by 2.05 (MUSL, USF) and 4.00
 * (USAVG) when theta halves from 0.1. On the bar of test_usavg.c (20 x 4
 * mm, halves moving apart, 40 ms) at cfl 0.4, 0.2, 0.1, max |E/E0 - 1|:
 * - MUSL  3.7316e-02, 1.7574e-02, 8.7073e-03: orders 1.086, 1.013;
 * - USF   3.8272e-02, 1.8264e-02, 8.6284e-03: orders 1.067, 1.082;
 * - USAVG 3.1183e-03, 8.1306e-04, 2.0510e-04: orders 1.939, 1.987;
 * - USL   2.3200e-01, 2.0045e-01, 1.8379e-01: orders 0.211, 0.125 (its
 *   loss is not a time-step error: eq. 20's small nodal masses).
 * Asserted: each order of MUSL, USF and USAVG within 0.15 of the order that
 * scheme_energy_departure() gives as theta goes to 0 (from theta = 0.01
 * to 0.005: 1.004 for a = 0 and 1, 2.000 for a = 1/2); USL's below 0.5.
 */
#include "testkit.h"

#include <math.h>
#include <stdio.h>

#include "hooks.h"
#include "usavg_scheme.h"

static const double PI = 3.14159265358979323846;

/** The rows of the scheme table, with their Task-2 share. */
typedef struct Row {
    const char *name;
    double a;
} Row;

static const Row ROWS[5] = {
    {"musl", 0.0}, {"usf", 1.0}, {"usavg", 0.5},
    {"quarter", 0.25}, {"three_quarters", 0.75},
};

/* Two rows between MUSL, USAVG and USF, as a later stage would add them. */
static void extra_rows(Hooks *h, void *arg)
{
    (void)arg;
    hooks_add_scheme(h, "quarter", 0.25, 0.75, 1);
    hooks_add_scheme(h, "three_quarters", 0.75, 0.25, 1);
}

/** The one-cell oscillator of test_oscillator.c, its point at the cell's
 *  centre moving at 1e-6 (all its energy kinetic), for @p periods. */
static Sim *load_oscillator(const char *scheme, double cfl, double periods)
{
    char text[2048], err[512];
    snprintf(text, sizeof text,
        "grid = { origin = [0.0, 0.0]; cells = [1, 1]; cell_size = [1.0, 1.0]; };\n"
        "run = { time = %.17g; cfl = %.17g; update = \"%s\"; snapshots = 0; };\n"
        "materials = ( { name = \"spring\"; E = %.17g; nu = 0.0; rho = 1.0; } );\n"
        "bodies = ( { name = \"point\"; material = \"spring\"; thickness = 1.0;\n"
        "  points_per_cell = 1; velocity = [1e-6, 0.0];\n"
        "  rectangle = { min = [0.0, 0.0]; max = [1.0, 1.0]; }; } );\n"
        "boundaries = (\n"
        "  { rectangle = { min = [-0.25, -0.25]; max = [0.25, 1.25]; }; fix = \"x\"; },\n"
        "  { rectangle = { min = [-0.25, -0.25]; max = [1.25, 1.25]; }; fix = \"y\"; } );\n",
        periods, cfl, scheme, 4.0 * PI * PI);
    Sim *sim = tk_load_with(text, extra_rows, NULL, err, sizeof err);
    if (!sim)
        fail_msg("%s", err);
    assert_int_equal(sim->pts.n, 1);
    return sim;
}

/** What one oscillator run shows. */
typedef struct Orbit {
    double theta;     /**< omega dt */
    double h_drift;   /**< max |H/H0 - 1| of scheme_modified_energy() */
    double departure; /**< max |E/E0 - 1| of kinetic + strain energy */
} Orbit;

static Orbit run_oscillator(const Row *row, double cfl, double periods)
{
    Sim *sim = load_oscillator(row->name, cfl, periods);
    const double omega = 2.0 * PI;       /* L = 1: the stretch u is eps_xx */
    Orbit o = {omega * sim->dt, 0.0, 0.0};
    Totals t0 = sim_totals(sim);
    double e0 = t0.kinetic + t0.strain;
    double h0 = scheme_modified_energy(row->a, o.theta, sim->pts.vx[0],
                                       omega * sim->pts.exx[0]);
    for (long k = 0; k < sim->nsteps; k++) {
        assert_int_equal(sim_advance(sim), 0);
        Totals t = sim_totals(sim);
        double h = scheme_modified_energy(row->a, o.theta, sim->pts.vx[0],
                                   omega * sim->pts.exx[0]);
        o.h_drift = fmax(o.h_drift, fabs(h / h0 - 1.0));
        o.departure = fmax(o.departure, fabs((t.kinetic + t.strain) / e0 - 1.0));
    }
    tk_free(sim);
    return o;
}

/* The step of each row conserves its modified energy, to round-off; the
 * form tends to the energy as the step goes to 0. */
static void modified_energy_is_conserved(void **state)
{
    (void)state;
    for (int r = 0; r < 5; r++) {
        Orbit o = run_oscillator(&ROWS[r], 0.2, 10.0);
        printf("  %-14s theta %.3f, 10 periods: max |H/H0 - 1| %.2e\n", ROWS[r].name,
               o.theta, o.h_drift);
        assert_true(o.h_drift <= 1e-10);
        /* the normalisation: H = v^2 + (omega u)^2 at theta = 0, and
         * |H - E| <= theta E */
        static const double y[3][2] = {{1.0, 0.0}, {0.0, 1.0}, {0.6, -0.8}};
        for (int i = 0; i < 3; i++) {
            double e = y[i][0] * y[i][0] + y[i][1] * y[i][1];
            assert_close(scheme_modified_energy(ROWS[r].a, 0.0, y[i][0], y[i][1]), e,
                         1e-15);
            assert_true(fabs(scheme_modified_energy(ROWS[r].a, 0.1, y[i][0], y[i][1]) - e)
                        <= 0.1 * e);
        }
    }
}

/* A long run samples its orbit densely: its largest departure of E from E0
 * is the one scheme_energy_departure() derives from the modified energy. */
static void departure_is_the_runs_largest(void **state)
{
    (void)state;
    for (int r = 0; r < 5; r++)
        for (double cfl = 0.4; cfl > 0.09; cfl /= 2) {
            Orbit o = run_oscillator(&ROWS[r], cfl, 50.0);
            double predicted = scheme_energy_departure(ROWS[r].a, o.theta);
            printf("  %-14s theta %.3f: max |E/E0 - 1| %.6e, predicted %.6e\n",
                   ROWS[r].name, o.theta, o.departure, predicted);
            assert_true(fabs(o.departure / predicted - 1.0) <= 1e-3);
        }
}

/* The bar of test_usavg.c at cfl @p cfl: max |E/E0 - 1| over 40 ms. */
static double bar_departure(const char *scheme, double cfl)
{
    char update[32], step[48];
    snprintf(update, sizeof update, "run.update=%s", scheme);
    snprintf(step, sizeof step, "run.cfl=%.17g", cfl);
    const char *const over[] = {update, step, NULL};
    Sim *sim = tk_load_file("tests/5-usavg/scenes/vibrating_bar.cfg", over);
    double worst = tk_energy_drift(sim, NULL);
    tk_free(sim);
    return worst;
}

/* The order of the energy error as the step halves: what the oscillator's
 * formula predicts, and what the bar, many modes at once, shows. */
static void orders_on_the_bar(void **state)
{
    (void)state;
    /* USL (a = -1 here) is not of the family: its Task 6 reads Task 4's
     * velocities, which the oscillator's map of share a does not have */
    static const Row bar_rows[4] = {
        {"musl", 0.0}, {"usf", 1.0}, {"usavg", 0.5}, {"usl", -1.0}};
    for (int r = 0; r < 4; r++) {
        double a = bar_rows[r].a;
        double predicted = a < 0 ? NAN
                           : log2(scheme_energy_departure(a, 0.01)
                                  / scheme_energy_departure(a, 0.005));
        double e[3];
        for (int i = 0; i < 3; i++)
            e[i] = bar_departure(bar_rows[r].name, 0.4 / (1 << i));
        double p1 = log2(e[0] / e[1]), p2 = log2(e[1] / e[2]);
        printf("  bar %-5s cfl 0.4, 0.2, 0.1: max |E/E0 - 1| %.4e %.4e %.4e, orders "
               "%.3f %.3f", bar_rows[r].name, e[0], e[1], e[2], p1, p2);
        printf(a < 0 ? "\n" : " (oscillator, theta to 0: %.3f)\n", predicted);
        if (a < 0) {              /* USL: a loss that the step does not set */
            assert_true(p1 < 0.5 && p2 < 0.5);
            continue;
        }
        assert_true(fabs(p1 - predicted) <= 0.15);
        assert_true(fabs(p2 - predicted) <= 0.15);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(modified_energy_is_conserved),
        cmocka_unit_test(departure_is_the_runs_largest),
        cmocka_unit_test(orders_on_the_bar),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
