/**
 * @file scene_crack_gimp.c
 * @brief Explicit cracks with uGIMP and CPDI (chapter 8, "Cracks with
 *        GIMP"): the crack patch test of chapter 2 (paper's section 3.1)
 *        with run.shape = "gimp" and "cpdi", and the three crossing
 *        searches giving the same run when a point's stencil reaches 3 x 3
 *        nodes.
 *
 * Both DCB scenes (figures/fig1) get a grid one cell wider on the left,
 * with the crack's mouth on the new edge node: uGIMP's points at the
 * beam's end reach a node one cell further than linear's (a node exactly
 * 1 + l cells away gets a weight of rounding size), and a mouth on that
 * node would move with their velocity and leave the grid.
 *
 * The bound, fixed before the first GIMP run, is chapter 2's for linear
 * shape functions (tests/2-fields/scene_patch.c): each quantity's largest
 * difference between the upper half of the full run and the half run at
 * most 1e-12 of the largest value it takes.
 *
 * - The crack through the whole beam (asserted, uGIMP and CPDI): the full
 *   beam cut from
 *   end to end by a crack on the mid-plane against its upper half alone,
 *   both free (no symmetry condition: each half flies off with its load).
 *   Only the crack's fields separate the halves, so every pair of the
 *   wider stencil that crosses the crack must get the right field.
 * - The paper's patch test (the crack half way, the half beam held on the
 *   ligament by symmetry), asserted with uGIMP and CPDI: the half beam's
 *   boundary on the ligament is a mirror (boundaries.[0].mirror = true,
 *   src/8-shapes/mirror.c). Ahead of the tip a point's domain that crosses
 *   the mid-plane weights the node row below it; in the full run that row
 *   carries the lower half's mirror image of the row above, and the mirror
 *   gives the half run the same. A pair that crosses the plane over the
 *   crack (x < 50) keeps a field of its own, as the crack gives it in the
 *   full run. The roller alone (no mirror) leaves differences up to 9.2e-3
 *   of vy at 20 ms: CRACK_GIMP_ROLLER=1 prints them. The test prints the
 *   last step's largest weight a ligament point puts on the row below.
 *
 * Both run 20 ms of the figure's 400 (177 steps); CRACK_GIMP_TIME (ms)
 * sets another time.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "crack_patch.h"
#include "stencil.h"
#include "testkit.h"

static const char *run_time = "run.time=20.0";
static const char *shape = "run.shape=\"gimp\"";   /* the tests' shape */

/** Load @p file with the tests' shape on the grid widened by a cell on the
 *  left (and two on the right when @p through), the crack (when @p crack)
 *  from its edge node to x = 50 or through the beam, and @p more (or
 *  NULL). */
static Sim *load_gimp(const char *file, int crack, int through,
                      const char *more)
{
    const char *ov[8];
    int n = 0;
    ov[n++] = shape;
    ov[n++] = "grid.origin=[-3.9215686274509802, -20.0]";
    ov[n++] = through ? "grid.cells=[56, 20]" : "grid.cells=[54, 20]";
    ov[n++] = run_time;
    if (crack)
        ov[n++] = through ? "cracks.[0].points=([-3.9215686274509802, 0.0], "
                            "[103.92156862745098, 0.0])"
                          : "cracks.[0].points=([-3.9215686274509802, 0.0], "
                            "[50.0, 0.0])";
    else if (through)
        ov[n++] = "boundaries=()";
    if (more)
        ov[n++] = more;
    ov[n] = NULL;
    return tk_load_file(file, ov);
}

/** Pairs keyed this step whose node is not one of its point's cell's
 *  four (the pairs only the wider stencil has). */
static int keyed_beyond_cell(const Sim *sim)
{
    const FieldTable *F = &sim->fields;
    int count = 0;
    for (int r = 0; r < F->nrows; r++) {
        int p = F->row_point[r], node[STENCIL_MAX], cell[STENCIL_NODES];
        int n = stencil_node_list(sim, sim->scene.run.stencil, p, node);
        stencil_nodes(sim, p, cell);
        for (int a = 0; a < n; a++) {
            int own = 0;
            for (int c = 0; c < STENCIL_NODES; c++)
                own |= node[a] == cell[c];
            count += !own && F->row_key[F->width * r + a] != 0;
        }
    }
    return count;
}

/** The largest weight a point of the half beam's ligament (x > 50) puts
 *  on a node below the mid-plane (y < 0), at its position @p x, @p y:
 *  a domain that crossed the plane (the patch test's cause, chapter 8). */
static double below_plane(const Sim *half, double *x, double *y)
{
    const Grid *g = &half->grid;
    double w = 0.0;
    for (int p = 0; p < half->pts.n; p++) {
        Stencil st;
        half->scene.run.stencil(half, p, &st);      /* nodes, field 0 */
        for (int a = 0; a < st.n; a++)
            if (half->pts.x[p] > 50.0 && g->oy + (st.slot[a] / g->nnx) * g->dy < 0.0
                && st.S[a] > w) {
                w = st.S[a];
                *x = half->pts.x[p];
                *y = half->pts.y[p];
            }
    }
    return w;
}

