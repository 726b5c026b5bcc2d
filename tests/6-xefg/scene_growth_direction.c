/**
 * @file scene_growth_direction.c
 * @brief Where a cohesive XEFG crack grows under direction = "hoop"
 *        (chapter 6b, "When and where a tip grows"): Rankine's sigma_1 >=
 *        f_t says when, the largest hoop stress of K_I, K_II by the
 *        interaction integral says where (issue 27: normal to sigma_1 the
 *        DCB's crack turned by 90 degrees and Kalthoff-Winkler's kinked at
 *        42.6 degrees).
 *
 * Bounds, fixed before the first run:
 * - dcb_grows_straight (tests/6-xefg/scenes/dcb_hoop.cfg, the DCB of make
 *   fig-growth at h = 2 mm, opened four times as fast, 170 ms): at least
 *   three events, and every point of the crack within 1e-6 of the beam's
 *   depth (36 mm) of its line y = 0 (the beam and its nodes are symmetric
 *   about the line, so K_II is round-off).
 * - Kalthoff-Winkler's first kink (kalthoff_coarse.cfg, h = 1.25 mm) is
 *   tests/6-xefg/scene_kalthoff_xefg.c's, with the rest of issue 27's
 *   bounds on the same run.
 * - inclined_kink_by_hoop_stress (Griffith's plate of griffith.h, beta =
 *   30 and 60 degrees, its loads ramped over 0.3 ms, a traction-free crack
 *   with cohesive growth, f_t = 1 MPa): both tips grow, and each tip's
 *   first segment turns from the crack's direction by Erdogan and Sih's
 *   angle for Griffith's K_I = sigma sqrt(pi a) cos^2 beta, K_II = sigma
 *   sqrt(pi a) sin beta cos beta within 3 degrees.
 * - failed_integral_stops_the_run (tests/6-xefg/scenes/growth_bar.cfg
 *   with direction = "hoop" and the ring made too thin to hold a Gauss
 *   point): the run stops at the first event that reaches f_t, with a
 *   diagnostic naming the direction and the crack, no segment added.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cohesive.h"
#include "griffith.h"
#include "growth.h"
#include "hoop_angle.h"
#include "testkit.h"
#include "xefg.h"

#define PI 3.14159265358979323846
#define DEG (180.0 / PI)

/** The turn (degrees, anticlockwise) of event @p ev's segment from the
 *  direction ahead of the old tip, the one from (@p px, @p py), the
 *  crack's point behind the tip, to the tip. */
static double turn_of(const GrowthEvent *ev, double px, double py)
{
    double d0 = atan2(ev->y0 - py, ev->x0 - px);
    double d1 = atan2(ev->y1 - ev->y0, ev->x1 - ev->x0);
    double t = d1 - d0;
    while (t > PI)
        t -= 2.0 * PI;
    while (t < -PI)
        t += 2.0 * PI;
    return t * DEG;
}

/** The DCB: K_II = 0 by symmetry, and the crack stays on its line. */
static void dcb_grows_straight(void **state)
{
    (void)state;
    Sim *s = tk_load_file("tests/6-xefg/scenes/dcb_hoop.cfg", NULL);
    Xefg *x = xefg_of(s);
    Growth *g = x->grow;
    tk_steps(s, s->nsteps - s->step);
    const CrackLine *l = &x->crack[0];
    double dev = 0.0, kii = 0.0, ki = 0.0;
    for (int i = 0; i < l->n; i++)
        dev = fmax(dev, fabs(l->y[i]));
    for (int e = 0; e < g->nevent; e++) {
        kii = fmax(kii, fabs(g->event[e].KII));
        ki = fmax(ki, g->event[e].KI);
    }
    printf("  DCB, h = %g mm: %d events, tip at (%g, %.3g); largest |y| of "
           "the crack %.3g mm (%.3g of the depth 36 mm); at the events K_I up "
           "to %.4g, |K_II| up to %.3g MPa sqrt(mm)\n", g->h, g->nevent,
           l->x[l->n - 1], l->y[l->n - 1], dev, dev / 36.0, ki, kii);
    if (g->nevent > 0)
        printf("    first event at t = %.4g ms: sigma_1 %.5g MPa, K_I %.4g, "
               "K_II %.3g\n", g->event[0].t, g->event[0].sigma1,
               g->event[0].KI, g->event[0].KII);
    TkBounds b = {0, 0};
    tk_bound(&b, 4, g->nevent >= 3, "%d events", g->nevent);
    tk_bound(&b, 4, dev <= 1e-6 * 36.0, "crack off its line by %.3g mm", dev);
    tk_bounds_finish(&b);
    tk_free(s);
}

/** Griffith's inclined crack at @p beta degrees: each tip's first kink
 *  against Erdogan and Sih's for Griffith's K. */
