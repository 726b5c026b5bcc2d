/**
 * @file scene_xefg_threads.c
 * @brief XEFG's Gauss points are updated on several threads
 *        (xefg_strain_update(), run.threads): every scene of chapter 6's
 *        folder writes the same bytes on 1, 2, 3 and 4 threads, a
 *        stationary crack, a cohesive one, and two that grow.
 *
 * The update of a Gauss point writes that point's stress and strain only,
 * and the forces are summed afterwards in the order of the points, as on
 * one thread: no sum depends on the number of threads. The files are
 * written with run.precision = "full" (17 digits: every bit), and compared
 * byte for byte; the run's first line names the threads it used.
 */
#include "testkit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define OUT "build/test-xefg-threads"

static const char *const scenes[] = {"plate_crack", "cohesive_bar",
                                     "growth_bar", "growth_beam"};
/** How long each runs (ms; "" the scene's time): the cohesive bar to a
 *  sixth of its pull, its crack open and softening (a tenth of G_f spent);
 *  the growing ones a little past their last growth event (the bar's
 *  seventh at 0.230 ms, the beam's second at 0.729 ms), so that every
 *  event is in the bytes compared: the run must say it grew that often. */
static const char *const times[] = {"", "0.5", "0.3", "0.8"};
static const char *const grew[] = {NULL, NULL, "crack 0 grew 7 of", "crack 0 grew 2 of"};

static void same_bytes_on_any_number_of_threads(void **state)
{
    (void)state;
    for (size_t s = 0; s < sizeof scenes / sizeof scenes[0]; s++) {
        for (int t = 1; t <= 4; t++) {
            char args[512], out[4096], want[32];
            snprintf(args, sizeof args, "tests/6-xefg/scenes/%s.cfg -q -o "
                     OUT "/%s.%d run.precision=\\\"full\\\" run.threads=%d%s%s",
                     scenes[s], scenes[s], t, t, times[s][0] ? " run.time=" : "",
                     times[s]);
            assert_int_equal(tk_run_mpm(args, out, sizeof out), 0);
            snprintf(want, sizeof want, ", %d thread%s\n", t, t == 1 ? "" : "s");
            if (!strstr(out, want))
                fail_msg("%s on %d threads: the first line does not say so:\n%s",
                         scenes[s], t, out);
            if (grew[s] && !strstr(out, grew[s]))
                fail_msg("%s on %d threads: no \"%s\" in its report:\n%s", scenes[s],
                         t, grew[s], out);
        }
        char one[128], other[128];
        snprintf(one, sizeof one, OUT "/%s.1", scenes[s]);
        for (int t = 2; t <= 4; t++) {          /* every file, every byte */
            snprintf(other, sizeof other, OUT "/%s.%d", scenes[s], t);
            tk_assert_same_outputs(one, other, NULL);
        }
        printf("  %-13s the same bytes on 1, 2, 3 and 4 threads\n", scenes[s]);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(same_bytes_on_any_number_of_threads),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
