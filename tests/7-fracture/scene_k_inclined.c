/**
 * @file scene_k_inclined.c
 * @brief Chapter 7: K_I and K_II at BOTH tips of Griffith's inclined
 *        centre crack by CRAMP and the interaction integral (j_integral.h),
 *        at beta = 30, 45 and 60 degrees (issue 28), against
 *        K_I = sigma sqrt(pi a) cos^2 beta and
 *        K_II = sigma sqrt(pi a) sin beta cos beta (Griffith's infinite
 *        plate; Anderson, Fracture Mechanics, ch. 2).
 *
 * A crack of length 2a = 4 mm, written as a polyline of two points through
 * the plate's centre, at beta to the x axis, in a square plate of half-side
 * b = 48.5 h (about 3 a), plane strain, E = 1000 MPa, nu = 0.3, cells of
 * h = a / 16 with 2 x 2 points each. The remote tension sigma = 1 MPa is
 * normal to the x axis. As in stage 6's scene_centre_crack.c, the plate's
 * edges carry the tractions of the infinite plate's exact state
 * (Westergaard's functions, griffith_stress() of
 * tests/support/westergaard.h), one load per point of the outermost row
 * (traction x h/2), so the finite plate holds Griffith's state and no
 * finite-width correction is needed (pulled uniformly, this plate would
 * need more than Feddersen's sqrt(sec(pi a / 2b)), +7 % at beta = 0,
 * which is for a long strip; Tada's handbook). Damped to rest as
 * scene_k_edge.c is.
 *
 * The crack's centre is a cell centre, so that grid, points and loads are
 * point-symmetric about it and the two tips see the same discretisation
 * (the slopes tan 30 and tan 60 are irrational: no node or point lies on
 * the crack). At 45 degrees a diagonal through any such centre runs
 * through points (2 x 2 per cell), and a point on the crack ties its faces
 * together (crossing.c: the line is not crossed); there the crack is moved
 * by h / (4 sqrt 2) along its normal, to mid-way between two diagonal rows
 * of points, and the tips' discretisations differ.
 *
 * Bounds, fixed before the first run, on cells of a / 16 and the domains
 * of 4, 6 and 8 cells (a / 4, 3a / 8, a / 2) about each tip: at every
 * angle, tip and domain K_I and K_II within 3 % of Griffith's; the two
 * tips agree to 1e-6 sigma sqrt(pi a) in K_I and in K_II at 30 and 60
 * degrees (the discretisation is point-symmetric: only round-off
 * differs), and to 1 % of sigma sqrt(pi a) at 45; each run at rest
 * (kinetic / strain energy <= 1e-6). Cells of a / 8 (domains of 2, 3, 4
 * cells: the same mm) are printed beside them, not bounded; with
 * K_INCLINED_A32 set in the environment, cells of a / 32 too (minutes).
 * J / J(K) - 1 compares J with (K_I^2 + K_II^2) / E' (printed).
 * They hold: on a/16 K is -2.1 to +2.1 % of Griffith's (K_I low at 60
 * deg, where T = sigma (sin^2 - cos^2) beta is +0.5 MPa: chapter 7), the
 * tips agree to 1e-13 at 30 and 60 and to 0.76 % at 45; on a/32 every K
 * is within 1.2 %. Red with the mode-II auxiliary field's sign swapped,
 * and with the first point's x1 turned back along the crack.
 */
#include <complex.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "j_integral.h"
#include "testkit.h"
#include "westergaard.h"

#define PI 3.14159265358979323846
#define CRACK 2.0                 /* a: half the crack's length (mm) */
#define SIGMA 1.0                 /* remote tension along y (MPa) */
#define RHO 1e-3                  /* g/mm^3 */
/* 1/ms: twice scene_k_edge.c's, for a plate of about half its size; on
 * a/8 at 30 deg K moved by at most 0.1 % against 100 /ms and against a
 * run on to 1 ms (kinetic / strain energy 6e-8) */
