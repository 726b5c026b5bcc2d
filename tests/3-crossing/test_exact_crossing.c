/**
 * @file test_exact_crossing.c
 * @brief The crossing test against an exact reference: 10^6 random
 *        particle-node lines and cracks on a lattice of 1/128 mm, many of
 *        them degenerate (points on crack lines, vertices on grid nodes,
 *        lines through vertices), classified by the sign table of eq. 33
 *        through each search and by an independent rule in integer
 *        arithmetic.
 *
 * On a lattice of 2^-7 the signed areas are exact in double precision, so
 * the two must agree in every case. The reference does not use the sign
 * table: it intersects the line with each segment's line and places the
 * intersection by its parameter t along the segment, as exact fractions:
 *   - a particle on the segment's line is not separated by it;
 *   - otherwise the node must lie on the line or across it, and then:
 *     a node on the segment counts for t in [0, 1) (the crack's last
 *     segment keeps its end point, t = 1: the tip node is on the crack);
 *     a line through the segment counts for t in (0, 1), and at t = 0
 *     unless it is the crack's first point (a line through the crack's
 *     mouth only grazes it); t = 1 is left to the next segment's t = 0.
 * A crack crossed an odd number of times separates the pair, on the side
 * of the sum of its crossings; the crack of lowest index decides.
 */
#include "testkit.h"

#include <stdint.h>
#include <stdlib.h>

#include "cracks.h"
#include "searches.h"

typedef long long i64;

#define UNIT 128       /* lattice points per mm */
#define CELLX 64       /* cell width in lattice units (0.5 mm) */
#define CELLY 32       /* cell height (0.25 mm) */
#define NCX 10         /* cells */
#define NCY 8
#define OX (-128)      /* grid origin in lattice units (-1 mm, -1.25 mm) */
#define OY (-160)
#define MAXC 3         /* cracks in a scene */
#define MAXV 7         /* points of a crack */

/** A small deterministic generator (xorshift64*). */
static uint64_t next_random(uint64_t *s)
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return *s * 2685821657736338717ull;
}

/** A whole number in [0, n). */
static i64 below(uint64_t *s, i64 n)
{
    return (i64)(next_random(s) % (uint64_t)n);
}

/** A random scene of cracks on the lattice, as integers. */
typedef struct LatticeCracks {
    int n;                      /* cracks */
    int nv[MAXC];               /* points of each */
    i64 x[MAXC][MAXV];
    i64 y[MAXC][MAXV];
} LatticeCracks;

/** Sign of the cross product (b - a) x (c - a), exactly. */
static int orient(i64 ax, i64 ay, i64 bx, i64 by, i64 cx, i64 cy)
{
    i64 v = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    return (v > 0) - (v < 0);
}

/** The reference for one segment a -> b: +1 or -1 (the particle's side of
 *  the segment's line), 0 when it does not separate particle p and node q. */
static int reference_segment(i64 px, i64 py, i64 qx, i64 qy, i64 ax, i64 ay,
                             i64 bx, i64 by, int first, int last)
{
    int sp = orient(ax, ay, bx, by, px, py);
    int sq = orient(ax, ay, bx, by, qx, qy);
    if (sp == 0 || sq == sp)
        return 0;
    /* p + s (q - p) = a + t (b - a): t = num / den, s in (0, 1] */
    i64 ex = qx - px, ey = qy - py, dx = bx - ax, dy = by - ay;
    i64 num = (px - ax) * ey - (py - ay) * ex;
    i64 den = dx * ey - dy * ex;
    if (den < 0) {
        num = -num;
        den = -den;
    }
    if (num < 0 || num > den)
        return 0;
    int inside = num > 0 && num < den;
    int ok = sq == 0 ? inside || num == 0 || (num == den && last)
                     : inside || (num == 0 && !first);
    return ok ? sp : 0;
}

/** The reference field of a line: 0, 1 (above) or 2 (below), and the hit. */
static int reference_field(const LatticeCracks *L, i64 px, i64 py, i64 qx,
                           i64 qy, CrackHit *hit)
{
    for (int c = 0; c < L->n; c++) {
        int count = 0, sum = 0, side[MAXV];
        for (int k = 0; k + 1 < L->nv[c]; k++) {
            side[k] = reference_segment(px, py, qx, qy, L->x[c][k], L->y[c][k],
                                        L->x[c][k + 1], L->y[c][k + 1], k == 0,
                                        k + 2 == L->nv[c]);
            count += side[k] != 0;
            sum += side[k];
        }
        if (count % 2 == 0)
            continue;
        hit->crack = c;
        hit->side = sum > 0 ? 1 : -1;
        for (int k = 0; k + 1 < L->nv[c]; k++)
            if (side[k] == hit->side) {
                hit->segment = k;
                break;
            }
        return hit->side > 0 ? 1 : 2;
    }
    return 0;
}

