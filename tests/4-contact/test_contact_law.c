/**
 * @file test_contact_law.c
 * @brief The contact adjustment at one node (section 2.2, eq. 10-19),
 *        checked against the properties that define it: total momentum
 *        unchanged; stick gives both fields the centre-of-mass velocity;
 *        frictionless removes the normal relative velocity and keeps the
 *        tangential one; friction reduces the tangential one by exactly
 *        mu times the normal impulse while sliding and never reverses it;
 *        a mu large enough gives exactly the stick result; kinetic energy
 *        never grows; and the detection of eq. 10-12.
 *
 * Each property is checked on 10^5 random pairs of fields (masses over
 * six decades, any velocities, any normal), so a sign or a factor wrong in
 * any branch fails.
 */
#include "testkit.h"

#include <float.h>
#include <string.h>

#include "contact_law.h"

/** A random pair of fields at a node. */
typedef struct Pair {
    double ma, mb, pa[2], pb[2], n[2];
} Pair;

/** Uniform in [0, 1) from a 64-bit linear congruential generator. */
static double uniform(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) * (1.0 / 9007199254740992.0);
}

static Pair random_pair(unsigned long long *s)
{
    Pair q;
    q.ma = pow(10.0, 6 * uniform(s) - 3);
    q.mb = pow(10.0, 6 * uniform(s) - 3);
    for (int k = 0; k < 2; k++) {
        q.pa[k] = q.ma * (2 * uniform(s) - 1);
        q.pb[k] = q.mb * (2 * uniform(s) - 1);
    }
    double a = 2 * 3.14159265358979323846 * uniform(s);
    q.n[0] = cos(a);
    q.n[1] = sin(a);
    return q;
}

/** Relative velocity (v_a - v_b) after field a's momentum changed by dp. */
static void relative_after(const Pair *q, const double dp[2], double dv[2])
{
    for (int k = 0; k < 2; k++)
        dv[k] = (q->pa[k] + dp[k]) / q->ma - (q->pb[k] - dp[k]) / q->mb;
}

/** Velocity scale of a pair, for round-off bounds. */
static double vscale(const Pair *q)
{
    return hypot(q->pa[0], q->pa[1]) / q->ma + hypot(q->pb[0], q->pb[1]) / q->mb;
}

static double kinetic(const Pair *q, const double dp[2])
{
    double e = 0;
    for (int k = 0; k < 2; k++) {
        double a = q->pa[k] + dp[k], b = q->pb[k] - dp[k];
        e += 0.5 * (a * a / q->ma + b * b / q->mb);
    }
    return e;
}

static const int N = 100000;
static const double EPS = 64 * DBL_EPSILON;

static void stick_moves_both_with_the_centre_of_mass(void **state)
{
    (void)state;
    unsigned long long s = 1;
    for (int i = 0; i < N; i++) {
        Pair q = random_pair(&s);
        double dp[2], dv[2];
        contact_stick(q.ma, q.pa, q.mb, q.pb, dp);
        relative_after(&q, dp, dv);
        assert_true(hypot(dv[0], dv[1]) <= EPS * vscale(&q));
        for (int k = 0; k < 2; k++)          /* the momentum each field ends with */
            assert_close(q.pa[k] + dp[k], q.ma * (q.pa[k] + q.pb[k]) / (q.ma + q.mb),
                         EPS * (fabs(q.pa[k]) + fabs(q.pb[k])));
        assert_true(kinetic(&q, dp) <= kinetic(&q, (double[2]){0, 0}) * (1 + EPS));
    }
}

static void frictionless_removes_the_normal_keeps_the_tangential(void **state)
{
    (void)state;
    unsigned long long s = 2;
    for (int i = 0; i < N; i++) {
        Pair q = random_pair(&s);
        double dp[2], dv[2], dv0[2], zero[2] = {0, 0}, t[2] = {-q.n[1], q.n[0]};
        contact_friction(q.ma, q.pa, q.mb, q.pb, q.n, 0.0, dp);
        relative_after(&q, dp, dv);
        relative_after(&q, zero, dv0);
        double v = vscale(&q);
        assert_true(fabs(dv[0] * q.n[0] + dv[1] * q.n[1]) <= EPS * v);
        assert_close(dv[0] * t[0] + dv[1] * t[1], dv0[0] * t[0] + dv0[1] * t[1], EPS * v);
        assert_true(fabs(dp[0] * t[0] + dp[1] * t[1]) <= EPS * hypot(dp[0], dp[1]));
        assert_true(kinetic(&q, dp) <= kinetic(&q, zero) * (1 + EPS));
    }
}