#define DAMPING 200.0
#define STOP 1e-6                 /* kinetic / strain energy at rest */
#define SETTLE (15.0 / (0.5 * DAMPING))  /* and not before (stage 6) */
#define T_MAX 1.0                 /* and not after (scene_k_edge.c) */
#define TOL 0.03                  /* K against Griffith */
#define SYM_EXACT 1e-6            /* tips, 30 and 60 deg (of sigma sqrt(pi a)) */
#define SYM_45 0.01               /* tips, 45 deg */

/** One run: K / (sigma sqrt(pi a)) per tip (0: first point) and domain. */
typedef struct Result {
    int n;                        /**< a / h */
    int nd;                       /**< domains */
    int cells[3];                 /**< their half-widths */
    double KI[2][3], KII[2][3];   /**< over sigma sqrt(pi a) */
    double JK[2][3];              /**< J / ((K_I^2 + K_II^2) / E') - 1 */
    double tip[2][2];             /**< the tips (mm) */
    long steps;
    double ratio;                 /**< kinetic / strain energy at the stop */
    double seconds;
} Result;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/** The plate with the crack at @p beta on cells of a / @p n, at rest. */
static Result inclined_crack(double beta, int n)
{
    double t0 = now(), h = CRACK / n;
    int half = 3 * n;                   /* b = (half + 1/2) h */
    double b = (half + 0.5) * h, hp = 0.5 * h;   /* hp: point spacing */
    /* the crack's centre: the plate's (a cell centre), or at 45 deg h / 4
     * off the diagonals of points along y - x */
    int diag = fabs(beta - 0.25 * PI) < 1e-9;
    double cx = diag ? -0.125 * h : 0.0, cy = diag ? 0.125 * h : 0.0;
    double ca = CRACK * cos(beta), sa = CRACK * sin(beta);
    int c = n / 4;                      /* a / 4 in cells */
    Text t = {malloc(1 << 16), 0, 1 << 16};
    assert_non_null(t.s);
    text_add(&t,
             "grid = { origin = [%#.17g, %#.17g]; cells = [%d, %d]; cell_size = [%#.17g, %#.17g]; };\n"
             "run = { time = 1000.0; snapshots = 0; plane = \"strain\"; damping = %#.17g; };\n"
             "materials = ( { name = \"m\"; E = 1000.0; nu = 0.3; rho = %#.17g; } );\n"
             "bodies = ( { name = \"plate\"; material = \"m\"; points_per_cell = 2;\n"
             "             rectangle = { min = [%#.17g, %#.17g]; max = [%#.17g, %#.17g]; }; } );\n"
             "cracks = ( { points = ( [%#.17g, %#.17g], [%#.17g, %#.17g] );\n"
             "             j_integral = { every = 1000000000; contours = [%d, %d, %d]; }; } );\n"
             "loads = (\n",
             -b - 2 * h, -b - 2 * h, 2 * half + 5, 2 * half + 5, h, h, DAMPING, RHO,
             -b, -b, b, b, cx - ca, cy - sa, cx + ca, cy + sa, c, c + c / 2, 2 * c);
    /* the outermost row of points, 2 (2 half + 1) a side, at h/4 from the
     * edge: each carries the exact traction at its place on the edge */
    int np = 2 * (2 * half + 1);
    const char *sep = "  ";
    for (int i = 0; i < np; i++)
        for (int j = 0; j < np; j++) {
            int tb = j == 0 || j == np - 1, lr = i == 0 || i == np - 1;
            if (!tb && !lr)
                continue;
            double px = -b + (i + 0.5) * hp, py = -b + (j + 0.5) * hp;
            double f[2] = {0.0, 0.0}, s[3];
            if (tb) {                   /* t = s . (0, +-1) */
                double ny = j == 0 ? -1.0 : 1.0;
                griffith_stress(SIGMA, beta, CRACK, px - cx, ny * b - cy, s);
                f[0] += s[2] * ny * hp;
                f[1] += s[1] * ny * hp;
            }
            if (lr) {                   /* t = s . (+-1, 0) */
                double nx = i == 0 ? -1.0 : 1.0;
                griffith_stress(SIGMA, beta, CRACK, nx * b - cx, py - cy, s);
                f[0] += s[0] * nx * hp;
                f[1] += s[2] * nx * hp;
            }
            text_add(&t, "%s{ rectangle = { min = [%#.17g, %#.17g]; max = [%#.17g, %#.17g]; };\n"
                     "    force = [%#.17g, %#.17g]; }\n", sep, px - 0.25 * hp,
                     py - 0.25 * hp, px + 0.25 * hp, py + 0.25 * hp, f[0], f[1]);
            sep = ", ";
        }
    text_add(&t, ");\n");
    Sim *sim = tk_load(t.s);
    free(t.s);
    for (int k = 0; k < sim->scene.nloads; k++)
        assert_int_equal(sim->scene.loads[k].count, 1);
    Result R = {.n = n, .ratio = INFINITY};
    while (sim->step < 10000000) {
        assert_int_equal(sim_advance(sim), 0);
        Totals e = sim_totals(sim);
        if ((sim->t >= SETTLE && e.strain > 0 && e.kinetic <= STOP * e.strain) ||
            sim->t >= T_MAX) {
            R.ratio = e.kinetic / e.strain;
            break;
        }
    }
    R.steps = sim->step;
    JState *S = sim_state(sim, "j-integral");
    assert_non_null(S);
    assert_int_equal(S->ntips, 2);
    assert_int_equal(j_integral_evaluate(sim, S), 0);
    const Material *m = &sim->scene.mat[0];
    double Ep = m->E / (1.0 - m->nu * m->nu), K0 = SIGMA * sqrt(PI * CRACK);
    R.nd = S->set[0].ncontours;
    for (int e = 0; e < 2; e++) {
        const JTip *T = &S->tip[e];
        assert_int_equal(T->end, e);
        R.tip[e][0] = T->x;
        R.tip[e][1] = T->y;
        for (int k = 0; k < R.nd; k++) {
            R.cells[k] = S->set[0].contour[k];
            R.KI[e][k] = T->KI[k] / K0;
            R.KII[e][k] = T->KII[k] / K0;
            R.JK[e][k] = T->J[k] / ((T->KI[k] * T->KI[k] + T->KII[k] * T->KII[k]) / Ep) - 1.0;
        }
    }
    R.seconds = now() - t0;
    tk_free(sim);
    return R;
}

