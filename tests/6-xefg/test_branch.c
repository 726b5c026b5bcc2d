/**
 * @file test_branch.c
 * @brief The tip enrichment (eq. 5-6): the jump of the branch functions
 *        across the crack behind the tip and its order r^m (xefg.md 5,
 *        Test 2b), continuity elsewhere, analytic gradients against central
 *        differences, a bent crack; the crack's side rule (eq. 3-4), its
 *        supports (eq. 1-2) and its tips.
 */
#include <stdio.h>
#include <stdlib.h>

#include "branch.h"
#include "crack_line.h"
#include "testkit.h"

static const double PI = 3.14159265358979323846;

/** A crack ending in a tip at end 1, 2 long, pointing along @p angle. */
static CrackLine straight_crack(double *x, double *y, double tx, double ty,
                                double angle, int tip_end)
{
    double dx = cos(angle), dy = sin(angle);
    /* the tip at end 1 points along +dir; at end 0, along it too */
    if (tip_end == 1) {
        x[0] = tx - 2 * dx, y[0] = ty - 2 * dy, x[1] = tx, y[1] = ty;
        return (CrackLine){2, x, y, {0, 1}};
    }
    x[0] = tx, y[0] = ty, x[1] = tx - 2 * dx, y[1] = ty - 2 * dy;
    return (CrackLine){2, x, y, {1, 0}};
}

/** The functions at (px, py) on their own side of the crack; count. */
static int eval(const CrackLine *c, int end, BranchKind kind, double m,
                double px, double py, double *B, double *Bx, double *By)
{
    double tip[2], dir[2];
    crack_line_tip(c, end, tip, dir);
    int side = crack_line_side(c, px, py, NULL);
    return branch_functions(kind, m, tip, dir, side, px, py, B, Bx, By);
}

/** B(q + delta n) - B(q - delta n) for each function, n the unit normal
 *  (nx, ny); the sides of the two points in s[2]. */
static int jump_across(const CrackLine *c, int end, BranchKind kind, double m,
                       double qx, double qy, double nx, double ny,
                       double delta, double *J, int s[2])
{
    double Bp[BRANCH_MAX], Bm[BRANCH_MAX];
    int nb = eval(c, end, kind, m, qx + delta * nx, qy + delta * ny, Bp, NULL,
                  NULL);
    assert_int_equal(eval(c, end, kind, m, qx - delta * nx, qy - delta * ny,
                          Bm, NULL, NULL), nb);
    s[0] = crack_line_side(c, qx + delta * nx, qy + delta * ny, NULL);
    s[1] = crack_line_side(c, qx - delta * nx, qy - delta * ny, NULL);
    for (int k = 0; k < nb; k++)
        J[k] = Bp[k] - Bm[k];
    return nb;
}

/* -- the jump of eq. 6: 2 r^m behind the tip, order m ------------------- */

