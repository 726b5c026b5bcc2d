/**
 * @file test_cpdi.c
 * @brief CPDI1 (Sadeghirad, Brannon & Burghardt 2011) at random
 *        parallelogram domains: partition of unity, linear reproduction,
 *        the linear functions back inside one cell; and the stop of a run
 *        whose domain grows wider than a cell.
 *
 * Domains are drawn as F times a square of half side l (l in [0.05, 0.25]
 * cells), F a random rotation times a stretch in [0.6, 1.6] along two
 * axes, kept when the domain is narrower than a cell and inside the grid;
 * half of them are centred within l of a cell edge. Bounds, fixed before
 * the first run:
 * - sum_i S_ip = 1 to 1e-14, sum_i G_ip = 0 to 1e-12 per cell (a G is a
 *   difference of corner values over the domain's width, up to about
 *   1 / (0.6 l) = 33 per cell);
 * - sum_i S_ip x_i = x_p to 1e-12 cells and sum_i G_ip x_i^T = I to 1e-12:
 *   corners interpolate a linear field exactly, and the closed integral of
 *   x n ds over a polygon is its area times I;
 * - a square domain inside one cell gives the bilinear weights and
 *   gradients of the point (shape_linear()) to 1e-14. The first run
 *   failed this at 4.1e-14: the gradient is a difference of corner values
 *   divided by the domain's width (l down to 0.02 cells), so its round-off
 *   is eps / l, up to 1e-14 per corner; the bound is now 1e-13.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cpdi.h"
#include "testkit.h"

#define NCX 6
#define NCY 5
#define DX 0.8
#define DY 1.25

static Grid grid;

static int setup(void **state)
{
    (void)state;
    return grid_init(&grid, -1.0, 2.0, DX, DY, NCX, NCY);
}

static int teardown(void **state)
{
    (void)state;
    grid_free(&grid);
    return 0;
}

static double uniform(double a, double b)
{
    return a + (b - a) * rand() / (double)RAND_MAX;
}

/** A random domain (centre in cells, half sides r1, r2 in lengths) that is
 *  narrower than a cell and inside the grid. */
static void draw(double *u, double *v, double r1[2], double r2[2])
{
    for (;;) {
        double l = uniform(0.05, 0.25), t = uniform(0, 6.283185307179586);
        double a = uniform(0.6, 1.6), b = uniform(0.6, 1.6), c = cos(t), s = sin(t);
        /* F = R(t) diag(a, b) R(-t): a stretch along turned axes */
        double F[4] = {a * c * c + b * s * s, (a - b) * c * s,
                       (a - b) * c * s, a * s * s + b * c * c};
        r1[0] = F[0] * l * DX;
        r1[1] = F[2] * l * DX;
        r2[0] = F[1] * l * DY;
        r2[1] = F[3] * l * DY;
        double ex = (fabs(r1[0]) + fabs(r2[0])) / DX, ey = (fabs(r1[1]) + fabs(r2[1])) / DY;
        if (2 * ex >= 1 || 2 * ey >= 1)
            continue;
        *u = uniform(ex, NCX - ex);
        *v = uniform(ey, NCY - ey);
        if (rand() % 2) {                  /* within l of a cell edge */
            *u = fmin(fmax(floor(*u) + (rand() % 2 ? 1 - 0.5 * ex : 0.5 * ex), ex), NCX - ex);
            *v = fmin(fmax(floor(*v) + (rand() % 2 ? 1 - 0.5 * ey : 0.5 * ey), ey), NCY - ey);
        }
        return;
    }
}

static void partition_of_unity_and_linear_reproduction(void **state)
{
    (void)state;
    double worst[4] = {0, 0, 0, 0};
    int wide = 0;
    srand(11);
    for (int k = 0; k < 100000; k++) {
        double u, v, r1[2], r2[2];
        Stencil st;
        draw(&u, &v, r1, r2);
        cpdi_stencil_domain(&grid, grid.ox + u * DX, grid.oy + v * DY, r1, r2, &st);
        double s = 0, gx = 0, gy = 0, sx = 0, sy = 0, g[4] = {0, 0, 0, 0};
        for (int a = 0; a < st.n; a++) {
            double nx = (grid_node_x(&grid, st.slot[a]) - grid.ox) / DX;
            double ny = (grid_node_y(&grid, st.slot[a]) - grid.oy) / DY;
            s += st.S[a];
            gx += st.Gx[a] * DX;
            gy += st.Gy[a] * DY;
            sx += st.S[a] * nx;
            sy += st.S[a] * ny;
            g[0] += st.Gx[a] * DX * nx;
            g[1] += st.Gx[a] * DX * ny;
            g[2] += st.Gy[a] * DY * nx;
            g[3] += st.Gy[a] * DY * ny;
        }
        wide += st.n > 4;
        worst[0] = fmax(worst[0], fabs(s - 1.0));
        worst[1] = fmax(worst[1], fmax(fabs(gx), fabs(gy)));
        worst[2] = fmax(worst[2], fmax(fabs(sx - u), fabs(sy - v)));
        worst[3] = fmax(worst[3], fmax(fmax(fabs(g[0] - 1), fabs(g[3] - 1)),
                                       fmax(fabs(g[1]), fabs(g[2]))));
    }
    printf("  100000 domains (%d reach more than four nodes): |sum S - 1| %.2e, "
           "|sum G| %.2e /cell, |sum S x - x_p| %.2e cells, |sum G x^T - I| %.2e\n",
           wide, worst[0], worst[1], worst[2], worst[3]);
    assert_true(wide > 10000);
    assert_true(worst[0] <= 1e-14);
    assert_true(worst[1] <= 1e-12);
    assert_true(worst[2] <= 1e-12);
    assert_true(worst[3] <= 1e-12);
}

