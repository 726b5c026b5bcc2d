/**
 * @file scene_growth_inclined.c
 * @brief Chapter 7's growth under mixed mode: the centre crack at 45
 *        degrees of tests/7-fracture/scenes/inclined_growth.cfg, pulled
 *        across by the grid, kinks at its first event by the angle of
 *        maximum hoop stress, and then grows across the load.
 *
 * For a crack at beta = 45 degrees to a uniaxial stress in an infinite
 * plate, K_II / K_I = tan(beta) = 1 and theta_c = -2 atan(1/2) = -53.13
 * degrees at both tips (each in its own frame). The plate's edges lie 24
 * mm from the tips (a/W = 0.1), and the MPM's K carry their own errors; a
 * change of K_II / K_I by 10 % moves theta_c by 1.4 degrees.
 * Bounds (chosen after one exploratory run of the scene, whose snapshots
 * showed the first new segments about 54 degrees from the crack): the
 * first kink at each tip within 3 degrees of -53.13;
 * the new segment turned from the crack by that kink (1e-9 rad); by the
 * end, the line from the first new point to the tip within 10 degrees of
 * the normal to the load (x).
 */
#include "testkit.h"

#include <stdio.h>

#include "crack_growth.h"
#include "cracks.h"

#define SCENE "tests/7-fracture/scenes/inclined_growth.cfg"
#define DEG (45.0 / atan(1.0))

static void kinks_by_the_hoop_angle_then_grows_across(void **state)
{
    (void)state;
    Sim *sim = tk_load_file(SCENE, NULL);
    const Crack *c = &cracks_of(sim)->crack[0];
    const CrackGrowth *G = sim_state(sim, "crack-growth");
    assert_non_null(G);
    double kink[2] = {0.0, 0.0}, turn[2] = {0.0, 0.0};
    double first[2][2] = {{0, 0}, {0, 0}};
    int seen[2] = {0, 0};
    for (long n = 0; n < sim->nsteps; n++) {
        tk_steps(sim, 1);
        for (int end = 0; end < 2; end++) {
            if (seen[end] || G->end[end].events == 0)
                continue;
            /* the new segment and the one before it, pointing ahead */
            int i = end ? c->n - 1 : 0, j = end ? i - 1 : 1, k = end ? i - 2 : 2;
            double a = atan2(c->y[i] - c->y[j], c->x[i] - c->x[j]);
            double b = atan2(c->y[j] - c->y[k], c->x[j] - c->x[k]);
            kink[end] = G->end[end].theta;
            turn[end] = remainder(a - b, 8.0 * atan(1.0));
            first[end][0] = c->x[i];
            first[end][1] = c->y[i];
            seen[end] = 1;
            printf("  %s point: first event after step %ld (t = %.2f ms), "
                   "kink %.3f degrees (infinite plate -53.130), segment "
                   "turned %.3f\n", end ? "last" : "first", G->end[end].last_step,
                   sim->t, kink[end] * DEG, turn[end] * DEG);
        }
    }
    assert_true(seen[0] && seen[1]);
    for (int end = 0; end < 2; end++) {
        assert_close(kink[end] * DEG, -53.130102, 3.0);
        assert_close(turn[end], kink[end], 1e-9);
        int i = end ? c->n - 1 : 0;
        double dx = c->x[i] - first[end][0], dy = c->y[i] - first[end][1];
        double path = atan(dy / dx) * DEG;      /* from x, either way */
        printf("  %s point: %ld events, tip (%.4f, %.4f), path from its first "
               "new point %.2f degrees from x\n", end ? "last" : "first",
               G->end[end].events, c->x[i], c->y[i], path);
        assert_true(G->end[end].events >= 10);
        assert_true(fabs(path) <= 10.0);
    }
    tk_free(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(kinks_by_the_hoop_angle_then_grows_across),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
