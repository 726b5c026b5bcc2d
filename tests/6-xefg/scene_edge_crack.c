/**
 * @file scene_edge_crack.c
 * @brief xefg.md Test 3: the LEFM stationary edge crack. A plate W x H =
 *        10 x 20 mm with an edge crack of a = 4.5 mm (a/W = 0.45) at
 *        mid-height, plane strain, E = 1000 MPa, nu = 0.3, pulled by a
 *        uniform tension sigma = 1 MPa on its top and bottom rows of points,
 *        the tip enriched with the LEFM branch functions (eq. 5), damped to
 *        the static state. K_I and K_II by the interaction integral
 *        (interaction_integral.h) against the handbook
 *        K_I = F(a/W) sigma sqrt(pi a) (Tada / Brown-Srawley, xefg.md 3.2).
 *
 * Pass (xefg.md Test 3): K_I / (sigma sqrt(pi a)) within 3 % of F(0.45)
 * at the finest of three spacings (and here at each), converging
 * monotonically: the three values move the same way by shrinking steps
 * (their limit lies 0.3 % above F, inside the handbook's own 0.5 %, so the
 * error against F itself need not fall), |K_II / K_I| <= 1 %, each static
 * state reached with kinetic / strain energy <= 1e-6 and 15 / omega_1
 * settled (the spec's 1e-4 alone comes too early, see STOP).
 *
 * Environment: XEFG_K_SPACINGS, the three divisions W / h (default
 * "10 20 40"; make fig-xefg-k runs "20 40 80"); XEFG_K_TABLE, a file for
 * the table (one row per spacing); XEFG_K_RATIO, another a/W (0.2 to 0.6;
 * make fig-k-edge runs 0.3 and 0.6 beside 0.45, where the pass above is
 * xefg.md's only at 0.45: at 0.3 the ring's outer radius, 3 mm, reaches
 * the mouth's edge).
 */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "interaction_integral.h"
#include "testkit.h"
#include "xefg.h"

#define PI 3.14159265358979323846
#define WIDTH 10.0                /* W (mm) */
#define HEIGHT 20.0               /* H (mm) */
#define CRACK 4.5                 /* a (mm); XEFG_K_RATIO sets another */
#define SIGMA 1.0                 /* applied tension (MPa) */
#define RHO 1e-3                  /* g/mm^3: c = sqrt(E / rho) = 1000 mm/ms */
/* kappa = 2 omega_1, critical for the lowest mode: omega_1 = 51 /ms, the
 * strongest frequency of K_I(t) in an undamped run at W/10 (the next is
 * 139 /ms) */
#define DAMPING 100.0
/* the damped run ends at kinetic / strain energy <= STOP, not before
 * SETTLE. xefg.md asks KE/SE <= 1e-4, but there K_I is still 1.5 to 4 %
 * low: a critically damped mode started from rest lags the static
 * displacement by (1 + w t) e^(-w t) while KE/SE = (w t)^2 e^(-2 w t) /
 * (1 - (1 + w t) e^(-w t))^2, which falls to 1e-4 at w t = 6.5 (lag 1.1 %)
 * and to 1e-6 at 9.1 (lag 0.1 %); on the fine spacings the lowest mode is
 * all that is left then. At w t = 15 it lags by 5e-6. */
#define STOP 1e-6
#define SETTLE (15.0 / (0.5 * DAMPING))
/* q = 1 within r_d of the tip, 0 beyond 2 r_d: a fixed ring, 1.5 to 3 mm
 * (1.5 to 3 spacings at W/10), clear of the edges (4.5 mm) */
#define RD 1.5

/** The handbook's F(a/W) (Tada / Brown-Srawley; xefg.md 3.2). */
static double handbook_F(double r)
{
    return 1.12 - 0.231 * r + 10.55 * r * r - 21.72 * r * r * r +
           30.39 * r * r * r * r;
}

