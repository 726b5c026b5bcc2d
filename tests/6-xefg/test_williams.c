/**
 * @file test_williams.c
 * @brief The auxiliary fields of the interaction integral
 *        (interaction_integral.h): the Williams near-tip fields of modes I
 *        and II are displacement fields whose gradients match differences,
 *        whose strains give the stresses by Hooke's law (plane strain and
 *        plane stress), whose stresses are in equilibrium and leave the
 *        crack faces free, and whose face jumps are those of unit K.
 */
#include <stdio.h>

#include "interaction_integral.h"
#include "testkit.h"

#define PI 3.14159265358979323846
#define MU 384.6153846153846      /* E = 1000, nu = 0.3 */
#define NU 0.3

/** kappa of plane strain (@p strain = 1) or plane stress. */
static double kappa_of(int strain)
{
    return strain ? 3.0 - 4.0 * NU : (3.0 - NU) / (1.0 + NU);
}

/** The field at (x1, x2) of the tip's frame. */
static void field_at(int mode, int strain, double x1, double x2, double s[3],
                     double u[2], double du[4])
{
    williams_field(mode, MU, kappa_of(strain), hypot(x1, x2), atan2(x2, x1), s,
                   u, du);
}

/** Gradients against central differences, Hooke's law and equilibrium, at
 *  points around the tip away from the faces (|theta| <= 0.9 pi). */
static void fields_are_consistent(void **state)
{
    (void)state;
    double worst_grad = 0.0, worst_hooke = 0.0, worst_div = 0.0;
    for (int mode = 1; mode <= 2; mode++)
        for (int strain = 0; strain <= 1; strain++) {
            /* plane Lame constant: 2 mu nu / (1 - 2 nu) or 2 mu nu / (1 - nu) */
            double lam = strain ? 2 * MU * NU / (1 - 2 * NU) : 2 * MU * NU / (1 - NU);
            for (int k = 0; k < 7; k++)
                for (int j = 0; j < 3; j++) {
                    double r = 0.3 * (j + 1), th = -0.9 * PI + 0.3 * PI * k;
                    double x1 = r * cos(th), x2 = r * sin(th), e = 1e-5 * r;
                    double s[3], u[2], du[4];
                    field_at(mode, strain, x1, x2, s, u, du);
                    /* d u_i / d x_j and d sigma_ij / d x_j by differences */
                    double sp[3], sm[3], up[2], um[2], ds[2][3];
                    for (int d = 0; d < 2; d++) {
                        field_at(mode, strain, x1 + (d == 0) * e, x2 + (d == 1) * e,
                                 sp, up, NULL);
                        field_at(mode, strain, x1 - (d == 0) * e, x2 - (d == 1) * e,
                                 sm, um, NULL);
                        for (int i = 0; i < 2; i++) {
                            double fd = (up[i] - um[i]) / (2 * e);
                            worst_grad = fmax(worst_grad, fabs(fd - du[2 * i + d]) /
                                                              (fabs(du[0]) + fabs(du[3]) + fabs(du[1]) + fabs(du[2])));
                        }
                        for (int c = 0; c < 3; c++)
                            ds[d][c] = (sp[c] - sm[c]) / (2 * e);
                    }
                    double exx = du[0], eyy = du[3], exy = 0.5 * (du[1] + du[2]);
                    double hooke[3] = {lam * (exx + eyy) + 2 * MU * exx,
                                       lam * (exx + eyy) + 2 * MU * eyy, 2 * MU * exy};
                    double size = fabs(s[0]) + fabs(s[1]) + fabs(s[2]);
                    for (int c = 0; c < 3; c++)
                        worst_hooke = fmax(worst_hooke, fabs(hooke[c] - s[c]) / size);
                    /* div sigma = 0: sigma_11,1 + sigma_12,2, sigma_12,1 + sigma_22,2 */
                    double div1 = ds[0][0] + ds[1][2], div2 = ds[0][2] + ds[1][1];
                    worst_div = fmax(worst_div, (fabs(div1) + fabs(div2)) * r / size);
                }
        }
    printf("  worst: gradient against differences %.2e, Hooke's law %.2e, "
           "r |div sigma| / |sigma| %.2e\n", worst_grad, worst_hooke, worst_div);
    assert_true(worst_grad <= 1e-7);
    assert_true(worst_hooke <= 1e-12);
    assert_true(worst_div <= 1e-7);
}

/** On the faces (theta = +-pi) the tractions sigma_22, sigma_12 vanish, and
 *  the jumps are those of unit K: mode I opens u_2 by (kappa + 1) / mu
 *  sqrt(r / (2 pi)) and does not slide; mode II slides u_1 by as much and
 *  does not open. */
static void faces_are_free_and_jumps_are_unit(void **state)
{
    (void)state;
    for (int mode = 1; mode <= 2; mode++)
        for (int strain = 0; strain <= 1; strain++) {
            double kap = kappa_of(strain), r = 0.7;
            double sp[3], sm[3], up[2], um[2];
            williams_field(mode, MU, kap, r, PI, sp, up, NULL);
            williams_field(mode, MU, kap, r, -PI, sm, um, NULL);
            double unit = (kap + 1) / MU * sqrt(r / (2 * PI)), p = 1 / sqrt(2 * PI * r);
            double open = up[1] - um[1], slide = up[0] - um[0];
            printf("  mode %d, plane %s: face tractions %.1e %.1e; opening %.6g, "
                   "sliding %.6g, unit jump %.6g\n", mode, strain ? "strain" : "stress",
                   fabs(sp[1]) + fabs(sm[1]), fabs(sp[2]) + fabs(sm[2]), open, slide, unit);
            assert_true(fabs(sp[1]) + fabs(sm[1]) + fabs(sp[2]) + fabs(sm[2]) <= 1e-15 * p);
            assert_close(mode == 1 ? open : slide, unit, 1e-14 * unit);
            assert_close(mode == 1 ? slide : open, 0.0, 1e-14 * unit);
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(fields_are_consistent),
        cmocka_unit_test(faces_are_free_and_jumps_are_unit),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
