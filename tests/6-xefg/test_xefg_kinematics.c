/**
 * @file test_xefg_kinematics.c
 * @brief The enriched approximation of eq. 1 on a real discretisation
 *        (xefg.md Test 2): a crack through the plate reproduces a jump plus
 *        a linear field exactly; the branch enrichment closes the crack at
 *        its tip with an opening that grows as r^m; and the Gauss
 *        quadrature of the weak form passes the integration-consistency
 *        check, with and without cut cells.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mls.h"
#include "quadrature.h"
#include "plate.h"
#include "testkit.h"
#include "xefg.h"

/** A cell list over the nodes, as xefg_build() makes one. */
static void nodes_cell_list(const Xefg *x, CellList *cl)
{
    double size = 0.0;
    for (int k = 0; k < x->nnode; k++)
        size = fmax(size, x->d[k]);
    assert_int_equal(cell_list_build(cl, x->nnode, x->X, x->Y, size), 0);
}

/** Component @p k of u(px, py) = sum psi_q u_q (eq. 1). */
static double field_at(const Xefg *x, const Sim *s, const CellList *cl,
                       const double *u, double px, double py, int k)
{
    ShapeRows R = {0};
    assert_int_equal(xefg_shape_row(x, cl, s->pts.body, 0, px, py, 0, &R), 0);
    double v = 0.0;
    for (int e = R.start[0]; e < R.start[1]; e++)
        v += R.N[e] * u[2 * R.dof[e] + k];
    shape_rows_free(&R);
    return v;
}

