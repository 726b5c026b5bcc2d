/**
 * @file test_cohesive_law.c
 * @brief The traction-separation law of a cohesive crack on its own
 *        (cohesive_law.c; xefg.md 2.3), both softening curves.
 *
 * Bounds, fixed before the first run:
 * - the peak t(delta_0) = f_t (0+ of the softening) to 1e-12 relative;
 *   t(delta_c) = 0 (linear) to 1e-15 f_t; exponential t(40 G_f / f_t) <=
 *   1e-12 f_t;
 * - the integral of t over delta, by 20000-panel Simpson, equals G_f to
 *   1e-8 relative, and the closed-form work at five openings to 1e-8;
 * - with K = 1e8 f_t / delta_c the law is the extrinsic one of xefg.md 2.3,
 *   f_t (1 - delta / delta_c) or f_t exp(-f_t delta / G_f), to 1e-6 f_t;
 * - secant unloading and reloading: half the opening gives half the
 *   traction, the history unchanged, to 1e-12; reloading past dmax
 *   returns to the envelope to 1e-12;
 * - compression: t_n = K delta_n and stored K delta_n^2 / 2, to 1e-12;
 * - the softening slope just past delta_0 (cohesive_softening_slope(),
 *   the crack band's modulus in growth) against a one-sided difference
 *   of the envelope over 1e-7 of delta_c - delta_0 (linear) or of
 *   G_f / f_t (exponential): to 1e-6 relative (the difference's own
 *   error: the linear branch is straight, the exponential's curvature
 *   over the step is 5e-8 of its slope);
 * - along a path of opening, unloading, closing, reopening and sliding
 *   (beta = 1) the work of the tractions, by the trapezoid rule on 4e5
 *   steps, equals stored + dissipated to 1e-6 of G_f.
 */
#include <math.h>
#include <stdio.h>

#include "cohesive_law.h"
#include "testkit.h"

static const CohesiveLaw linear = {COHESIVE_LINEAR, 2.0, 0.05, 1e4, 0.0};
static const CohesiveLaw expo = {COHESIVE_EXPONENTIAL, 2.0, 0.05, 1e4, 0.0};

/** Simpson's rule of the envelope on [a, b], n panels (even). */
static double simpson(const CohesiveLaw *L, double a, double b, int n)
{
    double h = (b - a) / n, s = cohesive_envelope(L, a) + cohesive_envelope(L, b);
    for (int k = 1; k < n; k++)
        s += (k % 2 ? 4.0 : 2.0) * cohesive_envelope(L, a + k * h);
    return s * h / 3.0;
}

static void peak_and_end(void **state)
{
    (void)state;
    for (int k = 0; k < 2; k++) {
        const CohesiveLaw *L = k ? &expo : &linear;
        double d0 = cohesive_delta0(L);
        double t0 = cohesive_envelope(L, d0);
        printf("  %s: delta_0 = %.6g, t(delta_0) = %.17g (f_t %g)\n",
               k ? "exponential" : "linear", d0, t0, L->f_t);
        assert_close(t0, L->f_t, 1e-12 * L->f_t);
        /* just past the peak, still f_t to first order */
        assert_close(cohesive_envelope(L, d0 * (1 + 1e-12)), L->f_t, 1e-9 * L->f_t);
    }
    double dc = cohesive_delta_c(&linear);
    assert_close(dc, 2.0 * linear.G_f / linear.f_t, 1e-15);
    assert_close(cohesive_envelope(&linear, dc), 0.0, 1e-15 * linear.f_t);
    assert_close(cohesive_envelope(&linear, 2 * dc), 0.0, 0.0);
    double far = cohesive_envelope(&expo, 40.0 * expo.G_f / expo.f_t);
    printf("  exponential t(40 G_f / f_t) = %.3g\n", far);
    assert_true(far <= 1e-12 * expo.f_t);
}

static void softening_slope(void **state)
{
    (void)state;
    for (int k = 0; k < 2; k++) {
        const CohesiveLaw *L = k ? &expo : &linear;
        double d0 = cohesive_delta0(L);
        double step = 1e-7 * (k ? L->G_f / L->f_t : cohesive_delta_c(L) - d0);
        double fd = (cohesive_envelope(L, d0 + step) - L->f_t) / step;
        double slope = cohesive_softening_slope(L);
        printf("  %s: slope %.10g, difference %.10g\n",
               k ? "exponential" : "linear", slope, fd);
        assert_true(slope < 0.0);
        assert_close(slope, fd, 1e-6 * fabs(slope));
    }
}

static void area_is_G_f(void **state)
{
    (void)state;
    for (int k = 0; k < 2; k++) {
        const CohesiveLaw *L = k ? &expo : &linear;
        double end = k ? 60.0 * L->G_f / L->f_t : cohesive_delta_c(L);
        /* from delta_0 on (the kink), the elastic triangle exactly */
        double d0 = cohesive_delta0(L);
        double a = 0.5 * L->f_t * d0 + simpson(L, d0, end, 20000);
        printf("  %s: integral of t = %.12g, G_f = %g (%.2e relative)\n",
               k ? "exponential" : "linear", a, L->G_f, a / L->G_f - 1);
        assert_close(a, L->G_f, 1e-8 * L->G_f);
        for (int j = 1; j <= 5; j++) {
            double d = d0 + (end - d0) * j / 6.0;
            assert_close(cohesive_envelope_work(L, d),
                         0.5 * L->f_t * d0 + simpson(L, d0, d, 20000),
                         1e-8 * L->G_f);
        }
    }
}

