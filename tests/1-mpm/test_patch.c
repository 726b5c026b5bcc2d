/**
 * @file test_patch.c
 * @brief Rigid translation (no strain, no stress, x = x0 + v t) and the
 *        uniform-stress patch test (equilibrium: the stress stays), for USL,
 *        MUSL and USF.
 *
 * Rigid translation.  Every point carries the same v, so every node with
 * mass gets p/m = sum S m v / sum S m = v (eq. 26, 34) up to round-off, the
 * velocity gradient sum_i v_i G_ip = v sum_i G_ip vanishes (the gradients of
 * a partition of unity sum to zero), and no force arises.  Round-off: each
 * nodal v is v (1 + d), |d| a few ulp, and sum_i G_ip is a few ulp of 1/dx,
 * so one step's strain increment is a few 1e-16 of |v| dt / dx; we allow
 * 1e-13 |v| dt / min(dx, dy) per step, summed over the n steps taken.
 * Positions: x += dt sum S_ip v_i = dt v (1 + d) per step: we allow
 * n * 1e-14 * (|x| + |v| dt), a hundred ulp a step.
 *
 * Uniform stress.  A rectangle of whole cells with 2 x 2 points per cell
 * (the points sit at the Gauss-like positions h/4, 3h/4, where sums of the
 * bilinear gradients are exact) holds a uniform sigma.  The internal force
 * on node i is -sigma . sum_p V_p G_ip = -sigma . oint N_i n ds (eq. 28):
 * zero at interior nodes, and on the boundary only the component the
 * boundary conditions remove: uniaxial sigma_xx needs x = const edges fixed
 * in x; biaxial sigma_xx, sigma_yy adds y = const edges fixed in y; a
 * general state with shear needs every boundary node fixed in x and y.
 * Then every nodal force is round-off (~1e-16 sigma V / dx), the grid stays
 * at rest up to round-off, and sigma and eps stay as set.  A round-off force
 * f moves the body by about K^-1 f, i.e. stresses of order N^2 1e-16 sigma
 * for N cells across; we allow 1e-12 |sigma| over 400 steps.
 */
#include <stdio.h>
#include <stdlib.h>

#include "testkit.h"

static const char *const SCHEMES[] = {"usl", "musl", "usf"};

/* ---- rigid translation ------------------------------------------------ */

static void translate(const char *scheme)
{
    char text[2048];
    const double vx = 0.6, vy = -0.4;        /* |v| ~ 0.7 c: many cells crossed */
    snprintf(text, sizeof text,
        "grid = { origin = [-2.0, -9.5]; cells = [24, 20]; cell_size = [1.0, 0.8]; };\n"
        "run = { time = 100.0; cfl = 0.5; update = \"%s\"; snapshots = 0; };\n"
        "materials = ( { name = \"soft\"; E = 1.0e-3; nu = 0.3; rho = 1.0e-3; } );\n"
        "bodies = ( { name = \"block\"; material = \"soft\"; velocity = [%#.17g, %#.17g];\n"
        "  points_per_cell = 2; rectangle = { min = [0.3, 2.1]; max = [3.3, 4.5]; }; } );\n",
        scheme, vx, vy);
    Sim *sim = tk_load(text);
    Particles *P = &sim->pts;
    assert_true(P->n > 20);
    double *x0 = malloc(sizeof(double) * (size_t)P->n * 2);
    assert_non_null(x0);
    for (int p = 0; p < P->n; p++) {
        x0[2 * p] = P->x[p];
        x0[2 * p + 1] = P->y[p];
    }
    const double v = hypot(vx, vy), h = fmin(sim->grid.dx, sim->grid.dy);
    double worst_e = 0, worst_s = 0, worst_x = 0, worst_v = 0, unit = 0;
    const double c11 = sim->scene.mat[0].c11;
    int n = 100;                             /* 13 cells along x, 11 along y */
    for (int k = 1; k <= n; k++) {
        tk_steps(sim, 1);
        unit = v * sim->dt / h;              /* one step's v dt / dx */
        for (int p = 0; p < P->n; p++) {
            double e = fmax(fabs(P->exx[p]), fmax(fabs(P->eyy[p]), fabs(P->exy[p])));
            double s = fmax(fabs(P->sxx[p]), fmax(fabs(P->syy[p]), fabs(P->sxy[p])));
            double dx = fabs(P->x[p] - (x0[2 * p] + vx * sim->t));
            double dy = fabs(P->y[p] - (x0[2 * p + 1] + vy * sim->t));
            double xs = fmax(fabs(P->x[p]), fabs(P->y[p])) + v * sim->dt;
            worst_e = fmax(worst_e, e / (k * unit));
            worst_s = fmax(worst_s, s / (c11 * k * unit));
            worst_x = fmax(worst_x, fmax(dx, dy) / (k * xs));
            worst_v = fmax(worst_v, hypot(P->vx[p] - vx, P->vy[p] - vy) / v);
        }
    }
    print_message("%-4s %d points, %d steps: max |eps| = %.1e n v dt/dx, max |sigma| = "
                  "%.1e n C11 v dt/dx, max |x - x0 - v t| = %.1e n (|x| + v dt), "
                  "max |v_p - v|/|v| = %.1e\n", scheme, P->n, n, worst_e, worst_s,
                  worst_x, worst_v);
    assert_true(worst_e <= 1e-13);
    assert_true(worst_s <= 1e-13);
    assert_true(worst_x <= 1e-14);
    assert_true(worst_v <= 1e-13);           /* no force: v stays v */
    free(x0);
    tk_free(sim);
}