/** A lattice point in the grid: a node, a point on a grid line, or any. */
static void random_vertex(uint64_t *s, i64 *x, i64 *y)
{
    i64 kind = below(s, 3);
    *x = OX + below(s, NCX * CELLX + 1);
    *y = OY + below(s, NCY * CELLY + 1);
    if (kind == 0) {                              /* a grid node */
        *x = OX + CELLX * below(s, NCX + 1);
        *y = OY + CELLY * below(s, NCY + 1);
    } else if (kind == 1) {                       /* on a grid line */
        if (below(s, 2))
            *x = OX + CELLX * below(s, NCX + 1);
        else
            *y = OY + CELLY * below(s, NCY + 1);
    }
    if (*x == OX + NCX * CELLX)                   /* inside the grid */
        *x -= 1;
    if (*y == OY + NCY * CELLY)
        *y -= 1;
}

/** Random cracks: 1-3 polylines of 1-6 segments, no segment of zero
 *  length, some kinked back on themselves, some along grid lines. */
static void random_cracks(uint64_t *s, LatticeCracks *L)
{
    L->n = 1 + (int)below(s, MAXC);
    for (int c = 0; c < L->n; c++) {
        L->nv[c] = 2 + (int)below(s, MAXV - 1);
        for (int k = 0; k < L->nv[c]; k++) {
            do {
                if (k > 0 && below(s, 3) == 0) {  /* a short step, often axial */
                    L->x[c][k] = L->x[c][k - 1] + CELLX / 4 * (below(s, 5) - 2);
                    L->y[c][k] = L->y[c][k - 1] + CELLY / 4 * (below(s, 5) - 2);
                } else {
                    random_vertex(s, &L->x[c][k], &L->y[c][k]);
                }
            } while ((k > 0 && L->x[c][k] == L->x[c][k - 1] &&
                      L->y[c][k] == L->y[c][k - 1]) ||
                     L->x[c][k] < OX || L->x[c][k] >= OX + NCX * CELLX ||
                     L->y[c][k] < OY || L->y[c][k] >= OY + NCY * CELLY);
        }
    }
}

