/**
 * @file test_searches.c
 * @brief Extent screening and the segment index give exactly the fields of
 *        the plain search: random particle-node lines in random cells,
 *        half of them with points and nodes snapped onto the cracks' own
 *        lattice (on segments, on their lines, on vertices), against
 *        polylines that zig-zag through cells, kink on nodes and run along
 *        grid lines; whole runs of a kinked crack and of an arc.
 */
#include "testkit.h"

#include <stdint.h>
#include <stdlib.h>

#include "cracks.h"
#include "searches.h"
#include "step.h"

/** A small deterministic generator (xorshift64*). */
static uint64_t next_random(uint64_t *s)
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return *s * 2685821657736338717ull;
}

/** A uniform number in [0, 1). */
static double uniform(uint64_t *s)
{
    return (double)(next_random(s) >> 11) * (1.0 / 9007199254740992.0);
}

/* on a grid of 8 x 6 cells of 0.5 x 0.5 from (-1, -1): a zig-zag, a crack
   kinked on grid nodes and lying along a grid line, and a short one */
static double zx[] = {0.1, 0.9, 0.15, 0.95, 0.2}, zy[] = {-0.8, -0.5, -0.2, 0.1, 0.4};
static double kx[] = {-1.0, 0.0, 0.5, 0.5, 1.5}, ky[] = {1.0, 1.0, 0.5, 0.0, 0.0};
static double sx[] = {1.6, 2.8}, sy[] = {1.7, 1.2};

static void every_line_same_fields(void **state)
{
    (void)state;
    Grid g;
    assert_int_equal(grid_init(&g, -1.0, -1.0, 0.5, 0.5, 8, 6), 0);
    Crack cracks[3] = {{5, zx, zy, 0, 0, 0, 0, 0}, {5, kx, ky, 0, 0, 0, 0, 0},
                       {2, sx, sy, 0, 0, 0, 0, 0}};
    for (int k = 0; k < 3; k++)
        crack_extent(&cracks[k]);
    Cracks plain = {.ncracks = 3, .crack = cracks, .search = &crossing_plain};
    Cracks screened = plain, indexed = plain;
    screened.search = &crossing_screened;
    indexed.search = &crossing_indexed;
    assert_int_equal(crossing_screened.update(&screened, &g), 0);
    assert_int_equal(crossing_indexed.update(&indexed, &g), 0);
    uint64_t s = 2026;
    long lines = 1000000, crossed = 0, skipped = 0, snapped = 0;
    for (long k = 0; k < lines; k++) {
        int ci = (int)(next_random(&s) % (uint64_t)g.ncx);
        int cj = (int)(next_random(&s) % (uint64_t)g.ncy);
        int cell = cj * g.nnx + ci, corner = (int)(next_random(&s) % 4);
        double px = g.ox + (ci + uniform(&s)) * g.dx;
        double py = g.oy + (cj + uniform(&s)) * g.dy;
        if (k % 2) {       /* onto the lattice of 0.05: lines, vertices */
            px = g.ox + ci * g.dx + 0.05 * (double)(next_random(&s) % 11);
            py = g.oy + cj * g.dy + 0.05 * (double)(next_random(&s) % 11);
            snapped++;
        }
        double nx = grid_node_x(&g, cell + (corner & 1));
        double ny = grid_node_y(&g, cell + (corner >> 1) * g.nnx);
        CrackHit a = {-1, -1, 0}, b = {-1, -1, 0}, c = {-1, -1, 0};
        int fa = crack_field(&plain, cell, px, py, nx, ny, &a);
        int fb = crack_field(&screened, cell, px, py, nx, ny, &b);
        int fc = crack_field(&indexed, cell, px, py, nx, ny, &c);
        if (fa != fb || fa != fc ||
            (fa && (a.crack != b.crack || a.segment != b.segment ||
                    a.crack != c.crack || a.segment != c.segment)))
            fail_msg("line (%.17g, %.17g)-(%g, %g) in cell %d: plain %d (%d, %d), "
                     "screened %d (%d, %d), indexed %d (%d, %d)", px, py, nx, ny,
                     cell, fa, a.crack, a.segment, fb, b.crack, b.segment, fc,
                     c.crack, c.segment);
        if (fa)
            crossed++;
        if (indexed.near_cell[cell] < 0) {  /* a skipped cell crosses nothing */
            assert_int_equal(fa, 0);
            skipped++;
        }
    }
    printf("  %ld lines (%ld snapped to the lattice): %ld cross a crack, %ld in "
           "cells the index skips; plain, screened and indexed agree on all\n",
           lines, snapped, crossed, skipped);
    assert_true(crossed > lines / 20 && skipped > lines / 20);
    crossing_screened.release(&screened);
    crossing_indexed.release(&indexed);
    grid_free(&g);
}

