/**
 * @file scene_growth_restart.c
 * @brief A grown XEFG crack restarts (issue 27; chapter 6b, "A crack's
 *        speed and its restart"): the checkpoint keeps the growth events,
 *        and the restore inserts them again before it loads the state.
 *
 * The bar of tests/6-xefg/scenes/growth_bar.cfg (its edge crack grows 7
 * segments to the top edge, events at steps 2022, 2026, 2030, 2033, 2037,
 * 2041 and 2046), on one thread, to t = 0.26 ms with 13 snapshots (one at
 * 0.24 ms, after the restart and after the step fell), stopped at step
 * 2031 (3 events in, 4 to come) and restarted. Bounds, fixed before the
 * first run (the laws of a restart, not numbers):
 * - grown_crack_restarts: every output (history.csv, particles_final.csv,
 *   the snapshots, the cracks_NNNNN paths, the .pvd series) the same bytes
 *   as the run not stopped, and the report's growth lines (events, the
 *   last tip, the stable step, the power iterations after set-up) the
 *   same text; so too with the crack given from its tip to its mouth (it
 *   grows at its end 0: new points go first) and with max_speed = 400
 *   mm/ms (steps waited, which the report counts, and the next event's
 *   time, taken from the last one's).
 * - foreign_grown_checkpoints_are_refused: the stopped run's scene edited
 *   (f_t) is refused as another scene; an event patched so that it no
 *   longer starts at its crack's tip (its old tip x moved 1 mm) is
 *   refused, naming the event, and the checkpoint.
 */
#include <stdlib.h>
#include <string.h>

#include "testkit.h"

#define SCENE "tests/6-xefg/scenes/growth_bar.cfg"
#define OUT "build/test-growth-restart"
#define ARGS "-q run.threads=1 run.time=0.26 run.history_every=10 run.snapshots=13"
#define STOP "2031"

static char out[16384];

/** $MPM_BIN with @p args; the test fails unless it exits 0. */
static void run_ok(const char *args)
{
    tk_run_mpm_ok(args, out, sizeof out);
}

/** The report's "mpm: growth:" lines of the last run, into @p lines. */
static void growth_lines(char *lines, size_t len)
{
    lines[0] = '\0';
    size_t used = 0;
    for (const char *l = strstr(out, "mpm: growth:"); l;
         l = strstr(l + 1, "mpm: growth:")) {
        const char *e = strchr(l, '\n');
        size_t n = e ? (size_t)(e - l) + 1 : strlen(l);
        if (used + n >= len)
            fail_msg("report too long");
        memcpy(lines + used, l, n);
        used += n;
        lines[used] = '\0';
    }
}

/** The scene with @p over, run whole into OUT/@p name/full and stopped at
 *  step STOP and restarted into OUT/@p name/split: the same bytes. */
static void same_bytes(const char *name, const char *over)
{
    char cmd[1024], full[2048], split[2048];
    snprintf(cmd, sizeof cmd, "rm -rf " OUT "/%s", name);
    assert_int_equal(system(cmd), 0);
    snprintf(cmd, sizeof cmd, SCENE " " ARGS " %s -o " OUT "/%s/full", over, name);
    run_ok(cmd);
    growth_lines(full, sizeof full);
    snprintf(cmd, sizeof cmd, SCENE " " ARGS " %s -o " OUT "/%s/split "
             "--stop-at " STOP, over, name);
    run_ok(cmd);
    assert_null(strstr(out, "mpm: growth:"));      /* stopped: no report */
    snprintf(cmd, sizeof cmd, "--restart " OUT "/%s/split -q", name);
    run_ok(cmd);
    growth_lines(split, sizeof split);
    printf("  %s: whole and restarted at step " STOP ":\n%s", name, full);
    assert_non_null(strstr(full, "grew 7 of"));
    assert_string_equal(full, split);
    char a[256], b[256];
    snprintf(a, sizeof a, OUT "/%s/full", name);
    snprintf(b, sizeof b, OUT "/%s/split", name);
    tk_assert_same_outputs(a, b, "checkpoint.mpm");
}

static void grown_crack_restarts(void **state)
{
    (void)state;
    same_bytes("end1", "");
    same_bytes("end0", "'cracks.[0].points=([6.0, 2.5], [6.0, 0.5])'");
    same_bytes("speed", "cracks.[0].cohesive.growth.max_speed=400");
}

/** Refused with exit 1, the message naming the checkpoint and @p why. */
static void restart_refused(const char *dir, const char *why)
{
    char args[512];
    snprintf(args, sizeof args, "--restart %s -q", dir);
    int rc = tk_run_mpm(args, out, sizeof out);
    if (rc != 1 || !strstr(out, "checkpoint.mpm") || !strstr(out, why))
        fail_msg("mpm %s: exit %d, want 1 and \"%s\":\n%s", args, rc, why, out);
    printf("  refused: %s", out);
}

/** A run of the bar (the scene copied to OUT/bad) stopped at step STOP. */
static void stopped_run(void)
{
    assert_int_equal(system("rm -rf " OUT "/bad && mkdir -p " OUT "/bad && cp "
                            SCENE " " OUT "/bad/scene.cfg"), 0);
    run_ok(OUT "/bad/scene.cfg " ARGS " -o " OUT "/bad --stop-at " STOP);
}

static void foreign_grown_checkpoints_are_refused(void **state)
{
    (void)state;
    stopped_run();                                    /* the scene edited */
    assert_int_equal(system("sed -i 's/f_t = 1.0/f_t = 1.1/' " OUT
                            "/bad/scene.cfg"), 0);
    restart_refused(OUT "/bad", "the scene or its overrides changed");

    stopped_run();             /* the first event: crack 0, end 1, step 2022 */
    size_t len;
    char *ck = tk_slurp(OUT "/bad/checkpoint.mpm", &len);
    struct { int crack, end; long step; } key = {0, 1, 2022};
    char *ev = NULL;
    for (size_t k = 0; !ev && k + sizeof key <= len; k++)
        if (memcmp(ck + k, &key, sizeof key) == 0)
            ev = ck + k;
    assert_non_null(ev);
    double x0;               /* after t, sigma1, KI, KII: the old tip's x */
    memcpy(&x0, ev + sizeof key + 4 * sizeof(double), sizeof x0);
    assert_true(x0 == 6.0);
    x0 = 5.0;
    memcpy(ev + sizeof key + 4 * sizeof(double), &x0, sizeof x0);
    FILE *f = fopen(OUT "/bad/checkpoint.mpm", "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(ck, 1, len, f), len);
    assert_int_equal(fclose(f), 0);
    free(ck);
    restart_refused(OUT "/bad", "event 0 of the checkpoint does not continue");
}

int main(void)
{
    assert_int_equal(system("mkdir -p " OUT), 0);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(grown_crack_restarts),
        cmocka_unit_test(foreign_grown_checkpoints_are_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
