/**
 * @file test_seams.c
 * @brief The seams prove themselves: a test-only plug-in adds a nested
 *        scene key (materials.group), a part of the field key and a Task 1
 *        subscriber without editing any file of stages 1-2; with a crack
 *        it gives a node four fields (two crack sides times two groups),
 *        and Task 7 moves the crack with the centre of mass of all of them.
 */
#include "testkit.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "cracks.h"
#include "scene_read.h"
#include "step.h"

/** The plug-in's state: the group of each material and its key part. */
typedef struct Plugin {
    int shift;          /* lowest bit of the "test group" part of the key */
    unsigned group[8];  /* per material */
    int subscribed;     /* its Task 1 subscriber is in place */
} Plugin;

/** Task 1: every pair gets its point's material group in the key. */
static int plugin_key_fields(Sim *sim, void *state, Seam seam)
{
    const Plugin *pl = state;
    (void)seam;
    for (int p = 0; p < sim->pts.n; p++)
        for (int a = 0; a < STENCIL_NODES; a++)
            if (fields_key(sim, p, a, pl->group[sim->pts.mat[p]] << pl->shift))
                return -1;
    return 0;
}

/** materials.group = 1..15: the material's group; subscribes Task 1. */
static int plugin_read_group(Sim *sim, const config_setting_t *s, int index,
                             SceneReader *r)
{
    Plugin *pl = sim_state(sim, "test plugin");
    if (!pl) {
        pl = calloc(1, sizeof *pl);
        assert_non_null(pl);
        assert_int_equal(sim_attach(sim, "test plugin", pl, free), 0);
        pl->shift = hooks_find_field_key(&sim->hooks, "test group")->shift;
    }
    int g = config_setting_get_int(s);
    if (config_setting_type(s) != CONFIG_TYPE_INT || g < 1 || g > 15 || index >= 8)
        return scene_error(r, s, "group", "expected a whole number in [1, 15]");
    pl->group[index] = (unsigned)g;
    if (!pl->subscribed) {
        pl->subscribed = 1;
        assert_int_equal(hooks_on_step(&sim->hooks, SEAM_TASK1_FIELDS,
                                       plugin_key_fields, pl), 0);
    }
    return 0;
}

/** The plug-in's installer: what a later stage's stageN_install() does. */
static void plugin_install(Hooks *h)
{
    assert_int_equal(hooks_add_key(h, "materials", "group", plugin_read_group, NULL), 0);
    assert_true(hooks_add_field_key(h, "test group", 4) >= 0);
}

static const char *scene =
    "grid = { origin = [0.0, 0.0]; cells = [10, 10]; cell_size = [1.0, 1.0]; };\n"
    "run = { time = 1.0; update = \"musl\"; snapshots = 0; };\n"
    "materials = ( { name = \"a\"; E = 1.0; nu = 0.3; rho = 1.0e-3; group = 1; },\n"
    "              { name = \"b\"; E = 2.0; nu = 0.3; rho = 2.0e-3; group = 2; } );\n"
    "bodies = ( { material = \"a\"; rectangle = { min = [2.0, 2.0]; max = [5.0, 8.0]; }; },\n"
    "           { material = \"b\"; rectangle = { min = [5.0, 2.0]; max = [8.0, 8.0]; }; } );\n"
    "cracks = ( { points = ( [1.5, 5.0], [5.0, 5.0] ); } );\n";

/** Plug-in with a refusal only: a build that knows who adds the key. */
static void refuse_group(Hooks *h, void *arg)
{
    (void)arg;
    hooks_add_refusal(h, "materials.group", NULL, "the test plug-in");
}

/** The plug-in as tk_load_with() takes it. */
static void with_plugin(Hooks *h, void *arg)
{
    (void)arg;
    plugin_install(h);
}

/** Load the scene with the plug-in; fail the test if refused. */
static Sim *load(void)
{
    char err[1024];
    Sim *sim = tk_load_with(scene, with_plugin, NULL, err, sizeof err);
    if (!sim)
        fail_msg("refused: %s", err);
    return sim;
}

static void nested_key_needs_its_plugin(void **state)
{
    (void)state;
    char err[1024];
    assert_null(tk_load_with(scene, NULL, NULL, err, sizeof err));
    assert_non_null(strstr(err, "scene:3: group: unknown key"));
    /* a build that knows who adds the key says so */
    assert_null(tk_load_with(scene, refuse_group, NULL, err, sizeof err));
    assert_non_null(strstr(err, "scene:3: group: this key needs the test plug-in"));
}

