/**
 * @file test_gimp.c
 * @brief The uGIMP functions (Bardenhagen & Kober 2004) at random points:
 *        partition of unity, linear reproduction, and gradients against
 *        central differences.
 *
 * Points are drawn in every cell of a small grid with random half sizes
 * l in [0.05, 0.5] cells, and placed on purpose so that their domain
 * straddles a cell edge (just left and right of one) and lies against the
 * grid's edge (touching it from inside). Bounds, fixed before the first
 * run:
 * - sum_i S_ip = 1 to 1e-14, and sum_i G_ip = 0 to 1e-13 per cell (the
 *   first run had 1e-14 for G too and failed at 1.3e-14: a G reaches
 *   1 / l = 20 per cell, so nine of them round off to 9 x 20 x 2.2e-16 =
 *   4e-14; the bound was set wrong, not the functions);
 * - sum_i S_ip x_i = x_p and sum_i G_ip x_i^T = I to 1e-12 (in cells);
 * - each G_ip against the central difference of S_ip with a step of 1e-7
 *   cells: S is piecewise quadratic, so the difference is exact but within
 *   a step of a break, where it is off by at most step / l = 2e-6 per cell,
 *   plus round-off 1e-16 / 1e-7; the bound is 5e-6 per cell.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "gimp.h"
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

/** The stencil of a point at (x, y) (lengths) with half sizes (lx, ly)
 *  in cells, located as Task 0 does. */
static void stencil_xy(double x, double y, double lx, double ly, Stencil *st)
{
    double xi, eta;
    int cell = shape_locate(&grid, x, y, &xi, &eta);
    gimp_stencil_cell(&grid, cell, xi, eta, lx, ly, st);
}

static double uniform(double a, double b)
{
    return a + (b - a) * rand() / (double)RAND_MAX;
}

/** A random point: half the time its domain straddles a cell edge, a
 *  tenth of the time it touches the grid's edge from inside. */
static void draw(double *x, double *y, double *lx, double *ly)
{
    *lx = uniform(0.05, 0.5);
    *ly = uniform(0.05, 0.5);
    double u = uniform(*lx, NCX - *lx), v = uniform(*ly, NCY - *ly);
    int kind = rand() % 10;
    if (kind < 5) {                    /* across an edge, by less than l */
        u = floor(u) + (rand() % 2 ? 1.0 - 0.5 * *lx : 0.5 * *lx);
        v = floor(v) + (rand() % 2 ? 1.0 - 0.5 * *ly : 0.5 * *ly);
        u = fmin(fmax(u, *lx), NCX - *lx);
        v = fmin(fmax(v, *ly), NCY - *ly);
    } else if (kind == 5) {            /* against the grid's edges */
        u = rand() % 2 ? *lx : NCX - *lx;
        v = rand() % 2 ? *ly : NCY - *ly;
    }
    *x = grid.ox + u * DX;
    *y = grid.oy + v * DY;
}

static void partition_of_unity_and_linear_reproduction(void **state)
{
    (void)state;
    double worst[4] = {0, 0, 0, 0};
    int straddle = 0, nine = 0;
    srand(8);
    for (int k = 0; k < 100000; k++) {
        double x, y, lx, ly;
        Stencil st;
        draw(&x, &y, &lx, &ly);
        stencil_xy(x, y, lx, ly, &st);
        double s = 0, gx = 0, gy = 0, sx = 0, sy = 0;
        double gxx = 0, gxy = 0, gyx = 0, gyy = 0;
        for (int a = 0; a < st.n; a++) {
            double nx = (grid_node_x(&grid, st.slot[a]) - grid.ox) / DX;
            double ny = (grid_node_y(&grid, st.slot[a]) - grid.oy) / DY;
            s += st.S[a];
            gx += st.Gx[a] * DX;
            gy += st.Gy[a] * DY;
            sx += st.S[a] * nx;
            sy += st.S[a] * ny;
            gxx += st.Gx[a] * DX * nx;
            gxy += st.Gx[a] * DX * ny;
            gyx += st.Gy[a] * DY * nx;
            gyy += st.Gy[a] * DY * ny;
        }
        straddle += st.n > 4;
        nine += st.n == 9;
        worst[0] = fmax(worst[0], fabs(s - 1.0));
        worst[1] = fmax(worst[1], fmax(fabs(gx), fabs(gy)));
        worst[2] = fmax(worst[2], fmax(fabs(sx - (x - grid.ox) / DX),
                                       fabs(sy - (y - grid.oy) / DY)));
        worst[3] = fmax(worst[3], fmax(fmax(fabs(gxx - 1.0), fabs(gyy - 1.0)),
                                       fmax(fabs(gxy), fabs(gyx))));
    }
    printf("  100000 points (%d straddle a cell edge, %d of them two): "
           "|sum S - 1| %.2e, |sum G| %.2e /cell, |sum S x - x_p| %.2e cells, "
           "|sum G x^T - I| %.2e\n", straddle, nine, worst[0], worst[1],
           worst[2], worst[3]);
    assert_true(straddle > 10000 && nine > 1000);
    assert_true(worst[0] <= 1e-14);
    assert_true(worst[1] <= 1e-13);
    assert_true(worst[2] <= 1e-12);
    assert_true(worst[3] <= 1e-12);
}

/** S of node @p node at (x, y), 0 when the stencil does not reach it. */
static double weight_of(int node, double x, double y, double lx, double ly)
{
    Stencil st;
    stencil_xy(x, y, lx, ly, &st);
    for (int a = 0; a < st.n; a++)
        if (st.slot[a] == node)
            return st.S[a];
    return 0.0;
}

static void gradients_match_differences(void **state)
{
    (void)state;
    double h = 1e-7, worst = 0;
    srand(9);
    for (int k = 0; k < 20000; k++) {
        double x, y, lx, ly;
        Stencil st;
        draw(&x, &y, &lx, &ly);
        /* keep the shifted points inside the grid's domains */
        x = fmin(fmax(x, grid.ox + (lx + 2 * h) * DX), grid.ox + (NCX - lx - 2 * h) * DX);
        y = fmin(fmax(y, grid.oy + (ly + 2 * h) * DY), grid.oy + (NCY - ly - 2 * h) * DY);
        stencil_xy(x, y, lx, ly, &st);
        for (int a = 0; a < st.n; a++) {
            int n = st.slot[a];
            double dsx = (weight_of(n, x + h * DX, y, lx, ly) -
                          weight_of(n, x - h * DX, y, lx, ly)) / (2 * h);
            double dsy = (weight_of(n, x, y + h * DY, lx, ly) -
                          weight_of(n, x, y - h * DY, lx, ly)) / (2 * h);
            worst = fmax(worst, fmax(fabs(st.Gx[a] * DX - dsx),
                                     fabs(st.Gy[a] * DY - dsy)));
        }
    }
    printf("  20000 points: largest |G - central difference| %.2e per cell "
           "(bound 5e-6)\n", worst);
    assert_true(worst <= 5e-6);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(partition_of_unity_and_linear_reproduction),
        cmocka_unit_test(gradients_match_differences),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
