/**
 * @file test_crack_check.c
 * @brief The self-crossing check of a crack, binned, against the
 *        definition checked pair by pair: random walks on an integer
 *        lattice (so that segments touch, overlap and cross exactly),
 *        the same answer and the same first pair.
 */
#include "testkit.h"

#include <stdint.h>
#include <stdlib.h>

#include "cracks.h"

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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(binned_check_equals_every_pair),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
