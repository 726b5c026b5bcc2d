/**
 * @file scene_same_numbers.c
 * @brief Same numbers across stages (architecture property 3): a scene an
 *        earlier stage can run gives byte-identical output on this stage.
 *
 * Every uncracked scene of the repository (a second test checks that none
 * is missing), with every update scheme, runs
 * on build/stage1/mpm and on this build's program (MPM_BIN); every cracked
 * scene runs on build/stage2/mpm and on MPM_BIN. The scenes between them
 * hold every input of stages 1 and 2: two materials, plane strain and
 * stress, gravity, damping, fixed x, y and xy edges, ramped and constant
 * loads, disks, a USL run that goes unstable (its diagnostic must match
 * too), cracks that split nodes. Each run is short (a few dozen steps) with
 * two snapshots; stdout (less its timing line and stage 5's energy report,
 * a line a later stage adds), stderr, the exit status and
 * every output file must be the same, byte for byte. The energy guard is
 * off (run.energy_limit = 0): from stage 5 on it counts the work of
 * gravity and loads, so it stops a run that blows up on such a scene
 * sooner than stages 1-4 do (tests/5-usavg/scene_energy_guard.c); with it
 * off, the steps are compared up to the point check's stop.
 * (tools/same_numbers.sh does the same against another commit's build.)
 *
 * The earlier stage's outputs are the same whichever stage's test asks for
 * them, so the first test to run a case keeps them in the build folder
 * (same-numbers-cache/, named after the program's inode, size and time of
 * change, the scene, its time and the scheme: a rebuilt program is run
 * afresh) and the later stages' tests compare with that copy. Every run is
 * on one thread (run.threads = 1, whatever OMP_NUM_THREADS says: the first
 * line names the count, and scene_threads checks the bytes on more). A copy is
 * written under a name of its own and renamed into place whole, so that
 * two tests running at once never read half of one.
 */
#define _XOPEN_SOURCE 700   /* realpath() */
#include "stages.h"
#include "testkit.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/** A scene, how long to run it, and the earliest stage that can. */
typedef struct SameCase {
    const char *scene;
    const char *time;     /* run.time override: a few dozen steps */
    int stage;            /* 1: uncracked, 2: cracked, 4: contact (cracks, bodies) */
    int own_scheme;       /* 1: the scene's scheme only (a large scene) */
} SameCase;

