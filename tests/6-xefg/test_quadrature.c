/**
 * @file test_quadrature.c
 * @brief Background-cell quadrature (xefg.md 2.6, pitfall 4): Gauss-Legendre
 *        exactness; tensor points of an uncut cell; a cell cut by a crack
 *        integrates each side's area and moments exactly; a tip cell keeps
 *        its points off the tip and integrates the r^-1/2 of eq. 5's
 *        gradients; bent, crossing, grid-aligned and random cracks.
 */
#include <float.h>
#include <stdio.h>
#include <stdlib.h>

#include "crack_line.h"
#include "quadrature.h"
#include "testkit.h"

/* room for the points of any cell of these tests */
#define NPTS 40000

/* -- helpers --------------------------------------------------------------- */

/** Area, int x, int y, int xy of a polygon (Green's theorem), any orientation. */
static void poly_moments(const double *x, const double *y, int n, double m[4])
{
    double a = 0, mx = 0, my = 0, mxy = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        double c = x[i] * y[j] - x[j] * y[i];
        a += c;
        mx += (x[i] + x[j]) * c;
        my += (y[i] + y[j]) * c;
        mxy += (x[i] * y[j] + 2 * x[i] * y[i] + 2 * x[j] * y[j] + x[j] * y[i]) * c;
    }
    double s = a < 0 ? -1 : 1;
    m[0] = s * a / 2;
    m[1] = s * mx / 6;
    m[2] = s * my / 6;
    m[3] = s * mxy / 24;
}

/** The part of a polygon left (keep = +1) or right (-1) of the line from a
 *  to b (Sutherland-Hodgman); its vertex count. */
static int clip(const double *x, const double *y, int n, const double a[2],
                const double b[2], int keep, double *ox, double *oy)
{
    int k = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        double si = keep * ((b[0] - a[0]) * (y[i] - a[1]) - (b[1] - a[1]) * (x[i] - a[0]));
        double sj = keep * ((b[0] - a[0]) * (y[j] - a[1]) - (b[1] - a[1]) * (x[j] - a[0]));
        if (si >= 0) {
            ox[k] = x[i];
            oy[k++] = y[i];
        }
        if ((si > 0 && sj < 0) || (si < 0 && sj > 0)) {
            double t = si / (si - sj);
            ox[k] = x[i] + t * (x[j] - x[i]);
            oy[k++] = y[i] + t * (y[j] - y[i]);
        }
    }
    return k;
}

/** The rectangle's polygon. */
static void rect(double x0, double y0, double x1, double y1, double *x,
                 double *y)
{
    x[0] = x0, y[0] = y0, x[1] = x1, y[1] = y0;
    x[2] = x1, y[2] = y1, x[3] = x0, y[3] = y1;
}

/**
 * Points of a cell: every one finite, strictly inside the cell, of positive
 * weight, off every crack (side != 0); sums of 1, x, y, xy per side of
 * crack 0 (m[0] right, m[1] left); the count.
 */
static int cell_points(const CrackLine *cracks, int nc, double x0, double y0,
                       double x1, double y1, int n, QuadPoint *q,
                       double m[2][4])
{
    int np = quad_cell(cracks, nc, x0, y0, x1, y1, n, q, NPTS);
    assert_true(np > 0 && np <= NPTS);
    for (int s = 0; s < 2; s++)
        for (int k = 0; k < 4; k++)
            m[s][k] = 0;
    for (int i = 0; i < np; i++) {
        assert_true(isfinite(q[i].x) && isfinite(q[i].y) && isfinite(q[i].w));
        assert_true(q[i].x > x0 && q[i].x < x1 && q[i].y > y0 && q[i].y < y1);
        assert_true(q[i].w > 0);
        int side = 1;
        for (int c = 0; c < nc; c++) {
            int s = crack_line_side(&cracks[c], q[i].x, q[i].y, NULL);
            if (s == 0)
                fail_msg("point (%.17g, %.17g) on crack %d", q[i].x, q[i].y, c);
            if (c == 0)
                side = s;
        }
        double *ms = m[side > 0];
        ms[0] += q[i].w;
        ms[1] += q[i].w * q[i].x;
        ms[2] += q[i].w * q[i].y;
        ms[3] += q[i].w * q[i].x * q[i].y;
    }
    return np;
}

