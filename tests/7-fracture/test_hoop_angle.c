/**
 * @file test_hoop_angle.c
 * @brief The kink angle of chapter 7's growth, hoop_angle(), against the
 *        maximum hoop stress criterion (Erdogan and Sih 1963) solved here
 *        by other means.
 *
 * Near the tip, sigma_thetatheta sqrt(2 pi r) = cos(theta/2) [K_I
 * cos^2(theta/2) - 3/2 K_II sin(theta)], whose derivative vanishes where
 * K_I sin(theta) + K_II (3 cos(theta) - 1) = 0. The test scans theta for
 * the largest hoop stress, then bisects that equation about it.
 * Bounds, fixed before the first run: pure mode I gives 0 exactly; pure
 * mode II gives -acos(1/3) = -70.5288 degrees (K_II > 0) and +70.5288
 * (K_II < 0) within 1e-12 rad; mixed cases meet the bisected root within
 * 1e-10 rad, and the hoop stress there is the largest of the scan.
 */
#include "testkit.h"

#include <stdio.h>

#include "crack_growth.h"

#define PI 3.14159265358979323846

/** The hoop stress times sqrt(2 pi r) at angle @p t. */
static double hoop(double KI, double KII, double t)
{
    double c = cos(0.5 * t);
    return c * (KI * c * c - 1.5 * KII * sin(t));
}

/** Its derivative's zero condition, K_I sin t + K_II (3 cos t - 1). */
static double condition(double KI, double KII, double t)
{
    return KI * sin(t) + KII * (3.0 * cos(t) - 1.0);
}

/** The angle of largest hoop stress: a scan of (-pi, pi), then bisection
 *  of condition() on the bracket about the best scanned angle. */
static double hoop_root(double KI, double KII)
{
    const int n = 200000;
    double best = 0.0, top = -1e300;
    for (int k = 1; k < n; k++) {
        double t = -PI + 2.0 * PI * k / n;
        double h = hoop(KI, KII, t);
        if (h > top) {
            top = h;
            best = t;
        }
    }
    double a = best - 2.0 * PI / n, b = best + 2.0 * PI / n;
    double fa = condition(KI, KII, a);
    assert_true(fa * condition(KI, KII, b) <= 0.0);  /* bracketed */
    for (int k = 0; k < 200 && b - a > 1e-15; k++) {
        double m = 0.5 * (a + b), fm = condition(KI, KII, m);
        if ((fm < 0) == (fa < 0)) {
            a = m;
            fa = fm;
        } else {
            b = m;
        }
    }
    return 0.5 * (a + b);
}

static void pure_mode_one_goes_straight(void **state)
{
    (void)state;
    const double KI[] = {1.0, 1e-6, 37.5};
    for (int k = 0; k < 3; k++) {
        double t = hoop_angle(KI[k], 0.0);
        printf("  K_I %g, K_II 0: theta %g degrees\n", KI[k], t * 180 / PI);
        assert_true(t == 0.0);
    }
    /* a K_II at round-off level of K_I: no kink worth a digit */
    assert_true(fabs(hoop_angle(1.0, 1e-19)) < 1e-18);
}

static void pure_mode_two_kinks_70_5_degrees(void **state)
{
    (void)state;
    double want = acos(1.0 / 3.0);      /* 70.5288 degrees */
    double plus = hoop_angle(0.0, 1.0), minus = hoop_angle(0.0, -1.0);
    printf("  K_I 0, K_II +1: %.6f degrees; K_II -1: %+.6f (exact -+%.6f)\n",
           plus * 180 / PI, minus * 180 / PI, want * 180 / PI);
    assert_close(plus, -want, 1e-12);
    assert_close(minus, want, 1e-12);
    assert_close(hoop_angle(0.0, 3.0), -want, 1e-12);   /* scale-free */
}

static void mixed_mode_meets_the_root(void **state)
{
    (void)state;
    const double cases[][2] = {{1.0, 0.1}, {1.0, 0.5}, {1.0, 1.0},
                               {1.0, 2.0}, {1.0, -0.5}, {2.0, -7.0}};
    for (int k = 0; k < 6; k++) {
        double KI = cases[k][0], KII = cases[k][1];
        double t = hoop_angle(KI, KII), r = hoop_root(KI, KII);
        printf("  K_I %g, K_II %+g: theta %+.9f degrees, root %+.9f, "
               "condition %.1e\n", KI, KII, t * 180 / PI, r * 180 / PI,
               condition(KI, KII, t));
        assert_close(t, r, 1e-10);
        assert_true(t * KII < 0.0);     /* turns away from K_II's sign */
        assert_true(hoop(KI, KII, t) >= hoop(KI, KII, r) - 1e-12);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(pure_mode_one_goes_straight),
        cmocka_unit_test(pure_mode_two_kinks_70_5_degrees),
        cmocka_unit_test(mixed_mode_meets_the_root),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
