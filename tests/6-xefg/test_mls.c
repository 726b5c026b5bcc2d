/**
 * @file test_mls.c
 * @brief The meshfree shape functions (xefg.md section 5, Test 1): the cubic
 *        spline, MLS partition of unity and linear reproduction with their
 *        gradients on a perturbed grid, the same far from the origin and at
 *        other length scales, the refusal of too few or collinear nodes,
 *        and the cell list against an all-pairs search.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cell_list.h"
#include "mls.h"
#include "spline.h"
#include "testkit.h"

#define SIDE 21                 /* nodes per side of the grid */
#define NNODE (SIDE * SIDE)
#define MAXNB 128               /* room for the neighbours of one point */
#define NPOINT 1000             /* random evaluation points */

/** A perturbed grid of side L: h = L/20, nodes moved by up to 0.3 h. */
typedef struct Cloud {
    double X[NNODE], Y[NNODE], d[NNODE];
    double L, h;
} Cloud;

/* The tests' own random numbers (a 64-bit LCG, top 53 bits), the same on
 * every platform, unlike rand(). */
static double uniform(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* Perturbed 21 x 21 grid on [0, L]^2 (+-0.3 h), support radius 2 h. */
static void make_cloud(Cloud *c, double L, unsigned long long seed)
{
    c->L = L;
    c->h = L / (SIDE - 1);
    for (int j = 0; j < SIDE; j++)
        for (int i = 0; i < SIDE; i++) {
            int k = i + SIDE * j;
            c->X[k] = (i + 0.6 * (uniform(&seed) - 0.5)) * c->h;
            c->Y[k] = (j + 0.6 * (uniform(&seed) - 0.5)) * c->h;
            c->d[k] = 2.0 * c->h;
        }
}

/* All nodes k with |x - X_k| < d_k + slack, by trying every node, in
 * increasing order. */
static int brute_neighbours(const Cloud *c, double x, double y, double slack,
                            int *out, int cap)
{
    int n = 0;
    for (int k = 0; k < NNODE; k++) {
        double rx = x - c->X[k], ry = y - c->Y[k], r = c->d[k] + slack;
        if (rx * rx + ry * ry < r * r) {
            assert_true(n < cap);
            out[n++] = k;
        }
    }
    return n;
}

/* Gather the coordinates and radii of the listed nodes. */
static void gather(const Cloud *c, int n, const int *nb, double *X, double *Y,
                   double *d)
{
    for (int a = 0; a < n; a++) {
        X[a] = c->X[nb[a]];
        Y[a] = c->Y[nb[a]];
        d[a] = c->d[nb[a]];
    }
}

/* ---- the cubic spline --------------------------------------------------- */

static void spline_values_and_smoothness(void **state)
{
    (void)state;
    double w1, w2;
    assert_close(spline_weight(0.0, &w1, &w2), 2.0 / 3.0, 1e-15);
    assert_close(w1, 0.0, 1e-15);
    assert_close(spline_weight(0.5, &w1, &w2), 1.0 / 6.0, 1e-15);
    assert_close(w1, -1.0, 1e-15);
    assert_close(w2, 4.0, 1e-15);
    assert_close(spline_weight(1.0, &w1, &w2), 0.0, 1e-15);
    assert_close(w1, 0.0, 1e-15);
    assert_close(w2, 0.0, 1e-15);

    /* C2 where the pieces meet: q = 1/2 and q = 1 from the left (the first
     * piece at 1/2 itself, the second just below 1) and from the right */
    static const double knot[2] = {0.5, 1.0};
    double worst = 0.0;
    for (int i = 0; i < 2; i++) {
        double l1, l2, r1, r2;
        double ql = i == 0 ? knot[i] : nextafter(knot[i], 0.0);
        double qr = i == 0 ? nextafter(knot[i], 2.0) : knot[i];
        double l0 = spline_weight(ql, &l1, &l2);
        double r0 = spline_weight(qr, &r1, &r2);
        assert_close(l0, r0, 1e-14);
        assert_close(l1, r1, 1e-14);
        assert_close(l2, r2, 1e-14);
        worst = fmax(worst, fmax(fabs(l0 - r0), fmax(fabs(l1 - r1), fabs(l2 - r2))));
    }
    printf("  spline: largest one-sided jump of w, w', w'' at q = 1/2, 1: %.3g\n", worst);

    /* the derivatives are those of w (central differences), w >= 0, and
     * w = 0 outside the support */
    double fd_err = 0.0;
    for (double q = 0.01; q < 1.2; q += 0.0137) {
        const double e = 1e-6;
        double d1, d2, dm, dp;
        double w = spline_weight(q, &d1, &d2);
        double wm = spline_weight(q - e, &dm, NULL);
        double wp = spline_weight(q + e, &dp, NULL);
        assert_true(w >= 0.0);
        if (q >= 1.0)
            assert_true(w == 0.0 && d1 == 0.0 && d2 == 0.0);
        fd_err = fmax(fd_err, fabs((wp - wm) / (2 * e) - d1));
        fd_err = fmax(fd_err, fabs((dp - dm) / (2 * e) - d2));
    }
    printf("  spline: largest |w' - dw/dq|, |w'' - dw'/dq| (differences): %.3g\n", fd_err);
    assert_true(fd_err <= 1e-7);
    /* without derivatives wanted */
    assert_close(spline_weight(0.25, NULL, NULL), 2.0 / 3.0 - 0.25 + 0.0625, 1e-15);
}

/* ---- MLS on the perturbed grid ------------------------------------------ */

/** Largest errors over the evaluation points (Test 1). */
typedef struct Errors {
    double unity, linear, grad_sum, grad_linear;
} Errors;

/* The reproduction errors of one point, fed with every node within d + h,
 * so that nodes outside their support (Phi = 0) are passed as well. */
static void check_reproduction(const Cloud *c, double x, double y, Errors *e)
{
    int nb[MAXNB];
    double X[MAXNB], Y[MAXNB], d[MAXNB], phi[MAXNB], gx[MAXNB], gy[MAXNB];
    int n = brute_neighbours(c, x, y, c->h, nb, MAXNB);
    gather(c, n, nb, X, Y, d);
    assert_int_equal(mls_shape(x, y, n, X, Y, d, phi, gx, gy), 0);
    double s = 0, sx = 0, sy = 0, gsx = 0, gsy = 0;
    double mxx = 0, mxy = 0, myx = 0, myy = 0;  /* sum X_I (x) grad Phi_I */
    for (int a = 0; a < n; a++) {
        double rx = x - X[a], ry = y - Y[a];
        if (!(rx * rx + ry * ry < d[a] * d[a]))
            assert_true(phi[a] == 0.0 && gx[a] == 0.0 && gy[a] == 0.0);
        s += phi[a];
        sx += phi[a] * X[a];
        sy += phi[a] * Y[a];
        gsx += gx[a];
        gsy += gy[a];
        mxx += X[a] * gx[a];
        mxy += X[a] * gy[a];
        myx += Y[a] * gx[a];
        myy += Y[a] * gy[a];
    }
    e->unity = fmax(e->unity, fabs(s - 1.0));
    e->linear = fmax(e->linear, fmax(fabs(sx - x), fabs(sy - y)) / c->L);
    e->grad_sum = fmax(e->grad_sum, fmax(fabs(gsx), fabs(gsy)) * c->h);
    e->grad_linear = fmax(e->grad_linear, fmax(fmax(fabs(mxx - 1.0), fabs(myy - 1.0)),
                                               fmax(fabs(mxy), fabs(myx))));
}

static void mls_reproduces_linear_fields(void **state)
{
    (void)state;
    Cloud c;
    make_cloud(&c, 1.0, 2024);
    unsigned long long seed = 7;
    Errors e = {0};
    for (int p = 0; p < NPOINT; p++) {
        double x = c.L * uniform(&seed), y = c.L * uniform(&seed);
        check_reproduction(&c, x, y, &e);
    }
    printf("  MLS, %d points: |sum Phi - 1| %.3g, |sum Phi X - x|/L %.3g, "
           "|sum grad Phi| h %.3g, |sum X (x) grad Phi - I| %.3g\n",
           NPOINT, e.unity, e.linear, e.grad_sum, e.grad_linear);
    assert_true(e.unity <= 1e-12);
    assert_true(e.linear <= 1e-12);
    assert_true(e.grad_sum <= 1e-10);
    assert_true(e.grad_linear <= 1e-10);
}

/* The gradients against central differences of Phi (step 1e-6 h), at the
 * points of the reproduction test; the error of a point is relative to its
 * largest gradient. */
static double gradient_error(const Cloud *c, int npoint, unsigned long long seed)
{
    double worst = 0.0;
    for (int p = 0; p < npoint; p++) {
        double x = c->L * uniform(&seed), y = c->L * uniform(&seed);
        const double e = 1e-6 * c->h;
        int nb[MAXNB];
        double X[MAXNB], Y[MAXNB], d[MAXNB], phi[MAXNB], gx[MAXNB], gy[MAXNB];
        double pxm[MAXNB], pxp[MAXNB], pym[MAXNB], pyp[MAXNB];
        /* the same nodes at all five points: those within d + h/100 */
        int n = brute_neighbours(c, x, y, 0.01 * c->h, nb, MAXNB);
        gather(c, n, nb, X, Y, d);
        assert_int_equal(mls_shape(x, y, n, X, Y, d, phi, gx, gy), 0);
        assert_int_equal(mls_shape(x - e, y, n, X, Y, d, pxm, NULL, NULL), 0);
        assert_int_equal(mls_shape(x + e, y, n, X, Y, d, pxp, NULL, NULL), 0);
        assert_int_equal(mls_shape(x, y - e, n, X, Y, d, pym, NULL, NULL), 0);
        assert_int_equal(mls_shape(x, y + e, n, X, Y, d, pyp, NULL, NULL), 0);
        double gmax = 0.0, err = 0.0;
        for (int a = 0; a < n; a++) {
            gmax = fmax(gmax, fmax(fabs(gx[a]), fabs(gy[a])));
            err = fmax(err, fabs((pxp[a] - pxm[a]) / (2 * e) - gx[a]));
            err = fmax(err, fabs((pyp[a] - pym[a]) / (2 * e) - gy[a]));
        }
        assert_true(gmax > 0.0);
        worst = fmax(worst, err / gmax);
    }
    return worst;
}

static void mls_gradient_matches_differences(void **state)
{
    (void)state;
    Cloud c;
    make_cloud(&c, 1.0, 2024);
    double err = gradient_error(&c, NPOINT, 7);
    /* radii that differ from node to node (2 h to 2.6 h), so that the scale
     * (the largest radius) is not every node's */
    unsigned long long seed = 99;
    for (int k = 0; k < NNODE; k++)
        c.d[k] = (2.0 + 0.6 * uniform(&seed)) * c.h;
    double err_var = gradient_error(&c, NPOINT, 8);
    printf("  MLS gradient vs central differences, relative: %.3g (d = 2h), "
           "%.3g (d = 2h..2.6h)\n", err, err_var);
    assert_true(err <= 1e-6);
    assert_true(err_var <= 1e-6);
    /* and the reproduction with those radii */
    Errors e = {0};
    for (int p = 0; p < NPOINT; p++) {
        double x = c.L * uniform(&seed), y = c.L * uniform(&seed);
        check_reproduction(&c, x, y, &e);
    }
    assert_true(e.unity <= 1e-12 && e.linear <= 1e-12);
    assert_true(e.grad_sum <= 1e-10 && e.grad_linear <= 1e-10);
}

/* Phi and its gradient of the same points for two clouds, the second one
 * the first moved by (T, T) and stretched by f (X' = f X + T): the largest
 * |Phi' - Phi| and |grad Phi' f - grad Phi| h. */
static void compare_moved(const Cloud *a, const Cloud *b, double T, double f,
                          double *dphi, double *dgrad)
{
    unsigned long long seed = 11;
    *dphi = *dgrad = 0.0;
    for (int p = 0; p < NPOINT; p++) {
        double x = a->L * uniform(&seed), y = a->L * uniform(&seed);
        double xb = f * x + T, yb = f * y + T;
        if (T != 0.0) {
            /* the points as moved: x = (x + T) - T is exact (Sterbenz) */
            x = xb - T;
            y = yb - T;
        }
        int nb[MAXNB];
        double X[MAXNB], Y[MAXNB], d[MAXNB], phi[MAXNB], gx[MAXNB], gy[MAXNB];
        double Xb[MAXNB], Yb[MAXNB], db[MAXNB], phib[MAXNB], gxb[MAXNB], gyb[MAXNB];
        int n = brute_neighbours(a, x, y, 0.0, nb, MAXNB);
        gather(a, n, nb, X, Y, d);
        gather(b, n, nb, Xb, Yb, db);
        assert_int_equal(mls_shape(x, y, n, X, Y, d, phi, gx, gy), 0);
        assert_int_equal(mls_shape(xb, yb, n, Xb, Yb, db, phib, gxb, gyb), 0);
        for (int k = 0; k < n; k++) {
            *dphi = fmax(*dphi, fabs(phib[k] - phi[k]));
            *dgrad = fmax(*dgrad, fabs(gxb[k] * f - gx[k]) * a->h);
            *dgrad = fmax(*dgrad, fabs(gyb[k] * f - gy[k]) * a->h);
        }
    }
}

/* xefg.md pitfall 1: the cloud 1e5 L from the origin gives the same Phi. The
 * cloud is moved exactly (X = (X + T) - T), so that what is measured is the
 * method, not the rounding of the moved coordinates (that alone would change
 * Phi by about 1e-10). */
static void mls_far_from_origin(void **state)
{
    (void)state;
    Cloud a, b;
    make_cloud(&a, 1.0, 2024);
    const double T = 1e5 * a.L;
    b = a;
    for (int k = 0; k < NNODE; k++) {
        b.X[k] = a.X[k] + T;
        b.Y[k] = a.Y[k] + T;
        a.X[k] = b.X[k] - T;
        a.Y[k] = b.Y[k] - T;
    }
    double dphi, dgrad;
    compare_moved(&a, &b, T, 1.0, &dphi, &dgrad);
    printf("  MLS moved by 1e5 L: largest |Phi' - Phi| %.3g, |grad Phi' - grad Phi| h %.3g\n",
           dphi, dgrad);
    assert_true(dphi <= 1e-10);
    assert_true(dgrad <= 1e-10);
}

/* The basis is scaled by the support radius: the same cloud at lengths
 * 2^-20 and 2^20 (about 1e-6 and 1e6; powers of two, so exact) gives the
 * same Phi and gradients times the scale. */
static void mls_any_length_scale(void **state)
{
    (void)state;
    Cloud a, b;
    make_cloud(&a, 1.0, 2024);
    static const double f[2] = {0x1p-20, 0x1p20};
    for (int i = 0; i < 2; i++) {
        b = a;
        b.L *= f[i];
        b.h *= f[i];
        for (int k = 0; k < NNODE; k++) {
            b.X[k] *= f[i];
            b.Y[k] *= f[i];
            b.d[k] *= f[i];
        }
        double dphi, dgrad;
        compare_moved(&a, &b, 0.0, f[i], &dphi, &dgrad);
        printf("  MLS scaled by %g: largest |Phi' - Phi| %.3g, |grad Phi' f - grad Phi| h %.3g\n",
               f[i], dphi, dgrad);
        assert_true(dphi <= 1e-12);
        assert_true(dgrad <= 1e-10);
    }
}

/* Three nodes off one line: the linear basis interpolates, so Phi are the
 * barycentric coordinates of the triangle and their gradients constant. */
static void mls_three_nodes_interpolate(void **state)
{
    (void)state;
    const double X[3] = {0.1, 1.3, 0.4}, Y[3] = {0.2, 0.5, 1.4};
    const double d[3] = {3.0, 3.0, 3.0};
    const double x = 0.5, y = 0.6;
    double phi[3], gx[3], gy[3];
    assert_int_equal(mls_shape(x, y, 3, X, Y, d, phi, gx, gy), 0);
    double area2 = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
    for (int a = 0; a < 3; a++) {
        int b = (a + 1) % 3, c = (a + 2) % 3;
        /* lambda_a = twice the area of (x, b, c) over twice the area of (a, b, c) */
        double lam = ((X[b] - x) * (Y[c] - y) - (X[c] - x) * (Y[b] - y)) / area2;
        assert_close(phi[a], lam, 1e-14);
        assert_close(gx[a], (Y[b] - Y[c]) / area2, 1e-13);
        assert_close(gy[a], (X[c] - X[b]) / area2, 1e-13);
    }
}

/* Fewer than three nodes with w > 0, or nodes on one line: refused. */
static void mls_refuses_too_few_or_collinear(void **state)
{
    (void)state;
    double phi[8], gx[8], gy[8];
    const double d[8] = {1.5, 1.5, 1.5, 1.5, 1.5, 1.5, 1.5, 1.5};
    /* none */
    assert_int_equal(mls_shape(0.0, 0.0, 0, NULL, NULL, NULL, phi, gx, gy), -1);
    /* two in reach, the third beyond its support (w(1) = 0 too) */
    const double X2[3] = {0.0, 1.0, 1.5}, Y2[3] = {0.0, 0.0, 1.5};
    assert_int_equal(mls_shape(0.5, 0.0, 3, X2, Y2, d, phi, gx, gy), -1);
    assert_int_equal(mls_shape(0.5, 0.0, 3, X2, Y2, d, phi, NULL, NULL), -1);
    /* the third exactly at distance d: w(1) = 0, it does not count */
    const double X3[3] = {0.0, 1.0, 0.0}, Y3[3] = {0.0, 0.0, 1.5};
    assert_int_equal(mls_shape(0.0, 0.0, 3, X3, Y3, d, phi, NULL, NULL), -1);
    /* four on the x axis, the point off it */
    const double X4[4] = {0.0, 0.3, 0.7, 1.0}, Y4[4] = {0.0, 0.0, 0.0, 0.0};
    assert_int_equal(mls_shape(0.5, 0.2, 4, X4, Y4, d, phi, gx, gy), -1);
    /* five on a slanted line, whose coordinates round: A is singular only
     * to rounding, and the condition check refuses it */
    double X5[5], Y5[5];
    for (int k = 0; k < 5; k++) {
        X5[k] = 0.1 + 0.21 * k;
        Y5[k] = 0.3 + 0.21 * k * 0.7;
    }
    assert_int_equal(mls_shape(0.5, 0.5, 5, X5, Y5, d, phi, gx, gy), -1);
    /* one node moved off that line: accepted */
    Y5[2] += 0.1;
    assert_int_equal(mls_shape(0.5, 0.5, 5, X5, Y5, d, phi, gx, gy), 0);
}

/* ---- the cell list ------------------------------------------------------ */

static void cell_list_matches_all_pairs(void **state)
{
    (void)state;
    Cloud c;
    make_cloud(&c, 1.0, 31);
    unsigned long long seed = 5;
    double size = 0.0;
    for (int k = 0; k < NNODE; k++) {
        c.d[k] = (1.5 + 0.5 * uniform(&seed)) * c.h;
        size = fmax(size, c.d[k]);
    }
    CellList cl;
    assert_int_equal(cell_list_build(&cl, NNODE, c.X, c.Y, size), 0);
    int most = 0, nquery = 0;
    for (int p = 0; p < 3000 + NNODE; p++) {
        double x, y;
        if (p < 3000) {  /* random points, some outside the cloud */
            x = -0.2 + 1.4 * uniform(&seed);
            y = -0.2 + 1.4 * uniform(&seed);
        } else {         /* on the nodes themselves */
            x = c.X[p - 3000];
            y = c.Y[p - 3000];
        }
        int a[MAXNB], b[MAXNB];
        int na = cell_list_find(&cl, c.X, c.Y, c.d, x, y, a, MAXNB);
        int nb = brute_neighbours(&c, x, y, 0.0, b, MAXNB);
        assert_int_equal(na, nb);
        for (int i = 0; i < na; i++)
            assert_int_equal(a[i], b[i]);   /* same nodes, increasing */
        most = na > most ? na : most;
        nquery++;
    }
    printf("  cell list: %d cells of %d x %d, %d queries agree with all pairs, "
           "at most %d neighbours\n", cl.nx * cl.ny, cl.nx, cl.ny, nquery, most);
    /* far away, and not a number: nothing */
    int out[4];
    assert_int_equal(cell_list_find(&cl, c.X, c.Y, c.d, 1e300, -1e300, out, 4), 0);
    assert_int_equal(cell_list_find(&cl, c.X, c.Y, c.d, NAN, 0.5, out, 4), 0);
    cell_list_free(&cl);
    assert_null(cl.start);

    /* a node exactly d away is not a neighbour (w(1) = 0); the distances
     * here are exact in binary */
    {
        const double X[4] = {0.0, 1.0, 0.0, 1.0}, Y[4] = {0.0, 0.0, 1.0, 1.0};
        const double dd[4] = {0.5, 0.5, 0.5, 0.5};
        assert_int_equal(cell_list_build(&cl, 4, X, Y, 0.5), 0);
        assert_int_equal(cell_list_find(&cl, X, Y, dd, 0.5, 0.0, out, 4), 0);
        assert_int_equal(cell_list_find(&cl, X, Y, dd, 1.0, 0.5, out, 4), 0);
        assert_int_equal(cell_list_find(&cl, X, Y, dd, 0.75, 1.0, out, 4), 1);
        assert_int_equal(out[0], 3);
        cell_list_free(&cl);
    }

    /* no nodes; a cell size that is not positive */
    assert_int_equal(cell_list_build(&cl, 0, c.X, c.Y, size), 0);
    assert_int_equal(cell_list_find(&cl, c.X, c.Y, c.d, 0.5, 0.5, out, 4), 0);
    cell_list_free(&cl);
    assert_int_equal(cell_list_build(&cl, NNODE, c.X, c.Y, 0.0), -1);
    cell_list_free(&cl);
}

/* With room for fewer nodes than there are, find says how many there are
 * and writes the first of them, in increasing order, and nothing beyond. */
static void cell_list_reports_count_beyond_cap(void **state)
{
    (void)state;
    Cloud c;
    make_cloud(&c, 1.0, 31);
    CellList cl;
    assert_int_equal(cell_list_build(&cl, NNODE, c.X, c.Y, 2.0 * c.h), 0);
    int all[MAXNB], out[MAXNB];
    int n = brute_neighbours(&c, 0.5, 0.5, 0.0, all, MAXNB);
    assert_true(n > 5);
    for (int cap = 0; cap <= n; cap++) {
        for (int i = 0; i < MAXNB; i++)
            out[i] = -7;
        assert_int_equal(cell_list_find(&cl, c.X, c.Y, c.d, 0.5, 0.5, out, cap), n);
        for (int i = 0; i < cap; i++)
            assert_int_equal(out[i], all[i]);
        assert_int_equal(out[cap], -7);
    }
    printf("  cell list: %d neighbours at the centre, reported for every cap 0..%d\n", n, n);
    cell_list_free(&cl);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(spline_values_and_smoothness),
        cmocka_unit_test(mls_reproduces_linear_fields),
        cmocka_unit_test(mls_gradient_matches_differences),
        cmocka_unit_test(mls_far_from_origin),
        cmocka_unit_test(mls_any_length_scale),
        cmocka_unit_test(mls_three_nodes_interpolate),
        cmocka_unit_test(mls_refuses_too_few_or_collinear),
        cmocka_unit_test(cell_list_matches_all_pairs),
        cmocka_unit_test(cell_list_reports_count_beyond_cap),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
