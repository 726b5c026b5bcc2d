/**
 * @file scene_threads.c
 * @brief The MPM step on several threads (run.threads): the same bytes on
 *        1, 2, 3 and 4 threads, for every scheme, with and (on the stages
 *        that have them) without cracks and contact (between bodies and
 *        across a crack), with linear and (stage 8) wider stencils and
 *        APIC's transfer.
 *
 * The point update (Task 5) and the stress update run on the threads: a
 * point writes only its own arrays, and an instability is recorded for
 * the lowest point, whatever thread met it (step_fail()). The scatters to
 * the grid run on them too: a thread owns a strip of node rows and adds
 * the points that reach it in their order (strips.h), so every node sums
 * what it sums on one thread in the same order. So no number may depend
 * on the thread count: each scene is run on 1 to 4 threads with
 * run.precision = "full" and its output compared byte for byte, a run that
 * goes unstable (USL on the disks, beyond their time; CPDI's domain grown
 * wider than a cell) included. Contact's node loops (between bodies and
 * across a crack, friction's work summed node by node in node order) and
 * Task 1's crossings (found on threads, keyed in point order) are among
 * them. A scene the build refuses (a crack before
 * stage 2, run.shape "gimp" before stage 8) is skipped, and every stage
 * runs this test (later_stages).
 */
#include "testkit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define OUT "build/test-threads"

typedef struct Case {
    const char *scene;      /* the scene file */
    const char *extra;      /* overrides: a shorter run, a scheme */
} Case;

static const Case cases[] = {
    {"tests/1-mpm/scenes/disks.cfg", "run.update=usl"},
    {"tests/1-mpm/scenes/disks.cfg", "run.update=musl"},
    {"tests/1-mpm/scenes/disks.cfg", "run.update=usf"},
    {"tests/1-mpm/scenes/disks.cfg", "run.update=usl run.time=5"},  /* unstable */
    {"figures/fig1/dcb_full.cfg", "run.time=20 run.snapshots=1"},
    {"figures/fig5/beam_impact_contact.cfg", "run.time=0.2 run.snapshots=1"},
    /* contact between bodies: the disks meet at 1.0 and touch at 1.5 */
    {"tests/4-contact/scenes/disks_contact.cfg", "run.time=1.5 run.snapshots=1"},
    /* crack contact, the opening rule: the faces touch by 8 */
    {"tests/4-contact/scenes/inclined_crack.cfg", "run.time=8 run.snapshots=1"},
    /* and with friction: 20 nodes slide, contact_work sums them */
    {"tests/4-contact/scenes/inclined_crack.cfg", "run.time=8 run.snapshots=1 "
     "cracks.[0].contact.law=friction cracks.[0].contact.mu=0.3"},
    /* contact between bodies with friction: the block slides from the
       start, material_contact_work sums 10 nodes */
    {"tests/4-contact/scenes/slide.cfg", "run.time=0.5 run.snapshots=1 "
     "bodies.[1].velocity=[5.0,0.0] contact.[0].law=friction contact.[0].mu=0.3"},
    /* and with the regression normal (its per-node fits on threads) */
    {"tests/4-contact/scenes/slide.cfg", "run.time=0.5 run.snapshots=1 "
     "bodies.[1].velocity=[5.0,0.0] contact.[0].law=friction contact.[0].mu=0.3 "
     "contact.[0].normal=\\\"regression\\\""},
    /* Task 1 through the index (stage 3's search, named) over a kinked crack */
    {"tests/3-crossing/scenes/dcb_kinked.cfg",
     "run.time=20 run.snapshots=1 run.crack_search=\\\"indexed\\\""},
    /* and through the screened search, whose fields are found line by line
       (it has no visit_lines) */
    {"tests/3-crossing/scenes/dcb_kinked.cfg",
     "run.time=20 run.snapshots=1 run.crack_search=\\\"screened\\\""},
    {"tests/1-mpm/scenes/disks.cfg", "run.shape=gimp run.time=1"},  /* 3 x 3 */
    {"tests/8-shapes/scenes/cpdi_stretch.cfg", ""},              /* unstable */
    {"tests/1-mpm/scenes/spinning_disk.cfg",                      /* APIC */
     "run.shape=gimp run.transfer=apic run.time=1 run.snapshots=1"},
};

/** The run's output, its thread count (", N threads" ending the first
 *  line) and its wall time (the "done" line) left out. */
static void strip_machine(char *out)
{
    char *eol = strchr(out, '\n');
    char *t = strstr(out, " thread");
    if (eol && t && t < eol) {
        char *c = t;
        while (c > out && !(c[0] == ',' && c[1] == ' '))
            c--;
        memmove(c, eol, strlen(eol) + 1);
    }
    char *d = strstr(out, "mpm: done");
    if (d)
        *d = '\0';
}

static void same_bytes_on_any_number_of_threads(void **state)
{
    (void)state;
    int ran = 0;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        char first[8192] = "";
        int rc1 = -1, skipped = 0;
        for (int t = 1; t <= 4 && !skipped; t++) {
            char args[512], out[8192], dir[64];
            snprintf(dir, sizeof dir, OUT "/%zu.%d", c, t);
            snprintf(args, sizeof args, "%s -q -o %s %s run.precision=\\\"full\\\" "
                     "run.threads=%d", cases[c].scene, dir, cases[c].extra, t);
            int rc = tk_run_mpm(args, out, sizeof out);
            if (t == 1 && rc == 1) {
                skipped = 1;              /* a feature of a later stage */
                break;
            }
            strip_machine(out);
            char *at = strstr(out, dir);          /* "output so far is in DIR" */
            if (at)
                memmove(at, at + strlen(dir), strlen(at + strlen(dir)) + 1);
            if (t == 1) {
                rc1 = rc;
                snprintf(first, sizeof first, "%s", out);
                continue;
            }
            if (rc != rc1 || strcmp(out, first) != 0)
                fail_msg("%s %s: exit %d and output\n%s\non %d threads, against "
                         "exit %d and\n%s\non one", cases[c].scene, cases[c].extra,
                         rc, out, t, rc1, first);
            char one[64];                    /* every file, every byte */
            snprintf(one, sizeof one, OUT "/%zu.1", c);
            tk_assert_same_outputs(one, dir, NULL);
        }
        if (skipped) {
            printf("  %-40s %-28s refused by this stage: skipped\n",
                   cases[c].scene, cases[c].extra);
            fflush(stdout);
            continue;
        }
        ran++;
        printf("  %-40s %-28s the same bytes on 1-4 threads (exit %d)\n",
               cases[c].scene, cases[c].extra, rc1);
        fflush(stdout);
    }
    assert_true(ran >= 4);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(same_bytes_on_any_number_of_threads),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