static void cohesive_jump_is_2_r_to_the_m(void **state)
{
    (void)state;
    static const double angles[] = {0.0, 0.7, 2.0, -2.5, PI / 2};
    double x[2], y[2];
    for (int end = 0; end < 2; end++)
        for (int a = 0; a < 5; a++) {
            /* the tip at the origin: r down to 1e-6 keeps its digits */
            CrackLine c = straight_crack(x, y, 0.0, 0.0, angles[a], end);
            double tip[2], dir[2];
            crack_line_tip(&c, end, tip, dir);
            assert_close(dir[0], cos(angles[a]), 1e-15);
            assert_close(dir[1], sin(angles[a]), 1e-15);
            for (int m = 1; m <= 3; m++) {
                double prev = 0, rprev = 0, smin = 1e9, smax = -1e9;
                for (double r = 1e-6; r <= 1.01; r *= 10) {
                    double J[BRANCH_MAX];
                    int s[2];
                    /* behind the tip, just either side of the crack */
                    assert_int_equal(jump_across(&c, end, BRANCH_COHESIVE, m,
                                                 tip[0] - r * dir[0],
                                                 tip[1] - r * dir[1], -dir[1],
                                                 dir[0], 1e-9 * r, J, s), 1);
                    assert_int_equal(s[0] * s[1], -1);
                    double expect = 2 * pow(r, m);
                    assert_close(fabs(J[0]), expect, 1e-12 * expect);
                    if (prev > 0) {
                        double slope = log(fabs(J[0]) / prev) / log(r / rprev);
                        smin = fmin(smin, slope);
                        smax = fmax(smax, slope);
                    }
                    prev = fabs(J[0]);
                    rprev = r;
                    /* ahead of the tip the function is continuous */
                    assert_int_equal(jump_across(&c, end, BRANCH_COHESIVE, m,
                                                 tip[0] + r * dir[0],
                                                 tip[1] + r * dir[1], -dir[1],
                                                 dir[0], 1e-9 * r, J, s), 1);
                    assert_int_equal(s[0] * s[1], -1);
                    assert_true(fabs(J[0]) <= 1e-8 * pow(r, m));
                }
                assert_true(smin >= m - 0.05 && smax <= m + 0.05);
                if (a == 0 && end == 1)
                    printf("  cohesive m = %d: log-log slope of the jump, "
                           "r = 1e-6 .. 1: %.15f .. %.15f\n", m, smin, smax);
            }
            /* at the tip itself: not defined, no functions */
            double B[BRANCH_MAX];
            assert_int_equal(branch_functions(BRANCH_COHESIVE, 2, tip, dir, 1,
                                              tip[0], tip[1], B, NULL, NULL),
                             0);
            assert_int_equal(branch_functions(BRANCH_LEFM, 0, tip, dir, -1,
                                              tip[0], tip[1], B, NULL, NULL),
                             0);
        }
}

/* -- eq. 5: only sqrt(r) sin(theta/2) jumps ------------------------------ */

static void lefm_only_the_first_function_jumps(void **state)
{
    (void)state;
    double x[2], y[2];
    double worst = 0;
    for (int end = 0; end < 2; end++)
        for (double ang = -3.0; ang < 3.2; ang += 0.75) {
            CrackLine c = straight_crack(x, y, -0.4, 0.9, ang, end);
            double tip[2], dir[2];
            crack_line_tip(&c, end, tip, dir);
            for (double r = 1e-4; r <= 1.5; r *= 3) {
                double J[BRANCH_MAX];
                int s[2];
                assert_int_equal(jump_across(&c, end, BRANCH_LEFM, 0,
                                             tip[0] - r * dir[0],
                                             tip[1] - r * dir[1], -dir[1],
                                             dir[0], 1e-10 * r, J, s), 4);
                assert_int_equal(s[0] * s[1], -1);
                assert_close(fabs(J[0]), 2 * sqrt(r), 1e-12 * sqrt(r));
                for (int k = 1; k < 4; k++) {
                    assert_true(fabs(J[k]) <= 1e-9 * sqrt(r));
                    worst = fmax(worst, fabs(J[k]) / sqrt(r));
                }
                /* ahead of the tip all four are continuous */
                assert_int_equal(jump_across(&c, end, BRANCH_LEFM, 0,
                                             tip[0] + r * dir[0],
                                             tip[1] + r * dir[1], -dir[1],
                                             dir[0], 1e-10 * r, J, s), 4);
                for (int k = 0; k < 4; k++)
                    assert_true(fabs(J[k]) <= 1e-9 * sqrt(r));
            }
        }
    printf("  LEFM: largest jump of the three continuous functions behind "
           "the tip: %.2e sqrt(r)\n", worst);
}

/* -- gradients against central differences ------------------------------- */

/**
 * Analytic gradients of every function against central differences at
 * @p npts random points of the box [-1.4, 1.4]^2 around the tip, farther
 * than 0.03 from the crack and from the line @p avoid (a point and a
 * direction; NULL: none); the largest relative error.
 */