/** The reference field: traction-free faces, sigma far away, and
 *  Griffith's K ahead of the tip. */
static void westergaard_field_is_griffiths(void **state)
{
    (void)state;
    double beta = 0.6, c = cos(beta), n = sin(beta), s[3];
    for (int k = -9; k <= 9; k++)
        for (int side = -1; side <= 1; side += 2) {
            double xl = 0.1 * k * CRACK, yl = side * 1e-12;
            griffith_stress(SIGMA, beta, CRACK, c * xl - n * yl, n * xl + c * yl, s);
            assert_close(-n * s[0] + c * s[2], 0.0, 1e-9);   /* normal (-n, c) */
            assert_close(-n * s[2] + c * s[1], 0.0, 1e-9);
        }
    griffith_stress(SIGMA, beta, CRACK, 3e6, -4e6, s);
    assert_close(s[0], 0.0, 1e-9);
    assert_close(s[1], SIGMA, 1e-9);
    assert_close(s[2], 0.0, 1e-9);
    double r = 1e-8 * CRACK, K0 = SIGMA * sqrt(PI * CRACK);
    for (int e = -1; e <= 1; e += 2) {          /* ahead of either tip */
        griffith_stress(SIGMA, beta, CRACK, e * (CRACK + r) * c, e * (CRACK + r) * n, s);
        double snn = n * n * s[0] - 2.0 * c * n * s[2] + c * c * s[1];
        double stn = c * n * (s[1] - s[0]) + (c * c - n * n) * s[2];
        assert_close(sqrt(2.0 * PI * r) * snn / K0, c * c, 1e-6);
        assert_close(sqrt(2.0 * PI * r) * stn / K0, n * c, 1e-6);
    }
}