static void subscribers_run_in_stage_order(void **state)
{
    (void)state;
    Sim *sim = load();
    /* the plug-in subscribed first (materials are read before cracks), yet
       stage 2's subscriber runs first: lists keep stage order */
    const SeamList *l = &sim->hooks.seam[SEAM_TASK1_FIELDS];
    assert_int_equal(l->n, 2);
    assert_ptr_equal(l->at[0].fn.step, cracks_key_fields);
    assert_ptr_equal(l->at[1].fn.step, plugin_key_fields);
    assert_ptr_equal(l->at[0].state, cracks_of(sim));
    tk_free(sim);
}

static void node_with_crack_side_and_two_materials(void **state)
{
    (void)state;
    Sim *sim = load();
    Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    const FieldTable *F = &sim->fields;
    const Cracks *C = cracks_of(sim);
    const Plugin *pl = sim_state(sim, "test plugin");
    int n = 5 * g->nnx + 5;           /* node (5, 5): crack tip, interface */
    for (int p = 0; p < P->n; p++) {  /* some motion to average */
        P->vx[p] = 0.3 + 0.1 * P->y[p] - 0.02 * P->x[p] * P->x[p];
        P->vy[p] = -0.2 + 0.05 * P->x[p] * P->y[p];
    }
    grid_clear(&sim->grid, 1);
    locate_points(sim);
    assert_int_equal(assign_fields(sim), 0);
    extrapolate(sim, EXTRAP_MASS);
    /* every pair at the node: its slot has the key of its side and group */
    double m = 0, px = 0, py = 0;
    int pairs = 0;
    for (int p = 0; p < P->n; p++) {
        Stencil st;
        stencil_of_point(sim, p, &st);
        for (int a = 0; a < STENCIL_NODES; a++) {
            if (grid_slot_node(g, st.slot[a]) != n)
                continue;
            int side = crack_crossing(&C->crack[0], P->x[p], P->y[p], 5.0, 5.0);
            unsigned want = ((unsigned)(side > 0 ? 1 : 2) << C->side_shift) |
                            (pl->group[P->mat[p]] << pl->shift);
            assert_int_not_equal(side, 0);          /* a node on the crack */
            assert_int_equal(field_key(F, g, st.slot[a]), want);
            m += P->m[p] * st.S[a];
            px += P->m[p] * st.S[a] * P->vx[p];
            py += P->m[p] * st.S[a] * P->vy[p];
            pairs++;
        }
    }
    assert_int_equal(pairs, 16);      /* 4 cells x 2 x 2 points */
    /* the node's list: exactly the four combinations, in key order, and
       its own field 0 is empty */
    unsigned keys[8];
    int nk = 0;
    for (int s = field_next(F, g, n); s >= 0; s = field_next(F, g, s)) {
        assert_true(nk < 8);
        assert_true(g->m[s] > 0);
        keys[nk++] = field_key(F, g, s);
    }
    assert_int_equal(nk, 4);
    unsigned want[4];
    for (unsigned side = 1, k = 0; side <= 2; side++)
        for (unsigned grp = 1; grp <= 2; grp++)
            want[k++] = (side << C->side_shift) | (grp << pl->shift);
    for (int i = 0; i < 4; i++)                    /* ascending */
        for (int j = i + 1; j < 4; j++)
            if (want[j] < want[i]) {
                unsigned t = want[i];
                want[i] = want[j];
                want[j] = t;
            }
    for (int k = 0; k < 4; k++)
        assert_int_equal(keys[k], want[k]);
    assert_true(g->m[n] == 0.0);
    assert_true(cracks_multi_field_nodes(sim) > 0);
    /* Task 7: the tip, on node n, moves with the centre of mass of all
       four fields: sum of momenta over sum of masses of every pair */
    double dt = sim->dt, x0 = C->crack[0].x[1], y0 = C->crack[0].y[1];
    assert_int_equal(cracks_move(sim), 0);
    /* to the rounding of x0 + dt v (half an ulp of x0) and of the sums */
    assert_close(C->crack[0].x[1], x0 + dt * px / m, 2 * DBL_EPSILON * x0);
    assert_close(C->crack[0].y[1], y0 + dt * py / m, 2 * DBL_EPSILON * y0);
    assert_true(fabs(dt * px / m) > 1e3 * DBL_EPSILON * x0);  /* it moved */
    tk_free(sim);
}

static void no_keys_no_table(void **state)
{
    (void)state;
    /* a scene whose stages key nothing has no field table: stage 1's cost */
    Sim *sim = tk_load_file("tests/1-mpm/scenes/disks.cfg", NULL);
    assert_null(sim->fields.first);
    assert_null(sim->fields.row_of);
    assert_int_equal(sim->hooks.seam[SEAM_TASK1_FIELDS].n, 0);
    tk_steps(sim, 3);
    assert_int_equal(sim->grid.nslots, sim->grid.nnodes);
    tk_free(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(nested_key_needs_its_plugin),
        cmocka_unit_test(subscribers_run_in_stage_order),
        cmocka_unit_test(node_with_crack_side_and_two_materials),
        cmocka_unit_test(no_keys_no_table),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