static void inclined(double beta, TkBounds *b)
{
    double r = beta / DEG;
    char *text = griffith_plate(r, 0, 0.6, 100.0,
                                " cohesive = { law = \"linear\"; f_t = 1.0; "
                                "G_f = 0.05; notch_segments = 1; growth = { "
                                "direction = \"hoop\"; }; };",
                                " ramp = 0.3;");
    Sim *s = tk_load(text);
    free(text);
    Xefg *x = xefg_of(s);
    Growth *g = x->grow;
    const CrackLine *l = &x->crack[0];
    /* the crack's two points: the direction ahead at end 1 is point 0 to
     * point 1, at end 0 the reverse */
    double p[2][2] = {{l->x[0], l->y[0]}, {l->x[1], l->y[1]}};
    int seen[2] = {0, 0};
    double kink[2] = {NAN, NAN}, t[2] = {NAN, NAN}, K[2][2];
    while (s->step < s->nsteps && !(seen[0] && seen[1])) {
        int n0 = g->nevent;
        tk_steps(s, 1);
        for (int k = n0; k < g->nevent; k++) {
            const GrowthEvent *ev = &g->event[k];
            int e = ev->end;
            if (seen[e])
                continue;
            seen[e] = 1;
            kink[e] = turn_of(ev, p[1 - e][0], p[1 - e][1]);
            t[e] = ev->t;
            K[e][0] = ev->KI;
            K[e][1] = ev->KII;
        }
    }
    double K0 = SIGMA * sqrt(PI * CRACK);
    double want = hoop_angle(cos(r) * cos(r), sin(r) * cos(r)) * DEG;
    for (int e = 0; e < 2; e++) {
        printf("  beta %2.0f deg, tip %d: ", beta, e);
        if (!seen[e]) {
            printf("no event\n");
            continue;
        }
        printf("first event at t = %.4g ms (load %.3g of sigma), K / (sigma "
               "sqrt(pi a)) at it %.4f, %.4f; kink %+.2f degrees, Erdogan and "
               "Sih for Griffith's K %+.2f (error %+.2f)\n", t[e],
               fmin(t[e] / 0.3, 1.0), K[e][0] / K0, K[e][1] / K0, kink[e],
               want, kink[e] - want);
    }
    tk_bound(b, 4, seen[0] && seen[1], "beta %g: a tip did not grow", beta);
    for (int e = 0; e < 2; e++)
        tk_bound(b, 4, seen[e] && fabs(kink[e] - want) <= 3.0,
                 "beta %g, tip %d: kink %.2f, want %.2f", beta, e, kink[e],
                 want);
    tk_free(s);
}

/** The inclined crack at 30 and 60 degrees. */
static void inclined_kink_by_hoop_stress(void **state)
{
    (void)state;
    TkBounds b = {0, 0};
    inclined(30.0, &b);
    inclined(60.0, &b);
    tk_bounds_finish(&b);
}

/** An interaction integral that fails stops the run, naming the crack. */
static void failed_integral_stops_the_run(void **state)
{
    (void)state;
    const char *const over[] = {"run.time=0.3",
                                "cracks.[0].cohesive.growth.direction=\"hoop\"",
                                NULL};
    Sim *s = tk_load_file("tests/6-xefg/scenes/growth_bar.cfg", over);
    Xefg *x = xefg_of(s);
    x->grow->k_radius = 1e-9;           /* no Gauss point in its ring */
    int n0 = x->crack[0].n, rc = 0;
    while (s->step < s->nsteps && (rc = sim_advance(s)) == 0)
        ;
    printf("  a failed integral: rc %d at step %ld (t = %g ms): \"%s = %g\"; "
           "%d events, %d points\n", rc, s->fail.step, s->t,
           s->fail.quantity ? s->fail.quantity : "(none)", s->fail.value,
           x->grow->nevent, x->crack[0].n);
    assert_true(rc != 0);
    assert_non_null(s->fail.quantity);
    assert_non_null(strstr(s->fail.quantity, "direction = \"hoop\" of crack"));
    assert_true(s->fail.value == 0.0);
    assert_int_equal(x->grow->nevent, 0);
    assert_int_equal(x->crack[0].n, n0);
    tk_free(s);
}

/** The step shortens as the crack grows (chapter 6b): the snapshots asked
 *  for are still written once each, the last at the run's end. Before
 *  the run loop counted them in steps of the new length from the start,
 *  this scene wrote 328 of 401 (and the figure's finer DCB wrote past the
 *  end of the snapshot list). */
static void snapshots_follow_a_shortened_step(void **state)
{
    (void)state;
    static char out[4096];
    const char *dir = "build/test-out/xefg-snapshots";
    char args[512];
    snprintf(args, sizeof args, "tests/6-xefg/scenes/dcb_hoop.cfg -q -o %s "
             "run.snapshots=400", dir);
    assert_int_equal(tk_run_mpm(args, out, sizeof out), 0);
    char path[256];
    snprintf(path, sizeof path, "%s/particles.pvd", dir);
    char *pvd = tk_slurp(path, NULL);
    int n = 0;
    double last = -1.0;
    for (const char *at = pvd; (at = strstr(at, "timestep=\"")) != NULL; n++) {
        at += strlen("timestep=\"");
        last = strtod(at, NULL);
    }
    free(pvd);
    printf("  400 snapshots asked: %d written (with t = 0), the last at t = "
           "%.5f ms of 170\n", n, last);
    assert_int_equal(n, 401);
    assert_true(fabs(last - 170.0) < 0.1);      /* the last step's time */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(dcb_grows_straight),
        cmocka_unit_test(inclined_kink_by_hoop_stress),
        cmocka_unit_test(failed_integral_stops_the_run),
        cmocka_unit_test(snapshots_follow_a_shortened_step),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
