/**
 * @file scene_k_freund_xefg.c
 * @brief Freund's crack struck by a plane tensile step wave, by XEFG: the
 *        dynamic K_I of the interaction integral (interaction_integral.h,
 *        with its inertia term) against Freund's solution; the same
 *        benchmark as chapter 7's CRAMP test (tests/7-fracture/
 *        scene_k_freund.c), for the side-by-side table of issue 28.
 *
 * Freund (Dynamic Fracture Mechanics, 1990, section 2.5): a plane wave of
 * tensile stress sigma reaches a semi-infinite crack, normal to it, at t0;
 * in plane strain, until a wave from anything but the tip arrives,
 *
 *   K_I(t) = 2 sigma / (1 - nu) sqrt(c_d (t - t0) (1 - 2 nu) / pi).
 *
 * The scene is CRAMP's: a plate W x H = 20 x 20 mm, plane strain,
 * E = 1000 MPa, nu = 0.3, rho = 1e-3 g/mm^3 (c_d = 1160.2 mm/ms), a step
 * traction of 1 MPa on the top row of points at t = 0, the bottom free.
 * XEFG's nodes are the points, at cell centres h/2 inside the body's
 * edges; the outermost columns of nodes are held in x (rollers, so the
 * wave is plane and each column is a mirror), and the crack runs along
 * y = 0 (between two rows of nodes) from outside the left edge to
 * a = W/2, mid-way between two columns, its tip enriched with the LEFM
 * branch functions. The window: the mirror tips lie W - h away, the
 * reflections from the bottom and top come back after H / c_d, so it is
 * (W - h) / c_d; t0 = (H/2 - h/2) / c_d (the wave leaves the loaded row).
 *
 * Bounds, fixed before the first run (those of the CRAMP test): on
 * spacings of 0.125 mm, K_I within 5 % of Freund's at every evaluation
 * with t - t0 in [0.25, 0.95] of the window, |K_II| <= 2 % of Freund's
 * K_I there, on the interaction integral's weights of r_d = 1 and 1.5 mm
 * (q = 1 within r_d, 0 beyond 2 r_d); and on each, the worst K_I error
 * falling from spacings of 0.25 mm to 0.125 mm. K_FREUND_ALL prints every
 * evaluation.
 */
#include <stdio.h>
#include <stdlib.h>

#include "interaction_integral.h"
#include "testkit.h"
#include "xefg.h"

#define PI 3.14159265358979323846
#define WIDTH 20.0                /* W (mm) */
#define HEIGHT 20.0               /* H (mm) */
#define SIGMA 1.0                 /* the step's tension (MPa) */
#define E_MOD 1000.0              /* MPa */
#define NU 0.3
#define RHO 1e-3                  /* g/mm^3 */
#define EVERY 4                   /* steps between evaluations */
#define NRD 2
static const double rds[NRD] = {1.0, 1.5};   /* r_d (mm) */

/** Freund's K_I at time @p tau after the wave reaches the crack. */
static double freund(double tau, double cd)
{
    return 2.0 * SIGMA / (1.0 - NU) * sqrt(cd * tau * (1.0 - 2.0 * NU) / PI);
}

/** The worst of one spacing's run over the judged part of the window. */
typedef struct Worst {
    double ki[NRD];    /**< max |K_I / K_Freund - 1| per r_d */
    double kii[NRD];   /**< max |K_II| / K_Freund per r_d */
    int n;             /**< evaluations judged */
} Worst;