/** The fields of every pair of @p sim now, as keys (0 without a row). */
static void keys_of(const Sim *sim, unsigned *keys)
{
    const FieldTable *F = &sim->fields;
    for (int p = 0; p < sim->pts.n; p++)
        for (int a = 0; a < STENCIL_NODES; a++)
            keys[STENCIL_NODES * p + a] = F->row_of[p] < 0 ? 0u :
                F->row_key[STENCIL_NODES * F->row_of[p] + a];
}

static void kinked_crack_run_same_fields(void **state)
{
    (void)state;
    static const char *const with[3][2] = {{"run.crack_search=plain", NULL},
                                           {"run.crack_search=screened", NULL},
                                           {"run.crack_search=indexed", NULL}};
    Sim *sim[3];
    for (int k = 0; k < 3; k++)
        sim[k] = tk_load_file("tests/3-crossing/scenes/dcb_kinked.cfg", with[k]);
    int n = sim[0]->pts.n;
    unsigned *keys[3];
    for (int k = 0; k < 3; k++) {
        keys[k] = malloc(sizeof(unsigned) * STENCIL_NODES * (size_t)n);
        assert_non_null(keys[k]);
    }
    for (int step = 0; step < 200; step++) {
        for (int k = 0; k < 3; k++) {
            tk_steps(sim[k], 1);
            keys_of(sim[k], keys[k]);
        }
        assert_memory_equal(keys[0], keys[1], sizeof(unsigned) * STENCIL_NODES * (size_t)n);
        assert_memory_equal(keys[0], keys[2], sizeof(unsigned) * STENCIL_NODES * (size_t)n);
    }
    for (int k = 1; k < 3; k++) {
        assert_memory_equal(sim[0]->pts.x, sim[k]->pts.x, sizeof(double) * (size_t)n);
        assert_memory_equal(sim[0]->pts.sxx, sim[k]->pts.sxx, sizeof(double) * (size_t)n);
    }
    for (int k = 0; k < 3; k++) {
        free(keys[k]);
        tk_free(sim[k]);
    }
}

/** Which side of crack @p c the point (x, y) starts on: +1, -1, or 0 where
 *  the crack does not separate it (past the tip). */
typedef int (*SideOf)(const Crack *c, double x, double y);

/** The kinked crack: above or below its line y = c(x), left of its tip. */
static int side_of_kinked(const Crack *c, double x, double y)
{
    for (int j = 0; j + 1 < c->n; j++)
        if (x >= c->x[j] && x <= c->x[j + 1])
            return y > c->y[j] + (c->y[j + 1] - c->y[j]) * (x - c->x[j]) /
                               (c->x[j + 1] - c->x[j]) ? 1 : -1;
    return 0;
}

/* tests/3-crossing/scenes/dcb_arc.cfg: the circle and the arc's angles */
static const double ARC_X = 0.0, ARC_Y = 60.0, ARC_R = 60.0;
static const double ARC_FROM = -92.0, ARC_TO = -60.0;

/** The arc crack: inside or outside its circle, within its angles. */
static int side_of_arc(const Crack *c, double x, double y)
{
    (void)c;
    double a = atan2(y - ARC_Y, x - ARC_X) * (180.0 / 3.14159265358979323846);
    if (a < ARC_FROM || a > ARC_TO)
        return 0;
    return hypot(x - ARC_X, y - ARC_Y) < ARC_R ? 1 : -1;
}