/** Rows of one run: per tip and domain, K and their errors. */
static void print_rows(double deg, const Result *R, double gI, double gII)
{
    for (int e = 0; e < 2; e++)
        for (int k = 0; k < R->nd; k++)
            printf("    %2.0f  %-5s  a/%-2d %2d (%4.2f mm)  %7.5f  %+6.2f %%  %7.5f  %+6.2f %%"
                   "  %+6.2f %%  %5ld  %.1e  %4.1f s\n", deg, e ? "last" : "first",
                   R->n, R->cells[k], R->cells[k] * CRACK / R->n, R->KI[e][k],
                   100 * (R->KI[e][k] / gI - 1.0), R->KII[e][k],
                   100 * (R->KII[e][k] / gII - 1.0), 100 * R->JK[e][k], R->steps,
                   R->ratio, R->seconds);
}

static void k_at_both_tips(void **state)
{
    (void)state;
    const double degrees[3] = {30.0, 45.0, 60.0};
    const int coarse = 8, fine = 16;
    TkBounds bd = {0, 0};
    printf("  K / (sigma sqrt(pi a)), a = %g mm, plane strain, exact tractions "
           "on the edges; Griffith K_I = cos^2 beta, K_II = sin beta cos beta:\n",
           CRACK);
    printf("    beta tip   cells domain       K_I      error     K_II     error "
           "  J/J(K)-1  steps  KE/SE   time\n");
    for (int i = 0; i < 3; i++) {
        double beta = degrees[i] * PI / 180.0;
        double gI = cos(beta) * cos(beta), gII = sin(beta) * cos(beta);
        Result Rc = inclined_crack(beta, coarse);
        print_rows(degrees[i], &Rc, gI, gII);
        Result R = inclined_crack(beta, fine);
        print_rows(degrees[i], &R, gI, gII);
        if (getenv("K_INCLINED_A32")) {   /* a third cell size, minutes */
            Result Rx = inclined_crack(beta, 2 * fine);
            print_rows(degrees[i], &Rx, gI, gII);
        }
        fflush(stdout);
        tk_bound(&bd, 4, R.ratio <= STOP, "beta %g: not at rest (KE/SE %.1e)",
                 degrees[i], R.ratio);
        double sym = i == 1 ? SYM_45 : SYM_EXACT, dmax = 0.0;
        for (int k = 0; k < R.nd; k++) {
            for (int e = 0; e < 2; e++) {
                double eI = R.KI[e][k] / gI - 1.0, eII = R.KII[e][k] / gII - 1.0;
                tk_bound(&bd, 4, fabs(eI) <= TOL, "beta %g, %s tip, %d cells: K_I "
                         "%+.2f %% of Griffith (bound 3 %%)", degrees[i],
                         e ? "last" : "first", R.cells[k], 100 * eI);
                tk_bound(&bd, 4, fabs(eII) <= TOL, "beta %g, %s tip, %d cells: K_II "
                         "%+.2f %% of Griffith (bound 3 %%)", degrees[i],
                         e ? "last" : "first", R.cells[k], 100 * eII);
            }
            double dI = fabs(R.KI[0][k] - R.KI[1][k]);
            double dII = fabs(R.KII[0][k] - R.KII[1][k]);
            dmax = fmax(dmax, fmax(dI, dII));
            tk_bound(&bd, 4, dI <= sym && dII <= sym, "beta %g, %d cells: the tips "
                     "differ by %.2e in K_I, %.2e in K_II (bound %.0e)", degrees[i],
                     R.cells[k], dI, dII, sym);
        }
        printf("    %2.0f: tips at (%.4f, %.4f) and (%.4f, %.4f); they differ by at "
               "most %.2e sigma sqrt(pi a) (bound %.0e)\n", degrees[i], R.tip[0][0],
               R.tip[0][1], R.tip[1][0], R.tip[1][1], dmax, sym);
    }
    tk_bounds_finish(&bd);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(westergaard_field_is_griffiths),
        cmocka_unit_test(k_at_both_tips),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
