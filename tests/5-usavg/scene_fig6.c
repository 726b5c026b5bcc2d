/**
 * @file scene_fig6.c
 * @brief The paper's Fig. 6, reduced: the beam impact (Fig. 5) with the
 *        four update schemes, total energy E = kinetic + strain, on two
 *        versions of the scene, both with the paper's 87 g impactor.
 *
 * Reduction: cfl 0.2 (the scenes' 0.1 takes twice as long), to 3.8 ms.
 *
 * One velocity field (figures/fig6/beam_impact.cfg with thickness 51.10,
 * so that the impactor is 87 g; it sticks to the beam): here the schemes
 * alone make the energy error, and the test asserts the paper's ordering:
 * USL stops with a diagnostic, MUSL's energy falls, USF's rises, and USAVG's
 * max |E/E0 - 1| is the smallest and at most 0.1 % (the aim; the
 * paper's band is +-0.18 % about the mean). Measured: USL stops at 0.103 ms;
 * MUSL E/E0 0.93325 at the end (max dev 6.78 %); USF 2.0925 at the end;
 * USAVG max dev 0.021 %. With USAVG's row made MUSL's, this test fails.
 *
 * With contact (figures/fig6/beam_supports.cfg: impactor, beam and
 * supports, frictionless, the default gap detection), at the scene's cfl
 * 0.1, to 3.8 ms, the paper's claims: USL stops with a diagnostic and
 * leaves no NaN (at cfl 0.2); MUSL's energy falls; USF's rises; USAVG's
 * E/E0 stays within +-0.18 % of its mean over the run (the paper's band;
 * bounds fixed before the run), its max |E/E0 - 1| is the smallest of
 * the three, and its band is a time-step error: at cfl 0.1 at most 0.6
 * of its band at cfl 0.2 (first order would give 0.5). Measured (every
 * step; chapter 5 quotes these lines): USAVG +-0.133 % at cfl 0.1 and
 * +-0.581 % at 0.2 (ratio 0.230); max |E/E0 - 1| USAVG 0.206 %, MUSL
 * 0.787 %, USF 3.705 %. (Before USF's stress saw the last step's contact
 * decision, issue 25: +-0.122 % and +-0.331 %.) With the paper's volume rule (V_sep 0.9, V_contact 1.1, the
 * scene before issue 25's gap rule) USAVG's band was +-0.62 % and did not
 * shrink with the step (1.05 % max dev at cfl 0.2, 0.94 % at 0.1): this
 * test fails on that scene.
 */
#include "testkit.h"

#include <stdio.h>
#include <string.h>

static const char *const CONTACT = "figures/fig6/beam_supports.cfg";
static const char *const ONE_FIELD = "figures/fig6/beam_impact.cfg";
/** The aim for USAVG, +-0.1 %, as a bound on |E/E0 - 1|. */
#define USAVG_BOUND 0.001

/** The paper's band for USAVG with contact, +-0.18 % about its mean. */
#define PAPER_BAND 0.0018

/** What one run saw. */
typedef struct Fig6Run {
    int failed;             /* sim_advance() returned non-zero */
    double e_end, dev;      /* E/E0 at the end, max |E/E0 - 1| */
    double band;            /* max |E/E0 - mean of E/E0| over the steps */
} Fig6Run;

static Sim *load(const char *scene, const char *scheme, const char *cfl)
{
    char ov[64], oc[64];
    snprintf(ov, sizeof ov, "run.update=%s", scheme);
    snprintf(oc, sizeof oc, "run.cfl=%s", cfl);
    /* 87 g: 454 points x 0.25 mm^2 x 0.015 g/mm^3 x 51.10 mm */
    const char *const over[] = {ov, oc, "run.time=3.8", "bodies.[1].thickness=51.10",
                                NULL};
    return tk_load_file(scene, over);
}