/**
 * Fail unless the moments agree to @p rel relative to the cell's own (@p
 * cell: its area, x, y, xy; a thin piece's moments carry the rounding of
 * its vertices, about 1e-16 of the cell); the largest such error.
 */
static double check_moments(const double got[4], const double want[4],
                            const double cell[4], double rel,
                            const char *what)
{
    double worst = 0;
    for (int k = 0; k < 4; k++) {
        double err = fabs(got[k] - want[k]) / fabs(cell[k]);
        if (!(err <= rel))
            fail_msg("%s, moment %d: %.17g, expected %.17g (error %.2e of "
                     "the cell's)", what, k, got[k], want[k], err);
        worst = fmax(worst, err);
    }
    return worst;
}

/* -- Gauss-Legendre ---------------------------------------------------------- */

static void gauss_legendre_is_exact_to_degree_2n_minus_1(void **state)
{
    (void)state;
    double xi[GAUSS_MAX], w[GAUSS_MAX], worst = 0;
    assert_int_equal(gauss_legendre(0, xi, w), -1);
    assert_int_equal(gauss_legendre(GAUSS_MAX + 1, xi, w), -1);
    for (int n = 1; n <= GAUSS_MAX; n++) {
        assert_int_equal(gauss_legendre(n, xi, w), 0);
        for (int i = 0; i < n; i++) {
            assert_true(xi[i] == -xi[n - 1 - i] && w[i] == w[n - 1 - i]);
            assert_true(w[i] > 0 && xi[i] > -1 && xi[i] < 1);
            if (i > 0)
                assert_true(xi[i] > xi[i - 1]);
        }
        for (int k = 0; k <= 2 * n - 1; k++) {
            double s = 0;
            for (int i = 0; i < n; i++)
                s += w[i] * pow(xi[i], k);
            double exact = k % 2 ? 0.0 : 2.0 / (k + 1);
            assert_close(s, exact, 1e-14);
            worst = fmax(worst, fabs(s - exact));
        }
        /* and not of degree 2n */
        double s = 0;
        for (int i = 0; i < n; i++)
            s += w[i] * pow(xi[i], 2 * n);
        assert_true(fabs(s - 2.0 / (2 * n + 1)) > 1e-6);
    }
    /* closed forms: n = 2, 3, 5 (nodes to an ulp or two, weights a few) */
    gauss_legendre(2, xi, w);
    assert_close(xi[1], 1 / sqrt(3.0), 3e-16);
    assert_close(w[0], 1.0, 1e-15);
    gauss_legendre(3, xi, w);
    assert_close(xi[1], 0.0, 0.0);
    assert_close(xi[2], sqrt(0.6), 3e-16);
    assert_close(w[1], 8.0 / 9, 1e-15);
    assert_close(w[2], 5.0 / 9, 1e-15);
    gauss_legendre(5, xi, w);
    double dn = 0, dw = 0;
    dn = fmax(dn, fabs(xi[2]));
    dn = fmax(dn, fabs(xi[3] - sqrt(5 - 2 * sqrt(10.0 / 7)) / 3));
    dn = fmax(dn, fabs(xi[4] - sqrt(5 + 2 * sqrt(10.0 / 7)) / 3));
    dw = fmax(dw, fabs(w[2] - 128.0 / 225));
    dw = fmax(dw, fabs(w[3] - (322 + 13 * sqrt(70.0)) / 900));
    dw = fmax(dw, fabs(w[4] - (322 - 13 * sqrt(70.0)) / 900));
    assert_true(dn <= 4e-16 && dw <= 2e-15);
    printf("  Gauss-Legendre n = 1..%d: largest error on x^k, k <= 2n-1: "
           "%.1e; n = 5 against its closed form: nodes %.1e, weights %.1e\n",
           GAUSS_MAX, worst, dn, dw);
}

