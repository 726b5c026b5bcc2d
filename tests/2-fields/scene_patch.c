/**
 * @file scene_patch.c
 * @brief The crack patch test (paper's section 3.1): the full double
 *        cantilever beam with an explicit crack, run by CRAMP, equals the
 *        half beam run by conventional MPM with the symmetry condition.
 *
 * The upper half of the full run must equal the half run at every step.
 * Bitwise equality is out of reach: at the ligament nodes on the mid-plane
 * the full run adds the lower half's contributions to the upper half's.
 * The scene puts the mid-plane at y = 0, so the lower half stays the exact
 * mirror image of the upper half (negation is exact in floating point), but
 * the sums run in particle order, lower rows first, and floating-point
 * addition in another order rounds differently.  So each quantity's
 * difference is bounded by 1e-12 times
 * the largest value that quantity takes during the run (round-off scales
 * with the values that produced it; velocities decay by damping, so a bound
 * relative to their final, tiny values would measure the damping instead).
 *
 * PATCH_SHIFT_Y=18 (mm) moves both scenes up by that much (the full
 * specimen at 0 < y < 36) and prints the same lines without judging them:
 * the mirror image is then lost to rounding (chapter 2 quotes the ratios).
 */
#include "crack_patch.h"
#include "testkit.h"

#include <stdio.h>
#include <stdlib.h>

static double shift;      /* PATCH_SHIFT_Y (mm); 0: the test */

/** Overrides that move the DCB scenes up by @p shift (the files' y values
 *  plus shift), into @p buf; a NULL-ended list in @p ov. */
static void shifted(int full, char buf[][128], const char *ov[])
{
    const double dx = 1.9607843137254901, d = shift;
    int n = 0;
    snprintf(buf[n++], 128, "grid.origin=[%#.17g, %#.17g]", -dx, -20.0 + d);
    snprintf(buf[n++], 128, "bodies.[0].rectangle.min=[0.0, %#.17g]", (full ? -18.0 : 0.0) + d);
    snprintf(buf[n++], 128, "bodies.[0].rectangle.max=[100.0, %#.17g]", 18.0 + d);
    snprintf(buf[n++], 128, "loads.[0].rectangle.min=[0.0, %#.17g]", d);
    snprintf(buf[n++], 128, "loads.[0].rectangle.max=[1.0, %#.17g]", 18.0 + d);
    if (full) {
        snprintf(buf[n++], 128, "loads.[1].rectangle.min=[0.0, %#.17g]", -18.0 + d);
        snprintf(buf[n++], 128, "loads.[1].rectangle.max=[1.0, %#.17g]", d);
        snprintf(buf[n++], 128, "cracks.[0].points=([%#.17g, %#.17g], [50.0, %#.17g])", -dx, d, d);
    } else {
        snprintf(buf[n++], 128, "boundaries.[0].rectangle.min=[50.0, %#.17g]", d);
        snprintf(buf[n++], 128, "boundaries.[0].rectangle.max=[110.0, %#.17g]", d);
    }
    for (int k = 0; k < n; k++)
        ov[k] = buf[k];
    ov[n] = NULL;
}

static void full_run_equals_half_run(void **state)
{
    (void)state;
    char bf[10][128], bh[10][128];
    const char *of[11], *oh[11];
    shifted(1, bf, of);
    shifted(0, bh, oh);
    Sim *full = tk_load_file("figures/fig1/dcb_full.cfg", shift != 0 ? of : NULL);
    Sim *half = tk_load_file("figures/fig1/dcb_half.cfg", shift != 0 ? oh : NULL);
    assert_true(full->nsteps == half->nsteps);
    Patch r = patch_compare(full, half, half->nsteps);
    patch_print(&r);
    for (int q = 0; q < PATCH_NQ; q++)
        if (shift == 0)
            assert_true(r.diff[q] <= 1e-12 * r.scale[q]);
    tk_free(full);
    tk_free(half);
}

int main(void)
{
    const char *sh = getenv("PATCH_SHIFT_Y");
    if (sh) {
        char *end;
        shift = strtod(sh, &end);
        if (end == sh || *end) {
            fprintf(stderr, "PATCH_SHIFT_Y=%s: give a shift in mm\n", sh);
            return 2;
        }
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(full_run_equals_half_run),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
