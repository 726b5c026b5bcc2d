/**
 * @file test_crossing_order.c
 * @brief The crossing seam does not depend on the order in which a search
 *        visits segments: a test search that visits every segment in a
 *        fresh random permutation gives the same field, crack and segment
 *        as the plain search for every line, and the same fields, step by
 *        step, in a whole run. (Stage 3's screened and indexed searches
 *        visit segments in other orders; this is what lets them promise
 *        the same numbers.)
 */
#include "testkit.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cracks.h"
#include "step.h"

/** A small deterministic generator (xorshift64*), state owned by a test. */
static uint64_t next_random(uint64_t *s)
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return *s * 2685821657736338717ull;
}

/** The shuffled search's state: its generator and a scratch list. */
typedef struct Shuffle {
    uint64_t seed;
    int n;
    int *crack;
    int *seg;
} Shuffle;

/** Every segment of every crack, in a new random order at every call. */
static void shuffled_visit(const Cracks *C, int cell, double px, double py,
                           double nx, double ny, Crossings *x)
{
    Shuffle *sh = C->search_state;
    int n = 0;
    (void)cell;
    for (int c = 0; c < C->ncracks; c++)
        for (int k = 0; k + 1 < C->crack[c].n; k++, n++) {
            sh->crack[n] = c;
            sh->seg[n] = k;
        }
    for (int i = n - 1; i > 0; i--) {          /* Fisher-Yates */
        int j = (int)(next_random(&sh->seed) % (uint64_t)(i + 1));
        int tc = sh->crack[i], ts = sh->seg[i];
        sh->crack[i] = sh->crack[j];
        sh->seg[i] = sh->seg[j];
        sh->crack[j] = tc;
        sh->seg[j] = ts;
    }
    for (int i = 0; i < n; i++)
        crossings_test(C, sh->crack[i], sh->seg[i], px, py, nx, ny, x);
}

/** Make the scratch list for the cracks' segments (once). */
static int shuffled_update(Cracks *C, const Grid *g)
{
    (void)g;
    if (C->search_state)
        return 0;
    int n = 0;
    for (int c = 0; c < C->ncracks; c++)
        n += C->crack[c].n;
    Shuffle *sh = calloc(1, sizeof *sh);
    if (!sh)
        return -1;
    sh->seed = 0x9e3779b97f4a7c15ull;
    sh->crack = malloc(sizeof(int) * (size_t)n);
    sh->seg = malloc(sizeof(int) * (size_t)n);
    C->search_state = sh;
    return sh->crack && sh->seg ? 0 : -1;
}

static void shuffled_release(Cracks *C)
{
    Shuffle *sh = C->search_state;
    if (sh) {
        free(sh->crack);
        free(sh->seg);
        free(sh);
    }
    C->search_state = NULL;
}

static const CrossingSearch shuffled = {"shuffled", shuffled_visit,
                                        shuffled_update, shuffled_release, NULL};

/* three cracks on a lattice of quarter units, so that particles and nodes
   fall exactly on segments, their lines and their vertices: a zig-zag
   (one line can cross it many times), a kinked crack, and a straight one
   crossing the zig-zag's region */
static double zx[] = {0, 2, 0, 2, 0, 2, 0, 2}, zy[] = {0, 0.5, 1, 1.5, 2, 2.5, 3, 3.5};
static double kx[] = {-1, 1, 1.5, 3}, ky[] = {4, 2, 2.5, 1};
static double sx[] = {3, -1}, sy[] = {-0.5, 3};

