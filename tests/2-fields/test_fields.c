/**
 * @file test_fields.c
 * @brief Field assignment v(p,i) by the line-crossing test (eq. 2 and the
 *        Appendix's signed areas), and momentum conservation over fields.
 */
#include "testkit.h"

#include <stdlib.h>

#include "cracks.h"
#include "shape.h"
#include "step.h"

/** A crack from (0, 0) to (10, 0): "above" is +y (left of 3 -> 4). */
static Crack straight(double *x, double *y)
{
    x[0] = 0;
    y[0] = 0;
    x[1] = 10;
    y[1] = 0;
    return (Crack){2, x, y, 0, 10, 0, 0, 0};
}

static void crossing_sides(void **state)
{
    (void)state;
    double x[2], y[2];
    Crack c = straight(x, y);
    assert_int_equal(crack_crossing(&c, 5, 1, 5, -1), 1);    /* (-,+,+,-) */
    assert_int_equal(crack_crossing(&c, 5, -1, 5, 1), -1);   /* (+,-,-,+) */
    assert_int_equal(crack_crossing(&c, 5, 1, 6, 2), 0);     /* same side */
    assert_int_equal(crack_crossing(&c, 12, 1, 12, -1), 0);  /* past the tip */
    assert_int_equal(crack_crossing(&c, -1, 1, -1, -1), 0);  /* before it */
}

static void node_on_the_crack(void **state)
{
    (void)state;
    double x[2], y[2];
    Crack c = straight(x, y);
    /* interior, start point and end point: above -> 1, below -> 2, never 0 */
    static const double nodes[3][2] = {{5, 0}, {0, 0}, {10, 0}};
    for (int k = 0; k < 3; k++) {
        double nx = nodes[k][0], ny = nodes[k][1];
        assert_int_equal(crack_crossing(&c, nx + 0.3, 0.4, nx, ny), 1);
        assert_int_equal(crack_crossing(&c, nx - 0.3, 0.4, nx, ny), 1);
        assert_int_equal(crack_crossing(&c, nx + 0.3, -0.4, nx, ny), -1);
        assert_int_equal(crack_crossing(&c, nx - 0.3, -0.4, nx, ny), -1);
    }
}

static void polyline_vertices_count_once(void **state)
{
    (void)state;
    /* a bent crack: (0,0) -> (4,0) -> (8,2); a line through the vertex
       (4,0) and a node on it cross once */
    double x[3] = {0, 4, 8}, y[3] = {0, 0, 2};
    Crack c = {3, x, y, 0, 8, 0, 2, 0};
    assert_int_equal(crack_crossing(&c, 3, 1, 5, -1), 1);    /* through vertex */
    assert_int_equal(crack_crossing(&c, 4.2, 1, 4, 0), 1);   /* node on vertex */
    assert_int_equal(crack_crossing(&c, 3.8, -1, 4, 0), -1);
    /* a zig-zag crossed twice by one line counts as not crossed (subtask 4) */
    double zx[4] = {0, 4, 0, 4}, zy[4] = {0, 1, 2, 3};
    Crack z = {4, zx, zy, 0, 4, 0, 3, 0};
    assert_int_equal(crack_crossing(&z, 2.5, -1, 2.5, 2.0), 0);
    assert_int_equal(crack_crossing(&z, 2.5, -1, 2.5, 2.9), -1);  /* three */
}

static const char *scene =
    "grid = { origin = [0.0, 0.0]; cells = [10, 10]; cell_size = [1.0, 1.0]; };\n"
    "run = { time = 1.0; update = \"musl\"; snapshots = 0; };\n"
    "materials = ( { name = \"m\"; E = 1.0; nu = 0.3; rho = 1.0e-3; } );\n"
    "bodies = ( { name = \"b\"; material = \"m\"; velocity = [0.3, -0.2];\n"
    "             rectangle = { min = [2.0, 2.0]; max = [8.0, 8.0]; }; } );\n"
    "cracks = ( { points = ( [1.5, 5.0], [5.0, 5.0] ); } );\n";

/** Field of pair (p, corner a) after Task 1: the crack side's part of
 *  the pair's key in the field table. */
static int field_of(const Sim *sim, int p, int a)
{
    const FieldTable *F = &sim->fields;
    int r = F->row_of[p];
    if (r < 0)
        return 0;
    return (int)(F->row_key[STENCIL_NODES * r + a] >> cracks_of(sim)->side_shift) & 3;
}

static void fields_at_nodes(void **state)
{
    (void)state;
    Sim *sim = tk_load(scene);
    const Grid *g = &sim->grid;
    const Particles *P = &sim->pts;
    locate_points(sim);
    assert_int_equal(assign_fields(sim), 0);
    /* per node: which fields its pairs use */
    int *seen = calloc((size_t)g->nnodes, sizeof(int));
    for (int p = 0; p < P->n; p++) {
        int node[4];
        stencil_nodes(sim, p, node);
        for (int a = 0; a < 4; a++) {
            int f = field_of(sim, p, a);
            seen[node[a]] |= 1 << f;
            double nx = grid_node_x(g, node[a]), ny = grid_node_y(g, node[a]);
            if (ny == 5.0 && nx >= 2.0 && nx <= 5.0)   /* node on the crack */
                assert_int_equal(f, P->y[p] > 5.0 ? 1 : 2);
            if (fabs(nx - P->x[p]) < 1 && nx < 5.0 &&
                (P->y[p] - 5.0) * (ny - 5.0) < 0)      /* across the crack */
                assert_int_equal(f, P->y[p] > 5.0 ? 1 : 2);
        }
    }
    for (int n = 0; n < g->nnodes; n++) {
        double nx = grid_node_x(g, n), ny = grid_node_y(g, n);
        if (ny == 5.0 && nx >= 2.0 && nx <= 5.0)
            assert_int_equal(seen[n], (1 << 1) | (1 << 2));   /* 1 and 2, no 0 */
        else if (ny == 5.0 && nx == 6.0)
            assert_int_equal(seen[n], 1);     /* beyond the tip: one field */
        if (ny <= 3.0 || ny >= 7.0 || nx >= 7.0)
            assert_true(seen[n] <= 1);        /* far away: field 0 only */
    }
    free(seen);
    tk_free(sim);
}

static void momentum_conserved_over_fields(void **state)
{
    (void)state;
    /* a free-flying cracked body that also spins and vibrates */
    Sim *sim = tk_load(scene);
    Particles *P = &sim->pts;
    for (int p = 0; p < P->n; p++) {
        P->vx[p] += 0.2 * (P->y[p] - 5.0);
        P->vy[p] -= 0.2 * (P->x[p] - 5.0) + 0.05 * (P->x[p] - 5) * (P->x[p] - 5);
    }
    sim_set_time_step(sim);
    Totals t0 = sim_totals(sim);
    double scale = 0;
    for (int p = 0; p < P->n; p++)
        scale += P->m[p] * hypot(P->vx[p], P->vy[p]);
    for (int s = 0; s < 200; s++) {
        tk_steps(sim, 1);
        Totals t = sim_totals(sim);
        assert_close(t.px, t0.px, 1e-13 * scale);
        assert_close(t.py, t0.py, 1e-13 * scale);
    }
    /* the crack really split nodes during the run */
    assert_true(cracks_multi_field_nodes(sim) > 0);
    tk_free(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(crossing_sides),
        cmocka_unit_test(node_on_the_crack),
        cmocka_unit_test(polyline_vertices_count_once),
        cmocka_unit_test(fields_at_nodes),
        cmocka_unit_test(momentum_conserved_over_fields),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
