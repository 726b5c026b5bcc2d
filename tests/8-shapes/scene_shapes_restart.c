/**
 * @file scene_shapes_restart.c
 * @brief A run with uGIMP or CPDI stopped and restarted gives the same
 *        bytes as one run through: CPDI's deformation gradients travel in
 *        the checkpoint (without them a restarted CPDI run starts its
 *        domains square again and its points differ), and so do APIC's
 *        affine parts B_p (run.transfer = "apic").
 *
 * The spinning disk (tests/1-mpm/scenes/spinning_disk.cfg) for 0.3 ms
 * (636 steps), stopped at step 300: by then each domain has turned 0.15
 * rad, so a lost F would show in the final points.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testkit.h"

#define OUT "build/test-shapes-restart"
#define SPIN "tests/1-mpm/scenes/spinning_disk.cfg run.time=0.3 run.snapshots=2"

static char out[16384];

/** $MPM_BIN with @p args; the test fails unless it exits 0. */
static void run_ok(const char *args)
{
    tk_run_mpm_ok(args, out, sizeof out);
}

static void restart_gives_the_same_bytes(void **state)
{
    (void)state;
    static const char *const shapes[] = {"gimp", "cpdi", "gimp run.transfer=apic"};
    for (int k = 0; k < 3; k++) {
        char args[512];
        system("rm -rf " OUT "/full " OUT "/split");
        snprintf(args, sizeof args, SPIN " run.shape=%s -q -o " OUT "/full", shapes[k]);
        run_ok(args);
        snprintf(args, sizeof args, SPIN " run.shape=%s -q -o " OUT "/split --stop-at 300",
                 shapes[k]);
        run_ok(args);
        run_ok("--restart " OUT "/split -q");
        tk_assert_same_outputs(OUT "/full", OUT "/split", "checkpoint.mpm");
        printf("  %s: stopped at step 300 and restarted, the same bytes\n", shapes[k]);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(restart_gives_the_same_bytes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