static double check_gradients(const CrackLine *c, int end, BranchKind kind,
                              double m, int npts, const double *avoid)
{
    double tip[2], dir[2], worst = 0;
    crack_line_tip(c, end, tip, dir);
    for (int k = 0; k < npts;) {
        double px = tip[0] + 2.8 * (rand() / (double)RAND_MAX - 0.5);
        double py = tip[1] + 2.8 * (rand() / (double)RAND_MAX - 0.5);
        double d, r = hypot(px - tip[0], py - tip[1]);
        crack_line_side(c, px, py, &d);
        if (d < 0.03 || r < 0.05)
            continue;
        if (avoid && fabs(avoid[2] * (py - avoid[1]) -
                          avoid[3] * (px - avoid[0])) < 0.03)
            continue;
        k++;
        double B[BRANCH_MAX], Bx[BRANCH_MAX], By[BRANCH_MAX];
        double Bp[BRANCH_MAX], Bm[BRANCH_MAX], fx[BRANCH_MAX], fy[BRANCH_MAX];
        int nb = eval(c, end, kind, m, px, py, B, Bx, By);
        assert_int_equal(nb, kind == BRANCH_LEFM ? 4 : 1);
        const double h = 1e-6;
        eval(c, end, kind, m, px + h, py, Bp, NULL, NULL);
        eval(c, end, kind, m, px - h, py, Bm, NULL, NULL);
        for (int i = 0; i < nb; i++)
            fx[i] = (Bp[i] - Bm[i]) / (2 * h);
        eval(c, end, kind, m, px, py + h, Bp, NULL, NULL);
        eval(c, end, kind, m, px, py - h, Bm, NULL, NULL);
        for (int i = 0; i < nb; i++)
            fy[i] = (Bp[i] - Bm[i]) / (2 * h);
        /* relative to the size of the gradient, or to its natural scale
         * (r^-1/2, r^(m-1)) where it nearly vanishes (ahead of the tip) */
        double scale = kind == BRANCH_LEFM ? 1 / sqrt(r) : pow(r, m - 1);
        for (int i = 0; i < nb; i++) {
            double err = hypot(Bx[i] - fx[i], By[i] - fy[i]) /
                         fmax(hypot(Bx[i], By[i]), 1e-2 * scale);
            if (!(err <= 1e-6))
                fail_msg("function %d at (%g, %g): gradient (%.12g, %.12g), "
                         "differences (%.12g, %.12g)", i, px, py, Bx[i], By[i],
                         fx[i], fy[i]);
            worst = fmax(worst, err);
        }
    }
    return worst;
}

static void gradients_match_differences(void **state)
{
    (void)state;
    srand(4242);
    double x[2], y[2], worst_l = 0, worst_c = 0;
    for (int end = 0; end < 2; end++)
        for (double ang = -2.9; ang < 3.2; ang += 1.1) {
            CrackLine c = straight_crack(x, y, 0.2, 0.1, ang, end);
            worst_l = fmax(worst_l, check_gradients(&c, end, BRANCH_LEFM, 0,
                                                    200, NULL));
            for (int m = 1; m <= 3; m++)
                worst_c = fmax(worst_c, check_gradients(&c, end,
                                                        BRANCH_COHESIVE, m,
                                                        100, NULL));
            worst_c = fmax(worst_c, check_gradients(&c, end, BRANCH_COHESIVE,
                                                    1.5, 100, NULL));
        }
    printf("  straight cracks: largest relative gradient error, LEFM %.2e, "
           "cohesive %.2e\n", worst_l, worst_c);
}

/* -- a bent crack --------------------------------------------------------- */

/* (-1, 0) -> (0, 0) -> (0.6, -0.8): the tip segment turns 53 degrees down */
static const double BX[3] = {-1.0, 0.0, 0.6}, BY[3] = {0.0, 0.0, -0.8};

