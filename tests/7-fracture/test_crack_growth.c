/**
 * @file test_crack_growth.c
 * @brief One growth event by hand: a crack with a tip at each end is
 *        given J, K_I and K_II, and crack_growth_step() must put the new
 *        points where the kink angle says, at both ends (the first point
 *        grows by shifting the points), hand them to the crossing search
 *        and the J tips, leave a tip with J < G_c alone, and stop when the
 *        reserved room is full.
 *
 * Exact geometry: with K_I = K_II, theta_c = -2 atan(1/2) = -53.13
 * degrees, cos = 0.6, sin = -0.8. The last point (7, 5) looks along +x
 * (left normal +y): its new point is (7 + 0.3, 5 - 0.4). The first point
 * (3, 5) looks along -x (left normal -y): its new point is (3 - 0.3,
 * 5 + 0.4). Bounds: 1e-12 mm. The block reaches 0.5 mm from the grid's
 * edges, so that the new tips' J domains (2 cells) stay inside it (a tip
 * whose domain reaches out of the body stops growing).
 */
#include "testkit.h"

#include <string.h>

#include "crack_growth.h"
#include "cracks.h"

static const char *const SCENE =
    "grid = { origin = [0.0, 0.0]; cells = [10, 10]; cell_size = [1.0, 1.0]; };\n"
    "run = { time = 0.01; snapshots = 0; };\n"
    "materials = ( { name = \"gel\"; E = 0.1; nu = 0.33; rho = 1.5e-3; } );\n"
    "bodies = ( { name = \"block\"; material = \"gel\";\n"
    "             rectangle = { min = [0.5, 0.5]; max = [9.5, 9.5]; }; } );\n"
    "cracks = ( { points = ( [3.0, 5.0], [7.0, 5.0] );\n"
    "             j_integral = { contours = [2]; };\n"
    "             growth = { G_c = 1e-4; length = 0.5; max_segments = 3; }; } );\n";

/** Give tip @p t the parameters J, K_I, K_II on its one contour. */
static void load_tip(JState *S, int t, double J, double KI, double KII)
{
    S->tip[t].J[0] = J;
    S->tip[t].KI[0] = KI;
    S->tip[t].KII[0] = KII;
}

/** The field of the line from (7.2, 4.9) to node (7, 4), in cell (7, 4):
 *  it crosses the segment the last point grows, (7, 5) to (7.3, 4.6). */
static int field_across_new_segment(const Sim *sim)
{
    const Grid *g = &sim->grid;
    return crack_field(cracks_of(sim), 4 * g->nnx + 7, 7.2, 4.9, 7.0, 4.0, NULL);
}

static void both_ends_grow_where_the_angle_says(void **state)
{
    (void)state;
    Sim *sim = tk_load(SCENE);
    JState *S = sim_state(sim, "j-integral");
    CrackGrowth *G = sim_state(sim, "crack-growth");
    const Crack *c = &cracks_of(sim)->crack[0];
    assert_non_null(S);
    assert_non_null(G);
    assert_int_equal(S->ntips, 2);
    assert_int_equal(S->tip[0].end, 0);
    assert_int_equal(field_across_new_segment(sim), 0);
    /* below G_c: nothing */
    load_tip(S, 0, 0.99e-4, 1.0, 1.0);
    load_tip(S, 1, 0.99e-4, 1.0, 1.0);
    assert_int_equal(crack_growth_step(sim, G, S), 0);
    assert_int_equal(c->n, 2);
    /* at G_c, both ends */
    load_tip(S, 0, 1e-4, 1.0, 1.0);
    load_tip(S, 1, 1e-4, 1.0, 1.0);
    assert_int_equal(crack_growth_step(sim, G, S), 0);
    printf("  theta %.6f degrees; points (%.6f, %.6f) (%g, %g) (%g, %g) "
           "(%.6f, %.6f)\n", hoop_angle(1.0, 1.0) * 45.0 / atan(1.0),
           c->x[0], c->y[0], c->x[1], c->y[1], c->x[2], c->y[2], c->x[3],
           c->y[3]);
    assert_int_equal(c->n, 4);
    assert_close(c->x[0], 2.7, 1e-12);
    assert_close(c->y[0], 5.4, 1e-12);
    assert_close(c->x[1], 3.0, 0.0);
    assert_close(c->x[2], 7.0, 0.0);
    assert_close(c->x[3], 7.3, 1e-12);
    assert_close(c->y[3], 4.6, 1e-12);
    assert_int_equal(G->end[0].events, 1);
    assert_int_equal(G->end[1].events, 1);
    /* the J tips follow: place and direction of the new segments */
    assert_close(S->tip[0].x, 2.7, 1e-12);
    assert_close(S->tip[0].ex, -0.6, 1e-12);
    assert_close(S->tip[0].ey, 0.8, 1e-12);
    assert_close(S->tip[1].x, 7.3, 1e-12);
    assert_close(S->tip[1].ex, 0.6, 1e-12);
    assert_close(S->tip[1].ey, -0.8, 1e-12);
    /* the crossing search sees the new segment (the point is above it) */
    assert_int_equal(field_across_new_segment(sim), 1);
    /* the room is full (3 segments): the next event stops the run */
    load_tip(S, 1, 2e-4, 1.0, 0.0);
    assert_int_equal(crack_growth_step(sim, G, S), -1);
    printf("  full: %s = %g\n", sim->fail.quantity, sim->fail.value);
    assert_non_null(strstr(sim->fail.quantity, "cracks.[0].growth.max_segments"));
    assert_int_equal(c->n, 4);
    tk_free(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(both_ends_grow_where_the_angle_says),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
