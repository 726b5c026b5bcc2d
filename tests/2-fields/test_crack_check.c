/**
 * @file test_crack_check.c
 * @brief The self-crossing check of a crack, binned, against the
 *        definition checked pair by pair: random walks on an integer
 *        lattice (so that segments touch, overlap and cross exactly),
 *        the same answer and the same first pair; and cracks of 100,000
 *        segments read through a scene, one that does not cross itself
 *        and one that does near its far end; a two-point crack that cuts
 *        a body through, both ends outside it, is accepted (it was refused
 *        as lying "outside every body"), and one that misses every body is
 *        still refused.
 */
#include "testkit.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cracks.h"
#include "scene_text.h"

static uint64_t next_random(uint64_t *s)
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return *s * 2685821657736338717ull;
}

/** Orientation of (a, b, c) on integer coordinates: exact. */
static long orient(const long *a, const long *b, const long *c)
{
    long v = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    return (v > 0) - (v < 0);
}

/** Is c on the closed segment a-b, given that the three are collinear? */
static int within(const long *a, const long *b, const long *c)
{
    return (c[0] - a[0]) * (c[0] - b[0]) <= 0 && (c[1] - a[1]) * (c[1] - b[1]) <= 0;
}

/** Do closed segments a-b and c-d share a point (the textbook test)? */
static int meet(const long *a, const long *b, const long *c, const long *d)
{
    long o1 = orient(a, b, c), o2 = orient(a, b, d);
    long o3 = orient(c, d, a), o4 = orient(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0)
        return 1;
    return (o1 == 0 && within(a, b, c)) || (o2 == 0 && within(a, b, d)) ||
           (o3 == 0 && within(c, d, a)) || (o4 == 0 && within(c, d, b));
}

static void binned_check_equals_every_pair(void **state)
{
    (void)state;
    uint64_t s = 7;
    long p[64][2];
    double x[64], y[64];
    int crossing = 0, clean = 0;
    for (int trial = 0; trial < 20000; trial++) {
        int n = 3 + (int)(next_random(&s) % 40);
        p[0][0] = p[0][1] = 0;
        for (int k = 1; k < n; k++) {
            do {       /* steps of -3..3, never of zero length */
                p[k][0] = p[k - 1][0] + (long)(next_random(&s) % 7) - 3;
                p[k][1] = p[k - 1][1] + (long)(next_random(&s) % 7) - 3;
            } while (p[k][0] == p[k - 1][0] && p[k][1] == p[k - 1][1]);
        }
        for (int k = 0; k < n; k++) {
            x[k] = (double)p[k][0] * 0.25;
            y[k] = (double)p[k][1] * 0.25;
        }
        int ri = -1, rj = -1;
        for (int i = 0; i + 1 < n && ri < 0; i++)
            for (int j = i + 2; j + 1 < n && ri < 0; j++)
                if (meet(p[i], p[i + 1], p[j], p[j + 1])) {
                    ri = i;
                    rj = j;
                }
        Crack c = {n, x, y, 0, 0, 0, 0, 0};
        int i = -1, j = -1, got = crack_self_crossing(&c, &i, &j);
        if (got != (ri >= 0) || (got && (i != ri || j != rj))) {
            for (int k = 0; k < n; k++)
                printf("(%ld,%ld) ", p[k][0], p[k][1]);
            printf("\n got %d (%d, %d), pair by pair %d (%d, %d)\n", got, i, j,
                   ri >= 0, ri, rj);
        }
        assert_int_equal(got, ri >= 0);
        if (got) {
            assert_int_equal(i, ri);
            assert_int_equal(j, rj);
            crossing++;
        } else {
            clean++;
        }
    }
    printf("  20000 random lattice walks: %d cross themselves, %d do not; the "
           "binned check agrees on each, first pair included\n", crossing, clean);
    assert_true(crossing > 1000 && clean > 1000);
}

/** A scene with one crack through the points (2k, 2 (k % 2)), k < n, of a
 *  lattice, scaled into its 10 x 10 mm block, and @p last when not NULL
 *  as one more point: the crack's points in @p p. */
