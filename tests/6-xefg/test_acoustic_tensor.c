/**
 * @file test_acoustic_tensor.c
 * @brief The material-stability criterion of crack growth (xefg.md 2.4,
 *        Test 5a): the acoustic tensor Q(n) = n.C.n of a 2D tangent, its
 *        determinant, the critical normal, on elastic and Rankine
 *        softening tangents, plane strain and plane stress.
 *
 * Bounds, fixed before the first run:
 * - a general (not symmetric) Voigt C, 20 of them with entries in [-1, 1],
 *   100 random normals and jumps g each: Q(n) g equals the traction
 *   sigma(sym(g (x) n)) . n computed from C directly, to 1e-13 of the
 *   largest entry of C (this pins the index order of Q_jk = n_i C_ijkl n_l);
 * - isotropic elasticity (four (E, nu), nu = 0 ... 0.49), 3600 normals
 *   over [0, 2 pi): Q positive definite; its eigenvalues lambda + 2 mu
 *   (P wave, eigenvector n) and mu (S wave) to 1e-12 relative, Q n =
 *   (lambda + 2 mu) n to 1e-12 of lambda + 2 mu; det Q = mu (lambda + 2 mu)
 *   for every normal to 1e-12 relative; acoustic_critical() says stable
 *   and finds that value to 1e-12 relative;
 * - the Rankine tangent at six stress states (uniaxial along x, along y,
 *   along 30 deg; biaxial sigma_1 > sigma_2 > 0; tension-compression with
 *   shear; pure shear) and H / h0 = +0.1, -0.01, -0.1, -0.5, -0.9: its
 *   m:C:m = lambda + 2 mu to 1e-12 relative; the critical angle within
 *   0.5 deg of the first principal direction; the verdict unstable exactly
 *   when H < 0; det Q at the critical angle equal to the derived
 *   mu (lambda + 2 mu) H / (h0 + H) to 1e-10 relative; det Q over 360
 *   normals equal to the derived mu (lambda + 2 mu) (1 - g(t) / (h0 + H))
 *   to 1e-10 mu (lambda + 2 mu) (1 + h0 / |h0 + H|);
 * - the critical softening modulus, uniaxial tension along x (and the
 *   other five states): the derived value is H_crit = 0 (acoustic_tensor.h),
 *   so "1e-6 relative" is |H_crit| <= 1e-6 h0, found by bisection of the
 *   sign of min det Q on [-h0/2, h0/2]; min det Q > 0 at H = +1e-4 h0 and
 *   < 0 at H = -1e-4 h0; past the snap-back limit, H = -2 h0, > 0 again.
 * - growth asks it (growth_stability_lost(), the steel of Kalthoff's
 *   plate): the six states scaled to sigma_1 = 0.5, 0.999, 1, 1.001 and 2
 *   f_t, H = -0.1 h0 and -0.5 h0: lost exactly when sigma_1 >= f_t, with
 *   det Q < 0 and the critical normal within 0.5 deg of n1; kept (det
 *   Q > 0) otherwise.
 * Each bound is checked in plane strain and in plane stress.
 */
#include <stdint.h>
#include <stdio.h>

#include "acoustic_tensor.h"
#include "growth.h"
#include "testkit.h"

static const double PI = 3.14159265358979323846;
static const double DEG = 3.14159265358979323846 / 180.0;

/** A uniform number in [-1, 1) from the generator state @p s. */
static double uniform(uint64_t *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / 4503599627370496.0 - 1.0;  /* / 2^52 */
}

/** The distance of two normals' angles, modulo pi (n and -n are one). */
static double angle_gap(double a, double b)
{
    double d = fmod(fabs(a - b), PI);
    return fmin(d, PI - d);
}

/** P- and S-wave moduli, lambda + 2 mu and mu, of one idealisation. */
static void moduli(double E, double nu, PlaneKind plane, double *P, double *S)
{
    *S = E / (2.0 * (1.0 + nu));
    if (plane == PLANE_STRAIN)
        *P = E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
    else
        *P = E / (1.0 - nu * nu);
}

static const char *plane_name(PlaneKind p)
{
    return p == PLANE_STRAIN ? "plane strain" : "plane stress";
}