static void bent_crack_jump_follows_the_crack(void **state)
{
    (void)state;
    CrackLine c = {3, BX, BY, {0, 1}};
    double tip[2], dir[2];
    crack_line_tip(&c, 1, tip, dir);
    assert_close(dir[0], 0.6, 1e-15);
    assert_close(dir[1], -0.8, 1e-15);
    double nx = -dir[1], ny = dir[0];
    for (int kind = 0; kind < 2; kind++)
        for (int m = 1; m <= (kind ? 3 : 1); m++) {
            BranchKind bk = kind ? BRANCH_COHESIVE : BRANCH_LEFM;
            double p = kind ? m : 0.5, J[BRANCH_MAX];
            int s[2];
            /* behind the tip on the tip segment: theta = +-pi, jump 2 r^p */
            for (double r = 0.01; r < 1.0; r += 0.2) {
                jump_across(&c, 1, bk, m, tip[0] - r * dir[0],
                            tip[1] - r * dir[1], nx, ny, 1e-10, J, s);
                assert_int_equal(s[0] * s[1], -1);
                assert_close(fabs(J[0]), 2 * pow(r, p), 1e-9 * pow(r, p));
            }
            /* across the first segment the crack opens too, by
             * 2 r^p sin(acos(x'/r)/2) (theta = side acos(x'/r)) */
            for (double qx = -0.9; qx < 0; qx += 0.2) {
                jump_across(&c, 1, bk, m, qx, 0.0, 0.0, 1.0, 1e-10, J, s);
                assert_int_equal(s[0], 1);
                assert_int_equal(s[1], -1);
                double r = hypot(qx - tip[0], -tip[1]);
                double xl = (qx - tip[0]) * dir[0] + (0 - tip[1]) * dir[1];
                double expect = 2 * pow(r, p) * sin(0.5 * acos(xl / r));
                assert_close(J[0], expect, 1e-8 * pow(r, p));
                assert_true(J[0] > 0.5 * pow(r, p));
            }
            /* the line of the tip segment behind the bend (not the crack):
             * no jump there. theta from atan2 in the tip frame alone would
             * open a crack along it. */
            for (double t = 1.2; t < 2.2; t += 0.2) {
                double qx = tip[0] - t * dir[0], qy = tip[1] - t * dir[1];
                jump_across(&c, 1, bk, m, qx, qy, nx, ny, 1e-10, J, s);
                assert_int_equal(s[0], 1);
                assert_int_equal(s[1], 1);
                double r = hypot(qx - tip[0], qy - tip[1]);
                for (int k = 0; k < (kind ? 1 : 4); k++)
                    assert_true(fabs(J[k]) <= 1e-8 * pow(r, p));
            }
        }
    /* the gradients, away from the crack and from that line */
    srand(99);
    const double avoid[4] = {tip[0], tip[1], dir[0], dir[1]};
    double wl = check_gradients(&c, 1, BRANCH_LEFM, 0, 300, avoid);
    double wc = 0;
    for (int m = 1; m <= 3; m++)
        wc = fmax(wc, check_gradients(&c, 1, BRANCH_COHESIVE, m, 300, avoid));
    printf("  bent crack: largest relative gradient error, LEFM %.2e, "
           "cohesive %.2e\n", wl, wc);
}

/* -- the side rule (eq. 3-4) --------------------------------------------- */