static void extrinsic_limit(void **state)
{
    (void)state;
    CohesiveLaw l = linear, e = expo;
    l.K = e.K = 1e8 * l.f_t / cohesive_delta_c(&linear);
    double dc = cohesive_delta_c(&l), worst = 0.0;
    for (int j = 1; j < 10; j++) {
        double d = dc * j / 10.0;
        double tl = cohesive_envelope(&l, d), te = cohesive_envelope(&e, d);
        worst = fmax(worst, fabs(tl - l.f_t * (1 - d / dc)));
        worst = fmax(worst, fabs(te - e.f_t * exp(-e.f_t * d / e.G_f)));
    }
    printf("  K = 1e8 f_t / delta_c: largest difference from the extrinsic laws "
           "%.3g (f_t %g)\n", worst, l.f_t);
    assert_true(worst <= 1e-6 * l.f_t);
}

static void secant_unloading_and_penalty(void **state)
{
    (void)state;
    for (int k = 0; k < 2; k++) {
        const CohesiveLaw *L = k ? &expo : &linear;
        double d1 = cohesive_delta0(L) + 0.3 * L->G_f / L->f_t, dmax = 0.0;
        CohesiveState s = cohesive_traction(L, d1, 0.0, &dmax, 1);
        double t1 = cohesive_envelope(L, d1);
        assert_close(s.tn, t1, 1e-12 * L->f_t);
        assert_close(dmax, d1, 0.0);
        s = cohesive_traction(L, 0.5 * d1, 0.0, &dmax, 1);   /* unload */
        assert_close(s.tn, 0.5 * t1, 1e-12 * L->f_t);
        assert_close(dmax, d1, 0.0);
        s = cohesive_traction(L, d1, 0.0, &dmax, 1);         /* reload */
        assert_close(s.tn, t1, 1e-12 * L->f_t);
        s = cohesive_traction(L, 1.2 * d1, 0.0, &dmax, 1);   /* past it */
        assert_close(s.tn, cohesive_envelope(L, 1.2 * d1), 1e-12 * L->f_t);
        assert_close(dmax, 1.2 * d1, 0.0);
        double x = 0.01 * cohesive_delta0(L);                 /* closing */
        s = cohesive_traction(L, -x, 0.0, &dmax, 1);
        assert_close(s.tn, -L->K * x, 1e-12 * L->K * x);
        assert_close(s.stored, 0.5 * L->K * x * x, 1e-12 * L->K * x * x);
        assert_close(dmax, 1.2 * d1, 0.0);
        printf("  %s: t(d1) = %.6g, unloaded to d1/2: %.6g, closed by %.3g: "
               "t_n = %.6g\n", k ? "exponential" : "linear", t1, 0.5 * t1, x,
               -L->K * x);
    }
}

/** The work of the tractions along a piecewise-linear path of openings
 *  (dn, ds), by the trapezoid rule, against stored + dissipated. */
static void work_is_stored_plus_dissipated(void **state)
{
    (void)state;
    for (int k = 0; k < 2; k++) {
        CohesiveLaw L = k ? expo : linear;
        L.beta = 1.0;
        double g = L.G_f / L.f_t;
        double path[][2] = {{0, 0},          {0.5 * g, 0},  {0.2 * g, 0.3 * g},
                            {-0.001 * g, 0}, {0.8 * g, -0.4 * g}, {3.0 * g, 0.1 * g},
                            {1.0 * g, 0}};
        int nseg = (int)(sizeof path / sizeof path[0]) - 1, n = 400000 / nseg;
        double dmax = 0.0, work = 0.0, pn = 0, ps = 0;
        CohesiveState s = cohesive_traction(&L, 0, 0, &dmax, 1);
        for (int j = 0; j < nseg; j++)
            for (int i = 1; i <= n; i++) {
                double f = (double)i / n;
                double dn = path[j][0] + f * (path[j + 1][0] - path[j][0]);
                double ds = path[j][1] + f * (path[j + 1][1] - path[j][1]);
                CohesiveState t = cohesive_traction(&L, dn, ds, &dmax, 1);
                work += 0.5 * (s.tn + t.tn) * (dn - pn) + 0.5 * (s.ts + t.ts) * (ds - ps);
                s = t, pn = dn, ps = ds;
            }
        double stored = s.stored, diss = cohesive_dissipated(&L, dmax);
        printf("  %s, beta = 1: work %.9g = stored %.9g + dissipated %.9g "
               "(difference %.2e G_f)\n", k ? "exponential" : "linear", work,
               stored, diss, (work - stored - diss) / L.G_f);
        assert_close(work, stored + diss, 1e-6 * L.G_f);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(peak_and_end),
        cmocka_unit_test(softening_slope),
        cmocka_unit_test(area_is_G_f),
        cmocka_unit_test(extrinsic_limit),
        cmocka_unit_test(secant_unloading_and_penalty),
        cmocka_unit_test(work_is_stored_plus_dissipated),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
