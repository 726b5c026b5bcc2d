/**
 * @file scene_restart.c
 * @brief Checkpoint and restart (issue 10): a run stopped after N steps
 *        and restarted writes the same bytes as a run that never stopped;
 *        an interrupt (SIGINT, SIGTERM) leaves whole files, a checkpoint
 *        and exit status 128 + the signal; a checkpoint of another
 *        stage, format or scene is refused.
 *
 * Scenes of chapter 1 (every build runs them); tests/4-contact adds the
 * cracked scene with contact.
 */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "stages.h"
#include "testkit.h"

#define OUT "build/test-restart"
#define DISKS "tests/1-mpm/scenes/disks.cfg"
/* a disk spinning for 600 ms: about a million steps, so an interrupt
   always comes before the end */
#define SPIN "tests/1-mpm/scenes/spinning_disk.cfg run.time=600 " \
             "run.history_every=20 run.snapshots=4000 run.checkpoint_every=500"

static char out[16384];

/** $MPM_BIN with @p args; the test fails unless it exits 0. */
static void run_ok(const char *args)
{
    tk_run_mpm_ok(args, out, sizeof out);
}

/** A run of 2N steps and one of N steps restarted for N more: the same
 *  files, byte for byte (the stopped run keeps its checkpoint). */
static void stop_and_restart_gives_the_same_bytes(void **state)
{
    (void)state;
    system("rm -rf " OUT "/full " OUT "/split");
    run_ok(DISKS " -q -o " OUT "/full run.snapshots=6");
    run_ok(DISKS " -q -o " OUT "/split run.snapshots=6 --stop-at 200");
    assert_non_null(strstr(out, "stopped as asked (--stop-at) after step 200 of 417"));
    assert_null(strstr(out, "done"));
    tk_assert_outputs_whole(OUT "/split");
    run_ok("--restart " OUT "/split -q");
    assert_non_null(strstr(out, "(217 steps in"));
    tk_assert_same_outputs(OUT "/full", OUT "/split", "checkpoint.mpm");
}

/** Start mpm on @p args in the background; @return its pid. */
static pid_t start_mpm(const char *args, const char *log)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "exec %s %s > %s 2>&1", tk_mpm_bin(), args, log);
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        execl("/bin/sh", "sh", "-c", cmd, (char *)NULL);
        _exit(127);
    }
    return pid;
}

/** Wait until @p path has @p rows lines (at most 60 s). */
static void wait_for_rows(const char *path, int rows)
{
    for (int k = 0; k < 6000; k++) {
        FILE *f = fopen(path, "r");
        int n = 0;
        if (f) {
            for (int c; (c = fgetc(f)) != EOF;)
                n += c == '\n';
            fclose(f);
        }
        if (n >= rows)
            return;
        struct timespec ts = {0, 10000000};
        nanosleep(&ts, NULL);
    }
    fail_msg("%s did not reach %d rows", path, rows);
}

/** Send @p signo mid-run; @return the step the run says it stopped at. */
static long interrupt_run(const char *dir, int signo)
{
    char args[1024], log[512], hist[512];
    snprintf(args, sizeof args, SPIN " -q -o %s", dir);
    snprintf(log, sizeof log, "%s.log", dir);
    snprintf(hist, sizeof hist, "%s/history.csv", dir);
    pid_t pid = start_mpm(args, log);
    wait_for_rows(hist, 30);
    assert_int_equal(kill(pid, signo), 0);
    int status;
    assert_int_equal(waitpid(pid, &status, 0), pid);
    char *text = tk_slurp(log, NULL);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 128 + signo)
        fail_msg("exit %d after signal %d, not %d:\n%s",
                 WIFEXITED(status) ? WEXITSTATUS(status) : -1, signo, 128 + signo, text);
    const char *at = strstr(text, " after step ");
    assert_non_null(at);
    assert_non_null(strstr(text, signo == SIGINT ? "interrupted (SIGINT)"
                                                 : "terminated (SIGTERM)"));
    assert_non_null(strstr(text, "go on with: mpm --restart"));
    long step = atol(at + 12);
    free(text);
    return step;
}

/** SIGINT mid-run: exit 130, every file whole (history.csv without a cut
 *  row), the points of the step it stopped at; restarted and stopped a
 *  little later, the same bytes as a run stopped there directly. */