/* -- an uncut cell ------------------------------------------------------------ */

static void uncut_cell_has_tensor_points(void **state)
{
    (void)state;
    QuadPoint *q = malloc(NPTS * sizeof *q);
    const double x0 = 0.3, y0 = -0.2, x1 = 1.1, y1 = 0.7;
    /* a crack that passes by */
    static const double cx[2] = {-1, 2}, cy[2] = {1.5, 0.9};
    CrackLine c = {2, cx, cy, {0, 0}};
    double worst = 0;
    for (int n = 1; n <= GAUSS_MAX; n++) {
        assert_int_equal(quad_cell(NULL, 0, x0, y0, x1, y1, n, q, NPTS), n * n);
        assert_int_equal(quad_cell(&c, 1, x0, y0, x1, y1, n, q, NPTS), n * n);
        for (int a = 0; a <= 2 * n - 1; a++)
            for (int b = 0; b <= 2 * n - 1; b++) {
                double s = 0;
                for (int i = 0; i < n * n; i++)
                    s += q[i].w * pow(q[i].x, a) * pow(q[i].y, b);
                double exact = (pow(x1, a + 1) - pow(x0, a + 1)) / (a + 1) *
                               (pow(y1, b + 1) - pow(y0, b + 1)) / (b + 1);
                double err = fabs(s - exact) / fmax(fabs(exact), 1e-3);
                if (!(err <= 1e-13))
                    fail_msg("n = %d: x^%d y^%d: %.17g, expected %.17g", n, a,
                             b, s, exact);
                worst = fmax(worst, err);
            }
    }
    printf("  uncut cell, n = 1..%d: largest relative error on x^a y^b, "
           "a, b <= 2n-1: %.1e\n", GAUSS_MAX, worst);
    /* too little room: the count needed, nothing written past cap */
    q[5].w = -7;
    assert_int_equal(quad_cell(NULL, 0, x0, y0, x1, y1, 4, q, 5), 16);
    assert_close(q[5].w, -7, 0);
    assert_int_equal(quad_cell(&c, 1, x0, y0, x1, y1, 4, NULL, 0), 16);
    assert_int_equal(quad_cell(NULL, 0, x0, y0, x1, y1, 0, q, NPTS), -1);
    assert_int_equal(quad_cell(NULL, 0, x0, y0, x1, y1, GAUSS_MAX + 1, q, NPTS), -1);
    free(q);
}

/* -- a cell cut through by a straight crack ----------------------------------- */

/**
 * A crack through (px, py) along (dx, dy), long enough to cross the cell:
 * each side's area and first and product moments against the polygons
 * clipped by hand, for n = 2, 3, 5 and 10. The largest relative error.
 */
static double straight_cut(double x0, double y0, double x1, double y1,
                           double px, double py, double dx, double dy,
                           const char *what)
{
    double cx[2] = {px - 5 * dx, px + 5 * dx}, cy[2] = {py - 5 * dy, py + 5 * dy};
    CrackLine c = {2, cx, cy, {0, 0}};
    double rx[4], ry[4], ox[8], oy[8], want[2][4], cell[4], worst = 0;
    rect(x0, y0, x1, y1, rx, ry);
    poly_moments(rx, ry, 4, cell);
    const double a[2] = {cx[0], cy[0]}, b[2] = {cx[1], cy[1]};
    for (int s = 0; s < 2; s++) {
        int k = clip(rx, ry, 4, a, b, s ? 1 : -1, ox, oy);
        poly_moments(ox, oy, k, want[s]);
    }
    QuadPoint *q = malloc(NPTS * sizeof *q);
    static const int ns[4] = {2, 3, 5, 10};
    for (int i = 0; i < 4; i++) {
        double got[2][4];
        cell_points(&c, 1, x0, y0, x1, y1, ns[i], q, got);
        for (int s = 0; s < 2; s++) {
            if (want[s][0] == 0) {
                assert_close(got[s][0], 0.0, 0.0);
                continue;
            }
            worst = fmax(worst, check_moments(got[s], want[s], cell, 1e-13, what));
        }
    }
    free(q);
    return worst;
}

