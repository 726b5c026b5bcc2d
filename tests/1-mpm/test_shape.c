/**
 * @file test_shape.c
 * @brief Linear shape functions: partition of unity and zero gradient sum,
 *        at random points and on cell edges and corners; nodal values.
 */
#include <stdlib.h>

#include "shape.h"
#include "testkit.h"

static const double idx = 1.0 / 0.7, idy = 1.0 / 1.3;  /* unequal cell sides */

static void check_point(double xi, double eta)
{
    double S[4], Gx[4], Gy[4];
    shape_linear(xi, eta, idx, idy, S, Gx, Gy);
    double s = 0, gx = 0, gy = 0, x = 0, y = 0, dxx = 0, dyy = 0;
    static const double cx[4] = {0, 1, 0, 1}, cy[4] = {0, 0, 1, 1};
    for (int a = 0; a < 4; a++) {
        assert_true(S[a] >= -1e-15 && S[a] <= 1 + 1e-15);
        s += S[a];
        gx += Gx[a];
        gy += Gy[a];
        x += S[a] * cx[a];       /* linear completeness: sum N_a x_a = x */
        y += S[a] * cy[a];
        dxx += Gx[a] * cx[a];    /* sum dN_a/dx x_a = 1 (in cell units) */
        dyy += Gy[a] * cy[a];
    }
    assert_close(s, 1.0, 1e-15);
    assert_close(gx, 0.0, 1e-14);
    assert_close(gy, 0.0, 1e-14);
    assert_close(x, xi, 1e-15);
    assert_close(y, eta, 1e-15);
    assert_close(dxx, idx, 1e-14);
    assert_close(dyy, idy, 1e-14);
}

static void partition_of_unity_random(void **state)
{
    (void)state;
    srand(12345);
    for (int k = 0; k < 10000; k++)
        check_point(rand() / (double)RAND_MAX, rand() / (double)RAND_MAX);
}

static void partition_of_unity_edges_and_corners(void **state)
{
    (void)state;
    static const double e[] = {0.0, 1.0, 0.5, 1e-17, 1.0 - 1e-16};
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 5; j++)
            check_point(e[i], e[j]);
}

static void kronecker_delta_at_nodes(void **state)
{
    (void)state;
    static const double cx[4] = {0, 1, 0, 1}, cy[4] = {0, 0, 1, 1};
    for (int b = 0; b < 4; b++) {
        double S[4], Gx[4], Gy[4];
        shape_linear(cx[b], cy[b], idx, idy, S, Gx, Gy);
        for (int a = 0; a < 4; a++)
            assert_close(S[a], a == b ? 1.0 : 0.0, 0.0);
    }
}

static void locate_on_grid_lines(void **state)
{
    (void)state;
    Grid g;
    assert_int_equal(grid_init(&g, -1.0, 2.0, 0.5, 0.25, 4, 8), 0);
    double xi, eta;
    /* a point on an interior grid line belongs to the cell on its right/top */
    int c = shape_locate(&g, -0.5, 2.5, &xi, &eta);
    assert_int_equal(c, 2 * g.nnx + 1);
    assert_close(xi, 0.0, 1e-15);
    assert_close(eta, 0.0, 1e-15);
    /* the grid's far corner belongs to the last cell */
    c = shape_locate(&g, 1.0, 4.0, &xi, &eta);
    assert_int_equal(c, 7 * g.nnx + 3);
    assert_close(xi, 1.0, 1e-15);
    assert_close(eta, 1.0, 1e-15);
    grid_free(&g);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(partition_of_unity_random),
        cmocka_unit_test(partition_of_unity_edges_and_corners),
        cmocka_unit_test(kronecker_delta_at_nodes),
        cmocka_unit_test(locate_on_grid_lines),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
