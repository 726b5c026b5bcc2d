/**
 * @file test_strips.c
 * @brief The strips of node rows that the threads own (strips.h): they
 *        cover the nodes once, each lists exactly the points whose stencil
 *        reaches its rows, in increasing index, and a point meets at most
 *        two strips.
 *
 * The threaded scatter gives one thread's bits only if every node's
 * owner visits every point that reaches the node, in index order; these
 * are exact properties (no tolerance), checked for the bilinear stencil
 * (node rows j and j + 1 of a point in cell row j) and for the 3 x 3 one
 * of chapter 8 (rows j - 1 .. j + 2), on the two disks of chapter 1 and
 * on a grid too low for two strips.
 */
#include "testkit.h"

#include <stdio.h>

#include "step.h"

/** The disks of tests/1-mpm/scenes/disks.cfg on @p threads threads and a
 *  grid @p rows cells high. */
static Sim *disks(int threads, int rows)
{
    char text[1024];
    snprintf(text, sizeof text,
             "grid = { origin = [0.0, 0.0]; cells = [20, %d]; "
             "cell_size = [0.05, %.17g]; };\n"
             "run = { time = 1.0; threads = %d; snapshots = 0; };\n"
             "materials = ( { name = \"e\"; E = 1.0e-3; nu = 0.3; rho = 1.0e-3; } );\n"
             "bodies = (\n"
             "  { material = \"e\"; velocity = [0.1, 0.1]; points_per_cell = 2;\n"
             "    disk = { center = [0.25, 0.25]; radius = 0.2; }; },\n"
             "  { material = \"e\"; velocity = [-0.1, -0.1]; points_per_cell = 2;\n"
             "    disk = { center = [0.75, 0.75]; radius = 0.2; }; } );\n",
             rows, 1.0 / rows, threads);
    return tk_load(text);
}

/** Is point @p p in strip @p t's list? */
static int listed(const Strips *S, int t, int p)
{
    for (int k = S->start[t]; k < S->start[t + 1]; k++)
        if (S->list[k] == p)
            return 1;
    return 0;
}

/** Bin with @p reach and check every property; @return the strips. */
static int check_strips(Sim *sim, int reach)
{
    Strips *S = &sim->strips;
    const Grid *g = &sim->grid;
    S->reach = reach;
    locate_points(sim);
    int w = 2 + 2 * reach;
    if (S->n == 0)
        return 0;
    assert_true(S->n >= 2 && S->n <= S->cap);
    assert_int_equal(S->first_node[0], 0);
    assert_int_equal(S->first_node[S->n], g->nnodes);
    for (int t = 0; t < S->n; t++) {             /* whole rows, w or more */
        assert_int_equal(S->first_node[t] % g->nnx, 0);
        assert_true(S->first_node[t + 1] - S->first_node[t] >= w * g->nnx);
        for (int k = S->start[t] + 1; k < S->start[t + 1]; k++)
            assert_true(S->list[k - 1] < S->list[k]);   /* increasing */
    }
    for (int p = 0; p < sim->pts.n; p++) {
        int j = sim->pts.cell[p] / g->nnx, strips = 0;
        int r0 = j - reach, r1 = j + 1 + reach;  /* the rows it reaches */
        for (int t = 0; t < S->n; t++) {
            int lo = S->first_node[t] / g->nnx;
            int hi = S->first_node[t + 1] / g->nnx - 1;
            int reaches = r0 <= hi && r1 >= lo;
            if (reaches != listed(S, t, p))
                fail_msg("point %d (cell row %d, reach %d): strip %d (rows %d-%d) "
                         "%s it", p, j, reach, t, lo, hi,
                         reaches ? "misses" : "lists");
            strips += reaches;
        }
        assert_true(strips >= 1 && strips <= 2);
    }
    return S->n;
}

static void strips_list_every_point_that_reaches_them(void **state)
{
    (void)state;
    for (int threads = 2; threads <= 4; threads++) {
        Sim *sim = disks(threads, 20);
        assert_int_equal(check_strips(sim, 0), threads);  /* 21 rows: room */
        assert_int_equal(check_strips(sim, 1), threads);  /* 3 x 3 nodes */
        tk_free(sim);
    }
}

static void one_thread_or_a_low_grid_makes_no_strips(void **state)
{
    (void)state;
    Sim *one = disks(1, 20);
    locate_points(one);
    assert_int_equal(one->strips.n, 0);
    tk_free(one);
    Sim *low = disks(4, 3);            /* 4 node rows: 2 strips of 2, */
    assert_int_equal(check_strips(low, 0), 2);
    assert_int_equal(check_strips(low, 1), 0);     /* none of 4 */
    tk_free(low);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(strips_list_every_point_that_reaches_them),
        cmocka_unit_test(one_thread_or_a_low_grid_makes_no_strips),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