static void interrupt_then_restart(void **state)
{
    (void)state;
    system("rm -rf " OUT "/int " OUT "/direct");
    long step = interrupt_run(OUT "/int", SIGINT);
    assert_true(step > 0);
    tk_assert_outputs_whole(OUT "/int");
    char want[64], args[512];
    char *pts = tk_slurp(OUT "/int/particles_final.csv", NULL);
    snprintf(want, sizeof want, ", step %ld\n", step);
    assert_non_null(strstr(pts, want));
    free(pts);
    snprintf(args, sizeof args, "--restart " OUT "/int -q --stop-at %ld", step + 700);
    run_ok(args);
    snprintf(args, sizeof args, SPIN " -q -o " OUT "/direct --stop-at %ld", step + 700);
    run_ok(args);
    tk_assert_same_outputs(OUT "/int", OUT "/direct", NULL);
}

/** SIGTERM: exit 143, files whole. */
static void sigterm_stops_with_143(void **state)
{
    (void)state;
    system("rm -rf " OUT "/term");
    assert_true(interrupt_run(OUT "/term", SIGTERM) > 0);
    tk_assert_outputs_whole(OUT "/term");
}

/** Overwrite @p len bytes at @p offset of @p path. */
static void patch(const char *path, long offset, const void *bytes, size_t len)
{
    FILE *f = fopen(path, "r+b");
    assert_non_null(f);
    assert_int_equal(fseek(f, offset, SEEK_SET), 0);
    assert_int_equal(fwrite(bytes, 1, len, f), len);
    assert_int_equal(fclose(f), 0);
}

/** Refused with exit 1, the message naming the checkpoint and saying why. */
static void restart_refused(const char *dir, const char *why)
{
    char args[512];
    snprintf(args, sizeof args, "--restart %s -q", dir);
    int rc = tk_run_mpm(args, out, sizeof out);
    if (rc != 1 || !strstr(out, "checkpoint.mpm") || !strstr(out, why))
        fail_msg("mpm %s: exit %d, want 1 and \"%s\":\n%s", args, rc, why, out);
}

/** A fresh stopped run of the disks in @p dir (the scene copied there). */
static void stopped_run(const char *dir)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "rm -rf %s && mkdir -p %s && cp " DISKS " %s/scene.cfg",
             dir, dir, dir);
    assert_int_equal(system(cmd), 0);
    snprintf(cmd, sizeof cmd, "%s/scene.cfg -q -o %s --stop-at 100", dir, dir);
    run_ok(cmd);
}

/** The header: 16 bytes of magic, then the format version (4 bytes) ...
 *  and the stage at byte 40 (checkpoint.c, Layout). */
static void foreign_checkpoints_are_refused(void **state)
{
    (void)state;
    const char *dir = OUT "/foreign", *ck = OUT "/foreign/checkpoint.mpm";
    stopped_run(dir);
    int stage = mpm_stage() + 1;
    patch(ck, 40, &stage, sizeof stage);
    restart_refused(dir, "written by stage");

    stopped_run(dir);
    unsigned version = 99;
    patch(ck, 16, &version, sizeof version);
    restart_refused(dir, "checkpoint format 99");

    stopped_run(dir);
    patch(ck, 0, "XPM", 3);
    restart_refused(dir, "not a checkpoint of mpm");

    stopped_run(dir);                                  /* cut short */
    assert_int_equal(truncate(ck, 4000), 0);
    restart_refused(dir, "cut short");

    stopped_run(dir);                                  /* the scene edited */
    assert_int_equal(system("sed -i 's/E = 1.0e-3/E = 1.1e-3/' " OUT "/foreign/scene.cfg"), 0);
    restart_refused(dir, "the scene or its overrides changed");

    assert_int_equal(system("rm -rf " OUT "/none && mkdir -p " OUT "/none"), 0);
    restart_refused(OUT "/none", "No such file or directory");
}

int main(void)
{
    assert_int_equal(system("mkdir -p " OUT), 0);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(stop_and_restart_gives_the_same_bytes),
        cmocka_unit_test(interrupt_then_restart),
        cmocka_unit_test(sigterm_stops_with_143),
        cmocka_unit_test(foreign_checkpoints_are_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
