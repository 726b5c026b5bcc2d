/**
 * @file test_bad_input.c
 * @brief Malformed scenes and overrides are refused, naming the file, the
 *        line and the problem, with exit status 1 and no crash.
 *
 * Every file in tests/N-name/bad/ is one malformed scene, checked by builds
 * of stage N and later (each chapter adds the bad inputs of what it adds,
 * e.g. tests/2-fields/bad/ holds malformed cracks).  Its header says
 * what the refusal must contain:
 *   # expect: <substring of the message>
 *   # refused-before-stage: N    (optional: only builds of stage < N refuse
 *                                 it, because stage N adds the feature;
 *                                 builds of stage N and later must load it)
 * and the offending line carries the comment "<- here"; the message must
 * start with "<file>:<that line>:".  The program (MPM_BIN; the sanitizer
 * build under make check's asan group) and the library (tk_try_file) must
 * both refuse it.
 */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stages.h"
#include "testkit.h"


#define OUT_DIR "build/test-bad-input-out"  /* written only if a scene is wrongly accepted */

/** What a bad scene's header and marker say. */
typedef struct BadCase {
    char path[512];
    char expect[256];
    int before_stage;   /* 0: refused by every stage */
    int line;           /* line carrying "<- here" */
} BadCase;

static void read_case(const char *dir, const char *name, BadCase *c)
{
    char buf[1024];
    if (snprintf(c->path, sizeof c->path, "%s/%s", dir, name) >= (int)sizeof c->path)
        fail_msg("file name too long: %s", name);
    c->expect[0] = '\0';
    c->before_stage = 0;
    c->line = 0;
    FILE *f = fopen(c->path, "r");
    assert_non_null(f);
    for (int n = 1; fgets(buf, sizeof buf, f); n++) {
        buf[strcspn(buf, "\n")] = '\0';
        if (strncmp(buf, "# expect: ", 10) == 0 &&
            snprintf(c->expect, sizeof c->expect, "%s", buf + 10) >= (int)sizeof c->expect)
            fail_msg("%s:%d: expected text too long", c->path, n);
        else if (strncmp(buf, "# refused-before-stage: ", 24) == 0)
            c->before_stage = atoi(buf + 24);
        if (strstr(buf, "<- here"))
            c->line = n;
    }
    fclose(f);
    if (!c->expect[0] || c->line == 0)
        fail_msg("%s: needs a '# expect: ...' line and a '<- here' marker", c->path);
}

static int by_name(const void *a, const void *b)
{
    return strcmp((const char *)a, (const char *)b);
}

/** Names of the .cfg files in @p dir, sorted; returns how many. */
static int list_cases(const char *dir, char names[][256], int max)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    int n = 0;
    const struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        size_t len = strlen(e->d_name);
        if (len > 4 && strcmp(e->d_name + len - 4, ".cfg") == 0) {
            assert_true(n < max);
            snprintf(names[n++], 256, "%s", e->d_name);
        }
    }
    closedir(d);
    qsort(names, (size_t)n, sizeof names[0], by_name);
    return n;
}

static void check_message(const char *who, const BadCase *c, const char *msg)
{
    if (strstr(msg, "syntax error: syntax error"))       /* libconfig's word twice */
        fail_msg("%s %s: message doubles a word: %s", who, c->path, msg);
    char where[600];
    snprintf(where, sizeof where, "%s:%d: ", c->path, c->line);
    if (!strstr(msg, where))
        fail_msg("%s %s: message does not name %s: %s", who, c->path, where, msg);
    if (!strstr(msg, c->expect))
        fail_msg("%s %s: message lacks \"%s\": %s", who, c->path, c->expect, msg);
}

/** The bad/ folders of chapters 1..mpm_stage(), "tests/N-name/bad". */
static int bad_dirs(char dirs[][256], int max)
{
    DIR *d = opendir("tests");
    assert_non_null(d);
    int n = 0;
    const struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        int stage = atoi(e->d_name);
        char path[512];
        if (stage < 1 || stage > mpm_stage() || !strchr(e->d_name, '-'))
            continue;
        snprintf(path, sizeof path, "tests/%.200s/bad", e->d_name);
        DIR *b = opendir(path);
        if (!b)
            continue;
        closedir(b);
        assert_true(n < max);
        snprintf(dirs[n++], 256, "%.250s", path);
    }
    closedir(d);
    qsort(dirs, (size_t)n, sizeof dirs[0], by_name);
    return n;
}

