/**
 * @file scene_spinning_disk_gimp.c
 * @brief The free spinning disk of tests/1-mpm/scenes/spinning_disk.cfg
 *        (1 mm cells, one revolution) with the paper's linear shape
 *        functions, uGIMP and CPDI: the noise of a rigid spin, and what
 *        the smoother functions leave of it.
 *
 * Physics puts a centripetal von Mises stress of 0.41 rho v^2 at the
 * centre (steady; a sudden start rings about it, to about twice that).
 *
 * Issue 30's target, fixed before the first run: with GIMP the largest
 * von Mises stress after one turn at most a tenth of linear's, and the
 * kinetic energy within 0.5 %. It is NOT met by uGIMP with the scene's
 * MUSL: the first run gave linear 27.4, GIMP 44.4 rho v^2 (median 10.9
 * and 10.8), kinetic energy 0.965 and 0.950 of the start. CPDI
 * (Sadeghirad et al. 2011), whose domains turn with the material, was
 * added after that run and does no better (median 11.49, largest 43.0).
 * The median point, inside the disk, is as noisy with all three, so this
 * noise is not chiefly the gradient's jump at cell edges; it falls with
 * finer cells and more points per cell, not with a smaller time step.
 * Its source is the transfer (chapter 8, test_apic.c): a node's velocity
 * is the mass average of its points' velocities, w x (their mass centre)
 * in a spin, not w x x_i. uGIMP with the APIC transfer meets the target
 * (scene_spinning_disk_apic.c); this test keeps the paper's transfer.
 *
 * What the test asserts by default, bounds set after that first run from
 * its numbers (so they record, they do not predict):
 * - linear with USL goes unstable within the turn (an empty cell's point
 *   takes its node's whole velocity), GIMP with USL completes it;
 * - GIMP with USL: largest von Mises at most 0.2 of linear MUSL's (3.86
 *   against 27.4 measured), angular momentum within 5 %;
 * - CPDI's angular momentum within 5 % (0.954 measured).
 * The five turns take about 18 s; MPM_SPIN_CELLS=0.5 runs them on the
 * finer grid of chapter 1's test (four times as long).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "spin.h"
#include "testkit.h"

/** One revolution with run.shape = @p shape; the ratios to the start. */
static Spin one_turn(const char *shape, const char *cells, const char *size,
                     Spin *ratio)
{
    char opt[64];
    snprintf(opt, sizeof opt, "run.shape=%s", shape);
    const char *const over[] = {opt, cells, size, NULL};
    Sim *sim = tk_load_file("tests/1-mpm/scenes/spinning_disk.cfg", over);
    Spin start = spin_measure(sim);
    tk_steps(sim, sim->nsteps);
    Spin end = spin_measure(sim);
    ratio->ke = end.ke / start.ke;
    ratio->lz = end.lz / start.lz;
    printf("  %-6s %d points, %ld steps to t = %.4f ms: kinetic energy %.5f of "
           "its start, angular momentum %.5f; von Mises / rho v^2: median %.3f, "
           "largest %.3f\n", shape, sim->pts.n, sim->step, sim->t, ratio->ke,
           ratio->lz, end.vm_median, end.vm_max);
    tk_free(sim);
    return end;
}

/** Does run.shape = @p shape with run.update = usl get through the turn? */
static int usl_completes(const char *shape, const char *cells, const char *size,
                         Spin *end, Spin *ratio)
{
    char opt[64];
    snprintf(opt, sizeof opt, "run.shape=%s", shape);
    const char *const over[] = {opt, "run.update=usl", cells, size, NULL};
    long k[2];
    Failure f;
    int rc = spin_turn(over, spin_measure, end, ratio, k, &f);
    if (rc == 0)
        printf("  %-6s usl:  %ld steps: kinetic energy %.5f, angular momentum "
               "%.5f; von Mises / rho v^2: median %.3f, largest %.3f\n", shape,
               k[0], ratio->ke, ratio->lz, end->vm_median, end->vm_max);
    else
        printf("  %-6s usl:  unstable at step %ld of %ld (%s of point %d)\n",
               shape, f.step, k[1], f.quantity, f.particle);
    return rc == 0;
}

static void gimp_and_cell_crossing_noise(void **state)
{
    (void)state;
    const char *h = getenv("MPM_SPIN_CELLS");
    int fine = h && strcmp(h, "0.5") == 0;
    const char *cells = fine ? "grid.cells=[64, 64]" : "grid.cells=[32, 32]";
    const char *size = fine ? "grid.cell_size=[0.5, 0.5]" : "grid.cell_size=[1.0, 1.0]";
    Spin rl, rg, ru = {0, 0, 0, 0}, gu = {0, 0, 0, 0};
    Spin rc;
    Spin lin = one_turn("linear", cells, size, &rl);
    Spin gimp = one_turn("gimp", cells, size, &rg);
    Spin cpdi = one_turn("cpdi", cells, size, &rc);
    printf("  musl, gimp / linear: largest von Mises %.4f (issue's target 0.1), "
           "median %.4f\n", gimp.vm_max / lin.vm_max, gimp.vm_median / lin.vm_median);
    printf("  musl, cpdi / linear: largest von Mises %.4f (issue's target 0.1), "
           "median %.4f\n", cpdi.vm_max / lin.vm_max, cpdi.vm_median / lin.vm_median);
    assert_close(rc.lz, 1.0, 0.05);              /* as linear's, 0.967 */
    int lin_usl = usl_completes("linear", cells, size, &ru, &ru);
    assert_true(usl_completes("gimp", cells, size, &gu, &ru));
    printf("  gimp usl / linear musl: largest von Mises %.4f (bound 0.2)\n",
           gu.vm_max / lin.vm_max);
    assert_false(lin_usl);
    assert_true(gu.vm_max <= 0.2 * lin.vm_max);
    assert_close(ru.lz, 1.0, 0.05);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(gimp_and_cell_crossing_noise),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