static void rigid_translation(void **state)
{
    (void)state;
    for (int k = 0; k < 3; k++)
        translate(SCHEMES[k]);
}

/* ---- uniform-stress patch ------------------------------------------------ */

typedef enum { UNIAXIAL, BIAXIAL, GENERAL } StressState;

static void patch(const char *scheme, StressState kind)
{
    /* cells 0.7 x 0.3 from (-0.13, 0.27) (no binary fractions, so round-off
     * is real); the body fills cells 2-5 along x and 1-4 along y:
     * [1.27, 4.07] x [0.57, 1.47]; the boxes catch the nodes on its edges */
    static const char *const bcs[3] = {
        "  { rectangle = { min = [1.22, 0.52]; max = [1.32, 1.52]; }; fix = \"x\"; },\n"
        "  { rectangle = { min = [4.02, 0.52]; max = [4.12, 1.52]; }; fix = \"x\"; } );\n",
        "  { rectangle = { min = [1.22, 0.52]; max = [1.32, 1.52]; }; fix = \"x\"; },\n"
        "  { rectangle = { min = [4.02, 0.52]; max = [4.12, 1.52]; }; fix = \"x\"; },\n"
        "  { rectangle = { min = [1.22, 0.52]; max = [4.12, 0.62]; }; fix = \"y\"; },\n"
        "  { rectangle = { min = [1.22, 1.42]; max = [4.12, 1.52]; }; fix = \"y\"; } );\n",
        "  { rectangle = { min = [1.22, 0.52]; max = [1.32, 1.52]; }; fix = \"xy\"; },\n"
        "  { rectangle = { min = [4.02, 0.52]; max = [4.12, 1.52]; }; fix = \"xy\"; },\n"
        "  { rectangle = { min = [1.22, 0.52]; max = [4.12, 0.62]; }; fix = \"xy\"; },\n"
        "  { rectangle = { min = [1.22, 1.42]; max = [4.12, 1.52]; }; fix = \"xy\"; } );\n"};
    static const double sig[3][3] = {{1.0, 0, 0}, {1.0, -0.5, 0}, {1.0, -0.5, 0.3}};
    char text[2048];
    snprintf(text, sizeof text,
        "grid = { origin = [-0.13, 0.27]; cells = [8, 6]; cell_size = [0.7, 0.3]; };\n"
        "run = { time = 100.0; cfl = 0.5; update = \"%s\"; snapshots = 0; };\n"
        "materials = ( { name = \"steel\"; E = 200.0; nu = 0.3; rho = 7.8e-3; } );\n"
        "bodies = ( { name = \"patch\"; material = \"steel\";\n"
        "  points_per_cell = 2; rectangle = { min = [1.27, 0.57]; max = [4.07, 1.47]; }; } );\n"
        "boundaries = (\n%s", scheme, bcs[kind]);
    Sim *sim = tk_load(text);
    Particles *P = &sim->pts;
    assert_int_equal(P->n, 4 * 4 * 3);
    const double E = 200.0, nu = 0.3;        /* plane stress compliance */
    const double *s = sig[kind];
    for (int p = 0; p < P->n; p++) {
        P->sxx[p] = s[0];
        P->syy[p] = s[1];
        P->sxy[p] = s[2];
        P->exx[p] = (s[0] - nu * s[1]) / E;
        P->eyy[p] = (s[1] - nu * s[0]) / E;
        P->exy[p] = (1 + nu) * s[2] / E;     /* tensor shear strain */
    }
    double smax = fmax(fabs(s[0]), fmax(fabs(s[1]), fabs(s[2])));
    double worst = 0, vmax = 0;
    const int n = 400;
    for (int k = 0; k < n; k++) {
        tk_steps(sim, 1);
        for (int p = 0; p < P->n; p++) {
            worst = fmax(worst, fabs(P->sxx[p] - s[0]));
            worst = fmax(worst, fabs(P->syy[p] - s[1]));
            worst = fmax(worst, fabs(P->sxy[p] - s[2]));
            vmax = fmax(vmax, hypot(P->vx[p], P->vy[p]));
        }
    }
    double c = sim->scene.mat[0].wave;
    print_message("%-4s %s: %d steps, max |sigma - sigma0| / |sigma0| = %.1e, "
                  "max |v| / c = %.1e\n", scheme,
                  kind == UNIAXIAL ? "uniaxial" : kind == BIAXIAL ? "biaxial " : "general ",
                  n, worst / smax, vmax / c);
    assert_true(worst <= 1e-12 * smax);
    /* the velocity a 1e-12 stress error would carry: sigma / (rho c) */
    assert_true(vmax <= 1e-12 * smax / (sim->scene.mat[0].rho * c));
    tk_free(sim);
}

static void uniaxial(void **state)
{
    (void)state;
    for (int k = 0; k < 3; k++)
        patch(SCHEMES[k], UNIAXIAL);
}

static void biaxial(void **state)
{
    (void)state;
    for (int k = 0; k < 3; k++)
        patch(SCHEMES[k], BIAXIAL);
}

static void general(void **state)
{
    (void)state;
    for (int k = 0; k < 3; k++)
        patch(SCHEMES[k], GENERAL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rigid_translation),
        cmocka_unit_test(uniaxial),
        cmocka_unit_test(biaxial),
        cmocka_unit_test(general),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
