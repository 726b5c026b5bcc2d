/**
 * @file scene_output_faults.c
 * @brief Output that cannot be written (issue 10): a full disk, a
 *        directory in the way of a file, an output directory that is a
 *        file, and a path longer than any fixed buffer. A failed write
 *        stops the run with exit status 2 and a message naming the file
 *        and the system's reason; every file left on disk is whole.
 *
 * A full disk is a file size limit here (ulimit -f, in 512-byte blocks):
 * the write fails with EFBIG, "File too large", as it would with ENOSPC.
 * Cracks add their files on stage 2 and later (cracks_NNNNN.vtp).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "stages.h"
#include "testkit.h"

#define OUT "build/test-output-faults"
#define DISKS "tests/1-mpm/scenes/disks.cfg"

static char out[16384];

static void expect_refusal(const char *cmd, const char *file, const char *why)
{
    int rc = tk_shell(cmd, out, sizeof out);
    char want[1024];
    snprintf(want, sizeof want, "cannot write %s: %s", file, why);
    if (rc != 2 || !strstr(out, want) || strstr(out, "done"))
        fail_msg("%s: exit %d, want 2 and \"%s\":\n%s", cmd, rc, want, out);
}

/** The first snapshot (about 60 kB) does not fit under a 15 kB limit:
 *  history.csv, written before it, stays whole; no half file is left. */
static void full_disk_at_a_snapshot(void **state)
{
    (void)state;
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "rm -rf " OUT "/full1; ulimit -f 30; exec %s " DISKS
             " -q -o " OUT "/full1 run.snapshots=3", tk_mpm_bin());
    expect_refusal(cmd, OUT "/full1/particles_00000.vtu", "File too large");
    assert_true(tk_assert_outputs_whole(OUT "/full1") >= 1);
}

/** history.csv, a row every step, outgrows the limit: the row that does
 *  not fit is cut off again, so the file ends with a whole row. */
static void full_disk_in_the_history(void **state)
{
    (void)state;
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "rm -rf " OUT "/full2; ulimit -f 30; exec %s " DISKS
             " -q -o " OUT "/full2 run.snapshots=0 run.history_every=1", tk_mpm_bin());
    expect_refusal(cmd, OUT "/full2/history.csv", "File too large");
    tk_assert_outputs_whole(OUT "/full2");
    char *h = tk_slurp(OUT "/full2/history.csv", NULL);
    assert_true(strlen(h) > 10000);               /* it did write rows */
    free(h);
}

/** A directory where a snapshot goes: "Is a directory", named. */
static void directory_in_the_way(void **state)
{
    (void)state;
    assert_int_equal(system("rm -rf " OUT "/way && mkdir -p " OUT
                            "/way/particles_00001.vtu"), 0);
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "exec %s " DISKS " -q -o " OUT "/way run.snapshots=3",
             tk_mpm_bin());
    expect_refusal(cmd, OUT "/way/particles_00001.vtu", "Is a directory");
    tk_assert_outputs_whole(OUT "/way");
    if (mpm_stage() < 2)
        return;
    /* a crack's polyline file (stage 2 and later) */
    assert_int_equal(system("rm -rf " OUT "/way2 && mkdir -p " OUT
                            "/way2/cracks_00001.vtp"), 0);
    snprintf(cmd, sizeof cmd, "exec %s figures/fig1/dcb_half.cfg -q -o " OUT "/way2 "
             "run.time=2 run.snapshots=2 'cracks=({points=([0.0,0.0],[50.0,0.0]);})'",
             tk_mpm_bin());
    expect_refusal(cmd, OUT "/way2/cracks_00001.vtp", "Is a directory");
    tk_assert_outputs_whole(OUT "/way2");
}

/** -o names a file: refused, naming it. */
static void output_directory_is_a_file(void **state)
{
    (void)state;
    assert_int_equal(system("mkdir -p " OUT " && touch " OUT "/plain"), 0);
    int rc = tk_run_mpm(DISKS " -q -o " OUT "/plain", out, sizeof out);
    if (rc != 2 || !strstr(out, "cannot create output directory " OUT
                            "/plain: Not a directory"))
        fail_msg("exit %d:\n%s", rc, out);
}

/** An output path of 1,700 characters is used as it is, not cut. */
static void long_output_path(void **state)
{
    (void)state;
    char dir[2048] = OUT "/long";
    for (int k = 0; k < 8; k++) {
        size_t n = strlen(dir);
        dir[n] = '/';
        memset(dir + n + 1, 'a' + k, 200);
        dir[n + 201] = '\0';
    }
    assert_true(strlen(dir) > 1600);
    assert_int_equal(system("rm -rf " OUT "/long"), 0);
    char args[4096], path[4096];
    snprintf(args, sizeof args, DISKS " -q -o %s run.snapshots=1", dir);
    int rc = tk_run_mpm(args, out, sizeof out);
    if (rc != 0)
        fail_msg("exit %d:\n%s", rc, out);
    struct stat st;
    snprintf(path, sizeof path, "%s/particles_00001.vtu", dir);
    assert_int_equal(stat(path, &st), 0);
    snprintf(path, sizeof path, "%s/particles_final.csv", dir);
    assert_int_equal(stat(path, &st), 0);
    tk_assert_outputs_whole(dir);
}

int main(void)
{
    assert_int_equal(system("mkdir -p " OUT), 0);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(full_disk_at_a_snapshot),
        cmocka_unit_test(full_disk_in_the_history),
        cmocka_unit_test(directory_in_the_way),
        cmocka_unit_test(output_directory_is_a_file),
        cmocka_unit_test(long_output_path),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