/** A small generator of uniform numbers in [0, 1). */
static double uniform(uint64_t *s)
{
    *s = *s * 6364136223846793005u + 1442695040888963407u;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/** Test 2a: with u_I = linear + c H(X_I) on unenriched nodes and a_I = c
 *  on step nodes, u = linear + c H everywhere off the crack. */
static void step_enrichment_reproduces_a_jump(void **state)
{
    (void)state;
    Sim *s = plate("cracks = ( { points = ( [0.1, 3.7], [6.0, 4.075], [11.9, 4.45] ); } );");
    Xefg *x = xefg_of(s);
    const CrackLine *c = &x->crack[0];
    const double jump = 0.37;
    assert_true(x->nstep > 0);
    assert_int_equal(x->nbranch, 0);
    double *u = calloc(2 * (size_t)x->ndof, sizeof(double));
    for (int q = 0; q < x->ndof; q++) {
        int I = x->dof_node[q];
        double lin = 0.1 + 0.02 * x->X[I] - 0.03 * x->Y[I];
        int has_step = x->node_dof[I + 1] - x->node_dof[I] > 1;
        if (x->dof_kind[q] == DOF_STANDARD)
            u[2 * q] = lin + (has_step ? 0.0 : jump * crack_line_side(c, x->X[I], x->Y[I], NULL));
        else
            u[2 * q] = jump;
    }
    CellList cl = {0};
    nodes_cell_list(x, &cl);
    uint64_t seed = 7;
    double worst = 0.0;
    for (int k = 0; k < 2000; k++) {
        double px = 1.0 + 10.0 * uniform(&seed), py = 1.0 + 6.0 * uniform(&seed), d;
        int side = crack_line_side(c, px, py, &d);
        if (d < 1e-6)
            continue;
        double want = 0.1 + 0.02 * px - 0.03 * py + jump * side;
        worst = fmax(worst, fabs(field_at(x, s, &cl, u, px, py, 0) - want));
    }
    printf("  linear field plus a jump of %g: largest error %.3g at 2000 points "
           "(%d step parameters)\n", jump, worst, x->nstep);
    assert_true(worst <= 1e-12);
    cell_list_free(&cl);
    free(u);
    tk_free(s);
}

/** Test 2b: branch parameters only, the opening behind the tip is 2 r^m
 *  sum Phi_I b_I: zero at the tip for any coefficients, slope m. */
static void branch_enrichment_closes_the_tip(void **state)
{
    (void)state;
    for (int m = 1; m <= 3; m++) {
        char extra[512];
        snprintf(extra, sizeof extra,
                 "xefg = { tip = \"cohesive\"; tip_exponent = %d; };\n"
                 "cracks = ( { points = ( [0.0, 4.2], [6.3, 4.2] ); } );", m);
        Sim *s = plate(extra);
        Xefg *x = xefg_of(s);
        assert_true(x->nbranch > 0);
        double *u = calloc(2 * (size_t)x->ndof, sizeof(double));
        CellList cl = {0};
        nodes_cell_list(x, &cl);
        uint64_t seed = 11;
        double tip_jump = 0.0;
        for (int trial = 0; trial < 20; trial++) {  /* any coefficients */
            for (int k = 0; k < 2 * x->ndof; k++)
                u[k] = uniform(&seed) - 0.5;
            double e = 1e-13;
            for (int k = 0; k < 2; k++)
                tip_jump = fmax(tip_jump, fabs(field_at(x, s, &cl, u, 6.3, 4.2 + e, k) -
                                               field_at(x, s, &cl, u, 6.3, 4.2 - e, k)));
        }
        for (int q = 0; q < x->ndof; q++)           /* b_I = 1, the rest 0 */
            u[2 * q + 1] = x->dof_kind[q] >= DOF_BRANCH ? 1.0 : 0.0;
        double r1 = 1e-3, r2 = 1e-2, e = 1e-9;
        double j1 = field_at(x, s, &cl, u, 6.3 - r1, 4.2 + e, 1) -
                    field_at(x, s, &cl, u, 6.3 - r1, 4.2 - e, 1);
        double j2 = field_at(x, s, &cl, u, 6.3 - r2, 4.2 + e, 1) -
                    field_at(x, s, &cl, u, 6.3 - r2, 4.2 - e, 1);
        double slope = log(fabs(j2 / j1)) / log(r2 / r1);
        printf("  m = %d: largest jump at the tip %.3g (20 random sets), opening "
               "%.4g at r = %g, %.4g at r = %g: slope %.4f\n", m, tip_jump, j1,
               r1, j2, r2, slope);
        assert_true(tip_jump <= 1e-12);
        assert_close(slope, (double)m, 0.05);
        cell_list_free(&cl);
        free(u);
        tk_free(s);
    }
}

/** max_I |int grad Phi_I . sigma0 - int_boundary Phi_I sigma0 . n| / (|sigma0| h)
 *  over the standard parameters (xefg.md pitfall 3), with n x n Gauss
 *  points per cell. */
static double consistency(int n, const char *crack)
{
    char extra[512];
    snprintf(extra, sizeof extra, "xefg = { gauss = %d; };\n%s", n, crack);
    Sim *s = plate(extra);
    Xefg *x = xefg_of(s);
    const double s0[3] = {0.8, -0.5, 0.33};
    double norm = sqrt(s0[0] * s0[0] + s0[1] * s0[1] + 2 * s0[2] * s0[2]);
    double *gs = malloc(3 * sizeof(double) * (size_t)x->ngauss);
    double *f = malloc(2 * sizeof(double) * (size_t)x->ndof);
    double *b = calloc(2 * (size_t)x->ndof, sizeof(double));
    for (int g = 0; g < x->ngauss; g++)
        memcpy(gs + 3 * g, s0, sizeof s0);
    xefg_internal_force(x, gs, f);              /* int B^T sigma0 */
    CellList cl = {0};
    nodes_cell_list(x, &cl);
    double xi[8], w[8];
    assert_int_equal(gauss_legendre(8, xi, w), 0);
    /* the plate's edges in pieces of a quarter spacing, outward normals */
    static const double edge[4][6] = {{1, 1, 11, 1, 0, -1}, {11, 1, 11, 7, 1, 0},
                                      {11, 7, 1, 7, 0, 1}, {1, 7, 1, 1, -1, 0}};
    for (int k = 0; k < 4; k++) {
        const double *E = edge[k];
        double len = hypot(E[2] - E[0], E[3] - E[1]);
        int pieces = (int)lround(4 * len);
        double tx = E[4] * s0[0] + E[5] * s0[2], ty = E[4] * s0[2] + E[5] * s0[1];
        for (int p = 0; p < pieces; p++)
            for (int g = 0; g < 8; g++) {
                double t = (p + 0.5 + 0.5 * xi[g]) / pieces;
                double px = E[0] + t * (E[2] - E[0]), py = E[1] + t * (E[3] - E[1]);
                double wt = 0.5 * w[g] * len / pieces;
                ShapeRows R = {0};
                assert_int_equal(xefg_shape_row(x, &cl, s->pts.body, 0, px, py, 0, &R), 0);
                for (int e = R.start[0]; e < R.start[1]; e++) {
                    b[2 * R.dof[e]] += wt * R.N[e] * tx;
                    b[2 * R.dof[e] + 1] += wt * R.N[e] * ty;
                }
                shape_rows_free(&R);
            }
    }
    double worst = 0.0;
    int at = 0;
    for (int I = 0; I < x->nnode; I++) {
        int q = x->node_dof[I];
        double r = hypot(f[2 * q] - b[2 * q], f[2 * q + 1] - b[2 * q + 1]);
        if (r > worst)
            worst = r, at = I;
    }
    (void)at;
    cell_list_free(&cl);
    free(gs), free(f), free(b);
    tk_free(s);
    return worst / norm;                       /* h = 1 */
}

/** The same residual in the layout of xefg.md's reference values: 11 x 11
 *  nodes on the corners of 10 x 10 cells of the unit square (h = 0.1),
 *  d/h = 2, n x n Gauss points per cell, cut by @p crack (NULL: none). */
static double consistency_on_corners(int n, const CrackLine *crack)
{
    enum { M = 11, NN = M * M };
    const double h = 0.1, s0[3] = {0.8, -0.5, 0.33};
    double X[NN], Y[NN], d[NN], phi[NN], px[NN], py[NN];
    double f[2 * NN] = {0}, b[2 * NN] = {0};
    for (int k = 0; k < NN; k++) {
        X[k] = h * (k % M);
        Y[k] = h * (k / M);
        d[k] = 2.0 * h;
    }
    QuadPoint q[4096];
    for (int c = 0; c < (M - 1) * (M - 1); c++) {
        double x0 = h * (c % (M - 1)), y0 = h * (c / (M - 1));
        int m = quad_cell(crack, crack ? 1 : 0, x0, y0, x0 + h, y0 + h, n, q, 4096);
        assert_true(m > 0 && m <= 4096);
        for (int g = 0; g < m; g++) {
            assert_int_equal(mls_shape(q[g].x, q[g].y, NN, X, Y, d, phi, px, py), 0);
            for (int k = 0; k < NN; k++) {
                f[2 * k] += q[g].w * (s0[0] * px[k] + s0[2] * py[k]);
                f[2 * k + 1] += q[g].w * (s0[2] * px[k] + s0[1] * py[k]);
            }
        }
    }
    double xi[8], w[8];
    assert_int_equal(gauss_legendre(8, xi, w), 0);
    static const double edge[4][6] = {{0, 0, 1, 0, 0, -1}, {1, 0, 1, 1, 1, 0},
                                      {1, 1, 0, 1, 0, 1}, {0, 1, 0, 0, -1, 0}};
    for (int e = 0; e < 4; e++) {
        const double *E = edge[e];
        double tx = E[4] * s0[0] + E[5] * s0[2], ty = E[4] * s0[2] + E[5] * s0[1];
        for (int p = 0; p < 40; p++)
            for (int g = 0; g < 8; g++) {
                double t = (p + 0.5 + 0.5 * xi[g]) / 40;
                assert_int_equal(mls_shape(E[0] + t * (E[2] - E[0]), E[1] + t * (E[3] - E[1]),
                                           NN, X, Y, d, phi, NULL, NULL), 0);
                for (int k = 0; k < NN; k++) {
                    b[2 * k] += 0.5 * w[g] / 40 * phi[k] * tx;
                    b[2 * k + 1] += 0.5 * w[g] / 40 * phi[k] * ty;
                }
            }
    }
    double worst = 0.0;
    for (int k = 0; k < NN; k++)
        worst = fmax(worst, hypot(f[2 * k] - b[2 * k], f[2 * k + 1] - b[2 * k + 1]));
    return worst / (sqrt(s0[0] * s0[0] + s0[1] * s0[1] + 2 * s0[2] * s0[2]) * h);
}

/** Test 2c: integration consistency. In the reference layout (nodes on
 *  the cells' corners, boundary nodes on the boundary) below 1e-4 with
 *  4 x 4 points, falling from 2 x 2 to 4 x 4 to 8 x 8, and below 1e-3 with
 *  cells cut by a crack (sub-triangulated); the same fall in the solver's
 *  own layout (a node in the middle of each cell). */
static void quadrature_is_consistent(void **state)
{
    (void)state;
    const double cx[3] = {-0.05, 0.5, 1.05}, cy[3] = {0.43, 0.5, 0.57};
    const CrackLine line = {3, cx, cy, {0, 0}};
    double k2 = consistency_on_corners(2, NULL), k4 = consistency_on_corners(4, NULL),
           k8 = consistency_on_corners(8, NULL);
    double l2 = consistency_on_corners(2, &line), l4 = consistency_on_corners(4, &line),
           l8 = consistency_on_corners(8, &line);
    printf("  reference layout, max |R_I| / (|sigma0| h), d/h = 2: %.3g (2x2) %.3g "
           "(4x4) %.3g (8x8) [xefg.md: 2.2e-3, 4.5e-5, 3.1e-6]; cut by a crack "
           "%.3g %.3g %.3g\n", k2, k4, k8, l2, l4, l8);
    assert_true(k4 <= 1e-4);
    assert_true(k8 < k4 && k4 < k2);
    assert_true(l4 <= 1e-3);
    assert_true(l8 < l4 && l4 < l2);
    const char *cut = "cracks = ( { points = ( [0.1, 3.7], [6.0, 4.075], [11.9, 4.45] ); } );";
    double r2 = consistency(2, ""), r4 = consistency(4, ""), r8 = consistency(8, "");
    double c2 = consistency(2, cut), c4 = consistency(4, cut), c8 = consistency(8, cut);
    printf("  the solver's layout (the scene's points), d/h = 2: uncut %.3g (2x2) "
           "%.3g (4x4) %.3g (8x8); cut by a crack %.3g %.3g %.3g\n", r2, r4, r8,
           c2, c4, c8);
    assert_true(r8 < r4 && r4 < r2);
    assert_true(c8 < c4 && c4 < c2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(step_enrichment_reproduces_a_jump),
        cmocka_unit_test(branch_enrichment_closes_the_tip),
        cmocka_unit_test(quadrature_is_consistent),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
