/**
 * @file scene_xefg_run.c
 * @brief The mpm program with the meshfree method: one scene file runs with
 *        either method; a run's files are whole; a run stopped and restarted
 *        gives the same bytes as one that was not; a step past the stable
 *        limit stops with a diagnostic, a crack out of room with its own.
 */
#include <stdlib.h>
#include <string.h>

#include "testkit.h"

#define SCENE "tests/6-xefg/scenes/plate_crack.cfg"
#define OUT "build/test-xefg-run"

static char out[8192];

/** $MPM_BIN with @p args; the test fails unless it exits 0. */
static void run_ok(const char *args)
{
    tk_run_mpm_ok(args, out, sizeof out);
}

/** The scene runs with both methods; XEFG's first line and report name it. */
static void one_scene_two_methods(void **state)
{
    (void)state;
    run_ok(SCENE " -q -o " OUT "/xefg");
    assert_non_null(strstr(out, "method xefg"));
    assert_non_null(strstr(out, "mpm: xefg: "));
    assert_non_null(strstr(out, "branch), "));
    tk_assert_outputs_whole(OUT "/xefg");
    run_ok(SCENE " -q -o " OUT "/mpm run.method=mpm");
    assert_non_null(strstr(out, "update musl"));
    assert_null(strstr(out, "mpm: xefg:"));
    tk_assert_outputs_whole(OUT "/mpm");
}

/** A checkpoint holds the parameters and Gauss points: the restart ends
 *  with the same bytes as a run without a stop. */
static void stop_and_restart_gives_the_same_bytes(void **state)
{
    (void)state;
    system("rm -rf " OUT "/full " OUT "/split");
    run_ok(SCENE " -q -o " OUT "/full");
    run_ok(SCENE " -q -o " OUT "/split --stop-at 37");
    assert_non_null(strstr(out, "stopped as asked (--stop-at) after step 37"));
    tk_assert_outputs_whole(OUT "/split");
    run_ok("--restart " OUT "/split -q");
    tk_assert_same_outputs(OUT "/full", OUT "/split", "checkpoint.mpm");
}

/** At the limit: run.cfl = 0.99 of the power iteration's step, undamped,
 *  stays stable for over 2000 steps. */
static void at_the_stable_step_it_runs(void **state)
{
    (void)state;
    run_ok(SCENE " -q -o " OUT "/limit run.cfl=0.99 run.damping=0 run.time=1.0 "
           "run.snapshots=0");
    assert_non_null(strstr(out, "done"));
}

/** Twice the stable step: the run stops with the step, the node and the
 *  quantity, exit status 3, its files whole. */
static void past_the_stable_step_it_stops(void **state)
{
    (void)state;
    int rc = tk_run_mpm(SCENE " -q -o " OUT "/unstable run.cfl=2.0 "
                        "run.allow_cfl_above_one=true run.damping=0", out, sizeof out);
    if (rc != 3)
        fail_msg("exit %d, expected 3: %s", rc, out);
    assert_non_null(strstr(out, "unstable at step"));
    assert_non_null(strstr(out, "particle"));
    assert_non_null(strstr(out, "left the grid"));
    tk_assert_outputs_whole(OUT "/unstable");
}

/** A crack that has used the room set aside for it stops the run by a
 *  rule, not an instability: exit status 3, the line says "stopped" and
 *  why, not "unstable", and the files are whole. */
static void a_crack_out_of_room_stops(void **state)
{
    (void)state;
    int rc = tk_run_mpm("tests/6-xefg/scenes/growth_bar.cfg -q -o " OUT "/room "
                        "run.time=0.6 cracks.[0].cohesive.growth.max_segments=3",
                        out, sizeof out);
    if (rc != 3)
        fail_msg("exit %d, expected 3: %s", rc, out);
    assert_non_null(strstr(out, "stopped at step"));
    assert_non_null(strstr(out, "max_segments = 3"));
    assert_null(strstr(out, "unstable"));
    tk_assert_outputs_whole(OUT "/room");
}

/** A discretisation that would not fit is refused before its rows are
 *  built, with the estimate and the limit. */
static void too_large_is_refused(void **state)
{
    (void)state;
    int rc = tk_run_mpm("figures/fig1/dcb_full.cfg -q -o " OUT "/large "
                        "run.method=xefg --max-memory 20", out, sizeof out);
    if (rc != 1)
        fail_msg("exit %d, expected 1: %s", rc, out);
    assert_non_null(strstr(out, "the XEFG discretisation needs about"));
    assert_non_null(strstr(out, "more than the 0.02 GB available"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(one_scene_two_methods),
        cmocka_unit_test(stop_and_restart_gives_the_same_bytes),
        cmocka_unit_test(at_the_stable_step_it_runs),
        cmocka_unit_test(past_the_stable_step_it_stops),
        cmocka_unit_test(a_crack_out_of_room_stops),
        cmocka_unit_test(too_large_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
