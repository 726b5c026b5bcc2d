/**
 * @file test_sign_table.c
 * @brief Every sign pattern of the Appendix's line-crossing table, one by
 *        one, and the cases around it: with 1 = particle, 2 = node and the
 *        crack segment 3 -> 4 from (0, 0) to (4, 0) ("above" is +y), the
 *        signs of A(123), A(124), A(341), A(342) (eq. 33) decide.
 */
#include "testkit.h"

#include "cracks.h"

static double sx[2] = {0, 4}, sy[2] = {0, 0};

/** The one-segment crack from (0, 0) to (4, 0). */
static Crack segment(void)
{
    return (Crack){2, sx, sy, 0, 4, 0, 0, 0};
}

/** Signed area of eq. 33, to show each case's pattern in the test. */
static int sgn(double x1, double y1, double x2, double y2, double x3, double y3)
{
    double a = x1 * (y2 - y3) + x2 * (y3 - y1) + x3 * (y1 - y2);
    return (a > 0) - (a < 0);
}

/** Check the pattern of (particle, node) against the segment, then the
 *  side crack_segment_side() gives. */
static void check(double px, double py, double nx, double ny, int s123,
                  int s124, int s341, int s342, int side)
{
    Crack c = segment();
    assert_int_equal(sgn(px, py, nx, ny, 0, 0), s123);
    assert_int_equal(sgn(px, py, nx, ny, 4, 0), s124);
    assert_int_equal(sgn(0, 0, 4, 0, px, py), s341);
    assert_int_equal(sgn(0, 0, 4, 0, nx, ny), s342);
    assert_int_equal(crack_segment_side(&c, 0, px, py, nx, ny), side);
    assert_int_equal(crack_crossing(&c, px, py, nx, ny), side);
}

static void particle_above(void **state)
{
    (void)state;
    check(2, 1, 2, -1, -1, +1, +1, -1, +1);   /* (-,+,+,-): the usual one */
    check(2, 1, 2, 0, -1, +1, +1, 0, +1);     /* (-,+,+,0): node on it */
    check(1, 1, 0, 0, 0, +1, +1, 0, +1);      /* (0,+,+,0): node on its start */
    check(3, 1, 4, 0, -1, 0, +1, 0, +1);      /* (-,0,+,0): node on its end */
}

static void particle_below(void **state)
{
    (void)state;
    check(2, -1, 2, 1, +1, -1, -1, +1, -1);   /* (+,-,-,+) */
    check(2, -1, 2, 0, +1, -1, -1, 0, -1);    /* (+,-,-,0) */
    check(1, -1, 0, 0, 0, -1, -1, 0, -1);     /* (0,-,-,0) */
    check(3, -1, 4, 0, +1, 0, -1, 0, -1);     /* (+,0,-,0) */
}

static void not_crossed(void **state)
{
    (void)state;
    check(1, 1, 3, 1, -1, -1, +1, +1, 0);     /* A123, A124 agree: early exit */
    check(2, 1, 3, 2, +1, -1, +1, +1, 0);     /* both above the crack */
    check(6, 1, 6, -1, -1, -1, +1, -1, 0);    /* past the end */
    check(-1, 1, -1, -1, +1, +1, +1, -1, 0);  /* before the start */
    check(5, 1, 4.5, 0, -1, -1, +1, 0, 0);    /* node on the line, past the end */
    check(2, 0, 2, -1, -1, +1, 0, -1, 0);     /* particle on the crack: contact
                                                 keeps points off cracks (the
                                                 table's ignored case) */
    check(1, 0, 3, 0, 0, 0, 0, 0, 0);         /* collinear with the crack */
    check(5, 0, 6, 0, 0, 0, 0, 0, 0);         /* collinear, beyond it */
}

static void nearly_collinear(void **state)
{
    (void)state;
    /* areas of 1e-300 still have their signs */
    check(2, 1e-300, 2, -1e-300, -1, +1, +1, -1, +1);
    check(2, -1e-300, 2, 1e-300, +1, -1, -1, +1, -1);
    check(4 + 1e-15, 1, 4 + 1e-15, -1, -1, -1, +1, -1, 0);   /* just past */
    check(4 - 1e-15, 1, 4 - 1e-15, -1, -1, +1, +1, -1, +1);  /* just before */
}

static void polylines(void **state)
{
    (void)state;
    /* a line through the vertex shared by two segments counts once */
    double x[3] = {0, 2, 4}, y[3] = {0, 0, 1};
    Crack c = {3, x, y, 0, 4, 0, 1, 0};
    assert_int_equal(crack_crossing(&c, 2, 1, 2, -1), +1);
    assert_int_equal(crack_crossing(&c, 2, -1, 2, 1), -1);
    assert_int_equal(crack_crossing(&c, 1.5, 1, 2.5, -1), +1);
    /* a node on the shared vertex: above or below, never 0 */
    assert_int_equal(crack_crossing(&c, 2.2, 0.8, 2, 0), +1);
    assert_int_equal(crack_crossing(&c, 1.8, -0.3, 2, 0), -1);
    /* a zig-zag crossed twice is not crossed; three times is */
    double zx[4] = {0, 2, 0, 2}, zy[4] = {0, 1, 2, 3};
    Crack z = {4, zx, zy, 0, 2, 0, 3, 0};
    assert_int_equal(crack_crossing(&z, 1, -1, 1, 1.9), 0);
    assert_int_equal(crack_crossing(&z, 1, -1, 1, 2.9), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(particle_above),
        cmocka_unit_test(particle_below),
        cmocka_unit_test(not_crossed),
        cmocka_unit_test(nearly_collinear),
        cmocka_unit_test(polylines),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