static void cut_cell_integrates_each_side_exactly(void **state)
{
    (void)state;
    const double x0 = 0.3, y0 = 0.2, x1 = 1.1, y1 = 0.9;
    double worst = 0;
    /* through an inner point at several angles */
    for (double ang = 0.1; ang < 6.3; ang += 0.6)
        worst = fmax(worst, straight_cut(x0, y0, x1, y1, 0.62, 0.47, cos(ang),
                                         sin(ang), "angle"));
    /* through a corner into the cell, and corner to corner */
    worst = fmax(worst, straight_cut(x0, y0, x1, y1, x0, y0, cos(0.5),
                                     sin(0.5), "through a corner"));
    worst = fmax(worst, straight_cut(x0, y0, x1, y1, x0, y0, x1 - x0, y1 - y0,
                                     "corner to corner"));
    worst = fmax(worst, straight_cut(x0, y0, x1, y1, x1, y0, -1.0, 0.3,
                                     "through the lower right corner"));
    /* along grid lines close to an edge, and through the middle */
    worst = fmax(worst, straight_cut(x0, y0, x1, y1, 0.7, y0 + 1e-3 * (y1 - y0),
                                     1.0, 0.0, "1e-3 above the bottom edge"));
    worst = fmax(worst, straight_cut(x0, y0, x1, y1, x1 - 1e-7, 0.5, 0.0,
                                     -1.0, "1e-7 left of the right edge"));
    worst = fmax(worst, straight_cut(x0, y0, x1, y1, 0.7, 0.55, 1.0, 0.0,
                                     "horizontal, the middle"));
    /* nearly along an edge, at a slant */
    worst = fmax(worst, straight_cut(x0, y0, x1, y1, 0.7, y1 - 1e-4, 1.0,
                                     1e-4, "slanting close to the top edge"));
    printf("  cut cells (straight crack, 18 lines, n = 2, 3, 5, 10): largest "
           "error of area, x, y, xy per side, relative to the cell's: %.1e\n",
           worst);

    /* a crack along an edge or touching a corner does not cut: the
     * tensor points, all on one side */
    QuadPoint *q = malloc(NPTS * sizeof *q);
    double m[2][4];
    static const double ex[2] = {-1, 2}, ey[2] = {0.2, 0.2};
    CrackLine e = {2, ex, ey, {0, 0}};
    assert_int_equal(cell_points(&e, 1, x0, y0, x1, y1, 4, q, m), 16);
    assert_close(m[1][0], (x1 - x0) * (y1 - y0), 1e-15);
    static const double tx[2] = {0.1, 0.5}, ty[2] = {0.4, 0.0};
    CrackLine t = {2, tx, ty, {0, 0}};
    assert_int_equal(cell_points(&t, 1, x0, y0, x1, y1, 4, q, m), 16);
    free(q);
}

/* -- a cell holding a tip --------------------------------------------------- */

/** int of r^-1/2 over [0, a] x [0, b], r from the corner at the origin: in
 *  polar coordinates, two smooth 1D integrals of (2/3) R(theta)^{3/2}. */