static const SameCase cases[] = {
    {"tests/1-mpm/scenes/loaded_block.cfg", "1.0", 1, 0},
    {"tests/1-mpm/scenes/disks.cfg", "0.12", 1, 0},
    {"tests/1-mpm/scenes/spinning_disk.cfg", "0.02", 1, 0},
    {"tests/1-mpm/scenes/dcb_half_si.cfg", "0.006", 1, 0},
    {"tests/1-mpm/scenes/driven_bar.cfg", "0.02", 1, 0},
    {"tests/1-mpm/scenes/usl_unstable.cfg", "32.0", 1, 0},
    {"chapters/1-mpm/example.cfg", "6.0", 1, 0},
    {"figures/fig1/dcb_half.cfg", "6.0", 1, 0},
    {"figures/fig1b/half_dcb.cfg", "1.5", 1, 0},
    {"figures/fig6/beam_impact.cfg", "0.01", 1, 0},
    {"figures/fig1/dcb_full.cfg", "6.0", 2, 0},
    {"tools/bench/dcb_crack.cfg", "1.0", 2, 1},
    {"tools/bench/dcb_crack_2x.cfg", "2.0", 2, 0},
    {"tools/bench/dcb_nocrack.cfg", "1.0", 1, 1},
    {"tools/bench/disks_50k.cfg", "0.02", 1, 1},
    {"tests/3-crossing/scenes/dcb_kinked.cfg", "6.0", 2, 0},
    {"tests/3-crossing/scenes/dcb_usf.cfg", "3.0", 2, 0},
    {"tests/3-crossing/scenes/dcb_usf_half.cfg", "3.0", 1, 0},
    {"tests/3-crossing/scenes/tip_node_2mm.cfg", "6.0", 2, 0},
    {"tests/3-crossing/scenes/tip_mid_51.cfg", "6.0", 2, 0},
    {"tests/3-crossing/scenes/tip_node_1mm.cfg", "3.0", 2, 0},
    {"tests/3-crossing/scenes/tip_mid_101.cfg", "3.0", 2, 0},
    {"figures/fig3/cracked_disks.cfg", "2.0", 4, 0},
    {"tests/4-contact/scenes/dcb_contact_never.cfg", "6.0", 4, 0},
    {"tests/4-contact/scenes/inclined_crack.cfg", "0.5", 4, 0},
    {"tests/4-contact/scenes/disks_tips_on_nodes.cfg", "2.0", 4, 0},
    {"tools/bench/dcb_crack_contact.cfg", "1.0", 4, 1},
    {"tests/4-contact/scenes/disks_contact.cfg", "1.0", 4, 0},
    {"tools/bench/disks_50k_contact.cfg", "0.02", 4, 1},
    {"tools/bench/disks_50k_touching.cfg", "0.02", 4, 1},
    {"figures/fig5/beam_impact_contact.cfg", "0.01", 4, 0},
    {"figures/fig4/five_disks.cfg", "0.002", 4, 1},
    {"figures/fig6/beam_supports.cfg", "0.01", 4, 0},
    {"tests/4-contact/scenes/slide.cfg", "0.5", 4, 0},
    {"tests/4-contact/scenes/bars_gap.cfg", "0.1", 4, 0},
    {"tests/4-contact/scenes/bars_touching.cfg", "0.1", 4, 0},
    {"tests/4-contact/scenes/bars_impedance.cfg", "0.1", 4, 0},
    {"tests/4-contact/scenes/bars_one_field.cfg", "0.1", 1, 0},
    {"tests/4-contact/scenes/bars_impedance_one_field.cfg", "0.1", 1, 0},
    {"tests/4-contact/scenes/bar_flying.cfg", "2.5", 1, 0},
    {"tests/5-usavg/scenes/block_to_rest.cfg", "0.5", 4, 0},
    {"tests/5-usavg/scenes/vibrating_bar.cfg", "2.0", 1, 0},
    {"tests/8-shapes/scenes/bar_crossing.cfg", "2.0", 1, 0},
};

/** Scenes of the repository that no earlier stage runs or that another
 *  case covers, and why. */
static const char *const elsewhere[][2] = {
    {"tools/bench/disks_200k.cfg", "disks_50k.cfg with four times the points"},
    {"tests/3-crossing/scenes/dcb_arc.cfg", "an arc is stage 3's"},
    {"tests/3-crossing/scenes/tip_node_05mm.cfg", "tip_node_1mm.cfg refined"},
    {"tests/3-crossing/scenes/tip_mid_201.cfg", "tip_mid_101.cfg refined"},
    {"tests/4-contact/scenes/inclined_crack_fine.cfg", "inclined_crack.cfg refined"},
    {"tests/6-xefg/scenes/plate_crack.cfg", "run.method = \"xefg\" is stage 6's"},
    {"tests/6-xefg/scenes/cohesive_bar.cfg", "run.method = \"xefg\" and cracks.cohesive are stage 6's"},
    {"tests/6-xefg/scenes/petersson.cfg", "run.method = \"xefg\" and cracks.cohesive are stage 6's"},
    {"tests/6-xefg/scenes/petersson_grow.cfg", "cracks.cohesive.growth is stage 6's"},
    {"figures/fig-growth/kalthoff_xefg.cfg", "run.method = \"xefg\" and cracks.cohesive are stage 6's"},
    {"tests/6-xefg/scenes/growth_bar.cfg", "cracks.growth is stage 6's"},
    {"tests/6-xefg/scenes/growth_beam.cfg", "cracks.growth is stage 6's"},
    {"tests/6-xefg/scenes/dcb_hoop.cfg", "cracks.cohesive.growth is stage 6's"},
    {"tests/6-xefg/scenes/kalthoff_coarse.cfg", "cracks.cohesive.growth is stage 6's"},
    {"tests/6-xefg/scenes/kalthoff_h1_667.cfg", "cracks.cohesive.growth is stage 6's"},
    {"tests/6-xefg/scenes/growth_diagonal.cfg", "cracks.cohesive.growth is stage 6's"},
    {"figures/fig-kalthoff/kalthoff_h2_5.cfg", "cracks.cohesive.growth is stage 6's"},
    {"tests/7-fracture/scenes/dcb_j.cfg", "cracks.j_integral is stage 7's"},
    {"tests/7-fracture/scenes/dcb_growth.cfg", "cracks.growth is stage 7's"},
    {"tests/7-fracture/scenes/inclined_growth.cfg", "cracks.growth is stage 7's"},
    {"tests/7-fracture/scenes/kalthoff_half.cfg", "cracks.growth is stage 7's"},
    {"tests/8-shapes/scenes/cpdi_stretch.cfg", "run.shape = \"cpdi\" is stage 8's"},
    {"tests/8-shapes/scenes/cpdi_invert.cfg", "run.shape = \"cpdi\" is stage 8's"},
};

