/**
 * @file scene_material_disks.c
 * @brief Chapter 1's two colliding disks (Sulsky, Chen and Schreyer 1994)
 *        with contact between bodies (tests/4-contact/scenes/
 *        disks_contact.cfg): each disk has its own velocity field where both
 *        reach a node, and the pair is frictionless.
 *
 * Checked every step: total momentum at its start value to round-off
 * (1e-12 of sum m|v|; contact moves momentum between fields exactly) and
 * the contact's work at round-off (frictionless: the impulse is normal,
 * the normal relative velocity it leaves is zero). At the end: the disks
 * have bounced apart (each moves away from the other, no node has both
 * disks' fields in contact in the last millisecond) and their translation
 * holds no more than the kinetic energy left. The coefficient of
 * restitution and the energy drift are printed, beside chapter 1's
 * single-field rebound of the same disks.
 *
 * Contact starts when the disks touch: their centres close at 0.2 sqrt 2
 * mm/ms from 0.5 sqrt 2 mm apart, radius 0.2 mm, so the disks touch at
 * t = (0.5 sqrt 2 - 0.4) / (0.2 sqrt 2) = 1.086 ms; the first contact must
 * come no earlier than half a cell (0.025 mm) of closing before that,
 * 0.998 ms (the gap test: contact at 1.009 ms at cfl 0.1, 1.004 at 0.05;
 * approach alone fired at 0.630 ms, when the disks first shared a node,
 * 1.5 cells apart). And the energy (issue 25's bound for Sulsky's disks,
 * below 0.5 % and falling with the step): with MUSL and USF the total
 * energy at the end within 0.5 % of its start at cfl 0.05 and closer than
 * at cfl 0.1 (measured MUSL -0.58 % and -0.27 %, USF +1.16 % and
 * +0.45 %); with USAVG, where the build has it (stage 5), within 0.5 % at
 * both steps and closer at 0.05 (+0.14 %, +0.06 %). Whose error the cfl
 * 0.1 rows are is printed beside them: chapter 1's disks (one velocity
 * field, no contact, the same cells and points) run to their 3.5 ms (they
 * leave chapter 1's grid before 4 ms) at the same cfl under the same
 * scheme.
 * Contact is decided at Task 2 on the gap the step would end with, as at
 * Task 4: deciding it at Task 2 on the gap at the step's start left the
 * whole meeting to Task 4, whose change the points receive, and MUSL
 * lost 4.6 % (the two fields' normal velocities meet inelastically at
 * each node).
 *
 * The same with the pair's volume test (V_sep = 0.9): the same checks,
 * and the restitution and energy printed.
 *
 * Bonded: with the pair's law set to "bonded" (what an unlisted pair gets)
 * the run must be the single-field run of chapter 1's scene: the positions
 * of every point agree to 1e-9 mm after the whole collision (the two
 * grids differ in origin, so round-off differs, not the method).
 */
#include "testkit.h"

#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "material_contact.h"

static const char *const SCENE = "tests/4-contact/scenes/disks_contact.cfg";

/** The disks' closing speed (mm/ms) and the time they touch (ms). */
#define CLOSING (0.2 * sqrt(2.0))
#define TOUCH ((0.5 * sqrt(2.0) - 0.4) / CLOSING)

/** Mean velocity of body @p b along the line of approach (1, 1)/sqrt 2. */
static double approach_speed(const Particles *P, int b)
{
    double m = 0, q = 0;
    for (int p = 0; p < P->n; p++)
        if (P->body[p] == b) {
            m += P->m[p];
            q += P->m[p] * (P->vx[p] + P->vy[p]) / sqrt(2.0);
        }
    return q / m;
}

/** What one run saw. */
typedef struct DisksRun {
    double restitution, gain, drift, work, translation, kinetic;
    double t_first, t_last;
} DisksRun;

static DisksRun collide(const char *scheme, const char *cfl, const char *extra)
{
    char ov[2][64];
    snprintf(ov[0], sizeof ov[0], "run.update=%s", scheme);
    snprintf(ov[1], sizeof ov[1], "run.cfl=%s", cfl);
    const char *const overrides[] = {ov[0], ov[1], extra, NULL};
    Sim *sim = tk_load_file(SCENE, overrides);
    const MaterialContact *M = sim_state(sim, "material contact");
    assert_non_null(M);
    Particles *P = &sim->pts;
    Totals t0 = sim_totals(sim);
    double E0 = t0.kinetic + t0.strain, mv = 0, v0 = approach_speed(P, 0);
    for (int p = 0; p < P->n; p++)
        mv += P->m[p] * hypot(P->vx[p], P->vy[p]);
    DisksRun r = {.t_first = -1, .t_last = -1};
    while (sim->step < sim->nsteps) {
        tk_steps(sim, 1);
        Totals t = sim_totals(sim);
        r.drift = fmax(r.drift, hypot(t.px - t0.px, t.py - t0.py) / mv);
        r.work = fmax(r.work, fabs(M->work) / E0);
        if (M->nodes > 0) {
            if (r.t_first < 0)
                r.t_first = sim->t;
            r.t_last = sim->t;
        }
    }
    Totals tn = sim_totals(sim);
    double vl = approach_speed(P, 0), vr = approach_speed(P, 1);
    r.restitution = (vr - vl) / (2 * v0);
    r.gain = (tn.kinetic + tn.strain) / E0 - 1;
    r.translation = 0.5 * (vl * vl + vr * vr) / (v0 * v0);   /* of E0 */
    r.kinetic = tn.kinetic / E0;
    printf("  %-4s cfl %s%s%s: contact %.3f to %.3f ms; restitution %.4f; energy %+.2f %%; "
           "momentum %.1e of sum m|v|; contact work %.1e E0\n", scheme, cfl,
           extra ? ", " : "", extra ? extra : "",
           r.t_first, r.t_last, r.restitution, 100 * r.gain, r.drift, r.work);
    assert_true(r.drift <= 1e-12);
    assert_true(r.work <= 1e-12);
    assert_true(r.t_first >= TOUCH - 0.025 / CLOSING);  /* not before touching */
    assert_true(r.t_last < sim->t - 1.0);       /* apart for the last ms */
    assert_true(vl < 0 && vr > 0);              /* bounced */
    assert_true(r.translation <= r.kinetic);
    tk_free(sim);
    return r;
}