static void traction_rule(void **state)
{
    (void)state;
    uint64_t seed = 27;
    double worst = 0.0;
    for (int c = 0; c < 20; c++) {
        double C[3][3], cmax = 0.0;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                C[a][b] = uniform(&seed);
                cmax = fmax(cmax, fabs(C[a][b]));
            }
        for (int k = 0; k < 100; k++) {
            double phi = PI * (uniform(&seed) + 1.0);
            double n[2] = {cos(phi), sin(phi)};
            double g[2] = {uniform(&seed), uniform(&seed)};
            double Q[2][2];
            acoustic_tensor(C, phi, Q);
            /* the strain sym(g (x) n) with engineering shear, its stress,
             * and the traction on the plane of normal n */
            double e[3] = {g[0] * n[0], g[1] * n[1], g[0] * n[1] + g[1] * n[0]};
            double s[3];
            for (int a = 0; a < 3; a++)
                s[a] = C[a][0] * e[0] + C[a][1] * e[1] + C[a][2] * e[2];
            double t[2] = {s[0] * n[0] + s[2] * n[1], s[2] * n[0] + s[1] * n[1]};
            for (int j = 0; j < 2; j++) {
                double qg = Q[j][0] * g[0] + Q[j][1] * g[1];
                double err = fabs(qg - t[j]) / cmax;
                worst = fmax(worst, err);
                assert_true(err <= 1e-13);
            }
            assert_close(acoustic_det(C, phi),
                         Q[0][0] * Q[1][1] - Q[0][1] * Q[1][0], 1e-14 * cmax * cmax);
        }
    }
    printf("  20 general C x 100 normals: |Q g - sigma(sym(g n)) n| <= %.2e "
           "max|C|\n", worst);
}

static void isotropic_elastic(void **state)
{
    (void)state;
    static const double cases[4][2] = {{1000.0, 0.0}, {30000.0, 0.2},
                                       {1000.0, 0.3}, {200e3, 0.49}};
    printf("  relative errors over 3600 normals, P = lambda + 2 mu, S = mu:\n"
           "  plane             E    nu    eig P    eig S   Qn - Pn    det Q"
           "   search\n");
    for (int p = 0; p < 2; p++) {
        PlaneKind plane = p ? PLANE_STRESS : PLANE_STRAIN;
        for (int c = 0; c < 4; c++) {
            double E = cases[c][0], nu = cases[c][1], P, S, C[3][3];
            moduli(E, nu, plane, &P, &S);
            acoustic_elastic_tangent(E, nu, plane, C);
            double ep = 0.0, es = 0.0, ed = 0.0, en = 0.0, dmin = INFINITY;
            for (int k = 0; k < 3600; k++) {
                double phi = 2.0 * PI * k / 3600.0, Q[2][2];
                double n[2] = {cos(phi), sin(phi)};
                acoustic_tensor(C, phi, Q);
                double tr = Q[0][0] + Q[1][1];
                double det = acoustic_det(C, phi);
                double dq = Q[0][0] - Q[1][1];
                double big = 0.5 * (tr + sqrt(dq * dq + 4.0 * Q[0][1] * Q[1][0]));
                double small = det / big;  /* no cancellation */
                assert_true(Q[0][0] > 0.0 && det > 0.0);  /* positive definite */
                assert_close(Q[0][1], Q[1][0], 1e-14 * P);
                ep = fmax(ep, fabs(big / P - 1.0));
                es = fmax(es, fabs(small / S - 1.0));
                ed = fmax(ed, fabs(det / (P * S) - 1.0));
                for (int j = 0; j < 2; j++)
                    en = fmax(en, fabs(Q[j][0] * n[0] + Q[j][1] * n[1] - P * n[j]) /
                                      P);
                dmin = fmin(dmin, det);
            }
            AcousticCritical r = acoustic_critical(C, ACOUSTIC_SAMPLES);
            double ec = fabs(r.det_min / (P * S) - 1.0);
            printf("  %-12s %6g  %4.2f %8.1e %8.1e %8.1e %8.1e %8.1e%s\n",
                   plane_name(plane), E, nu, ep, es, en, ed, ec,
                   r.unstable ? " UNSTABLE" : "");
            assert_true(ep <= 1e-12 && es <= 1e-12 && en <= 1e-12 && ed <= 1e-12);
            assert_true(dmin > 0.0);
            assert_false(r.unstable);
            assert_true(ec <= 1e-12);
        }
    }
}

