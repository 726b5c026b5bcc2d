/**
 * @file test_contact_contract.c
 * @brief The contact contract (paper's Task 4): a contact subscriber that
 *        changes only nodal momenta changes what Task 5 gives the points,
 *        and fixed directions stay fixed.
 *
 * A test subscriber at SEAM_TASK4_CONTACT adds m_i dv to the momentum of
 * every slot. The contract derives f += (p_new - p_old) / dt, a = f / m and
 * v = p / m, so a point's velocity gains sum_i S_ip dv over the nodes free
 * in that direction (eq. 30), and its position dt times the same; at nodes
 * fixed in y, v_y and a_y stay zero.
 */
#include "testkit.h"

#include <float.h>
#include <stdlib.h>

#include "step.h"

static const double DVX = 0.125, DVY = -0.0625;

/** Task 4 contact: a uniform velocity kick at every slot with mass. */
static int kick(Sim *sim, void *state, Seam seam)
{
    Grid *g = &sim->grid;
    int *calls = state;
    (void)seam;
    for (int s = 0; s < g->nslots; s++) {
        g->px[s] += g->m[s] * DVX;
        g->py[s] += g->m[s] * DVY;
    }
    (*calls)++;
    return 0;
}

static const char *scene =
    "grid = { origin = [0.0, 0.0]; cells = [8, 6]; cell_size = [1.0, 1.0]; };\n"
    "run = { time = 1.0; update = \"usl\"; snapshots = 0; gravity = [0.0, -0.01]; };\n"
    "materials = ( { name = \"m\"; E = 1.0; nu = 0.3; rho = 1.0e-3; } );\n"
    "bodies = ( { material = \"m\"; velocity = [0.02, 0.01];\n"
    "             rectangle = { min = [1.0, 1.0]; max = [7.0, 5.0]; }; } );\n"
    "boundaries = ( { rectangle = { min = [0.0, 1.0]; max = [8.0, 1.0]; }; fix = \"y\"; } );\n"
    "loads = ( { rectangle = { min = [6.0, 1.0]; max = [7.0, 5.0]; };\n"
    "            force = [1.0e-4, 2.0e-4]; } );\n";

/** The kick as a plug-in: subscribed at Task 4 with its call counter. */
static void with_kick(Hooks *h, void *calls)
{
    assert_int_equal(hooks_on_step(h, SEAM_TASK4_CONTACT, kick, calls), 0);
}

/** Load the scene, with the kick subscribed when @p calls is not NULL. */
static Sim *load(int *calls)
{
    char err[1024];
    Sim *sim = tk_load_with(scene, calls ? with_kick : NULL, calls, err, sizeof err);
    if (!sim)
        fail_msg("refused: %s", err);
    return sim;
}

/** Tasks 0-5 of one USL step, by hand (the grid is kept for checks). */
static void tasks_0_to_5(Sim *sim)
{
    grid_clear(&sim->grid, 1);
    locate_points(sim);
    assert_int_equal(assign_fields(sim), 0);
    extrapolate(sim, EXTRAP_MASS | EXTRAP_FORCE);
    grid_velocities(sim);
    assert_int_equal(grid_contact(sim, SEAM_TASK2_CONTACT), 0);
    grid_momentum_update(sim);
    assert_int_equal(grid_contact(sim, SEAM_TASK4_CONTACT), 0);
    assert_int_equal(update_points(sim), 0);
}

static void momentum_change_reaches_the_points(void **state)
{
    (void)state;
    int calls = 0;
    Sim *a = load(NULL), *b = load(&calls);
    tasks_0_to_5(a);
    tasks_0_to_5(b);
    assert_int_equal(calls, 1);
    const Grid *g = &b->grid;
    double dt = b->dt;
    int fixed_nodes = 0;
    for (int s = 0; s < g->nslots; s++) {
        if (!(g->fixed[grid_slot_node(g, s)] & GRID_FIX_Y) || g->m[s] <= 0)
            continue;
        fixed_nodes++;                 /* fixed in y: the kick is undone */
        assert_true(g->py[s] == 0.0 && g->fy[s] == 0.0);
        assert_true(g->vy[s] == 0.0 && g->ay[s] == 0.0);
        assert_close(g->vx[s], a->grid.vx[s] + DVX, 1e-15);
    }
    assert_true(fixed_nodes > 0);
    for (int p = 0; p < b->pts.n; p++) {
        Stencil st;
        stencil_of_point(b, p, &st);
        double free_y = 0;             /* weight of the nodes free in y */
        for (int k = 0; k < STENCIL_NODES; k++)
            if (!(g->fixed[grid_slot_node(g, st.slot[k])] & GRID_FIX_Y))
                free_y += st.S[k];
        /* to round-off: a few ulps of the velocities (about 0.1) and of
           the positions x0 + dt v (1 to 7) */
        assert_close(b->pts.vx[p] - a->pts.vx[p], DVX, 1e-15);
        assert_close(b->pts.vy[p] - a->pts.vy[p], free_y * DVY, 1e-15);
        assert_close(b->pts.x[p], a->pts.x[p] + dt * DVX, 4 * DBL_EPSILON * b->pts.x[p]);
        assert_close(b->pts.y[p], a->pts.y[p] + dt * free_y * DVY,
                     4 * DBL_EPSILON * b->pts.y[p]);
    }
    tk_free(a);
    tk_free(b);
}

static void no_subscriber_no_cost(void **state)
{
    (void)state;
    /* without contact subscribers the contract does nothing and the grid
       has no arrays for it */
    Sim *sim = load(NULL);
    assert_null(sim->grid.qx);
    int calls = 0;
    Sim *with = load(&calls);
    assert_non_null(with->grid.qx);
    tk_steps(with, 5);
    assert_int_equal(calls, 5);
    tk_free(with);
    tk_free(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(momentum_change_reaches_the_points),
        cmocka_unit_test(no_subscriber_no_cost),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
