/**
 * @file test_memory_limit.c
 * @brief A scene is refused when its estimated memory exceeds the limit
 *        (Sim::memory_limit, mpm --max-memory) and loaded under a larger
 *        one; the estimate never counts fewer points than a body gets.
 */
#include "testkit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "footprint.h"
#include "stages.h"

#define OUT_DIR "build/test-memory-limit-out"

/** A 20 x 10 grid of 1 mm cells and one body, given as @p shape, at
 *  @p ppc x ppc points per cell, into @p buf. */
static const char *scene_with(char *buf, size_t len, const char *shape, int ppc)
{
    snprintf(buf, len,
             "grid = { origin = [0.0, 0.0]; cells = [20, 10]; cell_size = [1.0, 1.0]; };\n"
             "run = { time = 0.01; snapshots = 0; };\n"
             "materials = ( { name = \"gel\"; E = 0.1; nu = 0.33; rho = 1.5e-3; } );\n"
             "bodies = ( { name = \"b\"; material = \"gel\"; points_per_cell = %d;\n"
             "  %s } );\n", ppc, shape);
    return buf;
}

/** Load @p text under @p limit bytes; 0 loaded, else the refusal in @p err. */
static int load_under(const char *text, size_t limit, char *err, size_t errlen)
{
    Sim sim;
    sim_init(&sim);
    sim.memory_limit = limit;
    mpm_install_stages(&sim.hooks);
    int rc = sim_load_string(&sim, text, "scene", err, errlen);
    sim_free(&sim);
    return rc;
}

static void limit_refuses_and_accepts(void **state)
{
    (void)state;
    char text[1024], err[1024];
    scene_with(text, sizeof text, "rectangle = { min = [2.0, 2.0]; max = [8.0, 8.0]; };", 4);
    /* 576 points and 231 nodes: the points take the most, the body is named */
    assert_int_not_equal(load_under(text, 1000, err, sizeof err), 0);
    if (!strstr(err, "scene:4: needs about ") || !strstr(err, "e+02 points, 2.3e+02 nodes)") ||
        !strstr(err, "more than the 1.0 kB allowed (--max-memory to change)"))
        fail_msg("unexpected message: %s", err);
    if (load_under(text, 100000000, err, sizeof err) != 0)
        fail_msg("refused under 100 MB: %s", err);
    if (load_under(text, 0, err, sizeof err) != 0)   /* the machine's memory */
        fail_msg("refused under the memory available: %s", err);
}

/** A large grid and a small body: the grid's line is named. */
static void grid_named_when_nodes_dominate(void **state)
{
    (void)state;
    char err[1024];
    const char *text =
        "run = { time = 0.01; snapshots = 0; };\n"
        "grid = { origin = [0.0, 0.0]; cells = [1000, 1000]; cell_size = [1.0, 1.0]; };\n"
        "materials = ( { name = \"gel\"; E = 0.1; nu = 0.33; rho = 1.5e-3; } );\n"
        "bodies = ( { name = \"b\"; material = \"gel\";\n"
        "  rectangle = { min = [2.0, 2.0]; max = [4.0, 4.0]; }; } );\n";
    assert_int_not_equal(load_under(text, 1000000, err, sizeof err), 0);
    if (!strstr(err, "scene:2: needs about ") || !strstr(err, "1.0e+06 nodes"))
        fail_msg("unexpected message: %s", err);
}

/** The estimate is at least the count fill_body() makes, and not far
 *  above it, for every kind of shape. */
static void estimate_bounds_the_count(void **state)
{
    (void)state;
    static const char *const shapes[] = {
        "rectangle = { min = [2.3, 2.1]; max = [8.7, 8.05]; };",
        "disk = { center = [10.0, 5.0]; radius = 4.3; };",
        "disk = { center = [10.0, 5.0]; radius = 4.3; inner_radius = 2.2; };",
        "polygon = ( [1.0, 1.0], [19.0, 2.0], [10.0, 9.0] );",
        /* crossing edges: the even-odd rule fills two triangles */
        "polygon = ( [1.0, 1.0], [19.0, 9.0], [19.0, 1.0], [1.0, 9.0] );",
    };
    char text[1024];
    for (size_t k = 0; k < sizeof shapes / sizeof shapes[0]; k++)
        for (int ppc = 1; ppc <= 4; ppc++) {
            Sim *sim = tk_load(scene_with(text, sizeof text, shapes[k], ppc));
            Footprint f = footprint_estimate(&sim->scene);
            double n = sim->pts.n;
            if (!(f.points >= n && f.points <= 2.0 * n + 200.0))
                fail_msg("%s at %d: estimate %g for %g points", shapes[k], ppc,
                         f.points, n);
            assert_close(f.nodes, 21.0 * 11.0, 0.0);
            tk_free(sim);
        }
}

/** mpm --max-memory: a tiny limit refuses, a large one runs, nonsense is
 *  refused. */
static void command_line_option(void **state)
{
    (void)state;
    static const char *const cases[][3] = {
        {"--max-memory 0.001", "1", "more than the 1.0 kB allowed"},
        {"--max-memory 100", "0", "mpm: done"},
        {"--max-memory 0", "1", "--max-memory 0: expected megabytes"},
        {"--max-memory lots", "1", "--max-memory lots: expected megabytes"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char args[512], out[4096];
        snprintf(args, sizeof args, "tests/1-mpm/bad/cfl_above_one.cfg -q -o %s "
                 "run.allow_cfl_above_one=true %s", OUT_DIR, cases[k][0]);
        int rc = tk_run_mpm(args, out, sizeof out);
        if (rc != atoi(cases[k][1]) || !strstr(out, cases[k][2]))
            fail_msg("mpm %s: exit %d, expected %s with \"%s\": %s", cases[k][0],
                     rc, cases[k][1], cases[k][2], out);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(limit_refuses_and_accepts),
        cmocka_unit_test(grid_named_when_nodes_dominate),
        cmocka_unit_test(estimate_bounds_the_count),
        cmocka_unit_test(command_line_option),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
