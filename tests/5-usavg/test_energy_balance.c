/**
 * @file test_energy_balance.c
 * @brief Stage 5's energy account: energy in (start + work of gravity and
 *        loads) = stored (kinetic + strain) + damping + contact + error.
 *
 * - free_fall: a block under gravity, no supports: every point gains
 *   exactly g dt per step, so the work of gravity (trapezoid rule on the
 *   points' velocities) equals the gain of kinetic energy to round-off:
 *   |error| <= 1e-12 of the work.
 * - damped_bar: a free bar whose halves start moving apart (USAVG, no
 *   supports): without damping the account's error is the scheme's and
 *   the first step's (the velocity jump between the halves is averaged
 *   away at the middle nodes: 1.1e-3 of the energy); with damping kappa =
 *   0.05/ms, which takes out more than half the energy, the error may
 *   differ from that by at most 1 % of what damping took out (the damping
 *   term is summed at the nodes, the kinetic energy at the points; the
 *   difference is printed, 2.3e-3). An account without the damping term
 *   would be off by all of it.
 * - plain_scene_costs_nothing: a scene without gravity, loads or damping
 *   subscribes nothing per step.
 */
#include "testkit.h"

#include <math.h>
#include <stdio.h>

#include "energy_balance.h"

static const char *const FALL =
    "grid = { origin = [0.0, 0.0]; cells = [20, 40]; cell_size = [1.0, 1.0]; };\n"
    "run = { time = 5.0; cfl = 0.4; update = \"usavg\"; gravity = [0.0, -0.5]; snapshots = 0; };\n"
    "materials = ( { name = \"m\"; E = 10.0; nu = 0.3; rho = 1.0e-3; } );\n"
    "bodies = ( { name = \"b\"; material = \"m\"; points_per_cell = 2; velocity = [0.3, 0.0];\n"
    "             rectangle = { min = [5.0, 25.0]; max = [10.0, 30.0]; }; } );\n";

static void free_fall(void **state)
{
    (void)state;
    Sim *sim = tk_load(FALL);
    tk_steps(sim, sim->nsteps);
    const EnergyBalance *B = sim_state(sim, "energy balance");
    assert_non_null(B);
    EnergyTerms e = energy_balance_terms(sim, B);
    printf("  free fall, %ld steps: work of gravity %.9g mJ, stored %.9g (start %.9g), "
           "error %.2e of the work\n", sim->step, B->w_ext, e.stored, B->e0,
           e.error / B->w_ext);
    assert_true(B->w_ext > 0);
    assert_true(fabs(e.error) <= 1e-12 * B->w_ext);
    tk_free(sim);
}

/** A 20 x 4 mm bar, its halves moving apart at 0.05 m/s; damping @p kappa. */
static EnergyTerms bar(double kappa)
{
    char text[1024];
    snprintf(text, sizeof text,
        "grid = { origin = [0.0, 0.0]; cells = [40, 12]; cell_size = [1.0, 1.0]; };\n"
        "run = { time = 40.0; cfl = 0.3; update = \"usavg\"; damping = %g; snapshots = 0; };\n"
        "materials = ( { name = \"m\"; E = 1.0; nu = 0.3; rho = 1.5e-3; } );\n"
        "bodies = ( { name = \"l\"; material = \"m\"; points_per_cell = 2; velocity = [-0.05, 0.0];\n"
        "             rectangle = { min = [10.0, 4.0]; max = [20.0, 8.0]; }; },\n"
        "           { name = \"r\"; material = \"m\"; points_per_cell = 2; velocity = [0.05, 0.0];\n"
        "             rectangle = { min = [20.0, 4.0]; max = [30.0, 8.0]; }; } );\n", kappa);
    Sim *sim = tk_load(text);
    tk_steps(sim, sim->nsteps);
    EnergyTerms e = energy_balance_terms(sim, sim_state(sim, "energy balance"));
    printf("  bar, kappa %g, %ld steps: in %.6g, stored %.6g, damping %.6g, "
           "error %+.2e of in\n", kappa, sim->step, e.in, e.stored, e.damping,
           e.error / e.in);
    tk_free(sim);
    return e;
}

static void damped_bar(void **state)
{
    (void)state;
    EnergyTerms free_bar = bar(0.0), damped = bar(0.05);
    printf("  the account's error with damping less without: %.2e of the damping\n",
           (damped.error - free_bar.error) / damped.damping);
    assert_true(damped.damping > 0.5 * damped.in);
    assert_true(fabs(damped.error - free_bar.error) <= 0.01 * damped.damping);
}

static void plain_scene_costs_nothing(void **state)
{
    (void)state;
    Sim *sim = tk_load_file("tests/1-mpm/scenes/disks.cfg", NULL);
    const EnergyBalance *B = sim_state(sim, "energy balance");
    assert_non_null(B);
    assert_null(B->vx);
    assert_int_equal(sim->hooks.seam[SEAM_TASK7].n, 0);
    tk_free(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(free_fall),
        cmocka_unit_test(damped_bar),
        cmocka_unit_test(plain_scene_costs_nothing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
