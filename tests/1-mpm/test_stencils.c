/**
 * @file test_stencils.c
 * @brief The stencils that Task 0 stores for the whole step (stencils.h,
 *        issue 29) are those the passes computed before: after Tasks 0
 *        and 1, every point's stored stencil equals stencil_of_point()'s,
 *        node for node and bit for bit (slots, S_ip, G_ip).
 *
 * An exact property (no tolerance): the same functions of the same Task 0
 * coordinates, and the slots Task 1 gave the pairs. Checked at the start
 * and after 5 and 10 steps (points moved, fields keyed afresh) on linear
 * scenes, with a crack's fields (stage 2 on), with contact (stage 4 on),
 * through uGIMP, CPDI and APIC's linear rows (stage 8); a scene the build
 * refuses is skipped, and every stage runs this test (later_stages).
 */
#include "testkit.h"

#include <stdio.h>
#include <string.h>

#include "step.h"

typedef struct Case {
    const char *scene;        /* the scene file */
    const char *over[5];      /* overrides, NULL-ended */
} Case;

static const Case cases[] = {
    {"tests/1-mpm/scenes/disks.cfg", {NULL}},
    {"figures/fig1/dcb_full.cfg", {NULL}},                       /* a crack */
    {"tests/4-contact/scenes/inclined_crack.cfg", {NULL}},       /* contact */
    {"tests/4-contact/scenes/disks_contact.cfg", {NULL}},
    {"tests/1-mpm/scenes/disks.cfg", {"run.shape=gimp", NULL}},  /* 3 x 3 */
    {"tests/1-mpm/scenes/spinning_disk.cfg", {"run.shape=cpdi", NULL}},
    {"tests/1-mpm/scenes/spinning_disk.cfg", {"run.transfer=apic", NULL}},
    {"figures/fig1/dcb_full.cfg",       /* both: a cell more beyond the edge */
     {"run.shape=gimp", "grid.origin=[-3.9215686274509802, -20.0]", "grid.cells=[54, 20]",
      "cracks.[0].points=([-3.9215686274509802, 0.0], [50.0, 0.0])", NULL}},
};

/** Tasks 0 and 1 of the next step, then every point's stored stencil
 *  against the one computed now; @return the points compared. */
static int compare(Sim *sim, const char *name)
{
    locate_points(sim);
    assert_int_equal(assign_fields(sim), 0);
    for (int p = 0; p < sim->pts.n; p++) {
        Stencil st;
        int n = stencil_of_point(sim, p, &st);
        StencilRow row = sim->scene.run.stencil
                             ? stencil_row(stencil_stored_wide(sim, p))
                             : stencil_stored(sim, p);
        if (row.n != n)
            fail_msg("%s, step %ld: point %d's stored stencil has %d nodes, "
                     "its stencil %d", name, sim->step, p, row.n, n);
        for (int a = 0; a < n; a++)     /* bit for bit */
            if (row.slot[a] != st.slot[a] || memcmp(&row.S[a], &st.S[a], sizeof(double)) ||
                memcmp(&row.Gx[a], &st.Gx[a], sizeof(double)) ||
                memcmp(&row.Gy[a], &st.Gy[a], sizeof(double)))
                fail_msg("%s, step %ld: point %d, node %d: stored slot %d, S %.17g, "
                         "G (%.17g, %.17g); computed slot %d, S %.17g, G (%.17g, %.17g)",
                         name, sim->step, p, a, row.slot[a], row.S[a], row.Gx[a],
                         row.Gy[a], st.slot[a], st.S[a], st.Gx[a], st.Gy[a]);
    }
    return sim->pts.n;
}

static void stored_stencils_are_the_computed_ones(void **state)
{
    (void)state;
    int scenes = 0;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char err[1024], name[256];
        Sim *sim = tk_try_load_file(cases[k].scene, cases[k].over, err, sizeof err);
        if (!sim)
            continue;                   /* a later stage's scene */
        snprintf(name, sizeof name, "%s %s", cases[k].scene,
                 cases[k].over[0] ? cases[k].over[0] : "");
        assert_true(compare(sim, name) > 0);
        for (int round = 0; round < 2; round++) {
            tk_steps(sim, 5);
            compare(sim, name);
        }
        tk_free(sim);
        scenes++;
    }
    print_message("stored stencils: %d scenes compared at steps 0, 5, 10\n", scenes);
    assert_true(scenes >= 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(stored_stencils_are_the_computed_ones),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