static char *long_crack_scene(int n, const long *last, long (*p)[2])
{
    SceneBuf b = {NULL, 0, 0};
    const char *head = "grid = { origin = [0.0, 0.0]; cells = [12, 12]; cell_size = [1.0, 1.0]; };\n"
        "run = { time = 0.01; snapshots = 0; };\n"
        "materials = ( { name = \"gel\"; E = 0.1; nu = 0.33; rho = 1.5e-3; } );\n"
        "bodies = ( { name = \"block\"; material = \"gel\";\n"
        "  rectangle = { min = [1.0, 1.0]; max = [11.0, 11.0]; }; } );\n"
        "cracks = ( { points = (\n";
    assert_int_equal(scene_buf_add(&b, head, strlen(head)), 0);
    for (int k = 0; k < n + (last != NULL); k++) {
        char row[96];
        p[k][0] = k < n ? 2L * k : last[0];
        p[k][1] = k < n ? 2L * (k % 2) : last[1];
        /* 4e-5 mm a lattice step: 100,000 points span 8 mm from x = 2 */
        int len = snprintf(row, sizeof row, "%s[%.17e, %.17e]\n", k ? "," : "",
                           2.0 + 4e-5 * (double)p[k][0], 6.0 + 4e-5 * (double)p[k][1]);
        assert_int_equal(scene_buf_add(&b, row, (size_t)len), 0);
    }
    assert_int_equal(scene_buf_add(&b, "); } );\n", 8), 0);
    return b.s;
}

/** A fine zigzag of 100,000 segments does not cross itself: read,
 *  checked and accepted in well under a second (with as many bins along
 *  y as along x, this thin crack put some 300 segments in each bin and
 *  took over half a minute). */
static void long_zigzag_is_accepted(void **state)
{
    (void)state;
    enum { N = 100001 };
    long (*p)[2] = malloc(sizeof *p * (N + 1));
    assert_non_null(p);
    char *text = long_crack_scene(N, NULL, p), err[1024];
    Sim *sim = tk_load_with(text, NULL, NULL, err, sizeof err);
    if (!sim)
        fail_msg("a zigzag of %d segments refused: %s", N - 1, err);
    const Cracks *C = cracks_of(sim);
    assert_non_null(C);
    assert_int_equal(C->crack[0].n, N);
    tk_free(sim);
    free(text);
    free(p);
}

/** The same zigzag with one more segment that turns back across it near
 *  its far end is refused, naming the first pair the definition finds. */
static void long_crack_crossing_near_its_end_is_refused(void **state)
{
    (void)state;
    enum { N = 100001 };
    long (*p)[2] = malloc(sizeof *p * (N + 1));
    assert_non_null(p);
    const long last[2] = {2L * (N - 6) + 1, 3};      /* back over the zigzag */
    char *text = long_crack_scene(N, last, p), err[1024];
    int t = N - 1, first = -1;                      /* the last segment */
    for (int s = 0; s + 2 <= t && first < 0; s++)
        if (meet(p[s], p[s + 1], p[t], p[t + 1]))
            first = s;
    assert_true(first > N - 10);                    /* near the far end */
    Sim *sim = tk_load_with(text, NULL, NULL, err, sizeof err);
    if (sim)
        fail_msg("a crack that crosses itself (segments %d and %d) was accepted",
                 first, t);
    char want[128];
    snprintf(want, sizeof want, "the crack crosses itself (segments %d and %d)",
             first, t);
    if (!strstr(err, want))
        fail_msg("message lacks \"%s\": %s", want, err);
    free(text);
    free(p);
}

/** A block cut through by a crack from outside to outside: accepted; the
 *  same crack moved off the block: refused. */
static void crack_cutting_a_body_through(void **state)
{
    (void)state;
    const char *fmt =
        "grid = { origin = [0.0, 0.0]; cells = [10, 10]; cell_size = [1.0, 1.0]; };\n"
        "run = { time = 0.1; snapshots = 0; };\n"
        "materials = ( { name = \"m\"; E = 1.0; nu = 0.3; rho = 1.0e-3; } );\n"
        "bodies = ( { material = \"m\"; rectangle = { min = [2.0, 2.0]; max = [8.0, 8.0]; }; } );\n"
        "cracks = ( { points = ( [1.0, %s], [9.0, %s] ); } );\n";
    char text[1024], err[512];
    snprintf(text, sizeof text, fmt, "5.2", "5.2");
    Sim *sim = tk_load_with(text, NULL, NULL, err, sizeof err);
    if (!sim)
        fail_msg("a crack cutting the block through was refused: %s", err);
    assert_int_equal(cracks_of(sim)->ncracks, 1);
    tk_free(sim);
    snprintf(text, sizeof text, fmt, "9.5", "9.5");
    sim = tk_load_with(text, NULL, NULL, err, sizeof err);
    assert_null(sim);
    printf("  a crack above the block: %s\n", err);
    assert_non_null(strstr(err, "lies outside every body"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(binned_check_equals_every_pair),
        cmocka_unit_test(long_zigzag_is_accepted),
        cmocka_unit_test(long_crack_crossing_near_its_end_is_refused),
        cmocka_unit_test(crack_cutting_a_body_through),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