static Fig6Run run(Sim *sim)
{
    Totals t = sim_totals(sim);
    double e0 = t.kinetic + t.strain;
    Fig6Run r = {0, 1.0, 0.0, 0.0};
    double lo = 1.0, hi = 1.0, sum = 1.0;
    long n = 1;
    while (sim->step < sim->nsteps) {
        if (sim_advance(sim) != 0) {
            r.failed = 1;
            break;
        }
        t = sim_totals(sim);
        r.e_end = (t.kinetic + t.strain) / e0;
        r.dev = fmax(r.dev, fabs(r.e_end - 1.0));
        lo = fmin(lo, r.e_end);
        hi = fmax(hi, r.e_end);
        sum += r.e_end;
        n++;
    }
    double mean = sum / (double)n;
    r.band = fmax(hi - mean, mean - lo);
    return r;
}

static void usl_stops(const char *scene)
{
    Sim *sim = load(scene, "usl", "0.2");
    Fig6Run r = run(sim);
    const Failure *f = &sim->fail;
    printf("  usl: %s at step %ld (t = %.4g ms): point %d, %s = %g\n",
           r.failed ? "stopped" : "ran to the end", f->step, f->time, f->particle,
           f->quantity ? f->quantity : "(none)", f->value);
    assert_true(r.failed);
    assert_true(f->step > 0 && f->step <= sim->step + 1);
    assert_true(f->particle >= 0 && f->particle < sim->pts.n);
    assert_non_null(f->quantity);
    assert_true(strlen(f->quantity) > 0);
    const Particles *P = &sim->pts;
    for (int p = 0; p < P->n; p++) {
        double v[] = {P->x[p], P->y[p], P->vx[p], P->vy[p], P->sxx[p], P->syy[p],
                      P->sxy[p], P->exx[p], P->eyy[p], P->exy[p]};
        for (size_t k = 0; k < sizeof v / sizeof v[0]; k++)
            if (isnan(v[k]))
                fail_msg("point %d: a NaN in the state USL left (value %zu)", p, k);
    }
    tk_free(sim);
}

static Fig6Run one_scheme(const char *scene, const char *name, const char *cfl)
{
    Sim *sim = load(scene, name, cfl);
    Fig6Run r = run(sim);
    printf("  %-5s cfl %s: %s, E/E0 at the end %.5f, max |E/E0 - 1| %.3f %%, "
           "within +-%.3f %% of its mean\n", name, cfl, r.failed ? "unstable" : "ran",
           r.e_end, 100 * r.dev, 100 * r.band);
    assert_false(r.failed);
    tk_free(sim);
    return r;
}

static void one_field_ordering(void **state)
{
    (void)state;
    usl_stops(ONE_FIELD);
    Fig6Run musl = one_scheme(ONE_FIELD, "musl", "0.2");
    Fig6Run usf = one_scheme(ONE_FIELD, "usf", "0.2");
    Fig6Run usavg = one_scheme(ONE_FIELD, "usavg", "0.2");
    assert_true(musl.e_end < 1.0);
    assert_true(usf.e_end > 1.0);
    assert_true(usavg.dev < musl.dev);
    assert_true(usavg.dev < usf.dev);
    assert_true(usavg.dev <= USAVG_BOUND);
}

static void contact_ordering(void **state)
{
    (void)state;
    usl_stops(CONTACT);
    Fig6Run musl = one_scheme(CONTACT, "musl", "0.1");
    Fig6Run usf = one_scheme(CONTACT, "usf", "0.1");
    Fig6Run usavg = one_scheme(CONTACT, "usavg", "0.1");
    Fig6Run twice = one_scheme(CONTACT, "usavg", "0.2");
    printf("  usavg: band at cfl 0.1 / at cfl 0.2 = %.3f\n", usavg.band / twice.band);
    assert_true(musl.e_end < 1.0);
    assert_true(usf.e_end > 1.0);
    assert_true(usavg.band <= PAPER_BAND);
    assert_true(usavg.dev < musl.dev);
    assert_true(usavg.dev < usf.dev);
    assert_true(usavg.band <= 0.6 * twice.band);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(one_field_ordering),
        cmocka_unit_test(contact_ordering),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
