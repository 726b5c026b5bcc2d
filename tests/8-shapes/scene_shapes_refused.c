/**
 * @file scene_shapes_refused.c
 * @brief What stage 8 refuses with run.shape = "gimp" or "cpdi", with exit
 *        status 1 and a message naming the scene: another run.method (contact
 *        between bodies and crack contact are no longer refused: a few
 *        steps of the touching bars and of Fig. 3's cracked disks end
 *        with exit status 0; scene_bars_gimp.c and scene_fig3_gimp.c
 *        test them); and the stop (exit
 *        status 3, naming step and point) when a domain leaves the grid:
 *        the DCB's beam against the grid's left edge (grid.origin moved to
 *        the beam's end) loses a point's domain in its first step.
 *        run.transfer = "apic" is refused with cracks and with XEFG alike.
 */
#include <stdio.h>
#include <string.h>

#include "testkit.h"

static char out[16384];

/** mpm on @p args must exit with @p status and @p expect in its message. */
static void ends(const char *args, int status, const char *expect)
{
    int rc = tk_run_mpm(args, out, sizeof out);
    printf("  %s\n    -> exit %d: %s", args, rc, out);
    if (rc != status || !strstr(out, expect))
        fail_msg("expected exit %d and \"%s\"", status, expect);
}

static void what_the_smooth_shapes_refuse(void **state)
{
    (void)state;
    /* contact is no longer refused (contact_stencil.h): both kinds run a
       few steps with either shape and end as a run does */
    ends("tests/4-contact/scenes/bars_touching.cfg -q -o build/test-shapes-refused "
         "run.shape=gimp run.time=0.1", 0, "mpm: done, output in build/test-shapes-refused");
    ends("tests/4-contact/scenes/bars_touching.cfg -q -o build/test-shapes-refused "
         "run.shape=cpdi run.time=0.1", 0, "mpm: done, output in build/test-shapes-refused");
    ends("figures/fig3/cracked_disks.cfg -q -o build/test-shapes-refused "
         "run.shape=gimp run.time=0.05 run.snapshots=0", 0,
         "mpm: done, output in build/test-shapes-refused");
    ends("figures/fig3/cracked_disks.cfg -q -o build/test-shapes-refused "
         "run.shape=cpdi run.time=0.05 run.snapshots=0", 0,
         "mpm: done, output in build/test-shapes-refused");
    ends("tests/1-mpm/scenes/spinning_disk.cfg -q -o build/test-shapes-refused "
         "run.shape=gimp run.method=xefg run.stress_rate=unrotated", 1,
         "needs run.method = \"mpm\"");
    ends("figures/fig1/dcb_full.cfg -q -o build/test-shapes-refused run.transfer=apic",
         1, "figures/fig1/dcb_full.cfg: run.transfer = \"apic\" with cracks or contact");
    ends("tests/1-mpm/scenes/spinning_disk.cfg -q -o build/test-shapes-refused "
         "run.transfer=apic run.method=xefg run.stress_rate=unrotated", 1,
         "run.transfer = \"apic\" needs run.method = \"mpm\"");
    ends("figures/fig1/dcb_half.cfg -q -o build/test-shapes-refused run.shape=gimp "
         "grid.origin=[0.0,-20.0]", 3,
         "unstable at step 1 (t = 0.113347 ms): particle 0 GIMP domain (left the grid)");
    ends("figures/fig1/dcb_half.cfg -q -o build/test-shapes-refused run.shape=cpdi "
         "grid.origin=[0.0,-20.0]", 3, "particle 0 CPDI domain x (left the grid)");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(what_the_smooth_shapes_refuse),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