/** One spacing's result. */
typedef struct Result {
    int n;          /**< W / h */
    double h;       /**< spacing (mm) */
    int nodes;      /**< nodes (points) */
    int dofs;       /**< parameters */
    int branch;     /**< branch parameters */
    long steps;     /**< steps to the static state */
    double ratio;   /**< kinetic / strain energy at the stop */
    double F;       /**< K_I / (sigma sqrt(pi a)) */
    double KII;     /**< K_II / K_I */
    double seconds; /**< wall time: build and run */
} Result;

/** Wall clock (s). */
static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/** The plate with crack @p a at spacing W / @p n, damped to its static
 *  state. */
static Result edge_crack(int n, double a)
{
    double h = WIDTH / n, t0 = now();
    char text[4096];
    /* points sit at cell centres: the body's edge is h/2 beyond the
     * outermost points; the loads take the top and bottom rows; the crack's
     * mouth lies outside the body, h/2 left of it */
    snprintf(text, sizeof text,
             "grid = { origin = [%#.17g, %#.17g]; cells = [%d, %d]; cell_size = [%#.17g, %#.17g]; };\n"
             "run = { time = 1000.0; method = \"xefg\"; snapshots = 0; plane = \"strain\";\n"
             "        damping = %#.17g; };\n"
             "materials = ( { name = \"m\"; E = 1000.0; nu = 0.3; rho = %#.17g; } );\n"
             "bodies = ( { name = \"plate\"; material = \"m\"; points_per_cell = 1;\n"
             "             rectangle = { min = [0.0, %#.17g]; max = [%#.17g, %#.17g]; }; } );\n"
             "loads = ( { rectangle = { min = [0.0, %#.17g]; max = [%#.17g, %#.17g]; };\n"
             "            force = [0.0, %#.17g]; },\n"
             "          { rectangle = { min = [0.0, %#.17g]; max = [%#.17g, %#.17g]; };\n"
             "            force = [0.0, %#.17g]; } );\n"
             "xefg = { tip = \"lefm\"; };\n"
             "cracks = ( { points = ( [%#.17g, 0.0], [%#.17g, 0.0] ); } );\n",
             -h, -0.5 * HEIGHT - h, n + 2, 2 * n + 2, h, h, DAMPING, RHO,
             -0.5 * HEIGHT, WIDTH, 0.5 * HEIGHT,
             0.5 * HEIGHT - h, WIDTH, 0.5 * HEIGHT, SIGMA * WIDTH,
             -0.5 * HEIGHT, WIDTH, -0.5 * HEIGHT + h, -SIGMA * WIDTH, -0.5 * h, a);
    Sim *s = tk_load(text);
    Xefg *x = xefg_of(s);
    Result R = {n, h, x->nnode, x->ndof, x->nbranch, 0, INFINITY, NAN, NAN, 0};
    while (s->step < 1000000) {
        assert_int_equal(sim_advance(s), 0);
        double ke = xefg_kinetic_energy(x), se = xefg_strain_energy(x, s);
        if (s->t >= SETTLE && se > 0 && ke <= STOP * se) {
            R.ratio = ke / se;
            break;
        }
    }
    R.steps = s->step;
    double K[2];
    assert_int_equal(xefg_stress_intensity(s, 0, 1, RD, K), 0);
    R.F = K[0] / (SIGMA * sqrt(PI * a));
    R.KII = K[1] / K[0];
    R.seconds = now() - t0;
    printf("  h = W/%d = %g mm: %d nodes, %d parameters (%d branch), dt %.4g ms; "
           "static at t = %.4g ms (%ld steps, damping %g /ms), "
           "kinetic / strain energy %.3g; K_I / (sigma sqrt(pi a)) = %.5f, "
           "K_II / K_I = %+.2e (r_d = %g mm); %.1f s\n", n, h, R.nodes, R.dofs,
           R.branch, s->dt, s->t, R.steps, DAMPING, R.ratio, R.F, R.KII, RD,
           R.seconds);
    fflush(stdout);
    tk_free(s);
    return R;
}