/** The stress states: sigma_1, sigma_2 and the angle of n1 (degrees). */
static const struct {
    const char *name;
    double s1, s2, deg;
} STATES[6] = {
    {"uniaxial x", 2.0, 0.0, 0.0},
    {"uniaxial y", 2.0, 0.0, 90.0},
    {"uniaxial 30 deg", 2.0, 0.0, 30.0},
    {"biaxial 2, 1", 2.0, 1.0, 0.0},
    {"tension-compression, shear", 1.0, -3.0, 112.5},
    {"pure shear", 1.5, -1.5, 45.0},
};

/** The Voigt stress (sxx, syy, sxy) of principal values s1, s2, n1 at deg. */
static void stress_of(int k, double s[3])
{
    double c = cos(STATES[k].deg * DEG), sn = sin(STATES[k].deg * DEG);
    double s1 = STATES[k].s1, s2 = STATES[k].s2;
    s[0] = s1 * c * c + s2 * sn * sn;
    s[1] = s1 * sn * sn + s2 * c * c;
    s[2] = (s1 - s2) * c * sn;
}

static void rankine_direction(void **state)
{
    (void)state;
    static const double ratios[5] = {0.1, -0.01, -0.1, -0.5, -0.9};
    const double E = 30000.0, nu = 0.2;  /* concrete, MPa */
    for (int p = 0; p < 2; p++) {
        PlaneKind plane = p ? PLANE_STRESS : PLANE_STRAIN;
        double P, S, C[3][3];
        moduli(E, nu, plane, &P, &S);
        double lambda = P - 2.0 * S;
        acoustic_elastic_tangent(E, nu, plane, C);
        printf("  %s, E %g, nu %.1f: h0 = %.6g, mu h0 = %.6g\n",
               plane_name(plane), E, nu, P, P * S);
        printf("  state                       n1 deg  |phi_c - n1| deg  "
               "det_min    curve\n");
        for (int k = 0; k < 6; k++) {
            double s[3], th = STATES[k].deg * DEG;
            stress_of(k, s);
            assert_true(angle_gap(acoustic_principal_angle(s), th) <= 1e-12);
            double worst_angle = 0.0, worst_det = 0.0, worst_curve = 0.0;
            for (int h = 0; h < 5; h++) {
                double H = ratios[h] * P, Ct[3][3];
                double h0 = acoustic_rankine_tangent(C, s, H, Ct);
                assert_close(h0, P, 1e-12 * P);
                AcousticCritical r = acoustic_critical(Ct, ACOUSTIC_SAMPLES);
                double want = P * S * H / (h0 + H);
                double gap = angle_gap(r.phi, th);
                worst_angle = fmax(worst_angle, gap);
                worst_det = fmax(worst_det, fabs(r.det_min / want - 1.0));
                assert_true(gap <= 0.5 * DEG);
                assert_int_equal(r.unstable, H < 0.0);
                assert_true(fabs(r.det_min / want - 1.0) <= 1e-10);
                /* the whole curve against the derivation */
                for (int j = 0; j < 360; j++) {
                    double phi = PI * j / 360.0, t = cos(phi - th);
                    t *= t;
                    double g = (lambda + 2.0 * S * t) * (lambda + 2.0 * S * t) / P +
                               4.0 * S * t * (1.0 - t);
                    double d = P * S * (1.0 - g / (h0 + H));
                    double err = fabs(acoustic_det(Ct, phi) - d) /
                                 (P * S * (1.0 + h0 / fabs(h0 + H)));
                    worst_curve = fmax(worst_curve, err);
                    assert_true(err <= 1e-10);
                }
            }
            printf("  %-27s %5.1f  %16.2e  %8.1e  %8.1e\n", STATES[k].name,
                   STATES[k].deg, worst_angle / DEG, worst_det, worst_curve);
        }
        /* what the search says at one state (n1 at 30 deg), as H falls */
        for (int h = 0; h < 5; h++) {
            double s[3], Ct[3][3];
            stress_of(2, s);
            acoustic_rankine_tangent(C, s, ratios[h] * P, Ct);
            AcousticCritical r = acoustic_critical(Ct, ACOUSTIC_SAMPLES);
            printf("    uniaxial 30 deg, H/h0 %+.2f: phi_c %.4f deg, "
                   "min det Q %+.4g%s\n", ratios[h], r.phi / DEG, r.det_min,
                   r.unstable ? " (lost)" : "");
        }
    }
}

