/**
 * @file test_snapshot_times.c
 * @brief Snapshots land on the step nearest the asked times k T / K, and
 *        every snapshot file carries its time.
 *
 * Steps are whole: step n ends at n dt. Snapshot k of K is asked at k T / K
 * and written after the step nearest it, so |t_k - k T / K| <= dt / 2 (the
 * first at least one step in, the last at most the last step). The VTU's
 * TimeValue field (what ParaView shows as the time) and step field must be
 * the pvd's time and t_k / dt.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testkit.h"

#define OUT "build/test-snapshot-times"

static void snapshots_at_the_nearest_steps(void **state)
{
    (void)state;
    const int K = 7;
    const double T = 1.05;                          /* 125 steps, not a multiple of 7 */
    char args[512], out[4096];
    snprintf(args, sizeof args, "tests/1-mpm/scenes/disks.cfg -o " OUT " run.time=%.17g "
             "run.snapshots=%d run.precision=full", T, K);
    assert_int_equal(tk_run_mpm(args, out, sizeof out), 0);
    const char *d = strstr(out, "dt = ");
    assert_non_null(d);
    double dt = strtod(d + 5, NULL);               /* printed to 6 digits */
    char *pvd = tk_slurp(OUT "/particles.pvd", NULL);
    const char *c = pvd;
    int k = 0;
    double worst = 0.0;
    while ((c = strstr(c, "timestep=\"")) != NULL) {
        double t = strtod(c + 10, NULL);
        char path[256];
        snprintf(path, sizeof path, OUT "/particles_%05d.vtu", k);
        char *vtu = tk_slurp(path, NULL);
        const char *tv = strstr(vtu, "Name=\"TimeValue\"");
        const char *st = strstr(vtu, "Name=\"step\"");
        assert_non_null(tv);
        assert_non_null(st);
        double vt = strtod(strchr(tv, '>') + 1, NULL);
        long step = strtol(strchr(st, '>') + 1, NULL, 10);
        assert_close(vt, t, 0.0);                   /* same 17 digits */
        assert_close(step * dt, t, 1e-5 * t + 1e-12);  /* dt has 6 digits */
        double off = fabs(t - k * T / K);
        if (k > 0)
            worst = fmax(worst, off);
        if (k > 0 && !(off <= 0.5 * dt * (1 + 1e-5)))
            fail_msg("snapshot %d at t = %.17g, asked %.17g: more than dt/2 = %g off",
                     k, t, k * T / K, 0.5 * dt);
        free(vtu);
        k++;
        c++;
    }
    assert_int_equal(k, K + 1);                     /* t = 0 and K more */
    printf("  %d snapshots, largest |t_k - k T / K| = %.3g (dt / 2 = %.3g)\n", K,
           worst, 0.5 * dt);
    free(pvd);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(snapshots_at_the_nearest_steps),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
