/**
 * @file scene_velocity_step.c
 * @brief A velocity step at a bar's end, prescribed on the nodes of the end
 *        (boundaries with a velocity): the front travels at the bar speed c.
 *
 * A bar 200 mm long and 2 mm high, 1 mm cells, 2 x 2 points per cell,
 * nu = 0 (so c = sqrt(E / rho) = 1000 m/s in plane stress, E = 1000 MPa,
 * rho = 1 g/cm^3), at rest; from t = 0 the nodes of its left end (x = 0)
 * move at v0 = 1 m/s. One-dimensional wave theory: a front runs right at c;
 * behind it the bar moves at v0 under sigma_xx = -rho c v0 = -1 MPa; ahead
 * of it, rest. At t = L / c the front is at L. Where is the front of a
 * discrete solution? Dispersion spreads the step into oscillations that
 * widen like t^(1/3), so the point where v first reaches v0/2 is no sharp
 * measure; the momentum is: the end pushes with rho c v0 A, so the bar's
 * momentum at t is rho A v0 c t, and P / (rho A v0) is the front's
 * position whatever its shape. The test asserts it within two cells of L
 * for L = 60, 120 and 180 cells, and, over the bar from 5 mm to 10 mm short
 * of the front, the mean velocity and stress within 1 % of v0 and
 * -rho c v0 (the oscillations about them average out). The driven nodes
 * hold v0 exactly. A fourth run ramps the velocity in over t_r = 0.02 ms
 * (L = 120): the end then gives the impulse rho c A v0 (t - t_r / 2), and
 * the front by momentum is at c (t - t_r / 2) = 110 mm; the plateau behind
 * the ramp ends 20 mm earlier. A ramp 20 cells long carries no wavelength
 * the grid disperses, and the sudden start's offset (-0.4 to -0.54 cells
 * above) is gone, so we ask for a tenth of a cell there (measured 0.005;
 * without the force m dv/dt at Task 4 it is 0.2).
 *
 * The same steps driven through the points instead (point_velocities: the
 * points of the end's first half cell held at v0, which holds the nodes
 * they reach, x = 0 and 1 mm): the first cell moves as a rigid piston, so
 * the wave starts at x = 1 mm and the slab behind it adds 1 mm to the
 * front by momentum; then the same bounds. Last, the ramp given as a
 * table, ( [0, 0, 0], [0.02, v0, 0] ), must give the same run to the bit.
 */
#include <stdio.h>
#include <stdlib.h>

#include "testkit.h"

#define V0 1.0
#define C 1000.0        /* mm/ms */
#define RHO 1.0e-3
#define AREA 2.0        /* height x thickness (mm^2) */

/** Drive the bar's end at V0 (ramped over @p tr, as a table when
 *  @p table) through its nodes or, with @p points, through its first
 *  points; check at t = L / c; return the front by momentum. */
static double drive_bar(double L, double tr, int points, int table)
{
    double T = L / C;
    char text[2048], drive[256];
    if (points)
        snprintf(drive, sizeof drive, "point_velocities = ( { rectangle = { min = "
                 "[0.0, 0.0]; max = [0.5, 2.0]; }; fix = \"x\"; velocity = [%#.17g, "
                 "0.0]; ramp = %#.17g; } );\n", V0, tr);
    else if (table)
        snprintf(drive, sizeof drive, "boundaries = ( { rectangle = { min = "
                 "[0.0, -2.0]; max = [0.0, 4.0]; }; fix = \"x\"; table = ( "
                 "[0.0, 0.0, 0.0], [%#.17g, %#.17g, 0.0] ); } );\n", tr, V0);
    else
        snprintf(drive, sizeof drive, "boundaries = ( { rectangle = { min = "
                 "[0.0, -2.0]; max = [0.0, 4.0]; }; fix = \"x\"; velocity = [%#.17g, "
                 "0.0]; ramp = %#.17g; } );\n", V0, tr);
    snprintf(text, sizeof text,
        "grid = { origin = [-2.0, -2.0]; cells = [204, 6]; cell_size = [1.0, 1.0]; };\n"
        "run = { time = %.17g; cfl = 0.5; update = \"musl\"; plane = \"stress\"; snapshots = 0; };\n"
        "materials = ( { name = \"m\"; E = 1000.0; nu = 0.0; rho = 1.0e-3; } );\n"
        "bodies = ( { name = \"bar\"; material = \"m\"; thickness = 1.0; points_per_cell = 2;\n"
        "  rectangle = { min = [0.0, 0.0]; max = [200.0, 2.0]; }; } );\n%s", T, drive);
    Sim *sim = tk_load(text);
    if (points)
        assert_int_equal(sim->scene.held[0].count, 4);  /* x = 0.25, 4 rows */
    else
        assert_int_equal(sim->nmoving, 7);             /* the column x = 0 */
    tk_steps(sim, sim->nsteps);
    const Particles *P = &sim->pts;
    Totals t = sim_totals(sim);
    double front = t.px / (RHO * AREA * V0);
    double v = 0, s = 0, half = 0;
    int n = 0;
    for (int p = 0; p < P->n; p++) {
        if (P->x[p] > 5.0 && P->x[p] < L - C * tr - 10.0) {
            v += P->vx[p];
            s += P->sxx[p];
            n++;
        }
        if (P->vx[p] >= 0.5 * V0 && P->x[p] > half)
            half = P->x[p];
    }
    v /= n;
    s /= n;
    double want = C * (T - 0.5 * tr) + (points ? 1.0 : 0.0);  /* the piston */
    printf("  %s, L = %3.0f mm, ramp %.2f ms, t = L/c = %.3f ms (%ld steps): front "
           "by momentum %.3f mm (%+.3f cells from %.0f), where v first reaches v0/2 "
           "%.3f mm; behind: v %.4f v0, sigma_xx %.4f rho c v0\n",
           points ? "points" : "nodes ", L, tr, sim->t, sim->step, front,
           front - want, want, half, v / V0, s / (RHO * C * V0));
    assert_close(front, want, tr > 0 ? 0.1 : 2.0);
    assert_close(v, V0, 0.01 * V0);
    assert_close(s, -RHO * C * V0, 0.01 * RHO * C * V0);
    const Grid *g = &sim->grid;
    for (int m = 0; m < sim->nmoving; m++)
        assert_close(g->vx[sim->moving[m]], V0, 0.0);
    tk_free(sim);
    return front;
}

static void front_runs_at_the_bar_speed(void **state)
{
    (void)state;
    double ramped = 0.0;
    for (int points = 0; points < 2; points++) {
        drive_bar(60.0, 0.0, points, 0);
        drive_bar(120.0, 0.0, points, 0);
        drive_bar(180.0, 0.0, points, 0);
        double f = drive_bar(120.0, 0.02, points, 0);
        if (!points)
            ramped = f;
    }
    assert_close(drive_bar(120.0, 0.02, 0, 1), ramped, 0.0);  /* the table */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(front_runs_at_the_bar_speed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