/** Run the plate on spacings of @p h; print K(t); the worst errors. */
static Worst struck_crack(double h)
{
    int nx = (int)(WIDTH / h + 0.5), ny = (int)(HEIGHT / h + 0.5);
    double c11 = E_MOD * (1.0 - NU) / ((1.0 + NU) * (1.0 - 2.0 * NU));
    double cd = sqrt(c11 / RHO);
    double t0 = (0.5 * HEIGHT - 0.5 * h) / cd, window = (WIDTH - h) / cd;
    char text[4096];
    snprintf(text, sizeof text,
             "grid = { origin = [%#.17g, %#.17g]; cells = [%d, %d]; cell_size = [%#.17g, %#.17g]; };\n"
             "run = { time = %#.17g; method = \"xefg\"; snapshots = 0; plane = \"strain\"; };\n"
             "materials = ( { name = \"m\"; E = %#.17g; nu = %#.17g; rho = %#.17g; } );\n"
             "bodies = ( { name = \"plate\"; material = \"m\"; points_per_cell = 1;\n"
             "             rectangle = { min = [0.0, %#.17g]; max = [%#.17g, %#.17g]; }; } );\n"
             "boundaries = ( { rectangle = { min = [0.0, %#.17g]; max = [%#.17g, %#.17g]; }; fix = \"x\"; },\n"
             "               { rectangle = { min = [%#.17g, %#.17g]; max = [%#.17g, %#.17g]; }; fix = \"x\"; } );\n"
             "loads = ( { rectangle = { min = [0.0, %#.17g]; max = [%#.17g, %#.17g]; };\n"
             "            force = [0.0, %#.17g]; } );\n"
             "xefg = { tip = \"lefm\"; };\n"
             "cracks = ( { points = ( [%#.17g, 0.0], [%#.17g, 0.0] ); } );\n",
             -h, -0.5 * HEIGHT - h, nx + 2, ny + 2, h, h, t0 + window,
             E_MOD, NU, RHO,
             -0.5 * HEIGHT, WIDTH, 0.5 * HEIGHT,
             -0.5 * HEIGHT, h, 0.5 * HEIGHT,
             WIDTH - h, -0.5 * HEIGHT, WIDTH, 0.5 * HEIGHT,
             0.5 * HEIGHT - h, WIDTH, 0.5 * HEIGHT, SIGMA * WIDTH,
             -0.5 * h, 0.5 * WIDTH);
    Sim *s = tk_load(text);
    Xefg *x = xefg_of(s);
    assert_non_null(x);
    Worst w = {{0, 0}, {0, 0}, 0};
    printf("  spacing %g mm: %d nodes, %d parameters (%d branch), dt %.4g us, "
           "t0 = %.3f us, window %.2f us:\n", h, x->nnode, x->ndof, x->nbranch,
           1e3 * s->dt, 1e3 * t0, 1e3 * window);
    printf("    t-t0 (us)  K_Freund  K_I (r_d 1, 1.5 mm) / K_Freund - 1   "
           "K_II / K_Freund (1, 1.5 mm)\n");
    while (s->step < s->nsteps) {
        assert_int_equal(sim_advance(s), 0);
        double tau = s->t - t0;
        if (s->step % EVERY != 0 || tau <= 0.0)
            continue;
        double K[NRD][2], kf = freund(tau, cd), u = tau / window;
        for (int k = 0; k < NRD; k++)
            assert_int_equal(xefg_stress_intensity(s, 0, 1, rds[k], K[k]), 0);
        if (s->step % (8 * EVERY) == 0 || getenv("K_FREUND_ALL"))
            printf("    %8.3f  %8.4f  %+7.2f %% %+7.2f %%            %+9.2e %+9.2e\n",
                   1e3 * tau, kf, 100 * (K[0][0] / kf - 1), 100 * (K[1][0] / kf - 1),
                   K[0][1] / kf, K[1][1] / kf);
        if (u < 0.25 || u > 0.95)
            continue;
        w.n++;
        for (int k = 0; k < NRD; k++) {
            w.ki[k] = fmax(w.ki[k], fabs(K[k][0] / kf - 1.0));
            w.kii[k] = fmax(w.kii[k], fabs(K[k][1]) / kf);
        }
    }
    tk_free(s);
    return w;
}

static void k_of_a_crack_struck_by_a_step_wave(void **state)
{
    (void)state;
    TkBounds b = {0, 0};
    Worst wc = struck_crack(0.25), w = struck_crack(0.125);
    tk_bound(&b, 4, w.n >= 10, "%d evaluations in the judged window (want >= 10)", w.n);
    printf("  worst over [0.25, 0.95] of the window, spacings 0.25 -> 0.125 mm:\n");
    for (int k = 0; k < NRD; k++) {
        printf("    r_d %-4g mm  |K_I / K_Freund - 1| %.2f %% -> %.2f %%,  "
               "|K_II| / K_Freund %.2f %% -> %.2f %%\n", rds[k], 100 * wc.ki[k],
               100 * w.ki[k], 100 * wc.kii[k], 100 * w.kii[k]);
        tk_bound(&b, 4, w.ki[k] <= 0.05, "r_d %g mm: K_I up to %.2f %% from "
                 "Freund's (bound 5 %%)", rds[k], 100 * w.ki[k]);
        tk_bound(&b, 4, w.kii[k] <= 0.02, "r_d %g mm: |K_II| up to %.2f %% of "
                 "Freund's K_I (bound 2 %%)", rds[k], 100 * w.kii[k]);
        tk_bound(&b, 4, w.ki[k] < wc.ki[k], "r_d %g mm: K_I's worst error did not "
                 "fall from 0.25 mm (%.2f %%) to 0.125 mm (%.2f %%)", rds[k],
                 100 * wc.ki[k], 100 * w.ki[k]);
    }
    tk_bounds_finish(&b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(k_of_a_crack_struck_by_a_step_wave),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