static const char *const schemes[] = {"usl", "musl", "usf"};

/** Run @p bin on case @p c with @p scheme into @p dir (stdout, stderr and
 *  the exit status kept as files there, the timing line and the stage
 *  number removed). */
/** What every run sets besides scheme and time; a part of the cache's
 *  names, so that a copy made with other settings is not taken. */
#define RUN_SETTINGS "run.snapshots=2 run.threads=1 run.energy_limit=0"
#define RUN_TAG "s2-t1-g0"

static void run_case(const char *bin, const SameCase *c, const char *scheme,
                     const char *dir)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "rm -rf %s && mkdir -p %s && %s %s -q -o %s/out "
             "run.update=%s run.time=%s " RUN_SETTINGS " >%s/stdout 2>%s/stderr; "
             "echo \"exit $?\" >>%s/stderr; sed -i -e '/particle-steps\\/s/d' -e '/^mpm: energy /d' "
             "-e 's/(stage [0-9]*)//' -e 's#%s/##g' %s/stdout %s/stderr", dir, dir, bin, c->scene, dir,
             scheme, c->time, dir, dir, dir, dir, dir, dir);
    assert_int_equal(system(cmd), 0);
}

/** The folder holding the outputs of @p bin (an earlier stage's program)
 *  on case @p c with @p scheme, written by run_case() unless an earlier
 *  run of this test (another stage's) left them; its path in @p dir.
 *  @return 1 when the copy was there already. */
static int reference_run(const char *bin, const SameCase *c, const char *scheme,
                         char *dir, size_t len)
{
    char *real = realpath(bin, NULL);
    struct stat st;
    if (!real || stat(real, &st) != 0)
        fail_msg("%s: cannot find the program", bin);
    char *slash = strrchr(real, '/');         /* .../build/stageK/mpm */
    *slash = '\0';
    char stage[64];
    snprintf(stage, sizeof stage, "%s", strrchr(real, '/') + 1);
    *strrchr(real, '/') = '\0';              /* .../build */
    char scene[256];
    snprintf(scene, sizeof scene, "%s", c->scene);
    for (char *q = scene; *q; q++)
        if (*q == '/')
            *q = '_';
    snprintf(dir, len, "%s/same-numbers-cache/%s-%lu-%lld-%lld.%09ld/%s-%s-%s-" RUN_TAG,
             real, stage, (unsigned long)st.st_ino, (long long)st.st_size,
             (long long)st.st_mtim.tv_sec, st.st_mtim.tv_nsec, scene, c->time, scheme);
    free(real);
    struct stat there;
    if (stat(dir, &there) == 0)
        return 1;
    char tmp[1200];
    snprintf(tmp, sizeof tmp, "%s.%ld", dir, (long)getpid());
    run_case(bin, c, scheme, tmp);
    if (rename(tmp, dir) != 0) {              /* another test kept its copy first */
        char cmd[1300];
        snprintf(cmd, sizeof cmd, "rm -rf %s", tmp);
        assert_int_equal(system(cmd), 0);
    }
    return 0;
}

