/**
 * @file test_loads.c
 * @brief External forces and damping against exact results: free fall
 *        under a body force, the impulse of a ramped point load, and the
 *        decay of a damped rigid motion (eq. 4).
 */
#include "testkit.h"

#include <stdio.h>

/** A free 4 x 2 mm block (no boundary conditions) with @p extra settings. */
static Sim *block(const char *run_extra, const char *loads)
{
    static char text[2048];
    snprintf(text, sizeof text,
             "grid = { origin = [0.0, 0.0]; cells = [20, 20]; cell_size = [1.0, 1.0]; };\n"
             "run = { time = 1.0; cfl = 0.5; snapshots = 0; %s };\n"
             "materials = ( { name = \"m\"; E = 1.0; nu = 0.25; rho = 1.0e-3; } );\n"
             "bodies = ( { name = \"b\"; material = \"m\"; thickness = 2.0;\n"
             "  velocity = [0.5, 0.0];\n"
             "  rectangle = { min = [4.0, 8.0]; max = [8.0, 10.0]; }; } );\n%s",
             run_extra, loads);
    return tk_load(text);
}

/** Under a body force alone every point falls with v = v0 + g t, exactly
 *  up to round-off, and nothing strains (a uniform acceleration has no
 *  gradient).  MUSL and USF only: USL at cfl 0.5 amplifies the round-off
 *  strain at this small block's edge nodes, which hold 1/16 of a point's
 *  mass, step after step (eq. 20): after 150 steps it measured a strain of
 *  2.2e-9 and a velocity error of 1e-8, where MUSL and USF stay at 1e-18. */
static void free_fall(void **state)
{
    (void)state;
    static const char *schemes[] = {"musl", "usf"};
    for (int k = 0; k < 2; k++) {
        char run[128];
        snprintf(run, sizeof run, "gravity = [0.0, -0.02]; update = \"%s\";",
                 schemes[k]);
        Sim *sim = block(run, "");
        tk_steps(sim, 150);
        const Particles *P = &sim->pts;
        double worst_v = 0, worst_e = 0;
        for (int p = 0; p < P->n; p++) {
            worst_v = fmax(worst_v, fabs(P->vy[p] - (-0.02 * sim->t)));
            worst_v = fmax(worst_v, fabs(P->vx[p] - 0.5));
            worst_e = fmax(worst_e, fabs(P->exx[p]) + fabs(P->eyy[p]) + fabs(P->exy[p]));
        }
        printf("%-4s free fall, %ld steps: max |v - (v0 + g t)| = %.2g, max |eps| = %.2g\n",
               schemes[k], sim->step, worst_v, worst_e);
        assert_true(worst_v <= 1e-13 * (0.5 + 0.02 * sim->t));
        assert_true(worst_e <= 1e-13 * 0.02 * sim->t * sim->t);
        tk_free(sim);
    }
}

/** A point load ramped over t_r gives the body, in step k (at time k dt),
 *  the impulse F min(k dt / t_r, 1) dt: the total momentum must equal that
 *  sum (momentum balance), to round-off, during and after the ramp. */
static void ramped_load_impulse(void **state)
{
    (void)state;
    Sim *sim = block("update = \"musl\";",
                     "loads = ( { rectangle = { min = [7.5, 8.0]; max = [8.0, 10.0]; };\n"
                     "            force = [0.002, -0.001]; ramp = 2.0; } );\n");
    Totals t0 = sim_totals(sim);
    double impulse = 0, mass = 0;
    for (int p = 0; p < sim->pts.n; p++)
        mass += sim->pts.m[p];
    while (sim->t < 4.0) {
        double ramp = fmin(sim->t / 2.0, 1.0);
        impulse += ramp * sim->dt;
        tk_steps(sim, 1);
        Totals t = sim_totals(sim);
        assert_close(t.px - t0.px, 0.002 * impulse, 1e-12 * (fabs(t0.px) + 0.002 * impulse));
        assert_close(t.py - t0.py, -0.001 * impulse, 1e-12 * (fabs(t0.px) + 0.001 * impulse));
    }
    printf("ramped load: %ld steps, impulse %.6g N ms, momentum x gained %.6g\n",
           sim->step, 0.002 * impulse, sim_totals(sim).px - t0.px);
    assert_true(sim->scene.loads[0].count == 4);   /* one column of points */
    (void)mass;
    tk_free(sim);
}

/** Damping -kappa p on every node of a rigid motion: each step multiplies
 *  every velocity by exactly (1 - kappa dt) (eq. 4 with no other force). */
static void damped_rigid_motion(void **state)
{
    (void)state;
    Sim *sim = block("update = \"musl\"; damping = 0.3;", "");
    double decay = 1 - 0.3 * sim->dt;
    tk_steps(sim, 200);
    double expect = 0.5 * pow(decay, 200);
    for (int p = 0; p < sim->pts.n; p++) {
        assert_close(sim->pts.vx[p], expect, 1e-12 * 0.5);
        assert_close(sim->pts.vy[p], 0.0, 1e-15);
    }
    printf("damping: v after 200 steps %.12g, (1 - kappa dt)^200 v0 = %.12g\n",
           sim->pts.vx[0], expect);
    tk_free(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(free_fall),
        cmocka_unit_test(ramped_load_impulse),
        cmocka_unit_test(damped_rigid_motion),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