static void side_rule_on_bent_cracks(void **state)
{
    (void)state;
    double d;
    /* the bent crack above: above the first segment is left (+1) */
    CrackLine c = {3, BX, BY, {0, 1}};
    assert_int_equal(crack_line_side(&c, -0.5, 0.3, &d), 1);
    assert_close(d, 0.3, 1e-15);
    /* the tip segment turns right: the inside of the bend is its right */
    assert_int_equal(crack_line_side(&c, 0.3, -0.41, NULL), -1);
    assert_int_equal(crack_line_side(&c, 0.3, -0.39, NULL), 1);
    assert_int_equal(crack_line_side(&c, 0.3, 0.1, NULL), 1);
    assert_int_equal(crack_line_side(&c, 0.2, 0.3, &d), 1);       /* closest: the vertex */
    assert_close(d, hypot(0.2, 0.3), 1e-15);
    assert_int_equal(crack_line_side(&c, -0.5, 0.0, &d), 0);      /* on it */
    assert_close(d, 0.0, 0.0);
    assert_int_equal(crack_line_side(&c, 0.0, 0.0, NULL), 0);     /* on the vertex */
    assert_int_equal(crack_line_side(&c, 0.9, -1.1, NULL), 1);    /* ahead of the tip */
    assert_int_equal(crack_line_side(&c, 0.8, -1.2, NULL), -1);
    assert_int_equal(crack_line_side(&c, -0.5, -0.3, &d), -1);
    assert_close(d, 0.3, 1e-15);

    /* a hairpin (169 degree turn): (-1, 0) -> (0, 0) -> (-1, 0.2). Beyond
     * the vertex the closest point is the vertex; the outside of the turn
     * is its right. The first segment's normal alone says "left" at
     * (0.5, 0.3); the pseudo-normal of the vertex says right. */
    static const double hx[3] = {-1.0, 0.0, -1.0}, hy[3] = {0.0, 0.0, 0.2};
    CrackLine h = {3, hx, hy, {0, 0}};
    assert_int_equal(crack_line_side(&h, 0.5, 0.3, &d), -1);
    assert_close(d, hypot(0.5, 0.3), 1e-15);
    assert_int_equal(crack_line_side(&h, 0.5, 0.0, NULL), -1);
    assert_int_equal(crack_line_side(&h, 0.5, -0.3, NULL), -1);
    assert_int_equal(crack_line_side(&h, 0.1, 0.5, NULL), -1);
    assert_int_equal(crack_line_side(&h, -0.5, 0.05, NULL), 1);   /* between the arms */
    assert_int_equal(crack_line_side(&h, -0.5, -0.1, NULL), -1);  /* below both */
    assert_int_equal(crack_line_side(&h, -0.5, 0.3, NULL), -1);   /* above both */
    /* the same hairpin walked the other way: every side flips */
    static const double gx[3] = {-1.0, 0.0, -1.0}, gy[3] = {0.2, 0.0, 0.0};
    CrackLine g = {3, gx, gy, {0, 0}};
    assert_int_equal(crack_line_side(&g, 0.5, 0.3, NULL), 1);
    assert_int_equal(crack_line_side(&g, -0.5, 0.05, NULL), -1);

    /* an S: east, north, west, north, east. The side is one side of the
     * whole curve: between the first and third segments it is the left of
     * both, between the third and fifth the right of both */
    static const double sx[6] = {0, 2, 2, 0, 0, 2}, sy[6] = {0, 0, 1, 1, 2, 2};
    CrackLine z = {6, sx, sy, {0, 0}};
    assert_int_equal(crack_line_side(&z, 1.0, 0.4, NULL), 1);
    assert_int_equal(crack_line_side(&z, 1.0, 0.6, NULL), 1);
    assert_int_equal(crack_line_side(&z, 1.0, 1.4, NULL), -1);
    assert_int_equal(crack_line_side(&z, 1.0, 1.6, NULL), -1);
    assert_int_equal(crack_line_side(&z, 3.0, 0.5, NULL), -1);
    assert_int_equal(crack_line_side(&z, -1.0, 1.5, NULL), 1);
    assert_int_equal(crack_line_side(&z, 1.0, -0.5, NULL), -1);
    assert_int_equal(crack_line_side(&z, 1.0, 2.5, NULL), 1);
    /* exactly on the line ahead of an axis-aligned end: 0 */
    assert_int_equal(crack_line_side(&z, 3.0, 2.0, NULL), 0);

    /* repeated points are no segments: a repeated first point, and one at
     * a bend (the pseudo-normal of the real segments either side) */
    static const double r1x[3] = {0.75, 0.75, 1.75}, r1y[3] = {0.25, 0.25, -0.5};
    CrackLine r1 = {3, r1x, r1y, {0, 0}};
    assert_int_equal(crack_line_side(&r1, 0.8, 0.5, &d), 1);
    assert_close(d, hypot(0.05, 0.25), 1e-15);
    assert_int_equal(crack_line_side(&r1, 0.7, 0.1, NULL), -1);
    static const double r2x[4] = {0, 1, 1, 1}, r2y[4] = {0, 0, 0, 1};
    CrackLine r2 = {4, r2x, r2y, {0, 0}};
    assert_int_equal(crack_line_side(&r2, 1.5, -0.5, NULL), -1);
    assert_int_equal(crack_line_side(&r2, 1.2, -0.1, NULL), -1);
    assert_int_equal(crack_line_side(&r2, 0.9, 0.1, NULL), 1);
    static const double r3x[2] = {0.5, 0.5}, r3y[2] = {0.5, 0.5};
    CrackLine r3 = {2, r3x, r3y, {0, 0}};
    assert_int_equal(crack_line_side(&r3, 0.5, 1.5, &d), 0);
    assert_close(d, 1.0, 0.0);
}