/** Chapter 1's single-field rebound (at its cfl, 0.2, to 3.5 ms), for
 *  comparison. */
static double one_field(const char *scheme)
{
    char ov[64];
    snprintf(ov, sizeof ov, "run.update=%s", scheme);
    const char *const overrides[] = {ov, NULL};
    Sim *sim = tk_load_file("tests/1-mpm/scenes/disks.cfg", overrides);
    double v0 = approach_speed(&sim->pts, 0);
    tk_steps(sim, sim->nsteps);
    double e = (approach_speed(&sim->pts, 1) - approach_speed(&sim->pts, 0)) / (2 * v0);
    tk_free(sim);
    return e;
}

/** The energy change of chapter 1's disks (one field) under @p scheme at
 *  cfl @p cfl, run to that scene's 3.5 ms: the scheme's own error on these
 *  cells and points, without contact. */
static double one_field_energy(const char *scheme, const char *cfl)
{
    char ov[2][64];
    snprintf(ov[0], sizeof ov[0], "run.update=%s", scheme);
    snprintf(ov[1], sizeof ov[1], "run.cfl=%s", cfl);
    const char *const overrides[] = {ov[0], ov[1], NULL};
    Sim *sim = tk_load_file("tests/1-mpm/scenes/disks.cfg", overrides);
    Totals t0 = sim_totals(sim);
    tk_steps(sim, sim->nsteps);
    Totals t = sim_totals(sim);
    tk_free(sim);
    return (t.kinetic + t.strain) / (t0.kinetic + t0.strain) - 1;
}

/** Runs at cfl 0.1 and 0.05; @p bounded 1: within 0.5 % at 0.05 and closer
 *  than at 0.1; 2: and within 0.5 % at 0.1 too; 0: printed. */
static void frictionless(const char *scheme, int bounded)
{
    DisksRun a = collide(scheme, "0.1", NULL), b = collide(scheme, "0.05", NULL);
    printf("  %-4s energy change at cfl 0.1 %+.2f %%, at 0.05 %+.2f %%; chapter 1's "
           "single field: restitution %.4f, energy at cfl 0.1 %+.2f %%\n", scheme,
           100 * a.gain, 100 * b.gain, one_field(scheme),
           100 * one_field_energy(scheme, "0.1"));
    if (bounded) {
        assert_true(fabs(b.gain) <= 0.005);
        assert_true(fabs(b.gain) < fabs(a.gain));
    }
    if (bounded > 1)
        assert_true(fabs(a.gain) <= 0.005);
}

static void musl(void **state) { (void)state; frictionless("musl", 1); }

/** The pair with the volume test (V_sep = 0.9): the disks bounce too; the
 *  energy and restitution are printed for chapter 4. */
static void volume_test(void **state)
{
    (void)state;
    collide("musl", "0.1", "contact.[0].V_sep=0.9");
}
static void usf(void **state) { (void)state; frictionless("usf", 1); }

/** USAVG, stage 5's scheme: the bound at both steps. */
static void usavg(void **state)
{
    (void)state;
    char err[512];
    const char *const ov[] = {"run.update=usavg", NULL};
    Sim *sim = tk_try_load_file(SCENE, ov, err, sizeof err);
    if (!sim) {
        printf("  usavg: skipped, this build refuses it (%s)\n", err);
        skip();
    }
    tk_free(sim);
    frictionless("usavg", 2);
}

/** A bonded pair is one field: chapter 1's run, to round-off. */
static void bonded_is_one_field(void **state)
{
    (void)state;
    Sim *a = tk_load_file(SCENE, NULL);
    Sim *b = tk_load_file("tests/1-mpm/scenes/disks.cfg", NULL);
    MaterialContact *M = sim_state(a, "material contact");
    for (int i = 0; i < (M->ngroups + 1) * (M->ngroups + 1); i++)
        M->law[i].kind = CONTACT_BONDED;
    assert_int_equal(a->pts.n, b->pts.n);
    assert_close(a->dt, b->dt, 1e-15 * b->dt);
    long n = b->nsteps;                          /* chapter 1's 3.5 ms */
    tk_steps(a, n);
    tk_steps(b, n);
    double worst = 0;
    for (int p = 0; p < a->pts.n; p++)
        worst = fmax(worst, hypot(a->pts.x[p] - b->pts.x[p], a->pts.y[p] - b->pts.y[p]));
    printf("  bonded pair vs one field, %ld steps: positions agree to %.1e mm\n", n, worst);
    assert_true(worst <= 1e-9);
    tk_free(a);
    tk_free(b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(musl),
        cmocka_unit_test(usf),
        cmocka_unit_test(usavg),
        cmocka_unit_test(volume_test),
        cmocka_unit_test(bonded_is_one_field),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