/** Growth asks the acoustic tensor (growth_stability_lost()): at each
 *  state scaled so that sigma_1 is 0.5, 0.999, 1, 1.001 and 2 times f_t,
 *  in plane strain and plane stress, with H = -0.1 h0 and -0.5 h0 (the
 *  crack band's modulus), stability is lost exactly when sigma_1 >= f_t
 *  (the Rankine tangent's H_crit = 0), det Q < 0 there, and the critical
 *  normal is n1 within 0.5 degrees (issue 27's bound). */
static void growth_asks_the_acoustic_tensor(void **state)
{
    (void)state;
    static const double scale[5] = {0.5, 0.999, 1.0, 1.001, 2.0};
    const double E = 190000.0, nu = 0.3, f_t = 1000.0;   /* the steel */
    double worst = 0.0;
    int lost = 0, kept = 0;
    for (int p = 0; p < 2; p++) {
        PlaneKind plane = p ? PLANE_STRESS : PLANE_STRAIN;
        double C[3][3];
        acoustic_elastic_tangent(E, nu, plane, C);
        for (int k = 0; k < 6; k++)
            for (int j = 0; j < 5; j++)
                for (int h = 1; h <= 5; h += 4) {
                    double s[3];
                    stress_of(k, s);
                    double f = scale[j] * f_t / STATES[k].s1;
                    for (int i = 0; i < 3; i++)
                        s[i] *= f;
                    double sigma1 = 0.5 * (s[0] + s[1]) +
                                    hypot(0.5 * (s[0] - s[1]), s[2]);
                    AcousticCritical a;
                    int u = growth_stability_lost(s, f_t, C, -0.1 * h * C[0][0],
                                                  &a);
                    assert_int_equal(u, sigma1 >= f_t);
                    if (u) {
                        double gap = angle_gap(a.phi, STATES[k].deg * DEG);
                        worst = fmax(worst, gap);
                        assert_true(a.det_min < 0.0);
                        assert_true(gap <= 0.5 * DEG);
                        lost++;
                    } else {
                        assert_true(a.det_min > 0.0);
                        kept++;
                    }
                }
    }
    printf("  %d states lost stability (sigma_1 >= f_t), %d kept it; the "
           "critical normal within %.2e degrees of n1\n", lost, kept,
           worst / DEG);
}

/** min det Q of the Rankine tangent at stress state @p k and modulus H. */
static double min_det(const double C[3][3], int k, double H)
{
    double s[3], Ct[3][3];
    stress_of(k, s);
    acoustic_rankine_tangent(C, s, H, Ct);
    return acoustic_critical(Ct, ACOUSTIC_SAMPLES).det_min;
}

static void critical_modulus(void **state)
{
    (void)state;
    const double E = 30000.0, nu = 0.2;
    for (int p = 0; p < 2; p++) {
        PlaneKind plane = p ? PLANE_STRESS : PLANE_STRAIN;
        double P, S, C[3][3];
        moduli(E, nu, plane, &P, &S);
        acoustic_elastic_tangent(E, nu, plane, C);
        printf("  %s: H_crit by bisection (derived: 0) and min det Q at H =\n"
               "  state                        H_crit/h0  +1e-4 h0    -1e-4 h0"
               "    -2 h0\n", plane_name(plane));
        for (int k = 0; k < 6; k++) {
            /* bisection of the sign change of min det Q over H */
            double lo = -0.5 * P, hi = 0.5 * P;
            assert_true(min_det(C, k, lo) < 0.0 && min_det(C, k, hi) > 0.0);
            for (int it = 0; it < 80; it++) {
                double mid = 0.5 * (lo + hi);
                if (min_det(C, k, mid) > 0.0)
                    hi = mid;
                else
                    lo = mid;
            }
            double Hc = 0.5 * (lo + hi);
            double up = min_det(C, k, 1e-4 * P), down = min_det(C, k, -1e-4 * P);
            double snap = min_det(C, k, -2.0 * P);
            printf("  %-27s %+10.2e  %+10.4g  %+10.4g  %+10.4g\n",
                   STATES[k].name, Hc / P, up, down, snap);
            assert_true(fabs(Hc) <= 1e-6 * P);
            assert_true(up > 0.0);
            assert_true(down < 0.0);
            assert_true(snap > 0.0);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(traction_rule),
        cmocka_unit_test(isotropic_elastic),
        cmocka_unit_test(rankine_direction),
        cmocka_unit_test(critical_modulus),
        cmocka_unit_test(growth_asks_the_acoustic_tensor),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
