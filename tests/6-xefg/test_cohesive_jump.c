/**
 * @file test_cohesive_jump.c
 * @brief The cohesive points of an edge crack with a tip inside the plate
 *        (cohesive_points.c): their weights add up to the crack's length
 *        inside the body times the thickness, and the opening their jump
 *        rows give, [[u]] = sum Phi_I [[E_q]] u_q, is the difference of
 *        the displacement just either side of the crack, for step and
 *        branch parameters (eq. 6 and eq. 5).
 *
 * Bounds, fixed before the first run:
 * - sum of the weights = 4.3 mm x 2 mm thickness to 1e-12 relative;
 * - for random parameters, |[[u]] - (u(x + e n) - u(x - e n))| <= 1e-6 of
 *   the largest |[[u]]|, with e = 1e-8 h, at every point;
 * - the opening at the point nearest the tip is below 0.2 of the largest
 *   (the branch function closes the crack at its tip, xefg.md 2.2).
 */
#include <stdio.h>
#include <stdlib.h>

#include "cell_list.h"
#include "cohesive.h"
#include "testkit.h"

/** The plate with an edge crack from outside (x = 0.5) to a tip at
 *  x = 6.3, on the line y = 5.2; tip functions @p tip. */
static Sim *cracked_plate(const char *tip)
{
    char text[2048];
    snprintf(text, sizeof text,
             "grid = { origin = [0.0, 0.0]; cells = [14, 10]; cell_size = [1.0, 1.0]; };\n"
             "run = { time = 0.01; method = \"xefg\"; snapshots = 0; };\n"
             "xefg = { tip = \"%s\"; };\n"
             "materials = ( { name = \"m\"; E = 1000.0; nu = 0.3; rho = 1e-3; } );\n"
             "bodies = ( { name = \"plate\"; material = \"m\"; points_per_cell = 2;\n"
             "             thickness = 2.0;\n"
             "             rectangle = { min = [2.0, 1.0]; max = [12.0, 9.0]; }; } );\n"
             "cracks = ( { points = ( [0.5, 5.2], [3.0, 5.2], [6.3, 5.2] );\n"
             "             cohesive = { f_t = 1.0; G_f = 0.05; }; } );\n", tip);
    return tk_load(text);
}

/** u at (px, py) of the parameters @p u, from a fresh row. */
static void u_at(const Xefg *x, const Sim *s, const CellList *cl, double px,
                 double py, const double *u, double out[2])
{
    ShapeRows R = {0};
    assert_int_equal(xefg_shape_row(x, cl, s->pts.body, 0, px, py, 0, &R), 0);
    out[0] = out[1] = 0.0;
    for (int e = 0; e < R.len; e++) {
        out[0] += R.N[e] * u[2 * R.dof[e]];
        out[1] += R.N[e] * u[2 * R.dof[e] + 1];
    }
    shape_rows_free(&R);
}

static void jump_rows_are_the_jump(const char *tip)
{
    Sim *s = cracked_plate(tip);
    const Xefg *x = xefg_of(s);
    const Cohesive *c = x->coh;
    assert_non_null(c);
    double size = 0.0, len = 0.0;
    for (int I = 0; I < x->nnode; I++)
        size = fmax(size, x->d[I]);
    CellList cl = {0};
    assert_int_equal(cell_list_build(&cl, x->nnode, x->X, x->Y, size), 0);
    double *u = malloc(2 * sizeof(double) * (size_t)x->ndof);
    assert_non_null(u);
    uint64_t r = 99u;
    for (int k = 0; k < 2 * x->ndof; k++) {
        r = r * 6364136223846793005u + 1442695040888963407u;
        u[k] = (double)(r >> 11) / 9007199254740992.0 - 0.5;
    }
    double eps = 1e-8 * 0.5, big = 0.0, worst = 0.0, near = 0.0, dtip = 1e300;
    for (int p = 0; p < c->npt; p++) {
        len += c->w[p];
        double jx = 0.0, jy = 0.0;
        for (int e = c->jump.start[p]; e < c->jump.start[p + 1]; e++) {
            jx += c->jump.N[e] * u[2 * c->jump.dof[e]];
            jy += c->jump.N[e] * u[2 * c->jump.dof[e] + 1];
        }
        double nx = -c->ty[p], ny = c->tx[p], up[2], um[2];
        u_at(x, s, &cl, c->px[p] + eps * nx, c->py[p] + eps * ny, u, up);
        u_at(x, s, &cl, c->px[p] - eps * nx, c->py[p] - eps * ny, u, um);
        double j = hypot(jx, jy);
        big = fmax(big, j);
        worst = fmax(worst, hypot(jx - (up[0] - um[0]), jy - (up[1] - um[1])));
        if (6.3 - c->px[p] < dtip)
            dtip = 6.3 - c->px[p], near = j;
    }
    printf("  tip \"%s\": %d points, length x thickness %.15g mm^2 (8.6); "
           "largest |[[u]]| %.4g, largest difference from u(+) - u(-) %.3g "
           "(%.2e of it); at %.4g mm from the tip |[[u]]| = %.3g (%.3f of the "
           "largest)\n", tip, c->npt, len, big, worst, worst / big, dtip, near,
           near / big);
    assert_close(len, 4.3 * 2.0, 1e-12 * 8.6);
    assert_true(worst <= 1e-6 * big);
    assert_true(near <= 0.2 * big);
    free(u);
    cell_list_free(&cl);
    tk_free(s);
}

static void cohesive_tip(void **state)
{
    (void)state;
    jump_rows_are_the_jump("cohesive");
}

static void lefm_tip(void **state)
{
    (void)state;
    jump_rows_are_the_jump("lefm");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(cohesive_tip),
        cmocka_unit_test(lefm_tip),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
