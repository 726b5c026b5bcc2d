/**
 * @file scene_same_numbers.c
 * @brief A scene without cracks gives the same numbers in stage 2 as in
 *        stage 1 (architecture property 3): byte-identical output files.
 */
#include "testkit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void uncracked_scene_matches_stage1(void **state)
{
    (void)state;
    char out[4096], cmd[512];
    const char *scene = "tests/1-mpm/scenes/disks.cfg run.time=1.5 run.snapshots=2";
    snprintf(cmd, sizeof cmd, "%s -q -o build/test-out/same-s2", scene);
    assert_int_equal(tk_run_mpm(cmd, out, sizeof out), 0);
    snprintf(cmd, sizeof cmd, "build/stage1/mpm %s -q -o build/test-out/same-s1 "
             ">/dev/null 2>&1", scene);
    assert_int_equal(system(cmd), 0);
    static const char *files[] = {"history.csv", "particles_final.csv",
                                  "particles_00002.vtu", "grid_00002.csv"};
    for (size_t k = 0; k < sizeof files / sizeof files[0]; k++) {
        char a[256], b[256];
        size_t na, nb;
        snprintf(a, sizeof a, "build/test-out/same-s1/%s", files[k]);
        snprintf(b, sizeof b, "build/test-out/same-s2/%s", files[k]);
        char *fa = tk_slurp(a, &na), *fb = tk_slurp(b, &nb);
        if (na != nb || memcmp(fa, fb, na) != 0)
            fail_msg("%s differs between stage 1 and stage 2", files[k]);
        free(fa);
        free(fb);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(uncracked_scene_matches_stage1),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