static void every_bad_scene_is_refused(void **state)
{
    (void)state;
    static char names[256][256], dirs[16][256], where[256][256];
    int n = 0, checked = 0, accepted = 0, ndirs = bad_dirs(dirs, 16);
    for (int k = 0; k < ndirs; k++) {
        int m = list_cases(dirs[k], names + n, 256 - n);
        for (int j = 0; j < m; j++)
            snprintf(where[n + j], 256, "%.250s", dirs[k]);
        n += m;
    }
    assert_true(n >= 20);                     /* the set is all there */
    for (int k = 0; k < n; k++) {
        BadCase c;
        read_case(where[k], names[k], &c);
        char args[1024], out[4096], err[1024];
        if (c.before_stage && mpm_stage() >= c.before_stage) {
            /* this build has the feature: the scene is a good one */
            if (tk_try_file(c.path, err, sizeof err) != 0)
                fail_msg("library: %s refused by a stage-%d build: %s", c.path,
                         mpm_stage(), err);
            accepted++;
            continue;
        }
        snprintf(args, sizeof args, "%s -q -o %s", c.path, OUT_DIR);
        int rc = tk_run_mpm(args, out, sizeof out);
        if (rc != 1)
            fail_msg("mpm %s: exit status %d, expected 1 (bad input): %s",
                     c.path, rc, out);
        if (strncmp(out, "mpm: ", 5) != 0 || strchr(out, '\n') != out + strlen(out) - 1)
            fail_msg("mpm %s: expected one line \"mpm: ...\", got: %s", c.path, out);
        check_message("mpm", &c, out);
        if (tk_try_file(c.path, err, sizeof err) == 0)
            fail_msg("library: %s was accepted", c.path);
        check_message("library", &c, err);
        checked++;
    }
    printf("  %d of %d bad scenes refused and %d, whose feature a stage-%d build "
           "has, accepted\n", checked, n, accepted, mpm_stage());
}

/** The cfl > 1 scene loads once it insists, with the step it asked for. */
static void cfl_above_one_accepted_when_insisted(void **state)
{
    (void)state;
    static const char *const insist[] = {"run.allow_cfl_above_one=true", NULL};
    Sim *sim = tk_load_file("tests/1-mpm/bad/cfl_above_one.cfg", insist);
    const Material *m = &sim->scene.mat[0];
    assert_close(sim->scene.run.cfl, 1.5, 0.0);
    /* points at rest: dt = cfl * cell / c, c = sqrt(c11 / rho) */
    assert_close(sim->dt, 1.5 * 1.0 / sqrt(m->c11 / m->rho), 1e-15);
    tk_free(sim);
}

/** Overrides on the command line that cannot apply are refused, naming the
 *  override or the key it set. */
static void bad_overrides_are_refused(void **state)
{
    (void)state;
    static const char *const cases[][2] = {
        {"nosuch.key=1", "override \"nosuch.key=1\": no group \"nosuch\""},
        {"=5", "override \"=5\": expected key.path=value"},
        /* a value found wrong names the override as typed (issue 10) */
        {"run.tme=5", "override \"run.tme=5\": tme: unknown key"},
        {"run.cfl=fast", "override \"run.cfl=fast\": cfl: expected a number"},
        {"grid.cells=5", "override \"grid.cells=5\": cells: expected two numbers"},
        {"run.time=-1", "override \"run.time=-1\": time: -1 must be > 0"},
        {"materials.[0].E=-1", "override \"materials.[0].E=-1\": E: -1: Young's"},
        {"bodies.[0].rectangle={min=[0,0];max=[0x5,5];}",
         "override \"bodies.[0].rectangle={min=[0,0];max=[0x5,5];}\": max: 0x5 is "
         "hexadecimal"},
        /* hexadecimal, integers libconfig would wrap, fractions (issue 10) */
        {"run.time=0x10", "override \"run.time=0x10\": time: 0x10 is hexadecimal"},
        {"grid.cells=[99999999999999999999, 20]", "override \"grid.cells=[99999"
         "999999999999999, 20]\": cells: 99999999999999999999 does not fit an integer"},
        {"materials.[0].E=3000000000", "E: 3000000000 does not fit an integer"},
        {"run.snapshots=-2147483649", "snapshots: -2147483649 does not fit an integer"},
        {"run.time=99999999999999999999L", "time: 99999999999999999999L does not fit "
         "an integer (with L"},
        {"grid.cells=(10.5, 20)", "[10.5, 20] must be whole numbers"},
        /* values whose derived quantities leave their range (issue 10) */
        {"run.time=1e308", "is more steps than a run can count"},
        {"run.cfl=1e-308", "(run.cfl 1e-308,"},
        {"run.time=1e-308", "is not one step"},
        {"materials.[0].E=1e308", "gives no time step"},
        {"bodies.[0].thickness=1e-308", "the mass is outside [1e-300, 1e300]"},
        {"materials.[0].rho=1e308", "the mass is outside [1e-300, 1e300]"},
        {"grid.cell_size=[1e200, 1e200]", "= inf: the mass is outside [1e-300, 1e300]"},
        {"bodies.[0].thickness=1e-305' 'materials.[0].rho=1e10", /* two */
         "the volume is outside [1e-300, 1e300]"},
        {"bodies.[0].velocity=[1e309, 0.0]", "value inf is not finite"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char args[1024], out[4096];
        snprintf(args, sizeof args, "tests/1-mpm/bad/cfl_above_one.cfg -q -o %s "
                 "run.allow_cfl_above_one=true '%s'", OUT_DIR, cases[k][0]);
        int rc = tk_run_mpm(args, out, sizeof out);
        if (rc != 1)
            fail_msg("override %s: exit status %d, expected 1: %s", cases[k][0], rc, out);
        if (!strstr(out, cases[k][1]))
            fail_msg("override %s: message lacks \"%s\": %s", cases[k][0], cases[k][1], out);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_bad_scene_is_refused),
        cmocka_unit_test(cfl_above_one_accepted_when_insisted),
        cmocka_unit_test(bad_overrides_are_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
