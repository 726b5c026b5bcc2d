/**
 * @file test_crack_motion.c
 * @brief Task 7: crack points move with the centre-of-mass velocity of the
 *        fields at their nodes (eq. 7 and 32).
 */
#include "testkit.h"

#include "cracks.h"
#include "step.h"

static const char *scene =
    "grid = { origin = [0.0, 0.0]; cells = [10, 10]; cell_size = [1.0, 1.0]; };\n"
    "run = { time = 1.0; update = \"musl\"; snapshots = 0; };\n"
    "materials = ( { name = \"m\"; E = 1.0; nu = 0.3; rho = 1.0e-3; } );\n"
    "bodies = ( { name = \"b\"; material = \"m\"; velocity = [0.3, -0.2];\n"
    "             rectangle = { min = [2.0, 2.0]; max = [8.0, 8.0]; }; } );\n"
    "cracks = ( { points = ( [3.0, 5.0], [4.5, 5.25], [6.0, 5.0] ); } );\n";

/** A body in rigid translation carries its crack along: every crack point
 *  moves by v t, to round-off (the grid velocity is v wherever there is
 *  mass, so any interpolation of it gives v). */
static void crack_translates_with_its_body(void **state)
{
    (void)state;
    Sim *sim = tk_load(scene);
    Crack c = cracks_of(sim)->crack[0];
    double x0[3], y0[3];
    for (int j = 0; j < 3; j++) {
        x0[j] = c.x[j];
        y0[j] = c.y[j];
    }
    tk_steps(sim, 100);
    for (int j = 0; j < 3; j++) {
        assert_close(c.x[j], x0[j] + 0.3 * sim->t, 1e-12);
        assert_close(c.y[j], y0[j] - 0.2 * sim->t, 1e-12);
    }
    /* the extent follows the points (used by the crossing screen) */
    assert_close(cracks_of(sim)->crack[0].xmin, c.x[0], 0.0);
    assert_close(cracks_of(sim)->crack[0].ymax, c.y[1], 0.0);
    tk_free(sim);
}

/** At a node split by the crack, the crack moves with the centre of mass of
 *  both fields: upper half moving up at 1, lower half at rest, equal
 *  masses, so a crack point on the node moves up at 1/2 (eq. 32). */
static void crack_moves_with_centre_of_mass(void **state)
{
    (void)state;
    Sim *sim = tk_load(scene);
    Particles *P = &sim->pts;
    for (int p = 0; p < P->n; p++) {
        P->vx[p] = 0;
        P->vy[p] = P->y[p] > 5.0 ? 1.0 : 0.0;
    }
    grid_clear(&sim->grid, 1);
    locate_points(sim);
    assert_int_equal(assign_fields(sim), 0);
    extrapolate(sim, EXTRAP_MASS);
    sim->dt = 0.01;
    assert_int_equal(cracks_move(sim), 0);
    const Crack *c = &cracks_of(sim)->crack[0];
    assert_close(c->y[0], 5.0 + 0.5 * 0.01, 1e-15);   /* start point, a node */
    assert_close(c->y[2], 5.0 + 0.5 * 0.01, 1e-15);   /* end point, a node */
    assert_close(c->x[0], 3.0, 1e-15);
    tk_free(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(crack_translates_with_its_body),
        cmocka_unit_test(crack_moves_with_centre_of_mass),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