static void friction_reduces_sliding_by_coulomb(void **state)
{
    (void)state;
    unsigned long long s = 3;
    int slid = 0, stuck = 0;
    for (int i = 0; i < N; i++) {
        Pair q = random_pair(&s);
        double mu = 2 * uniform(&s);
        double dp[2], st[2], dv[2], dv0[2], zero[2] = {0, 0}, t[2] = {-q.n[1], q.n[0]};
        contact_friction(q.ma, q.pa, q.mb, q.pb, q.n, mu, dp);
        contact_stick(q.ma, q.pa, q.mb, q.pb, st);
        relative_after(&q, dp, dv);
        relative_after(&q, zero, dv0);
        double v = vscale(&q), P = hypot(st[0], st[1]);
        double dpn = dp[0] * q.n[0] + dp[1] * q.n[1], dpt = dp[0] * t[0] + dp[1] * t[1];
        double vt = dv[0] * t[0] + dv[1] * t[1], vt0 = dv0[0] * t[0] + dv0[1] * t[1];
        /* the normal part is always stick's: normal approach removed */
        assert_close(dpn, st[0] * q.n[0] + st[1] * q.n[1], EPS * P);
        assert_true(fabs(dv[0] * q.n[0] + dv[1] * q.n[1]) <= EPS * v);
        if (memcmp(dp, st, sizeof dp) == 0) {    /* stuck: |dp_t| <= mu |dp_n| */
            assert_true(fabs(dpt) <= mu * fabs(dpn) * (1 + EPS) + EPS * P);
            stuck++;
        } else {                                 /* sliding: at the Coulomb limit */
            assert_close(fabs(dpt), mu * fabs(dpn), EPS * P);
            assert_true(vt * vt0 >= 0);          /* slows, never reverses */
            assert_true(fabs(vt) <= fabs(vt0) * (1 + EPS));
            assert_true(fabs(vt) > 0);
            slid++;
        }
        assert_true(kinetic(&q, dp) <= kinetic(&q, zero) * (1 + EPS));
    }
    printf("  %d sliding, %d stuck by friction\n", slid, stuck);
    assert_true(slid > N / 10 && stuck > N / 10);   /* both branches tried */
}

static void large_mu_gives_exactly_stick(void **state)
{
    (void)state;
    unsigned long long s = 4;
    for (int i = 0; i < N; i++) {
        Pair q = random_pair(&s);
        double dp[2], st[2];
        contact_stick(q.ma, q.pa, q.mb, q.pb, st);
        double tn = fabs(st[0] * q.n[0] + st[1] * q.n[1]);
        double tt = fabs(-st[0] * q.n[1] + st[1] * q.n[0]);
        if (!(tn > 1e-3 * tt))
            continue;                           /* mu would have to be huge */
        contact_friction(q.ma, q.pa, q.mb, q.pb, q.n, 1.01 * tt / tn + 1e-12, dp);
        assert_memory_equal(dp, st, sizeof dp);  /* bit for bit */
    }
}

static void momentum_is_exact(void **state)
{
    (void)state;
    unsigned long long s = 5;
    for (int i = 0; i < N; i++) {
        Pair q = random_pair(&s);
        double dp[2];
        contact_friction(q.ma, q.pa, q.mb, q.pb, q.n, uniform(&s), dp);
        for (int k = 0; k < 2; k++) {            /* as crack_contact.c applies it */
            double a = q.pa[k] + dp[k], b = q.pb[k] - dp[k];
            assert_close(a + b, q.pa[k] + q.pb[k],
                         4 * DBL_EPSILON * (fabs(q.pa[k]) + fabs(q.pb[k]) + fabs(dp[k])));
        }
    }
}

static void detection_follows_eq_10_to_12(void **state)
{
    (void)state;
    /* below V_sep: separated, even when approaching */
    assert_int_equal(contact_detected(0.89, 0.9, 1.1, 1.0), 0);
    /* above V_contact: in contact, even when separating (the paper) */
    assert_int_equal(contact_detected(1.11, 0.9, 1.1, -1.0), 1);
    /* grey zone: approach decides (eq. 12) */
    assert_int_equal(contact_detected(1.0, 0.9, 1.1, 1e-300), 1);
    assert_int_equal(contact_detected(1.0, 0.9, 1.1, 0.0), 0);
    assert_int_equal(contact_detected(1.0, 0.9, 1.1, -1e-300), 0);
    /* the bounds belong to the grey zone */
    assert_int_equal(contact_detected(0.9, 0.9, 1.1, -1.0), 0);
    assert_int_equal(contact_detected(0.9, 0.9, 1.1, 1.0), 1);
    assert_int_equal(contact_detected(1.1, 0.9, 1.1, -1.0), 0);
    /* V_sep = V_contact: no grey zone but the point itself */
    assert_int_equal(contact_detected(0.999, 1.0, 1.0, 1.0), 0);
    assert_int_equal(contact_detected(1.001, 1.0, 1.0, -1.0), 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(stick_moves_both_with_the_centre_of_mass),
        cmocka_unit_test(frictionless_removes_the_normal_keeps_the_tangential),
        cmocka_unit_test(friction_reduces_sliding_by_coulomb),
        cmocka_unit_test(large_mu_gives_exactly_stick),
        cmocka_unit_test(momentum_is_exact),
        cmocka_unit_test(detection_follows_eq_10_to_12),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