static i64 gcd(i64 a, i64 b)
{
    a = a < 0 ? -a : a;
    b = b < 0 ? -b : b;
    while (b) {
        i64 t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/** A particle for a line: anywhere in a random cell, or on the lattice
 *  points of a crack segment or its line, or on the line from a node
 *  through a crack point. Returns 0 when the point falls off the grid, 2
 *  when it chose the node too (q), 1 when not. */
static int random_particle(uint64_t *s, const LatticeCracks *L, i64 *px,
                           i64 *py, i64 *qx, i64 *qy)
{
    int c = (int)below(s, L->n), k = (int)below(s, L->nv[c] - 1);
    i64 ax = L->x[c][k], ay = L->y[c][k], bx = L->x[c][k + 1], by = L->y[c][k + 1];
    i64 kind = below(s, 4), g = gcd(bx - ax, by - ay);
    if (kind == 0) {                              /* anywhere */
        *px = OX + below(s, NCX * CELLX);
        *py = OY + below(s, NCY * CELLY);
    } else if (kind == 1) {                       /* on the segment */
        i64 j = below(s, g + 1);
        *px = ax + (bx - ax) / g * j;
        *py = ay + (by - ay) / g * j;
    } else if (kind == 2) {                       /* on its line, beyond */
        i64 j = below(s, 3 * g + 1) - g;
        *px = ax + (bx - ax) / g * j;
        *py = ay + (by - ay) / g * j;
    } else {                                      /* node, vertex, particle */
        i64 ci = (ax - OX) / CELLX - below(s, 2), cj = (ay - OY) / CELLY - below(s, 2);
        *qx = OX + CELLX * (ci + below(s, 2));
        *qy = OY + CELLY * (cj + below(s, 2));
        i64 h = gcd(ax - *qx, ay - *qy), j = below(s, 3) + 1;
        if (h == 0)
            return 0;
        *px = ax + (ax - *qx) / h * j;          /* beyond the vertex */
        *py = ay + (ay - *qy) / h * j;
    }
    if (!(*px >= OX && *px < OX + NCX * CELLX && *py >= OY &&
          *py < OY + NCY * CELLY))
        return 0;
    return kind == 3 ? 2 : 1;
}

static double mm(i64 v)
{
    return (double)v / UNIT;    /* exact: a power of two */
}

static void every_line_matches_the_exact_reference(void **state)
{
    (void)state;
    Grid g;
    assert_int_equal(grid_init(&g, mm(OX), mm(OY), mm(CELLX), mm(CELLY), NCX, NCY), 0);
    const CrossingSearch *search[3] = {&crossing_plain, &crossing_screened,
                                       &crossing_indexed};
    uint64_t s = 33;
    long lines = 0, crossed = 0, degenerate = 0, node_on_crack = 0;
    long per_field[3] = {0, 0, 0};
    static double cx[MAXC][MAXV], cy[MAXC][MAXV];
    while (lines < 1000000) {
        LatticeCracks L;
        random_cracks(&s, &L);
        Crack cracks[MAXC];
        for (int c = 0; c < L.n; c++) {
            for (int k = 0; k < L.nv[c]; k++) {
                cx[c][k] = mm(L.x[c][k]);
                cy[c][k] = mm(L.y[c][k]);
            }
            cracks[c] = (Crack){L.nv[c], cx[c], cy[c], 0, 0, 0, 0, 0};
            crack_extent(&cracks[c]);
        }
        Cracks C[3];
        for (int m = 0; m < 3; m++) {
            C[m] = (Cracks){.ncracks = L.n, .crack = cracks, .search = search[m]};
            assert_true(!search[m]->update || search[m]->update(&C[m], &g) == 0);
        }
        for (int j = 0; j < 1000; j++) {
            i64 px, py, qx = 0, qy = 0;
            int got_node = random_particle(&s, &L, &px, &py, &qx, &qy);
            if (!got_node)
                continue;
            /* the particle's cell; the node one of its corners */
            i64 ci = (px - OX) / CELLX, cj = (py - OY) / CELLY;
            if (got_node < 2 || qx < OX + CELLX * ci || qx > OX + CELLX * (ci + 1) ||
                qy < OY + CELLY * cj || qy > OY + CELLY * (cj + 1)) {
                qx = OX + CELLX * (ci + below(&s, 2));
                qy = OY + CELLY * (cj + below(&s, 2));
            }
            int cell = (int)(cj * (NCX + 1) + ci);
            CrackHit ref = {-1, -1, 0};
            int want = reference_field(&L, px, py, qx, qy, &ref);
            for (int m = 0; m < 3; m++) {
                CrackHit hit = {-1, -1, 0};
                int got = crack_field(&C[m], cell, mm(px), mm(py), mm(qx), mm(qy), &hit);
                if (got != want || (want && (hit.crack != ref.crack ||
                                             hit.segment != ref.segment)))
                    fail_msg("%s search, line (%lld, %lld)-(%lld, %lld) /128 mm: "
                             "field %d (crack %d, segment %d), exact %d (crack %d, "
                             "segment %d)", search[m]->name, px, py, qx, qy, got,
                             hit.crack, hit.segment, want, ref.crack, ref.segment);
            }
            int on_line = 0, on_crack = 0;
            for (int c = 0; c < L.n; c++)        /* touches a crack's line */
                for (int k = 0; k + 1 < L.nv[c]; k++) {
                    int op = orient(L.x[c][k], L.y[c][k], L.x[c][k + 1], L.y[c][k + 1], px, py);
                    int oq = orient(L.x[c][k], L.y[c][k], L.x[c][k + 1], L.y[c][k + 1], qx, qy);
                    on_line |= op == 0 || oq == 0;
                    on_crack |= oq == 0 && reference_segment(px, py, qx, qy,
                        L.x[c][k], L.y[c][k], L.x[c][k + 1], L.y[c][k + 1], k == 0,
                        k + 2 == L.nv[c]) != 0;
                }
            degenerate += on_line;
            node_on_crack += on_crack;
            per_field[want]++;
            crossed += want != 0;
            lines++;
        }
        for (int m = 0; m < 3; m++)
            if (search[m]->release)
                search[m]->release(&C[m]);
    }
    printf("  %ld lines: %ld separated by a crack (%ld above, %ld below), %ld "
           "with the particle or the node on a crack's line, %ld with the node on "
           "a crack; plain, "
           "screened and indexed match the exact reference in every one\n",
           lines, crossed, per_field[1], per_field[2], degenerate, node_on_crack);
    /* the degenerate cases are there in numbers */
    assert_true(crossed > lines / 10 && degenerate > lines / 10 &&
                node_on_crack > lines / 100);
    grid_free(&g);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_line_matches_the_exact_reference),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