static double corner_rhalf(double a, double b)
{
    double xi[GAUSS_MAX], w[GAUSS_MAX], s = 0;
    gauss_legendre(GAUSS_MAX, xi, w);
    for (int half = 0; half < 2; half++) {
        double p = half ? b : a, t1 = half ? atan(a / b) : atan(b / a);
        const int m = 64;
        for (int k = 0; k < m; k++)
            for (int i = 0; i < GAUSS_MAX; i++) {
                double th = t1 * (k + 0.5 * (1 + xi[i])) / m;
                s += 0.5 * t1 / m * w[i] * (2.0 / 3) * pow(p / cos(th), 1.5);
            }
    }
    return s;
}

/** int of 1/r over [0, a] x [0, b], r from the corner at the origin (the
 *  size of a product of two gradients of eq. 5), in closed form. */
static double corner_rinv(double a, double b)
{
    double d = hypot(a, b);
    return a * log((b + d) / a) + b * log((a + d) / b);
}

/** int over the rectangle of one of the above, r from (tx, ty) on it. */
static double rect_int(double (*corner)(double, double), double x0, double y0,
                       double x1, double y1, double tx, double ty)
{
    double s = 0;
    if (x1 > tx && y1 > ty)
        s += corner(x1 - tx, y1 - ty);
    if (tx > x0 && y1 > ty)
        s += corner(tx - x0, y1 - ty);
    if (tx > x0 && ty > y0)
        s += corner(tx - x0, ty - y0);
    if (x1 > tx && ty > y0)
        s += corner(x1 - tx, ty - y0);
    return s;
}

/**
 * A cell holding the tip of @p c (end 1): the area exact, each side's area
 * that of the cell cut by the tip segment's line (straight crack), no point
 * near the tip, int r^-1/2 (one gradient of eq. 5) converging and int 1/r
 * (two) converging fast: with the fan from the tip, 1/r times the Duffy
 * Jacobian is smooth, r^-1/2 times it goes as sqrt(u). Prints the errors.
 */
static void tip_cell(const CrackLine *c, double x0, double y0, double x1,
                     double y1, const char *what)
{
    QuadPoint *q = malloc(NPTS * sizeof *q);
    double tip[2], dir[2];
    crack_line_tip(c, 1, tip, dir);
    double area = (x1 - x0) * (y1 - y0);
    double exact = rect_int(corner_rhalf, x0, y0, x1, y1, tip[0], tip[1]);
    double exact1 = rect_int(corner_rinv, x0, y0, x1, y1, tip[0], tip[1]);
    double rx[4], ry[4], ox[8], oy[8], want[2][4];
    rect(x0, y0, x1, y1, rx, ry);
    const double a[2] = {tip[0] - dir[0], tip[1] - dir[1]};
    for (int s = 0; s < 2; s++) {
        int k = clip(rx, ry, 4, a, tip, s ? 1 : -1, ox, oy);
        poly_moments(ox, oy, k, want[s]);
    }
    printf("  tip cell, %s: relative error of int r^-1/2 for n = 1..%d:\n   ",
           what, GAUSS_MAX);
    double err[GAUSS_MAX + 1], err1[GAUSS_MAX + 1], rmin = INFINITY;
    for (int n = 1; n <= GAUSS_MAX; n++) {
        double m[2][4];
        int np = cell_points(c, 1, x0, y0, x1, y1, n, q, m);
        assert_close(m[0][0] + m[1][0], area, 1e-14 * area);
        for (int s = 0; s < 2; s++)
            assert_close(m[s][0], want[s][0], 1e-13 * area);
        double sum = 0, sum1 = 0;
        for (int i = 0; i < np; i++) {
            double r = hypot(q[i].x - tip[0], q[i].y - tip[1]);
            rmin = fmin(rmin, r);
            sum += q[i].w / sqrt(r);
            sum1 += q[i].w / r;
        }
        err[n] = fabs(sum - exact) / exact;
        err1[n] = fabs(sum1 - exact1) / exact1;
        printf(" %.1e", err[n]);
    }
    printf("\n    and of int 1/r:");
    for (int n = 1; n <= GAUSS_MAX; n++)
        printf(" %.1e", err1[n]);
    /* the same integral with the cell's tensor points, crack ignored */
    double tens[3];
    for (int i = 0; i < 3; i++) {
        int n = (int[]){2, 5, 10}[i], np = quad_cell(NULL, 0, x0, y0, x1, y1, n,
                                                     q, NPTS);
        double sum = 0;
        for (int k = 0; k < np; k++)
            sum += q[k].w / sqrt(hypot(q[k].x - tip[0], q[k].y - tip[1]));
        tens[i] = fabs(sum - exact) / exact;
    }
    printf("\n    closest point to the tip: %.2e of the cell; tensor Gauss "
           "without the crack, n = 2, 5, 10: %.1e %.1e %.1e\n",
           rmin / sqrt(area), tens[0], tens[1], tens[2]);
    assert_true(rmin > 1e-12);
    assert_true(err[2] < 2e-2 && err[5] < 2e-3 && err[GAUSS_MAX] < 3e-4);
    assert_true(err[GAUSS_MAX] < err[2] / 20);
    assert_true(err1[GAUSS_MAX] < 1e-8);
    free(q);
}

