/**
 * @file scene_restart_contact.c
 * @brief Restart with cracks and contact (issue 10): a run of 2N steps and
 *        one of N steps restarted for N more write the same bytes, for a
 *        crack with contact (its points move, its contact work adds up)
 *        and for contact between bodies; on stage 5 with USAVG, whose
 *        energy account (e0, the work of loads and damping) goes on too.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stages.h"
#include "testkit.h"

#define OUT "build/test-restart-contact"

static char out[16384];

/** @p scene run whole and split at @p at: the same files, byte for byte. */
static void same_bytes(const char *scene, long at)
{
    const char *update = mpm_stage() >= 5 ? " run.update=usavg" : "";
    char args[1024];
    assert_int_equal(system("rm -rf " OUT " && mkdir -p " OUT), 0);
    snprintf(args, sizeof args, "%s -q -o " OUT "/full run.snapshots=5%s", scene, update);
    if (tk_run_mpm(args, out, sizeof out))
        fail_msg("%s\n%s", args, out);
    static char report[sizeof out];       /* stage 5 prints the energy account */
    memcpy(report, out, sizeof out);
    snprintf(args, sizeof args, "%s -q -o " OUT "/split run.snapshots=5%s --stop-at %ld",
             scene, update, at);
    if (tk_run_mpm(args, out, sizeof out))
        fail_msg("%s\n%s", args, out);
    if (tk_run_mpm("--restart " OUT "/split -q", out, sizeof out))
        fail_msg("restart:\n%s", out);
    tk_assert_same_outputs(OUT "/full", OUT "/split", "checkpoint.mpm");
    const char *a = strstr(report, "mpm: energy"), *b = strstr(out, "mpm: energy");
    if (mpm_stage() >= 5) {
        assert_non_null(a);
        assert_non_null(b);
        assert_memory_equal(a, b, strcspn(a, "\n"));
    }
}

static void crack_with_contact(void **state)
{
    (void)state;
    same_bytes("tests/4-contact/scenes/inclined_crack.cfg", 541);
}

static void contact_between_bodies(void **state)
{
    (void)state;
    same_bytes("tests/4-contact/scenes/disks_contact.cfg", 250);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(crack_with_contact),
        cmocka_unit_test(contact_between_bodies),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