static void random_lines_any_order(void **state)
{
    (void)state;
    Crack cracks[3] = {
        {8, zx, zy, 0, 2, 0, 3.5, 0}, {4, kx, ky, -1, 3, 1, 4, 0}, {2, sx, sy, -1, 3, -0.5, 3, 0},
    };
    Cracks plain = {.ncracks = 3, .crack = cracks, .search = &crossing_plain};
    Cracks mixed = plain;
    mixed.search = &shuffled;
    assert_int_equal(shuffled_update(&mixed, NULL), 0);
    uint64_t s = 12345;
    long crossed = 0, odd = 0, lines = 200000;
    for (long k = 0; k < lines; k++) {
        double v[4];
        for (int j = 0; j < 4; j++) {   /* half on the quarter lattice */
            double u = (double)(next_random(&s) % 1000000) / 1e6;
            v[j] = -1.5 + 5.5 * u;
            if (next_random(&s) % 2)
                v[j] = 0.25 * (double)(long)(4 * v[j]);
        }
        CrackHit a = {-1, -1, 0}, b = {-1, -1, 0};
        int fa = crack_field(&plain, -1, v[0], v[1], v[2], v[3], &a);
        int fb = crack_field(&mixed, -1, v[0], v[1], v[2], v[3], &b);
        if (fa != fb || (fa && (a.crack != b.crack || a.segment != b.segment ||
                                a.side != b.side)))
            fail_msg("line (%g, %g)-(%g, %g): plain %d (crack %d seg %d), "
                     "shuffled %d (crack %d seg %d)", v[0], v[1], v[2], v[3], fa,
                     a.crack, a.segment, fb, b.crack, b.segment);
        crossed += fa != 0;
        Crossings x = {0, 0, {{0, 0, 0}}};
        crossing_plain.visit(&plain, -1, v[0], v[1], v[2], v[3], &x);
        odd += x.n > 1;
    }
    printf("  %ld lines: %ld cross a crack, %ld cross more than one segment; "
           "every field, crack and segment equal in random order\n", lines,
           crossed, odd);
    assert_true(crossed > lines / 10 && odd > lines / 100);
    shuffled_release(&mixed);
}

static const char *scene =
    "grid = { origin = [0.0, 0.0]; cells = [16, 12]; cell_size = [1.0, 1.0]; };\n"
    "run = { time = 20.0; update = \"musl\"; snapshots = 0; crack_search = \"%s\"; };\n"
    "materials = ( { name = \"m\"; E = 1.0; nu = 0.3; rho = 1.0e-3; } );\n"
    "bodies = ( { material = \"m\"; velocity = [0.02, -0.01];\n"
    "             rectangle = { min = [2.0, 2.0]; max = [14.0, 10.0]; }; } );\n"
    "loads = ( { rectangle = { min = [2.0, 6.0]; max = [3.0, 10.0]; }; force = [0.0, 1e-4]; },\n"
    "          { rectangle = { min = [2.0, 2.0]; max = [3.0, 5.5]; }; force = [0.0, -1e-4]; } );\n"
    "cracks = ( { points = ( [1.5, 6.0], [4.0, 6.0], [5.0, 5.5], [6.0, 6.5], [7.0, 5.5],\n"
    "                        [8.0, 6.0], [9.5, 6.0] ); },\n"
    "           { points = ( [11.0, 3.0], [12.0, 5.0], [11.5, 7.5] ); } );\n";

/** The shuffled search as a plug-in: one more row of the table. */
static void with_shuffled(Hooks *h, void *arg)
{
    (void)arg;
    hooks_add_choice(h, "run.crack_search", "shuffled", &shuffled);
}

/** The scene with search @p name, the shuffled search registered too. */
static Sim *load(const char *name)
{
    char text[2048], err[1024];
    snprintf(text, sizeof text, scene, name);
    Sim *sim = tk_load_with(text, with_shuffled, NULL, err, sizeof err);
    if (!sim)
        fail_msg("refused: %s", err);
    return sim;
}

static void whole_run_any_order(void **state)
{
    (void)state;
    Sim *a = load("plain"), *b = load("shuffled");
    assert_ptr_equal(cracks_of(b)->search, &shuffled);
    int n = a->pts.n, multi = 0;
    for (int step = 0; step < 300; step++) {
        tk_steps(a, 1);
        tk_steps(b, 1);
        const FieldTable *Fa = &a->fields, *Fb = &b->fields;
        assert_int_equal(Fa->nrows, Fb->nrows);
        for (int p = 0; p < n; p++) {
            int ra = Fa->row_of[p], rb = Fb->row_of[p];
            assert_int_equal(ra < 0, rb < 0);
            if (ra >= 0)
                assert_memory_equal(&Fa->row_key[STENCIL_NODES * ra],
                                    &Fb->row_key[STENCIL_NODES * rb],
                                    STENCIL_NODES * sizeof(unsigned));
        }
        multi += cracks_multi_field_nodes(a) > 0;
    }
    /* and so the same numbers */
    assert_memory_equal(a->pts.x, b->pts.x, (size_t)n * sizeof(double));
    assert_memory_equal(a->pts.vy, b->pts.vy, (size_t)n * sizeof(double));
    assert_memory_equal(a->pts.sxx, b->pts.sxx, (size_t)n * sizeof(double));
    assert_int_equal(multi, 300);
    tk_free(a);
    tk_free(b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(random_lines_any_order),
        cmocka_unit_test(whole_run_any_order),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