static void tip_cell_points_avoid_the_tip(void **state)
{
    (void)state;
    /* a slanting crack whose tip lies inside the cell */
    static const double ax[2] = {-0.5, 0.55}, ay[2] = {0.1, 0.43};
    CrackLine a = {2, ax, ay, {0, 1}};
    tip_cell(&a, 0.0, 0.0, 1.0, 1.0, "slanting crack");
    /* grid-aligned: a tip at the cell's centre */
    static const double bx[2] = {-1.0, 0.5}, by[2] = {0.5, 0.5};
    CrackLine b = {2, bx, by, {0, 1}};
    tip_cell(&b, 0.0, 0.0, 1.0, 1.0, "tip at the centre");
    /* a tip on an edge, the crack along the cell's line */
    static const double cx[2] = {0.5, 0.5}, cy[2] = {-1.0, 0.0};
    CrackLine c = {2, cx, cy, {0, 1}};
    tip_cell(&c, 0.0, 0.0, 1.0, 1.0, "tip on the bottom edge");
    /* a tip at the cell's corner, the crack along its edge */
    static const double dx[2] = {-1.0, 0.0}, dy[2] = {0.0, 0.0};
    CrackLine d = {2, dx, dy, {0, 1}};
    tip_cell(&d, 0.0, 0.0, 1.0, 1.0, "tip at a corner, crack along an edge");
    /* a tip at the corner, the crack arriving along the diagonal */
    static const double ex[2] = {-1.0, 0.0}, ey[2] = {-1.0, 0.0};
    CrackLine e = {2, ex, ey, {0, 1}};
    tip_cell(&e, 0.0, 0.0, 1.0, 1.0, "tip at a corner, diagonal crack");
}

/* -- bent and crossing cracks -------------------------------------------------- */