/** Run @p scene 300 steps: no node slot ever holds points of both sides
 *  of its crack, away from the tip (within two cells of it the crack
 *  does not separate the body); and the crack did split nodes. */
static void sides_never_share_a_field(const char *scene, SideOf side_of)
{
    static const char *const over[] = {"run.crack_search=indexed", NULL};
    Sim *sim = tk_load_file(scene, over);
    const Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    /* side of each point, fixed by where it starts */
    const Crack *c0 = &cracks_of(sim)->crack[0];
    double tipx = c0->x[c0->n - 1], tipy = c0->y[c0->n - 1];
    signed char *side = malloc((size_t)P->n);
    unsigned char *seen = malloc((size_t)g->capacity + 1);
    assert_non_null(side);
    for (int p = 0; p < P->n; p++)
        side[p] = (signed char)side_of(c0, P->x[p], P->y[p]);
    long split = 0;
    for (int step = 0; step < 300; step++) {
        tk_steps(sim, 1);
        free(seen);
        seen = calloc((size_t)g->capacity + 1, 1);
        assert_non_null(seen);
        for (int p = 0; p < P->n; p++) {
            if (!side[p])
                continue;
            Stencil st;
            stencil_of_point(sim, p, &st);
            for (int a = 0; a < STENCIL_NODES; a++) {
                int nd = grid_slot_node(g, st.slot[a]);
                if (hypot(grid_node_x(g, nd) - tipx, grid_node_y(g, nd) - tipy) <
                    2 * fmax(g->dx, g->dy))
                    continue;                /* near the tip */
                seen[st.slot[a]] |= side[p] > 0 ? 1 : 2;
            }
        }
        for (int s = 0; s < g->nslots; s++) {
            if (seen[s] == 3)
                fail_msg("%s, step %d: slot %d of node %d holds both sides",
                         scene, step, s, grid_slot_node(g, s));
            split += s >= g->nnodes && seen[s];
        }
    }
    assert_true(split > 0);                  /* the crack did split nodes */
    free(seen);
    free(side);
    tk_free(sim);
}

static void kinked_crack_sides_never_share_a_field(void **state)
{
    (void)state;
    sides_never_share_a_field("tests/3-crossing/scenes/dcb_kinked.cfg", side_of_kinked);
}

/** An arc in a scene is its polyline: the default number of segments
 *  (about half a cell each), every point on the circle, the ends at the
 *  arc's angles; and its sides never share a field. */
static void arc_crack_is_a_polyline_on_its_circle(void **state)
{
    (void)state;
    Sim *sim = tk_load_file("tests/3-crossing/scenes/dcb_arc.cfg", NULL);
    const Crack *c = &cracks_of(sim)->crack[0];
    double rad = 3.14159265358979323846 / 180.0;
    /* 32 degrees of a 60 mm circle in steps of at most half of 2 mm */
    assert_int_equal(c->n - 1, (int)ceil(32.0 * rad * ARC_R / 1.0));
    for (int k = 0; k < c->n; k++)
        assert_close(hypot(c->x[k] - ARC_X, c->y[k] - ARC_Y), ARC_R, 1e-13);
    assert_close(c->x[0], ARC_R * cos(ARC_FROM * rad), 1e-13);
    assert_close(c->y[c->n - 1], ARC_Y + ARC_R * sin(ARC_TO * rad), 1e-13);
    for (int k = 1; k < c->n; k++)        /* equal segments, in order */
        assert_close(hypot(c->x[k] - c->x[k - 1], c->y[k] - c->y[k - 1]),
                     2 * ARC_R * sin(16.0 * rad / (c->n - 1)), 1e-12);
    tk_free(sim);
    sides_never_share_a_field("tests/3-crossing/scenes/dcb_arc.cfg", side_of_arc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_line_same_fields),
        cmocka_unit_test(kinked_crack_run_same_fields),
        cmocka_unit_test(kinked_crack_sides_never_share_a_field),
        cmocka_unit_test(arc_crack_is_a_polyline_on_its_circle),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
