/**
 * @file test_mirror.c
 * @brief The mirror (boundaries.[k].mirror, chapter 8): a block symmetric
 *        about y = 0, squeezed toward the plane and pulled along it,
 *        against its upper half with the mirror on the plane.
 *
 * The loads squeeze the block toward y = 0, so that the points next to the
 * plane move toward it and their uGIMP (CPDI) domains cross it: they weight
 * the node row below, which in the whole block carries the image of the
 * row above. With the mirror the half run must give the whole run's grid
 * on the kept side (y >= 0: mass, momentum) and its points, step by step.
 * Bound, fixed before the first run: each quantity's largest difference
 * at most 1e-12 of the largest value it takes (round-off: the sums are
 * added in another order). The test also counts the pairs the mirror
 * folded, so that it cannot pass with no domain across the plane, and
 * prints what the roller alone (no mirror) gives with MIRROR_ROLLER=1.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "mirror.h"
#include "testkit.h"

/** The whole block (@p half 0) or its upper half (1, with @p mirror), with
 *  run.shape @p shape and run.update @p update. */
static Sim *block(int half, int mirror, const char *shape, const char *update)
{
    char text[2048];
    snprintf(text, sizeof text,
        "grid = { origin = [0.0, -6.0]; cells = [10, 12]; cell_size = [1.0, 1.0]; };\n"
        "run = { time = 3.0; cfl = 0.5; update = \"%s\"; shape = \"%s\"; snapshots = 0; };\n"
        "materials = ( { name = \"soft\"; E = 0.1; nu = 0.33; rho = 1.5e-3; } );\n"
        "bodies = ( { name = \"block\"; material = \"soft\"; points_per_cell = 2;\n"
        "             rectangle = { min = [2.0, %s]; max = [8.0, 4.0]; }; } );\n"
        "%s"
        "loads = ( { rectangle = { min = [2.0, 3.0]; max = [8.0, 4.0]; }; force = [0.0, -0.001]; },\n"
        "          { rectangle = { min = [7.0, %s]; max = [8.0, 4.0]; }; force = [%s, 0.0]; }%s );\n",
        update, shape, half ? "0.0" : "-4.0",
        half ? (mirror ? "boundaries = ( { rectangle = { min = [0.0, 0.0]; max = [10.0, 0.0]; };\n"
                         "                 fix = \"y\"; mirror = true; } );\n"
                       : "boundaries = ( { rectangle = { min = [0.0, 0.0]; max = [10.0, 0.0]; };\n"
                         "                 fix = \"y\"; } );\n")
             : "",
        half ? "0.0" : "-4.0", half ? "0.001" : "0.002",
        half ? "" : ",\n          { rectangle = { min = [2.0, -4.0]; max = [8.0, -3.0]; }; "
                    "force = [0.0, 0.001]; }");
    return tk_load(text);
}

/** Largest differences on the kept side over the run: grid m, px, py on
 *  the nodes y >= 0, points x, y, vx, vy, sigma_yy; and their scales. */
#define NQ 8
static const char *const qname[NQ] = {"grid m", "grid px", "grid py", "x",
                                      "y", "vx", "vy", "sigma_yy"};

/** Run the whole block and the half, compare after each step; return the
 *  pairs the mirror folded (0 with no mirror). */
static long compare(const char *shape, const char *update, int mirror,
                    double diff[NQ], double scale[NQ])
{
    Sim *full = block(0, 0, shape, update), *half = block(1, mirror, shape, update);
    const Mirror *M = sim_state(half, MIRROR_STATE);
    long folded = 0;
    int n = half->pts.n, off = full->pts.n - n;
    assert_int_equal(full->pts.n, 2 * n);
    assert_true(full->dt == half->dt);
    for (int q = 0; q < NQ; q++)
        diff[q] = scale[q] = 0.0;
    while (half->t < half->scene.run.time) {
        tk_steps(full, 1);
        tk_steps(half, 1);
        for (int k = 0; M && k < M->n; k++)
            folded += M->use[k];
        const Grid *F = &full->grid, *H = &half->grid;
        for (int node = 6 * H->nnx; node < H->nnodes; node++) {   /* y >= 0 */
            const double f[3] = {F->m[node], F->px[node], F->py[node]};
            const double h[3] = {H->m[node], H->px[node], H->py[node]};
            for (int q = 0; q < 3; q++) {
                diff[q] = fmax(diff[q], fabs(f[q] - h[q]));
                scale[q] = fmax(scale[q], fabs(h[q]));
            }
        }
        const double *fa[5] = {full->pts.x, full->pts.y, full->pts.vx,
                               full->pts.vy, full->pts.syy};
        const double *ha[5] = {half->pts.x, half->pts.y, half->pts.vx,
                               half->pts.vy, half->pts.syy};
        for (int q = 0; q < 5; q++)
            for (int p = 0; p < n; p++) {
                diff[3 + q] = fmax(diff[3 + q], fabs(fa[q][off + p] - ha[q][p]));
                scale[3 + q] = fmax(scale[3 + q], fabs(ha[q][p]));
            }
    }
    printf("%s, %s, %s: %ld steps, %ld pairs folded\n", shape, update,
           mirror ? "mirror" : "roller alone", half->step, folded);
    for (int q = 0; q < NQ; q++)
        printf("  %-9s max |full - half| = %.3g of %.3g (ratio %.3g)\n", qname[q],
               diff[q], scale[q], diff[q] / scale[q]);
    tk_free(full);
    tk_free(half);
    return folded;
}

static void check(const char *shape, const char *update)
{
    double diff[NQ], scale[NQ];
    long folded = compare(shape, update, 1, diff, scale);
    assert_true(folded > 0);
    for (int q = 0; q < NQ; q++)
        assert_true(diff[q] <= 1e-12 * scale[q]);
}

static void gimp_musl(void **state)
{
    (void)state;
    check("gimp", "musl");
}

static void gimp_usf(void **state)
{
    (void)state;
    check("gimp", "usf");
}

static void cpdi_musl(void **state)
{
    (void)state;
    check("cpdi", "musl");
}

/** The roller alone (MIRROR_ROLLER=1): printed, to show what the mirror
 *  takes away (the plane's row carries half the whole block's mass). */
static void gimp_roller_alone(void **state)
{
    double diff[NQ], scale[NQ];
    (void)state;
    if (getenv("MIRROR_ROLLER"))
        compare("gimp", "musl", 0, diff, scale);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(gimp_musl),
        cmocka_unit_test(gimp_usf),
        cmocka_unit_test(cpdi_musl),
        cmocka_unit_test(gimp_roller_alone),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