/* -- supports and tips (eq. 1-2) ------------------------------------------ */

static void supports_and_tips(void **state)
{
    (void)state;
    CrackLine c = {3, BX, BY, {1, 1}};
    int end = 7;
    assert_int_equal(crack_line_cut(&c, 0.6, -0.5, 0.31, &end), SUPPORT_TIP);
    assert_int_equal(end, 1);
    assert_int_equal(crack_line_cut(&c, -1.2, 0.1, 0.3, &end), SUPPORT_TIP);
    assert_int_equal(end, 0);
    assert_int_equal(crack_line_cut(&c, -0.5, 0.2, 0.3, &end), SUPPORT_CUT);
    assert_int_equal(end, -1);
    assert_int_equal(crack_line_cut(&c, -0.5, 0.2, 0.2, NULL), SUPPORT_UNCUT);
    assert_int_equal(crack_line_cut(&c, -0.5, 0.5, 0.3, &end), SUPPORT_UNCUT);
    /* both tips in the disk: the nearer */
    assert_int_equal(crack_line_cut(&c, -0.1, -0.3, 5.0, &end), SUPPORT_TIP);
    assert_int_equal(end, 1);
    /* a mouth (not a tip) is no tip: the support is cut through */
    c.tip[0] = 0;
    assert_int_equal(crack_line_cut(&c, -1.2, 0.1, 0.3, &end), SUPPORT_CUT);
    double tip[2], dir[2];
    crack_line_tip(&c, 0, tip, dir);
    assert_close(tip[0], -1.0, 0.0);
    assert_close(tip[1], 0.0, 0.0);
    assert_close(dir[0], -1.0, 1e-15);
    assert_close(dir[1], 0.0, 1e-15);
    /* a repeated last point: the direction of the last real segment */
    static const double rx[4] = {0, 1, 2, 2}, ry[4] = {0, 0, 1, 1};
    CrackLine r = {4, rx, ry, {1, 1}};
    crack_line_tip(&r, 1, tip, dir);
    assert_close(dir[0], sqrt(0.5), 1e-15);
    assert_close(dir[1], sqrt(0.5), 1e-15);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(cohesive_jump_is_2_r_to_the_m),
        cmocka_unit_test(lefm_only_the_first_function_jumps),
        cmocka_unit_test(gradients_match_differences),
        cmocka_unit_test(bent_crack_jump_follows_the_crack),
        cmocka_unit_test(side_rule_on_bent_cracks),
        cmocka_unit_test(supports_and_tips),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