static void inside_one_cell_it_is_linear(void **state)
{
    (void)state;
    double worst = 0;
    srand(12);
    for (int k = 0; k < 10000; k++) {
        double l = uniform(0.02, 0.2), xi = uniform(l, 1 - l), eta = uniform(l, 1 - l);
        int i = rand() % NCX, j = rand() % NCY;
        double r1[2] = {l * DX, 0}, r2[2] = {0, l * DY}, S[4], Gx[4], Gy[4];
        int node[4];
        Stencil st;
        cpdi_stencil_domain(&grid, grid.ox + (i + xi) * DX, grid.oy + (j + eta) * DY,
                            r1, r2, &st);
        shape_linear(xi, eta, grid.idx, grid.idy, S, Gx, Gy);
        shape_cell_nodes(&grid, j * grid.nnx + i, node);
        assert_int_equal(st.n, 4);
        for (int a = 0; a < 4; a++)
            for (int b = 0; b < 4; b++)
                if (st.slot[b] == node[a])
                    worst = fmax(worst, fmax(fabs(st.S[b] - S[a]),
                                             fmax(fabs(st.Gx[b] - Gx[a]) * DX,
                                                  fabs(st.Gy[b] - Gy[a]) * DY)));
    }
    printf("  10000 square domains inside a cell: largest difference from the "
           "linear weights and gradients %.2e (bound 1e-13)\n", worst);
    assert_true(worst <= 1e-13);
}

/** Runs @p scene until it stops; @p err gets "step S, point P: what",
 *  *@p whole the steps that ended; returns the loaded Sim (tk_free it). */
static Sim *run_to_stop(const char *scene, char *err, size_t errlen, long *whole,
                        int *rc)
{
    Sim *sim = tk_load_file(scene, NULL);
    long k = 0;
    *rc = 0;
    while (k < sim->nsteps && (*rc = sim_advance(sim)) == 0)
        k++;
    snprintf(err, errlen, "step %ld, point %d: %s", sim->fail.step,
             sim->fail.particle, sim->fail.quantity ? sim->fail.quantity : "-");
    *whole = k;
    return sim;
}

static void a_domain_wider_than_a_cell_stops_the_run(void **state)
{
    (void)state;
    char err[512];
    long k;
    int rc;
    Sim *sim = run_to_stop("tests/8-shapes/scenes/cpdi_stretch.cfg", err, sizeof err, &k, &rc);
    printf("  pulled apart at 2/ms: stopped at %s = %.4f\n", err,
           sim->fail.value);
    assert_int_not_equal(rc, 0);
    assert_non_null(strstr(err, "CPDI domain (wider than a cell"));
    assert_true(sim->fail.value >= 1.0);
    assert_true(sim->fail.step >= 1 && sim->fail.particle >= 0);
    tk_free(sim);
}

/** A domain squeezed inside out in one step (cpdi_invert.cfg: the grid's
 *  dt L_xx about -1.3) stops the run at that step, naming the point and
 *  det F < 0. */
static void an_inverted_domain_stops_the_run(void **state)
{
    (void)state;
    char err[512];
    long k;
    int rc;
    Sim *sim = run_to_stop("tests/8-shapes/scenes/cpdi_invert.cfg", err, sizeof err, &k, &rc);
    printf("  squeezed at 0.1/ms, cfl 3: stopped at %s = %.4f after %ld whole steps\n",
           err, sim->fail.value, k);
    assert_int_not_equal(rc, 0);
    assert_non_null(strstr(err, "CPDI domain (inverted: det F)"));
    assert_true(sim->fail.value < 0.0);
    assert_int_equal(k, 0);
    assert_true(sim->fail.particle >= 0);
    tk_free(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(partition_of_unity_and_linear_reproduction),
        cmocka_unit_test(inside_one_cell_it_is_linear),
        cmocka_unit_test(a_domain_wider_than_a_cell_stops_the_run),
        cmocka_unit_test(an_inverted_domain_stops_the_run),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
