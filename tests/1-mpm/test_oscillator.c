/**
 * @file test_oscillator.c
 * @brief One material point in one cell: the single-particle oscillator
 *        (after Bardenhagen 2002), period 1 for E = 4 pi^2, rho = L = 1.
 *
 * Set-up: one cell of size L = 1; its two left nodes fixed in x, all four
 * nodes fixed in y; nu = 0, so sigma_xx = E eps_xx; one point of mass
 * m = rho V at local x coordinate x_p (a fraction of the cell), eta = 1/2.
 *
 * Derivation (time-continuous limit).  The two free (right) nodes carry
 * mass m x_p in total and internal force -V sigma / L (eq. 28), so their
 * acceleration is a = -sigma / (rho L x_p).  The point's velocity changes
 * by the shape-weighted nodal acceleration (eq. 30), x_p a = -sigma/(rho L),
 * and every step the free nodes start again from the point's velocity
 * (eq. 26: p/m = m x_p v / (m x_p) = v), whose strain rate is v / L
 * (eq. 35).  Hence
 *     d2 eps / dt2 = -E eps / (rho L^2),   omega^2 = E / (rho L^2),
 * the lumped mass-spring m = rho A L, k = E A / L, whatever x_p and V: the
 * 1/x_p of the nodal acceleration is undone by the x_p of the shape
 * function that carries it back to the point.  Period 2 pi sqrt(rho/E) L
 * = 1 for E = 4 pi^2.  (A model that kept the nodal acceleration and
 * forgot the interpolation back would give omega^2 = E/(rho L^2 x_p); the
 * runs below show that MPM does not.)
 *
 * Discrete map, h = (omega dt)^2, state (v, eps L) over one step:
 * - MUSL: v' = v - dt k u, then the re-extrapolated nodal velocity is v',
 *   u' = u + dt v'; USF: u' = u + dt v, v' = v - dt k u'.  Both are the
 *   symplectic Euler map, trace 2 - h, determinant 1: the orbit neither
 *   grows nor decays and cos(theta) = 1 - h/2, T = 2 pi dt / theta.
 * - USL: the strain reads the updated nodal velocity v + dt a, so
 *   u' = u + dt v - (h / x_p) u; trace 2 - h/x_p, determinant
 *   1 - h (1/x_p - 1): amplitude times sqrt(det) per step (decay for
 *   x_p < 1), cos(theta) = trace / (2 sqrt(det)); unstable when
 *   x_p < 2h / (4 + h) (test_instability.c).
 * The tests assert |T - 1| < 0.5 % (the target) and, much tighter,
 * T against the discrete map, whose only other errors are round-off and
 * the point's tiny motion (amplitude 1e-7 of the cell).
 */
#include <stdio.h>

#include "testkit.h"

static const double PI = 3.14159265358979323846;

/** The one-cell scene with its single point at the cell centre. */
static Sim *load_cell(const char *scheme, double cfl)
{
    char text[2048];
    snprintf(text, sizeof text,
        "grid = { origin = [0.0, 0.0]; cells = [1, 1]; cell_size = [1.0, 1.0]; };\n"
        "run = { time = 10.0; cfl = %.17g; update = \"%s\"; snapshots = 0; };\n"
        "materials = ( { name = \"spring\"; E = %.17g; nu = 0.0; rho = 1.0; } );\n"
        "bodies = ( { name = \"point\"; material = \"spring\"; thickness = 1.0;\n"
        "  points_per_cell = 1; rectangle = { min = [0.0, 0.0]; max = [1.0, 1.0]; }; } );\n"
        "boundaries = (\n"
        "  { rectangle = { min = [-0.25, -0.25]; max = [0.25, 1.25]; }; fix = \"x\"; },\n"
        "  { rectangle = { min = [-0.25, -0.25]; max = [1.25, 1.25]; }; fix = \"y\"; } );\n",
        cfl, scheme, 4.0 * PI * PI);
    Sim *sim = tk_load(text);
    assert_int_equal(sim->pts.n, 1);
    return sim;
}

/** Measured period and amplitude ratio of eps_xx over @p nhalf half periods. */
typedef struct { double T, dt, ratio; } Period;

