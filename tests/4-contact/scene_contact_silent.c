/**
 * @file scene_contact_silent.c
 * @brief Contact costs nothing in numbers where it finds no contact: the
 *        DCB of Fig. 1 with crack contact switched on, but with critical
 *        volumes (V_sep = V_contact = 1.5) that no node of this opening
 *        crack reaches, gives stage 3's output byte for byte, with every
 *        update scheme; only history.csv's two new columns are added.
 *
 * Every part of stage 4 runs in that scene (normals from Task 1's
 * crossings, their sums and the nodal volumes at the step's first contact,
 * the node loop at Tasks 2, 4 and 6), so any change it made to a
 * node it does not adjust, or to the order of a sum, would show here.
 */
#include "testkit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const schemes[] = {"usl", "musl", "usf"};

/** Run @p bin on @p scene into @p dir for 6 ms with @p scheme. */
static void run(const char *bin, const char *scene, const char *scheme,
                const char *dir)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "rm -rf %s && %s %s -q -o %s run.time=6.0 "
             "run.snapshots=2 run.update=%s", dir, bin, scene, dir, scheme);
    assert_int_equal(system(cmd), 0);
}

static void same_numbers_as_stage3(void **state)
{
    (void)state;
    const char *bin = getenv("MPM_BIN");
    assert_non_null(bin);
    const char *a = "build/test-out/silent-3", *b = "build/test-out/silent-4";
    for (size_t k = 0; k < sizeof schemes / sizeof schemes[0]; k++) {
        run("build/stage3/mpm", "figures/fig1/dcb_full.cfg", schemes[k], a);
        run(bin, "tests/4-contact/scenes/dcb_contact_never.cfg", schemes[k], b);
        char cmd[1024];
        /* every file but history.csv byte for byte; history.csv less the
           contact columns (the last two) */
        snprintf(cmd, sizeof cmd, "cd %s && for f in *; do [ $f = history.csv ] || "
                 "cmp -s $f ../silent-4/$f || { echo \"$f differs\"; exit 1; }; done && "
                 "diff -q history.csv <(rev ../silent-4/history.csv | cut -d, -f3- | rev) && "
                 "test \"$(head -1 ../silent-4/history.csv | rev | cut -d, -f1-2 | rev)\" = "
                 "contact_nodes,contact_work && "
                 "awk -F, 'NR > 1 && ($(NF-1) != 0 || $NF != 0) { exit 1 }' "
                 "../silent-4/history.csv", a);
        FILE *p = popen("bash", "w");
        assert_non_null(p);
        fprintf(p, "%s\n", cmd);
        int rc = pclose(p);
        if (rc != 0)
            fail_msg("%s: stage 4 with silent contact differs from stage 3", schemes[k]);
        printf("  %s: every output the same as stage 3's, no node in contact\n",
               schemes[k]);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(same_numbers_as_stage3),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