/** Run the full and half scenes with the tests' shape; print and return
 *  the patch test's differences. */
static Patch gimp_patch(int through, const char *half_more)
{
    Sim *full = load_gimp("figures/fig1/dcb_full.cfg", 1, through, NULL);
    Sim *half = load_gimp("figures/fig1/dcb_half.cfg", 0, through, half_more);
    assert_true(full->nsteps == half->nsteps);
    assert_int_equal(full->fields.width, STENCIL_MAX);
    Patch r = patch_compare(full, half, half->nsteps);
    printf("%s, crack %s, %ld steps to t = %g ms; pairs keyed beyond the "
           "cell's four on the last step: %d\n", shape, through ? "through the beam" :
           "to x = 50 (paper)", full->step, full->t, keyed_beyond_cell(full));
    patch_print(&r);
    if (!through) {
        double x = 0.0, y = 0.0, w = below_plane(half, &x, &y);
        printf("largest weight of a ligament point on the node row below the "
               "mid-plane, last step: %.3g (point at %.6g, %.9g)\n", w, x, y);
    }
    tk_free(full);
    tk_free(half);
    return r;
}

/// [patch_gimp]
static void crack_through_the_beam(void **state)
{
    (void)state;
    Patch r = gimp_patch(1, NULL);
    for (int q = 0; q < PATCH_NQ; q++)
        assert_true(r.diff[q] <= 1e-12 * r.scale[q]);
}
/// [patch_gimp]

/** The same with CPDI, whose domains the material carries (Task 7 reads
 *  the step's fields to turn them). */
static void crack_through_the_beam_cpdi(void **state)
{
    shape = "run.shape=\"cpdi\"";
    crack_through_the_beam(state);
    shape = "run.shape=\"gimp\"";
}

/** The paper's patch test, the half beam's ligament a mirror. */
static void paper_patch_test(void **state)
{
    (void)state;
    Patch r = gimp_patch(0, "boundaries.[0].mirror=true");
    for (int q = 0; q < PATCH_NQ; q++)
        assert_true(r.diff[q] <= 1e-12 * r.scale[q]);
}

/** The same with CPDI. */
static void paper_patch_test_cpdi(void **state)
{
    shape = "run.shape=\"cpdi\"";
    paper_patch_test(state);
    shape = "run.shape=\"gimp\"";
}

/** Without the mirror (the roller alone, CRACK_GIMP_ROLLER=1): the
 *  differences the mirror takes away, printed. */
static void paper_patch_test_roller(void **state)
{
    (void)state;
    if (!getenv("CRACK_GIMP_ROLLER"))
        return;
    Patch r = gimp_patch(0, NULL);
    int met = 1;
    for (int q = 0; q < PATCH_NQ; q++)
        met &= r.diff[q] <= 1e-12 * r.scale[q];
    printf("%s: the paper's patch test with the roller alone\n",
           met ? "met" : "not met");
}

/** The through-cracked GIMP beam with run.crack_search = @p search. */
static Sim *run_search(const char *search, long steps)
{
    char opt[64];
    snprintf(opt, sizeof opt, "run.crack_search=\"%s\"", search);
    Sim *sim = load_gimp("figures/fig1/dcb_full.cfg", 1, 1, opt);
    tk_steps(sim, steps);
    return sim;
}

/** Every search must give the plain search's fields (chapter 3), so the
 *  same bits, with 3 x 3 stencils too: the index covers the cells around
 *  a point's own (Cracks::reach). */
static void searches_agree_with_gimp(void **state)
{
    (void)state;
    long steps = 100;
    Sim *s[3] = {run_search("plain", steps), run_search("screened", steps),
                 run_search("indexed", steps)};
    size_t bytes = sizeof(double) * (size_t)s[0]->pts.n;
    for (int k = 1; k < 3; k++) {
        const Particles *A = &s[0]->pts, *B = &s[k]->pts;
        printf("%s after %ld steps: %d pairs keyed beyond the cell (plain %d)\n",
               k == 1 ? "screened" : "indexed", steps, keyed_beyond_cell(s[k]),
               keyed_beyond_cell(s[0]));
        assert_int_equal(s[k]->fields.nrows, s[0]->fields.nrows);
        assert_memory_equal(A->x, B->x, bytes);
        assert_memory_equal(A->y, B->y, bytes);
        assert_memory_equal(A->vx, B->vx, bytes);
        assert_memory_equal(A->vy, B->vy, bytes);
        assert_memory_equal(A->sxx, B->sxx, bytes);
        assert_memory_equal(A->syy, B->syy, bytes);
    }
    for (int k = 0; k < 3; k++)
        tk_free(s[k]);
}

int main(void)
{
    static char buf[64];
    const char *t = getenv("CRACK_GIMP_TIME");
    if (t) {
        snprintf(buf, sizeof buf, "run.time=%s", t);
        run_time = buf;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(crack_through_the_beam),
        cmocka_unit_test(crack_through_the_beam_cpdi),
        cmocka_unit_test(paper_patch_test),
        cmocka_unit_test(paper_patch_test_cpdi),
        cmocka_unit_test(paper_patch_test_roller),
        cmocka_unit_test(searches_agree_with_gimp),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