static Period measure(const char *scheme, double cfl, double xp, int nhalf)
{
    Sim *sim = load_cell(scheme, cfl);
    const double v0 = 1e-6;                  /* eps amplitude v0/omega ~ 1.6e-7 */
    sim->pts.x[0] = xp;
    sim->pts.vx[0] = v0;
    sim_set_time_step(sim);
    Period r = {0, sim->dt, 0};
    double prev = 0.0, t0 = -1, t1 = -1, peak_first = 0, peak_last = 0, peak = 0;
    int crossings = 0;
    while (crossings <= nhalf) {
        if (sim_step(sim))
            fail_msg("%s unstable at x_p = %g", scheme, xp);
        double e = sim->pts.exx[0];
        if (sim->step > 1 && ((prev < 0) != (e < 0))) {
            /* linear interpolation: a sine is straight at its zeros */
            double tc = sim->t - sim->dt * e / (e - prev);
            if (crossings == 0)
                t0 = tc;
            else if (crossings == 1)
                peak_first = peak;
            peak_last = peak;                /* the half period just ended */
            t1 = tc;
            crossings++;
            peak = 0;
        }
        peak = fmax(peak, fabs(e));
        prev = e;
        assert_true(sim->step < 100000);
    }
    r.T = 2.0 * (t1 - t0) / nhalf;
    r.ratio = peak_last / peak_first;        /* last half period / first */
    tk_free(sim);
    return r;
}

/** Period of the discrete map above for scheme @p scheme. */
static double discrete_period(const char *scheme, double dt, double xp)
{
    double h = 4.0 * PI * PI * dt * dt, c;
    if (scheme[0] == 'u' && scheme[2] == 'l')       /* usl */
        c = (2.0 - h / xp) / (2.0 * sqrt(1.0 - h * (1.0 / xp - 1.0)));
    else
        c = 1.0 - 0.5 * h;
    return 2.0 * PI * dt / acos(c);
}

static void check(const char *scheme, double xp)
{
    const double cfl = 0.1;                  /* omega dt ~ 0.1: ~63 steps a period */
    Period r = measure(scheme, cfl, xp, 16);
    double Td = discrete_period(scheme, r.dt, xp);
    print_message("%-4s x_p = %-8g dt = %.6f  T = %.9f  |T-1| = %.2e  "
                  "|T-Td|/Td = %.1e  amplitude ratio over 7.5 periods %.6f\n",
                  scheme, xp, r.dt, r.T, fabs(r.T - 1.0), fabs(r.T - Td) / Td, r.ratio);
    assert_close(r.T, 1.0, 5e-3);            /* the issue: period 1 within 0.5 % */
    /* the discrete map: only round-off and the 1e-7 motion of the point;
     * zero-crossing interpolation errs by O(dt^3) of a half period */
    assert_close(r.T, Td, 1e-6 * Td);
}

static void musl_period(void **state)
{
    (void)state;
    check("musl", 1.0 - 1e-3);
    check("musl", 0.5);
    check("musl", 0.2);
}

static void usf_period(void **state)
{
    (void)state;
    check("usf", 1.0 - 1e-3);
    check("usf", 0.5);
    check("usf", 0.2);
}

static void usl_period(void **state)
{
    (void)state;
    check("usl", 1.0 - 1e-3);
    check("usl", 0.5);
}

/** MUSL and USF conserve the orbit (det 1); USL shrinks it by det^(n/2). */
static void amplitude(void **state)
{
    (void)state;
    const double xp = 0.5;
    Period m = measure("musl", 0.1, xp, 16), f = measure("usf", 0.1, xp, 16);
    Period l = measure("usl", 0.1, xp, 16);
    assert_close(m.ratio, 1.0, 2e-3);        /* peaks sampled every dt: O(h) */
    assert_close(f.ratio, 1.0, 2e-3);
    double h = 4.0 * PI * PI * l.dt * l.dt;
    double per_step = sqrt(1.0 - h * (1.0 / xp - 1.0));
    double expect = pow(per_step, 7.5 * l.T / l.dt);  /* 15 half periods */
    print_message("usl x_p = 0.5: amplitude ratio %.6f, discrete map %.6f\n",
                  l.ratio, expect);
    assert_close(l.ratio, expect, 2e-3);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(musl_period),
        cmocka_unit_test(usf_period),
        cmocka_unit_test(usl_period),
        cmocka_unit_test(amplitude),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