static void bent_crack_areas_per_side(void **state)
{
    (void)state;
    QuadPoint *q = malloc(NPTS * sizeof *q);
    double worst = 0;
    /* a gentle bend at (0.4, 0.5), inside the unit cell */
    static const double ax[3] = {-0.5, 0.4, 1.5}, ay[3] = {0.3, 0.5, 0.2};
    double yl = 0.3 + 0.2 * 0.5 / 0.9, yr = 0.5 - 0.3 * 0.6 / 1.1;
    double px[5] = {0, 0.4, 1, 1, 0}, py[5] = {yl, 0.5, yr, 1, 1};
    double mx[5] = {0, 1, 1, 0.4, 0}, my[5] = {0, 0, yr, 0.5, yl};
    CrackLine a = {3, ax, ay, {0, 0}};
    double want[2][4], cell[4], ux[4], uy[4];
    rect(0, 0, 1, 1, ux, uy);
    poly_moments(ux, uy, 4, cell);
    poly_moments(mx, my, 5, want[0]);
    poly_moments(px, py, 5, want[1]);
    for (int n = 2; n <= GAUSS_MAX; n += 4) {
        double got[2][4];
        cell_points(&a, 1, 0, 0, 1, 1, n, q, got);
        for (int s = 0; s < 2; s++)
            worst = fmax(worst, check_moments(got[s], want[s], cell, 1e-13,
                                              "gentle bend"));
    }
    /* a sharp V pointing right, vertex at (0.8, 0.5): right of the vertex
     * the closest point of the crack is the vertex (the pseudo-normal) */
    static const double bx[3] = {-0.5, 0.8, -0.5}, by[3] = {0.2, 0.5, 0.8};
    CrackLine b = {3, bx, by, {0, 0}};
    double ya = 0.2 + 0.3 * 0.5 / 1.3, yb = 0.8 - 0.3 * 0.5 / 1.3;
    double vx[3] = {0, 0.8, 0}, vy[3] = {ya, 0.5, yb};
    double ox[7] = {0, 1, 1, 0, 0, 0.8, 0}, oy[7] = {0, 0, 1, 1, yb, 0.5, ya};
    poly_moments(vx, vy, 3, want[1]);   /* inside the V: left of the walk */
    poly_moments(ox, oy, 7, want[0]);
    for (int n = 2; n <= GAUSS_MAX; n += 4) {
        double got[2][4];
        cell_points(&b, 1, 0, 0, 1, 1, n, q, got);
        for (int s = 0; s < 2; s++)
            worst = fmax(worst, check_moments(got[s], want[s], cell, 1e-13,
                                              "sharp V"));
    }
    printf("  bent cracks, vertex inside the cell: largest error of area, x, "
           "y, xy per side, relative to the cell's: %.1e\n", worst);
    free(q);
}

static void crossing_and_grid_aligned_cracks(void **state)
{
    (void)state;
    QuadPoint *q = malloc(NPTS * sizeof *q);
    /* two cracks along the cell's middle lines: four quarters */
    static const double hx[2] = {-1, 2}, hy[2] = {0.5, 0.5};
    static const double vx[2] = {0.5, 0.5}, vy[2] = {2, -1};
    CrackLine two[2] = {{2, hx, hy, {0, 0}}, {2, vx, vy, {0, 0}}};
    int np = quad_cell(two, 2, 0, 0, 1, 1, 3, q, NPTS);
    double quarter[4] = {0};
    for (int i = 0; i < np; i++) {
        int s0 = crack_line_side(&two[0], q[i].x, q[i].y, NULL);
        int s1 = crack_line_side(&two[1], q[i].x, q[i].y, NULL);
        assert_true(s0 != 0 && s1 != 0);
        quarter[(s0 > 0) + 2 * (s1 > 0)] += q[i].w;
    }
    for (int k = 0; k < 4; k++)
        assert_close(quarter[k], 0.25, 1e-15);
    /* a crack whose vertex is the cell's corner, then along its diagonal */
    static const double dx[3] = {-1, 0, 2}, dy[3] = {-0.5, 0, 2};
    CrackLine d = {3, dx, dy, {0, 0}};
    double m[2][4];
    cell_points(&d, 1, 0, 0, 1, 1, 4, q, m);
    assert_close(m[0][0], 0.5, 1e-15);
    assert_close(m[1][0], 0.5, 1e-15);
    /* a crack ending exactly on the cell's edge (its tip there) and
     * crossing the next cell */
    static const double ex[2] = {0.3, 1.0}, ey[2] = {0.4, 0.4};
    CrackLine e = {2, ex, ey, {0, 1}};
    cell_points(&e, 1, 1, 0, 2, 1, 4, q, m);
    assert_close(m[0][0] + m[1][0], 1.0, 1e-15);
    assert_close(m[1][0], 0.6, 1e-14);
    /* far from the origin: a cell of 1e-2 at x = 1e5 */
    double X = 1e5, h = 1e-2;
    double fx[2] = {X - h, X + 2 * h}, fy[2] = {0.3 * h, 0.7 * h};
    CrackLine f = {2, fx, fy, {0, 0}};
    double x1 = X + h, wx = x1 - X;   /* the cell as the doubles have it */
    cell_points(&f, 1, X, 0, x1, h, 5, q, m);
    /* the exact part above, in coordinates from the cell's corner */
    double rx[4], ry[4], ox[8], oy[8], want[4];
    rect(0, 0, wx, h, rx, ry);
    const double a[2] = {fx[0] - X, fy[0]}, b[2] = {fx[1] - X, fy[1]};
    int k = clip(rx, ry, 4, a, b, 1, ox, oy);
    poly_moments(ox, oy, k, want);
    printf("  cell of 1e-2 at x = 1e5: relative area error above the crack "
           "%.1e, total %.1e\n", fabs(m[1][0] - want[0]) / want[0],
           fabs(m[0][0] + m[1][0] - wx * h) / (wx * h));
    assert_close(m[1][0], want[0], 1e-13 * want[0]);
    assert_close(m[0][0] + m[1][0], wx * h, 1e-14 * wx * h);
    free(q);
}