/**
 * Test 3: K_I within 3 % of the handbook at the finest spacing (and at
 * every spacing), the discretisation error falling with h, K_II / K_I
 * within 1 %, each run static.
 *
 * "Error falling" is checked as the change between successive spacings
 * shrinking, |F_3 - F_2| < |F_2 - F_1|: the error against the handbook is
 * already below 0.3 % at W/10, under the handbook's own accuracy (about
 * 0.5 %), and the method converges to about 0.3 % above it (the Aitken
 * limit of the three, printed; a plate twice as tall, H = 4 W, gives
 * 0.08 % less at W/20), so that the error against the handbook need not
 * fall, and here it does not.
 */
static void stress_intensity_of_an_edge_crack(void **state)
{
    (void)state;
    int n[3] = {10, 20, 40};
    const char *env = getenv("XEFG_K_SPACINGS");
    if (env)
        assert_int_equal(sscanf(env, "%d %d %d", &n[0], &n[1], &n[2]), 3);
    double a = CRACK;
    const char *ratio = getenv("XEFG_K_RATIO");
    if (ratio) {
        double r = atof(ratio);
        assert_true(r >= 0.2 && r <= 0.6);     /* the handbook's range */
        a = r * WIDTH;
    }
    double F = handbook_F(a / WIDTH);
    printf("  handbook F(a/W = %g) = %.5f (Tada / Brown-Srawley)\n",
           a / WIDTH, F);
    Result R[3];
    for (int k = 0; k < 3; k++)
        R[k] = edge_crack(n[k], a);
    double d1 = R[1].F - R[0].F, d2 = R[2].F - R[1].F;
    double limit = R[2].F - d2 * d2 / (d2 - d1);          /* Aitken */
    const char *path = getenv("XEFG_K_TABLE");
    FILE *f = path ? fopen(path, "w") : NULL;
    if (path)
        assert_non_null(f);
    if (f)
        fprintf(f, "# W/h h_mm nodes parameters steps KE/SE K_I/(sigma*sqrt(pi*a)) "
                "handbook error_%% K_II/K_I seconds\n");
    int falls = 1;
    for (int k = 0; k < 3; k++) {
        double err = R[k].F / F - 1.0;
        falls &= k == 0 || fabs(err) < fabs(R[k - 1].F / F - 1.0);
        printf("  W/%-3d h = %-6g F = %.5f  error %+.2f %%  K_II/K_I %+.2e  "
               "KE/SE %.2e  %ld steps  %.1f s\n", R[k].n, R[k].h, R[k].F,
               100 * err, R[k].KII, R[k].ratio, R[k].steps, R[k].seconds);
        if (f)
            fprintf(f, "%d %.6g %d %d %ld %.3e %.6f %.6f %+.4f %+.3e %.2f\n",
                    R[k].n, R[k].h, R[k].nodes, R[k].dofs, R[k].steps,
                    R[k].ratio, R[k].F, F, 100 * err, R[k].KII, R[k].seconds);
    }
    printf("  changes between spacings %+.5f, %+.5f; Aitken limit F = %.5f "
           "(%+.2f %% of the handbook); the handbook error %s\n", d1, d2, limit,
           100 * (limit / F - 1.0), falls ? "falls" : "does not fall monotonically");
    fflush(stdout);
    if (f) {
        fprintf(f, "# Aitken limit %.6f (%+.3f %% of the handbook)\n", limit,
                100 * (limit / F - 1.0));
        fclose(f);
    }
    for (int k = 0; k < 3; k++) {
        assert_true(R[k].ratio <= STOP);                      /* static */
        assert_true(fabs(R[k].F / F - 1.0) <= 0.03);          /* 3 % */
        assert_true(fabs(R[k].KII) <= 0.01);                  /* mode I */
    }
    assert_true(d1 * d2 > 0.0 && fabs(d2) < fabs(d1));      /* monotone */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(stress_intensity_of_an_edge_crack),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
