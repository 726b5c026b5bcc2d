/**
 * @file test_method_seams.c
 * @brief A method row names the seams its step runs, and set-up refuses a
 *        scene that asks the method for what it would skip (issue 26):
 *        subscribers at seams it does not run, settings it does not read.
 *
 * The rows are checked against the steps themselves: counters at every
 * step seam, one step of each method. The scenes of tests/6-xefg/bad/ that
 * XEFG refuses (contact between bodies, crack contact, run.update, ...)
 * load with run.method = "mpm", so the refusal is the method's; a cracked
 * XEFG scene (its cracks are the method's own) and the default run.update
 * are not refused.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testkit.h"

#define PLATE "tests/6-xefg/scenes/plate_crack.cfg"

/** A cracked plate pulled at its ends; %s: the method, and what else
 *  run has. */
static const char *const plate_text =
    "grid = { origin = [0.0, 0.0]; cells = [14, 10]; cell_size = [1.0, 1.0]; };\n"
    "run = { time = 0.05; method = \"%s\";%s snapshots = 0; };\n"
    "materials = ( { name = \"m\"; E = 1000.0; nu = 0.3; rho = 1e-3; } );\n"
    "bodies = ( { name = \"plate\"; material = \"m\";\n"
    "             rectangle = { min = [2.0, 1.0]; max = [12.0, 9.0]; }; } );\n"
    "loads = ( { rectangle = { min = [2.0, 8.5]; max = [12.0, 9.0]; };\n"
    "            force = [0.0, 0.5]; } );\n"
    "cracks = ( { points = ( [1.0, 4.6], [4.0, 5.1], [6.3, 5.4] ); } );\n";

/** A step seam's counter: the bits of the seams it was called at. */
static int note_seam(Sim *sim, void *state, Seam seam)
{
    (void)sim;
    *(unsigned *)state |= SEAM_BIT(seam);
    return 0;
}

/** Subscribe note_seam() with @p called at every step seam. */
static void note_every_seam(Hooks *h, void *called)
{
    for (int s = 0; s < SEAM_COUNT; s++)
        if (SEAMS_OF_STEP & SEAM_BIT(s))
            assert_int_equal(hooks_on_step(h, (Seam)s, note_seam, called), 0);
}

/** The plate with method @p method, into @p buf; the MPM step runs USAVG,
 *  whose stress update at the step's start calls the held-contact seam. */
static const char *plate(const char *method, char *buf, size_t len)
{
    int mpm = strcmp(method, "mpm") == 0;
    snprintf(buf, len, plate_text, method, mpm ? " update = \"usavg\";" : "");
    return buf;
}

/** MPM's row names every step seam, and one USAVG step calls every one. */
static void mpm_row_names_the_seams_its_step_calls(void **state)
{
    (void)state;
    char text[2048], err[1024];
    unsigned called = 0;
    Sim *sim = tk_load_with(plate("mpm", text, sizeof text), note_every_seam,
                            &called, err, sizeof err);
    if (!sim)
        fail_msg("refused: %s", err);
    tk_steps(sim, 1);
    printf("  mpm: row 0x%x, one step called 0x%x\n",
           sim->scene.run.method->seams, called);
    assert_int_equal(sim->scene.run.method->seams, SEAMS_OF_STEP);
    assert_int_equal(called, sim->scene.run.method->seams);
    tk_free(sim);
}

/** XEFG's row names no seam, and its step calls none (the counters are
 *  subscribed after set-up, which would refuse them; the XEFG step does
 *  not touch the grid that a late contact subscriber would need). */
static void xefg_row_names_the_seams_its_step_calls(void **state)
{
    (void)state;
    char text[2048];
    unsigned called = 0;
    Sim *sim = tk_load(plate("xefg", text, sizeof text));
    note_every_seam(&sim->hooks, &called);
    tk_steps(sim, 1);
    printf("  xefg: row 0x%x, one step called 0x%x\n",
           sim->scene.run.method->seams, called);
    assert_int_equal(called, 0);
    assert_int_equal(sim->scene.run.method->seams, called);
    tk_free(sim);
}

/** A stage's own subscriber at a seam XEFG skips is refused by its stage. */
static void a_stage_subscriber_xefg_skips_is_refused(void **state)
{
    (void)state;
    char text[2048], err[1024];
    unsigned called = 0;
    Sim *sim = tk_load_with(plate("xefg", text, sizeof text), note_every_seam,
                            &called, err, sizeof err);
    assert_null(sim);
    printf("  %s\n", err);
    assert_non_null(strstr(err, "scene: stage 99: run.method \"xefg\" does not "
                            "run the seams where it acts (Task 1 fields, Task 2 "
                            "held contact, Task 2 contact, Task 4 contact, Task 6 "
                            "contact, Task 7 crack motion)"));
}

/** A cracked XEFG scene, run.update left at its default, runs. */
static void plain_xefg_scene_runs(void **state)
{
    (void)state;
    Sim *sim = tk_load_file(PLATE, NULL);
    assert_string_equal(sim->scene.run.method->name, "xefg");
    tk_steps(sim, 20);
    tk_free(sim);
}

/** Each bad scene of XEFG's: refused naming its key, and a good scene
 *  with run.method = "mpm". Also the plate with crack contact or
 *  run.update set on the command line. */
static void what_xefg_skips_is_refused_naming_the_key(void **state)
{
    (void)state;
    static const struct { const char *path, *over, *key; } cases[] = {
        {"tests/6-xefg/bad/contact_with_xefg.cfg", NULL, ":10: contact: "},
        {"tests/6-xefg/bad/crack_contact_with_xefg.cfg", NULL, ":9: cracks.contact: "},
        {"tests/6-xefg/bad/update_with_xefg.cfg", NULL, ":8: run.update: "},
        {"tests/6-xefg/bad/stress_rate_with_xefg.cfg", NULL, ":6: run.stress_rate: "},
        {"tests/6-xefg/bad/crack_search_with_xefg.cfg", NULL, ":6: run.crack_search: "},
        {PLATE, "cracks.[0].contact={law=\"stick\";}", "cracks.contact (set on the "
         "command line): run.method \"xefg\" does not run"},
        {PLATE, "run.update=musl", "override \"run.update=musl\": run.update: "
         "run.method \"xefg\" does not read it"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const char *xefg[] = {cases[k].over, NULL};
        const char *mpm[] = {"run.method=mpm", cases[k].over, NULL};
        char err[1024];
        Sim *sim = tk_try_load_file(cases[k].path, xefg, err, sizeof err);
        if (sim)
            fail_msg("%s %s: accepted with xefg", cases[k].path,
                     cases[k].over ? cases[k].over : "");
        printf("  %s\n", err);
        if (!strstr(err, cases[k].key))
            fail_msg("message lacks \"%s\": %s", cases[k].key, err);
        sim = tk_try_load_file(cases[k].path, mpm, err, sizeof err);
        if (!sim)
            fail_msg("%s: refused with mpm: %s", cases[k].path, err);
        tk_free(sim);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(mpm_row_names_the_seams_its_step_calls),
        cmocka_unit_test(xefg_row_names_the_seams_its_step_calls),
        cmocka_unit_test(a_stage_subscriber_xefg_skips_is_refused),
        cmocka_unit_test(plain_xefg_scene_runs),
        cmocka_unit_test(what_xefg_skips_is_refused_naming_the_key),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