/* -- random cracks ----------------------------------------------------------- */

static void random_cracks_keep_the_area(void **state)
{
    (void)state;
    /* polylines of 2-4 points, one or two cracks, half of them on a grid of
     * 1/4 (points on the cell's edges and corners, segments along them),
     * tips at random ends: every point finite, inside, of positive weight,
     * and the weights sum to the cell's area */
    QuadPoint *q = malloc(NPTS * sizeof *q);
    srand(2024);
    double worst = 0;
    int most = 0;
    for (int it = 0; it < 20000; it++) {
        double xs[2][4], ys[2][4];
        CrackLine c[2];
        int nc = 1 + (it % 3 == 0);
        for (int k = 0; k < nc; k++) {
            int n = 2 + rand() % 3;
            for (int i = 0; i < n; i++) {
                double x = -1 + 3 * (rand() / (double)RAND_MAX);
                double y = -1 + 3 * (rand() / (double)RAND_MAX);
                xs[k][i] = it % 2 ? round(4 * x) / 4 : x;
                ys[k][i] = it % 2 ? round(4 * y) / 4 : y;
            }
            c[k] = (CrackLine){n, xs[k], ys[k], {rand() % 2, rand() % 2}};
        }
        int n = 1 + rand() % 6;
        int np = quad_cell(c, nc, 0, 0, 1, 1, n, q, NPTS);
        assert_true(np >= n * n && np <= NPTS);
        most = np > most ? np : most;
        double a = 0;
        for (int i = 0; i < np; i++) {
            assert_true(q[i].x > 0 && q[i].x < 1 && q[i].y > 0 && q[i].y < 1);
            assert_true(q[i].w > 0);
            a += q[i].w;
        }
        if (!(fabs(a - 1) <= 1e-13))
            fail_msg("case %d: the weights sum to %.17g", it, a);
        worst = fmax(worst, fabs(a - 1));
    }
    printf("  20000 random cracks: largest area error %.1e, most points %d\n",
           worst, most);
    free(q);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(gauss_legendre_is_exact_to_degree_2n_minus_1),
        cmocka_unit_test(uncut_cell_has_tensor_points),
        cmocka_unit_test(cut_cell_integrates_each_side_exactly),
        cmocka_unit_test(tip_cell_points_avoid_the_tip),
        cmocka_unit_test(bent_crack_areas_per_side),
        cmocka_unit_test(crossing_and_grid_aligned_cracks),
        cmocka_unit_test(random_cracks_keep_the_area),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