/** Compare every file of folder @p a with the same file of @p b. */
static int same_files(const char *a, const char *b, char *why, size_t len)
{
    DIR *d = opendir(a);
    assert_non_null(d);
    const struct dirent *e;
    int files = 0;
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.')
            continue;
        char pa[600], pb[600];
        snprintf(pa, sizeof pa, "%s/%s", a, e->d_name);
        snprintf(pb, sizeof pb, "%s/%s", b, e->d_name);
        if (strcmp(e->d_name, "out") == 0) {
            int sub = same_files(pa, pb, why, len);
            if (sub < 0) {                /* why says which file */
                files = -1;
                break;
            }
            files += sub;
            continue;
        }
        size_t na, nb;
        char *fa = tk_slurp(pa, &na), *fb = tk_slurp(pb, &nb);
        int same = na == nb && memcmp(fa, fb, na) == 0;
        free(fa);
        free(fb);
        if (!same) {
            snprintf(why, len, "%s differs", e->d_name);
            files = -1;
            break;
        }
        files++;
    }
    closedir(d);
    return files;
}

static void every_scene_every_scheme(void **state)
{
    (void)state;
    const char *bin = getenv("MPM_BIN");
    assert_non_null(bin);
    int runs = 0, cached = 0;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const SameCase *c = &cases[k];
        if (c->stage > mpm_stage())
            continue;                     /* this build cannot run it */
        char earlier[64];
        snprintf(earlier, sizeof earlier, "build/stage%d/mpm", c->stage);
        for (size_t s = 0; s < sizeof schemes / sizeof schemes[0]; s++) {
            if (c->own_scheme && strcmp(schemes[s], "musl") != 0)
                continue;                 /* their scheme, MUSL, alone */
            char why[700] = "";
            char ref[1100];
            cached += reference_run(earlier, c, schemes[s], ref, sizeof ref);
            run_case(bin, c, schemes[s], "build/test-out/same-b");
            int files = same_files(ref, "build/test-out/same-b", why, sizeof why);
            if (files < 0)
                fail_msg("%s %s: %s between %s and %s", c->scene, schemes[s], why,
                         earlier, bin);
            if (files < 5)                /* history, snapshots, final points */
                fail_msg("%s %s: %d output files, expected 5 or more", c->scene,
                         schemes[s], files);
            printf("  same: %-38s %-4s %d files (%s vs %s)\n", c->scene, schemes[s],
                   files, earlier, bin);
            runs++;
        }
    }
    printf("  %d runs byte-identical (%d of the earlier stage's from the cache)\n", runs,
           cached);
}

/** Every scene file of the repository (outside build/, the bad/ folders
 *  and the fuzz inputs of tests/fuzz/) is a case above, or is listed with
 *  the reason it is not. */
static void every_scene_of_the_repository_is_a_case(void **state)
{
    (void)state;
    FILE *f = popen("find . -name '*.cfg' -not -path './build/*' "
                    "-not -path '*/bad/*' -not -path './tests/fuzz/*' | sort", "r");
    assert_non_null(f);
    char line[512];
    int n = 0;
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\n")] = '\0';
        const char *path = line + 2;           /* less "./" */
        int found = 0;
        for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++)
            found |= strcmp(cases[k].scene, path) == 0;
        for (size_t k = 0; k < sizeof elsewhere / sizeof elsewhere[0]; k++)
            found |= strcmp(elsewhere[k][0], path) == 0;
        if (!found)
            fail_msg("%s is not a case of scene_same_numbers.c (add it, or list "
                     "it in elsewhere[] with the reason)", path);
        n++;
    }
    assert_int_equal(pclose(f), 0);
    printf("  %d scene files, every one a case or listed with its reason\n", n);
    assert_true(n >= 15);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_scene_of_the_repository_is_a_case),
        cmocka_unit_test(every_scene_every_scheme),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
