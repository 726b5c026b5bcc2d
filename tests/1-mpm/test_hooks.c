/**
 * @file test_hooks.c
 * @brief The seams and tables of stage 1: subscribers run in stage order
 *        whatever order they subscribe in, the method and law tables are
 *        chosen by the scene (a later stage's row refused naming it), and a
 *        full registry refuses every scene instead of dropping a feature.
 */
#include "testkit.h"

#include <stdlib.h>
#include <string.h>

#include "stages.h"
#include "step.h"

/** Appends its tag to the trace in its state. */
static int trace(Sim *sim, void *state, Seam seam)
{
    char *log = state;
    (void)sim;
    (void)seam;
    strcat(log, "x");
    return 0;
}

static int first(Sim *sim, void *state, Seam seam)
{
    (void)seam;
    (void)sim;
    strcat((char *)state, "1");
    return 0;
}

static int second(Sim *sim, void *state, Seam seam)
{
    (void)seam;
    (void)sim;
    strcat((char *)state, "2");
    return 0;
}

static void lists_keep_stage_order(void **state)
{
    (void)state;
    Hooks h;
    memset(&h, 0, sizeof h);
    char log[16] = "";
    hooks_begin_stage(&h, 4);                  /* a later stage first */
    assert_int_equal(hooks_on_step(&h, SEAM_TASK7, second, log), 0);
    hooks_begin_stage(&h, 2);
    assert_int_equal(hooks_on_step(&h, SEAM_TASK7, first, log), 0);
    hooks_begin_stage(&h, 4);
    assert_int_equal(hooks_on_step(&h, SEAM_TASK7, trace, log), 0);
    Sim sim;
    sim_init(&sim);
    sim.hooks = h;
    assert_int_equal(hooks_run_step(&sim, SEAM_TASK7), 0);
    assert_string_equal(log, "12x");           /* stage 2, then 4 in order */
    assert_int_equal(hooks_on_step(&h, SEAM_SNAPSHOT, trace, log), -1);
}

static const char *scene =
    "grid = { origin = [0.0, 0.0]; cells = [4, 4]; cell_size = [1.0, 1.0]; };\n"
    "run = { time = 1.0; %s };\n"
    "materials = ( { name = \"m\"; %s E = 1.0; nu = 0.3; rho = 1.0e-3; } );\n"
    "bodies = ( { material = \"m\"; rectangle = { min = [1.0, 1.0]; max = [3.0, 3.0]; }; } );\n";

/** Try the scene with @p run and @p mat inserted; the message in err. */
static int try_scene(const char *run, const char *mat, char *err, size_t len)
{
    char text[2048];
    snprintf(text, sizeof text, scene, run, mat);
    Sim *sim = tk_load_with(text, NULL, NULL, err, len);
    if (!sim)
        return -1;
    int ok = sim->scene.run.method == hooks_find_choice(&sim->hooks, "run.method", "mpm") &&
             sim->scene.mat[0].law == &material_hooke;
    tk_free(sim);
    return ok ? 0 : -2;
}

static void tables_chosen_by_the_scene(void **state)
{
    (void)state;
    char err[1024];
    assert_int_equal(try_scene("", "", err, sizeof err), 0);       /* defaults */
    assert_int_equal(try_scene("method = \"mpm\";", "law = \"hooke\";", err,
                               sizeof err), 0);
    if (mpm_stage() < 6) {
        assert_int_equal(try_scene("method = \"xefg\";", "", err, sizeof err), -1);
        assert_non_null(strstr(err, "scene:2: method: \"xefg\" is added by stage 6"));
    }
    assert_int_equal(try_scene("method = \"fem\";", "", err, sizeof err), -1);
    assert_non_null(strstr(err, "scene:2: method: \"fem\" is not known (expected "
                            "one of: mpm"));
    assert_int_equal(try_scene("", "law = \"plastic\";", err, sizeof err), -1);
    assert_non_null(strstr(err, "scene:3: law: \"plastic\" is not known "
                            "(expected one of: hooke"));
    /* the law's keys are the material's keys: E of Hooke's law is checked */
    assert_int_equal(try_scene("", "Q = 1;", err, sizeof err), -1);
    assert_non_null(strstr(err, "scene:3: Q: unknown key (expected one of: "
                            "name, law, rho, E, nu"));
}

/** A plug-in that fills the choice table past its size. */
static void too_many(Hooks *h, void *arg)
{
    (void)arg;
    for (int k = 0; k < HOOKS_MAX; k++)
        hooks_add_choice(h, "run.method", "mpm", hooks_find_choice(h, "run.method", "mpm"));
}

static void full_registry_refuses_every_scene(void **state)
{
    (void)state;
    char text[2048], err[1024];
    snprintf(text, sizeof text, scene, "", "");
    assert_null(tk_load_with(text, too_many, NULL, err, sizeof err));
    assert_non_null(strstr(err, "more than HOOKS_MAX"));
}

/* This build's keys and table rows, each registered once: the reader
 * takes the first registration of a section's key (hooks_find_key()) and
 * of a row, so a second stage's would be shadowed without a word (stages
 * 6 and 7 both registered cracks.growth once). */
static void every_key_and_row_registered_once(void **state)
{
    (void)state;
    Hooks *h = calloc(1, sizeof *h);
    assert_non_null(h);
    mpm_install_stages(h);
    assert_int_equal(h->overflow, 0);
    for (int a = 0; a < h->nkeys; a++)
        for (int b = a + 1; b < h->nkeys; b++)
            if (strcmp(h->keys[a].section, h->keys[b].section) == 0 &&
                strcmp(h->keys[a].key, h->keys[b].key) == 0)
                fail_msg("%s.%s registered twice (stages %d and %d)",
                         h->keys[a].section, h->keys[a].key, h->keys[a].rank,
                         h->keys[b].rank);
    for (int a = 0; a < h->nchoices; a++)
        for (int b = a + 1; b < h->nchoices; b++)
            if (strcmp(h->choices[a].key, h->choices[b].key) == 0 &&
                strcmp(h->choices[a].name, h->choices[b].name) == 0)
                fail_msg("%s = \"%s\" registered twice", h->choices[a].key,
                         h->choices[a].name);
    printf("  stage %d: %d keys and %d table rows, each registered once\n",
           mpm_stage(), h->nkeys, h->nchoices);
    free(h);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(lists_keep_stage_order),
        cmocka_unit_test(tables_chosen_by_the_scene),
        cmocka_unit_test(full_registry_refuses_every_scene),
        cmocka_unit_test(every_key_and_row_registered_once),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
