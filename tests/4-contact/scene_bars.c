/**
 * @file scene_bars.c
 * @brief Two elastic bars colliding head-on: the 1D impact benchmark of
 *        contact between bodies, for the four update schemes at three time
 *        steps.
 *
 * Scenes (tests/4-contact/scenes/): bars_gap.cfg, two identical bars
 * 10 x 1 mm (L = 20 cells of h = 0.5 mm, two cells tall, 2 x 2 points per
 * cell) approaching at +-v0 from a gap of two cells; bars_touching.cfg, the
 * same starting in touch (their faces on one grid line: the points fill
 * each body, so the bodies' edges meeting is touching); bars_impedance.cfg,
 * bars of equal length and equal wave speed whose impedances rho c differ
 * by a factor 2 (the right bar's E and rho doubled), from the gap. Plane
 * stress with nu = 0 makes each bar exactly a 1D bar: c = sqrt(E / rho)
 * (31.6 mm/ms), and v0 = 1 % of c. Each bar is its own contact group, the
 * pair frictionless.
 *
 * Exact 1D solution (d'Alembert; bars of length L, wave speed c,
 * impedances Z1 = rho1 c A, Z2 = rho2 c A, velocities v1 > v2): the faces
 * touch at t0 = gap / (v1 - v2). Then the interface moves at v_i = (Z1 v1
 * + Z2 v2) / (Z1 + Z2) under the stress -Z1 (v1 - v_i) / A, and a
 * compressive front runs into each bar at c, leaving it at v_i. The fronts
 * reach the free ends together at L / c (equal L and c) and come back as
 * unloading fronts behind which the stress is zero and the velocity
 * 2 v_i - v1 in bar 1, 2 v_i - v2 in bar 2. They reach the interface
 * together at t0 + 2L / c, when both bars are stress-free and uniform and
 * their faces separate (2 v_i - v1 < 2 v_i - v2): the contact lasts
 * exactly 2L / c and the bars leave as rigid bodies after an elastic
 * collision of masses m1 and m2,
 *   v1' = ((m1 - m2) v1 + 2 m2 v2) / (m1 + m2),
 *   v2' = ((m2 - m1) v2 + 2 m1 v1) / (m1 + m2),
 * with no vibration left and the energy all kinetic again. Identical bars
 * (m1 = m2) exchange velocities: -v0 and +v0. Impedances 1 : 2 (m2 = 2 m1)
 * at +-v0: v_i = -v0 / 3, v1' = -5/3 v0, v2' = +1/3 v0. (Unequal lengths
 * of equal impedance were left out: there the short bar stops pushing at
 * 2L / c but the long bar's face moves with it, force-free, until the long
 * bar's own reflection returns, so "contact" has two meanings.)
 *
 * The discretisation's own rebound. On 20 cells a bar no nodal scheme
 * gives the exact rebound, contact or not: a lumped-mass chain of 20
 * linear elements stopped by a rigid wall and released when its end force
 * turns to tension leaves at 0.96 v0 (central differences, cfl 0.1 to
 * 0.5), and the MPM bars rebound slower still, converging with the cell
 * (rebound_converges_with_the_cell). So the contact is judged against
 * the same bars run as one velocity field (bars_one_field.cfg,
 * bars_impedance_one_field.cfg: touching, no contact groups): while they
 * push on each other, frictionless contact along the bar axis must give
 * what one field gives, and a perfect release happens when the one field's
 * interface force turns to tension, which is when each bar's momentum in
 * that run reaches its extreme. That extreme is the rebound this grid
 * allows; the gap scene's bars meet as the touching ones, one cell over.
 *
 * Bounds, the (fixed before any run), for every scheme (usl, musl,
 * usf, and usavg where this build has it: stage 5) at cfl 0.5, 0.25 and
 * 0.1; where the exact answer is out of this grid's reach (rebound,
 * parting time) they measure the contact's own share, from the one-field
 * run:
 *  - contact starts when the bodies touch, not earlier: the first step
 *    with MaterialContact::nodes > 0 (pairs in contact at the step's
 *    decision, Task 4) starts at t_start with |t_start - t0| (v1 - v2) <=
 *    h / 2, half a cell of closing travel.
 *  - duration: the first unbroken run of steps in contact, each step
 *    accounting for dt, within 5 % of 2L / c of the time the one field
 *    parts (printed beside 2L / c; the bars leave ringing, and a later
 *    touch is printed).
 *  - rebound: each bar's mean velocity at the end (2.5 cells apart)
 *    within 2 % of v0 of the one-field run's extreme; its distance from
 *    the exact v' is printed, and rebound_converges_with_the_cell checks
 *    that it falls with the cell.
 *  - energy: kinetic + strain (sim_totals) at the end within 1 % of its
 *    start at cfl 0.5, within 0.5 % at 0.25 and 0.1 (the exact change is
 *    zero). USF and MUSL are first-order in their energy: on the one-field
 *    bars over the same time their energy swings by more than that at cfl
 *    0.5 and 0.25 (printed), so for them the bound is the larger of the
 *    two: contact adds no error beyond the scheme's own.
 *  - momentum: at its start value to 1e-12 of sum m |v| at every step
 *    (contact moves momentum between the two fields of a node exactly).
 *  - the run and the one-field run stay stable.
 * USL is asked the start and the momentum at every step, and the rest but
 * the energy at cfl 0.1 only: USL cannot carry one bar in free flight
 * across the cells at cfl 0.5 (bar_flying.cfg goes unstable; asserted by
 * usl_cannot_carry_a_free_bar), and the bars, once parted, go the same
 * way; at cfl 0.1 the one-field bars themselves lose 3 to 4 % of their
 * energy under USL (printed), so its energy is printed only.
 *
 * Every run prints one line of what it measured; a failed bound prints a
 * FAIL line and the test fails at its end when any did. On a stage-4 build
 * (no run.update = "usavg": the scene is refused) usavg is skipped with a
 * line saying so.
 */
#include "testkit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "material_contact.h"
#include "stages.h"

#define NSCHEMES 4
static const char *const SCHEMES[NSCHEMES] = {"usl", "musl", "usf", "usavg"};
#define NCFL 3
static const double CFL[NCFL] = {0.5, 0.25, 0.1};

/** Count bound @p ok of @p c, printing it indented when it fails. */
#define check(c, ok, ...) tk_bound((c), 6, (ok), __VA_ARGS__)


/** Does this build have run.update = @p scheme? Prints a line if not. */
static int has_scheme(const char *scene, const char *scheme)
{
    char ov[64], err[1024];
    snprintf(ov, sizeof ov, "run.update=%s", scheme);
    const char *const overrides[] = {ov, NULL};
    Sim *sim = tk_try_load_file(scene, overrides, err, sizeof err);
    if (!sim) {
        printf("  %s: skipped, this build refuses it (%s)\n", scheme, err);
        return 0;
    }
    tk_free(sim);
    return 1;
}

/** Mass and mean x velocity of body @p b. */
static void body_motion(const Particles *P, int b, double *m, double *v)
{
    double mm = 0, q = 0;
    for (int p = 0; p < P->n; p++)
        if (P->body[p] == b) {
            mm += P->m[p];
            q += P->m[p] * P->vx[p];
        }
    *m = mm;
    *v = q / mm;
}

#define MAX_OVERRIDES 8

/** @p out: run.update = @p scheme, run.cfl = @p cfl (written into @p ov),
 *  then the NULL-terminated @p more (at most MAX_OVERRIDES; NULL: none). */
static void scheme_overrides(char ov[2][64], const char *scheme, double cfl,
                             const char *const *more, const char **out)
{
    snprintf(ov[0], sizeof ov[0], "run.update=%s", scheme);
    snprintf(ov[1], sizeof ov[1], "run.cfl=%.17e", cfl);
    int n = 0;
    out[n++] = ov[0];
    out[n++] = ov[1];
    for (int k = 0; more && more[k]; k++) {
        assert_true(k < MAX_OVERRIDES);
        out[n++] = more[k];
    }
    out[n] = NULL;
}

/** What the one-field run of the same bars gives (see the file's header). */
typedef struct OneField {
    double u1, u2;     /**< each bar's extreme mean velocity: the rebound */
    double t_part;     /**< when bar 1's velocity reached its extreme: the
                            time a perfect release parts the bars */
    double swing;      /**< largest |E(t)/E0 - 1| over the run */
    int stable;        /**< the run stayed stable */
} OneField;

/** Run @p scene (one field) with @p scheme at @p cfl and @p grid (more
 *  overrides, NULL-terminated, or NULL): the extremes of the bars' mean velocities within
 *  1.25 x 2L/c of the touch (bar 1 is on the left, moving right), and the
 *  energy's swing over the whole run. */
static OneField one_field(const char *scene, const char *scheme, double cfl,
                          const char *const *grid)
{
    char ov[2][64];
    const char *overrides[MAX_OVERRIDES + 3];
    scheme_overrides(ov, scheme, cfl, grid, overrides);
    Sim *sim = tk_load_file(scene, overrides);
    const Scene *sc = &sim->scene;
    const Body *B1 = &sc->bodies[0];
    const Material *m1 = &sc->mat[B1->material];
    double tc = 2 * (B1->shape.xmax - B1->shape.xmin) / sqrt(m1->E / m1->rho);
    Particles *P = &sim->pts;
    Totals T0 = sim_totals(sim);
    double E0 = T0.kinetic + T0.strain, M1, M2;
    OneField r = {0, 0, 0, 0, 1};
    body_motion(P, 0, &M1, &r.u1);
    body_motion(P, 1, &M2, &r.u2);
    while (sim->step < sim->nsteps) {
        if (sim_advance(sim)) {
            r.stable = 0;
            break;
        }
        Totals t = sim_totals(sim);
        r.swing = fmax(r.swing, fabs((t.kinetic + t.strain) / E0 - 1));
        if (sim->t <= 1.25 * tc) {
            double u1, u2;
            body_motion(P, 0, &M1, &u1);
            body_motion(P, 1, &M2, &u2);
            if (u1 < r.u1)
                r.t_part = sim->t;
            r.u1 = fmin(r.u1, u1);
            r.u2 = fmax(r.u2, u2);
        }
    }
    tk_free(sim);
    return r;
}

/** The one-field scene that goes with the contact scene @p scene. */
static const char *one_field_scene(const char *scene)
{
    return strstr(scene, "impedance") ? "tests/4-contact/scenes/bars_impedance_one_field.cfg"
                                      : "tests/4-contact/scenes/bars_one_field.cfg";
}

/** What impact() measured, for the study of the cell (BARS_CELLS). */
typedef struct Impact {
    double miss;       /**< rebound's largest error against exact, / v0 */
    double ref_miss;   /**< the one field's, / v0 */
    double start;      /**< contact start - touch, in h of closing travel */
    double dur;        /**< contact duration / (2L/c) - 1 */
    double ref_part;   /**< the one field's parting / (2L/c) - 1 */
    double dE;         /**< energy at the end / at the start - 1 */
    double swing;      /**< the one field's largest |E/E0 - 1| */
    int stable;        /**< both runs stayed stable */
} Impact;

/** What impact() measures of the normal at the contact nodes, for
 *  corners_part_with_the_faces(). */
typedef struct Corners {
    const char *normal;  /**< contact.normal of the run */
    double tilt;         /**< largest angle (degrees) of the fitted normal
                              (candidate 2: the average of the gradients
                              for "gradients") from the bars' axis, over
                              the nodes and steps in contact */
    double late;         /**< contact's duration less the one field's
                              parting time, in steps */
} Corners;

/** The largest angle (degrees) from the x axis of candidate 2 at the
 *  nodes where two fields met at the step just taken and one was found in
 *  contact (MaterialContact::nodes > 0). */
static double candidate_tilt(const Sim *sim, const MaterialContact *M)
{
    const FieldTable *F = &sim->fields;
    double worst = 0.0;
    if (M->nodes == 0)
        return 0.0;
    for (int k = 0; k < F->ntouched; k++) {
        int n = F->touched[k];
        double cx = M->cx[CONTACT_AXES * n + 2], cy = M->cy[CONTACT_AXES * n + 2];
        if (cx != 0.0 || cy != 0.0)
            worst = fmax(worst, atan2(fabs(cy), fabs(cx)) * 45.0 / atan(1.0));
    }
    return worst;
}

/** One run of @p scene with @p scheme at @p cfl, checked against the
 *  exact solution and the one-field run (the file's header). @p grid and
 *  @p grid1 (more overrides for the contact and the one-field scene,
 *  NULL-terminated, or NULL) refine the grid; @p out (or NULL) gets what
 *  was measured; @p corners (or NULL: "gradients") names the normal and
 *  gets what it measured. */
static void impact(TkBounds *c, const char *scene, const char *scheme, double cfl,
                   const char *const *grid, const char *const *grid1, Impact *out,
                   Corners *corners)
{
    char ov[2][64], nv[64];
    const char *overrides[MAX_OVERRIDES + 4];
    scheme_overrides(ov, scheme, cfl, grid, overrides);
    if (corners) {                              /* the normal, last */
        int n = 0;
        while (overrides[n])
            n++;
        snprintf(nv, sizeof nv, "contact.[0].normal=\"%s\"", corners->normal);
        overrides[n] = nv;
        overrides[n + 1] = NULL;
    }
    OneField ref = one_field(one_field_scene(scene), scheme, cfl, grid1);
    Sim *sim = tk_load_file(scene, overrides);
    const MaterialContact *M = sim_state(sim, "material contact");
    assert_non_null(M);
    const Scene *sc = &sim->scene;
    assert_int_equal(sc->nbodies, 2);
    const Body *B1 = &sc->bodies[0], *B2 = &sc->bodies[1];
    const Material *m1 = &sc->mat[B1->material], *m2 = &sc->mat[B2->material];
    /* the 1D solution: equal lengths and wave speeds, bar 1 on the left */
    double L = B1->shape.xmax - B1->shape.xmin, h = sc->dx;
    double c1 = sqrt(m1->E / m1->rho), c2 = sqrt(m2->E / m2->rho);
    assert_close(B2->shape.xmax - B2->shape.xmin, L, 1e-12 * L);
    assert_close(c2, c1, 1e-12 * c1);
    assert_true(m1->nu == 0.0 && m2->nu == 0.0 && sc->run.plane == PLANE_STRESS);
    double gap = B2->shape.xmin - B1->shape.xmax, v1 = B1->vx, v2 = B2->vx;
    assert_true(v1 > v2 && gap >= 0);
    double t0 = gap / (v1 - v2), tc = 2 * L / c1, v0 = 0.5 * (v1 - v2);
    Particles *P = &sim->pts;
    double M1, M2, u1, u2;
    body_motion(P, 0, &M1, &u1);
    body_motion(P, 1, &M2, &u2);
    double e1 = ((M1 - M2) * v1 + 2 * M2 * v2) / (M1 + M2);
    double e2 = ((M2 - M1) * v2 + 2 * M1 * v1) / (M1 + M2);
    Totals T0 = sim_totals(sim);
    double E0 = T0.kinetic + T0.strain, mv = 0;
    for (int p = 0; p < P->n; p++)
        mv += P->m[p] * hypot(P->vx[p], P->vy[p]);
    long first = -1, parted = -1, later = 0, unstable = -1;
    double drift = 0, t_start = -1;
    while (sim->step < sim->nsteps) {
        double t_before = sim->t;
        if (sim_advance(sim)) {
            unstable = sim->fail.step;
            printf("      unstable at step %ld (t = %.4f ms): point %d %s = %g\n",
                   sim->fail.step, sim->t, sim->fail.particle, sim->fail.quantity,
                   sim->fail.value);
            break;
        }
        Totals t = sim_totals(sim);
        drift = fmax(drift, hypot(t.px - T0.px, t.py - T0.py) / mv);
        if (corners && parted < 0)
            corners->tilt = fmax(corners->tilt, candidate_tilt(sim, M));
        if (M->nodes > 0 && first < 0) {
            first = sim->step;
            t_start = t_before;
        } else if (M->nodes == 0 && first >= 0 && parted < 0) {
            parted = sim->step;                 /* the first step apart */
        } else if (M->nodes > 0 && parted >= 0) {
            later++;                            /* touching again */
        }
    }
    Totals TN = sim_totals(sim);
    double dE = (TN.kinetic + TN.strain) / E0 - 1;
    body_motion(P, 0, &M1, &u1);
    body_motion(P, 1, &M2, &u2);
    double dur = first >= 0 ? (double)((parted >= 0 ? parted : sim->step + 1) - first) *
                              sim->dt : 0.0;
    double travel = first >= 0 ? fabs(t_start - t0) * (v1 - v2) : 1e300;
    printf("    %-5s cfl %.2f: contact from %.4f ms (t0 %.4f: %+.3f h of closing "
           "travel), for %.4f ms (2L/c %.4f: %+.2f %%; one field parts at %+.2f %%), %ld steps in "
           "touch again; "
           "v1 %+.5f, v2 %+.5f: %+.2f %%, %+.2f %% of v0 from exact %+.5f, %+.5f; "
           "%+.2f %%, %+.2f %% of v0 from one field's %+.5f, %+.5f; energy %+.3f %% "
           "(one field swings %.3f %%); momentum %.1e; %ld steps\n", scheme, cfl,
           t_start, t0, first >= 0 ? (t_start - t0) * (v1 - v2) / h : 0.0, dur, tc,
           100 * (dur / tc - 1), 100 * (ref.t_part / tc - 1), later, u1, u2, 100 * (u1 - e1) / v0,
           100 * (u2 - e2) / v0, e1, e2, 100 * (u1 - ref.u1) / v0,
           100 * (u2 - ref.u2) / v0, ref.u1, ref.u2, 100 * dE, 100 * ref.swing,
           drift, sim->step);
    fflush(stdout);
    /* USL: what the file's header says it is not asked */
    int usl = strcmp(scheme, "usl") == 0, all = !usl || cfl < 0.2;
    check(c, first >= 0, "%s cfl %.2f: no contact at all", scheme, cfl);
    check(c, travel <= 0.5 * h, "%s cfl %.2f: contact started at %.4f ms, t0 = %.4f "
          "ms: %.3f h of closing travel away (bound h/2)", scheme, cfl, t_start, t0,
          travel / h);
    check(c, drift <= 1e-12, "%s cfl %.2f: momentum drifted by %.2e of sum m|v| "
          "(bound 1e-12)", scheme, cfl, drift);
    if (out)
        *out = (Impact){fmax(fabs(u1 - e1), fabs(u2 - e2)) / v0,
                        fmax(fabs(ref.u1 - e1), fabs(ref.u2 - e2)) / v0,
                        first >= 0 ? (t_start - t0) * (v1 - v2) / h : NAN,
                        dur / tc - 1, ref.t_part / tc - 1, dE, ref.swing,
                        unstable < 0 && ref.stable};
    if (corners)
        corners->late = (dur - ref.t_part) / sim->dt;
    tk_free(sim);
    if (!all)
        return;
    check(c, unstable < 0, "%s cfl %.2f: unstable at step %ld", scheme, cfl, unstable);
    check(c, ref.stable, "%s cfl %.2f: the one-field run went unstable", scheme, cfl);
    check(c, fabs(dur - ref.t_part) <= 0.05 * tc, "%s cfl %.2f: contact lasted %.4f "
          "ms, the one field parts at %.4f ms (2L/c = %.4f ms; bound 5 %% of it)",
          scheme, cfl, dur, ref.t_part, tc);
    check(c, fabs(u1 - ref.u1) <= 0.02 * v0 && fabs(u2 - ref.u2) <= 0.02 * v0,
          "%s cfl %.2f: rebound %+.5f, %+.5f; one field's %+.5f, %+.5f (bound 2 %% "
          "of v0 = %.5f)", scheme, cfl, u1, u2, ref.u1, ref.u2, 0.02 * v0);
    double etol = cfl > 0.3 ? 0.01 : 0.005;
    if (strcmp(scheme, "usf") == 0 || strcmp(scheme, "musl") == 0)
        etol = fmax(etol, ref.swing);           /* first order: its own swing */
    if (!usl)
        check(c, fabs(dE) <= etol, "%s cfl %.2f: energy changed by %+.3f %% (bound "
              "%.3f %%)", scheme, cfl, 100 * dE, 100 * etol);
}

/** Every scheme this build has, at each cfl. */
static void all_schemes(const char *scene)
{
    TkBounds c = {0, 0};
    printf("  %s\n", scene);
    for (int s = 0; s < NSCHEMES; s++) {
        if (!has_scheme(scene, SCHEMES[s]))
            continue;
        for (int k = 0; k < NCFL; k++)
            impact(&c, scene, SCHEMES[s], CFL[k], NULL, NULL, NULL, NULL);
    }
    tk_bounds_finish(&c);
}

static void identical_bars_from_a_gap(void **state)
{
    (void)state;
    all_schemes("tests/4-contact/scenes/bars_gap.cfg");
}

static void identical_bars_touching(void **state)
{
    (void)state;
    all_schemes("tests/4-contact/scenes/bars_touching.cfg");
}

static void impedances_one_to_two(void **state)
{
    (void)state;
    all_schemes("tests/4-contact/scenes/bars_impedance.cfg");
}

/** Issue 25, normals that hold at a body's corners: the 1:2 bars at cfl
 *  0.5 with contact.normal = "regression" (the line fitted between the
 *  two clouds of points joins the candidates, chapter 4b). The faces are
 *  flat and square to the axis, so at every node in contact, the bars'
 *  corners included, the true normal is the axis. Bounds, fixed before the
 *  first run: the fitted normal within 1 degree of the axis at every node
 *  and step in contact, and the contact parts within one step of the one
 *  field (the corners release with the faces); and every bound of
 *  impact(). MUSL is asked (the case the gradients' candidates part two
 *  steps late); with CORNERS_OPEN=1, USF and USAVG too, where the contact
 *  parts two steps late with either normal (OPEN), and each scheme with
 *  "gradients" beside it (printed). */
static void corners_part_with_the_faces(void **state)
{
    (void)state;
    const char *scene = "tests/4-contact/scenes/bars_impedance.cfg";
    static const char *const schemes[] = {"musl", "usf", "usavg"};
    int all = getenv("CORNERS_OPEN") != NULL;
    TkBounds c = {0, 0};
    for (int s = 0; s < (all ? 3 : 1); s++) {
        if (!has_scheme(scene, schemes[s]))
            continue;
        Corners r = {"regression", 0.0, 0.0};
        impact(&c, scene, schemes[s], 0.5, NULL, NULL, NULL, &r);
        printf("  %-5s cfl 0.50, regression: the normal tilts up to %.3f deg; contact "
               "parts %+.1f steps from the one field\n", schemes[s], r.tilt, r.late);
        if (all) {
            Corners g = {"gradients", 0.0, 0.0};
            TkBounds quiet = {0, 0};            /* asked by impedances_one_to_two */
            impact(&quiet, scene, schemes[s], 0.5, NULL, NULL, NULL, &g);
            printf("  %-5s cfl 0.50, gradients: their average tilts up to %.3f deg; "
                   "contact parts %+.1f steps from the one field\n", schemes[s],
                   g.tilt, g.late);
        }
        check(&c, r.tilt <= 1.0, "%s: the fitted normal tilts %.3f deg from the "
              "axis (bound 1 deg)", schemes[s], r.tilt);
        check(&c, fabs(r.late) <= 1.0 + 1e-9, "%s: contact parts %+.2f steps from "
              "the one field (bound 1 step)", schemes[s], r.late);
    }
    tk_bounds_finish(&c);
}

/** The rebound of a lumped-mass chain of @p n linear elements (a bar of
 *  unit length, wave speed and density) moving at -1 onto a rigid wall at
 *  its node 0, released when that node's force turns to tension, by
 *  central differences at @p cfl: what a nodal scheme gives on n cells. */
static double chain_rebound(int n, double cfl)
{
    double h = 1.0 / n, dt = cfl * h, x[641], v[641], f[641];
    assert_true(n <= 640);
    for (int i = 0; i <= n; i++) {
        x[i] = 0.0;
        v[i] = -1.0;
    }
    for (double t = 0; t < 3.0; t += dt) {     /* 2L/c = 2; then free */
        for (int i = 0; i <= n; i++)
            f[i] = 0.0;
        for (int i = 0; i < n; i++) {           /* element force E A strain */
            double s = (x[i + 1] - x[i]) / h;
            f[i] += s;
            f[i + 1] -= s;
        }
        for (int i = 0; i <= n; i++)            /* lumped masses h, h/2 at ends */
            v[i] += dt * f[i] / (i == 0 || i == n ? 0.5 * h : h);
        if (x[0] + dt * v[0] < 0.0)             /* the wall: no penetration */
            v[0] = 0.0;
        for (int i = 0; i <= n; i++)
            x[i] += dt * v[i];
    }
    double p = 0.0;
    for (int i = 0; i <= n; i++)
        p += v[i] * (i == 0 || i == n ? 0.5 * h : h);
    return p;                                   /* mass 1: the mean velocity */
}

/** The bars' rebound on finer grids: bars_gap.cfg with cells of 0.5, 0.25
 *  and 0.125 mm (20, 40, 80 cells a bar), MUSL at cfl 0.25. The exact
 *  rebound does not depend on the grid, so its error must fall at each
 *  halving of the cell: what is left on the coarse grid is the
 *  discretisation's (the ringing the bars leave with), not the contact's.
 *  Measured: 6.5 %, 4.2 %, 3.2 % of v0 slow. Beside it, the lumped-mass
 *  chain of the same cells with a perfect wall (chain_rebound()): on 20
 *  cells it is more than 2 % of v0 slow too, so the exact 2 % bound is out
 *  of any nodal scheme's reach there. */
static void rebound_converges_with_the_cell(void **state)
{
    (void)state;
    const char *grids[3][3] = {{"grid.cell_size=[0.5, 0.5]", "grid.cells=[52, 4]", NULL},
                               {"grid.cell_size=[0.25, 0.25]", "grid.cells=[104, 8]", NULL},
                               {"grid.cell_size=[0.125, 0.125]", "grid.cells=[208, 16]", NULL}};
    TkBounds c = {0, 0};
    double miss[3];
    for (int k = 0; k < 3; k++) {
        printf("  %s\n", grids[k][0]);
        Impact r;
        impact(&c, "tests/4-contact/scenes/bars_gap.cfg", "musl", 0.25, grids[k],
               grids[k], &r, NULL);
        miss[k] = r.miss;
    }
    for (int k = 1; k < 3; k++) {
        printf("  halving the cell: rebound error %.4f -> %.4f of v0\n", miss[k - 1],
               miss[k]);
        tk_bound(&c, 4, miss[k] < miss[k - 1], "rebound error did not fall");
    }
    for (int n = 20; n <= 80; n *= 2) {
        printf("  lumped-mass chain of %d elements, perfect wall:", n);
        for (int k = 0; k < NCFL; k++)
            printf(" cfl %.2f: %.4f v0 (%.2f %% slow)", CFL[k], chain_rebound(n, CFL[k]),
                   100 * (1 - chain_rebound(n, CFL[k])));
        printf("\n");
    }
    tk_bound(&c, 4, chain_rebound(20, 0.5) < 0.98, "the 20-element chain rebounds "
             "within 2 %% of v0: the header's claim is wrong");
    tk_bounds_finish(&c);
}

/** The study of the cell behind `make fig-bars` (the only test run when
 *  BARS_CELLS lists cells per bar, e.g. "20 40 80 160 320"): bars_gap.cfg on cells of
 *  h = 10 mm / N, the bars kept two cells tall (nu = 0 and plane stress make
 *  the height irrelevant; it keeps the points per cell of bar length), for
 *  each scheme of BARS_SCHEMES ("musl usf usavg usl") at each cfl of
 *  BARS_CFL ("0.25"). One row each: the rebound's error against the exact
 *  v' and the one field's, the contact's start and duration, the energy;
 *  beside them the lumped-mass chain's rebound on N elements. Every bound
 *  of impact() holds at every N, as in make check; the table says from
 *  which N the rebound is within the 2 % of v0 of the exact one. */
static void cell_study(void **state)
{
    (void)state;
    const char *cells = getenv("BARS_CELLS");
    const char *schemes = getenv("BARS_SCHEMES"), *cfls = getenv("BARS_CFL");
    schemes = schemes ? schemes : "musl usf usavg usl";
    cfls = cfls ? cfls : "0.25";
    TkBounds c = {0, 0};
    printf("  study: N cells a bar (h = 10/N mm), scheme, cfl; rebound error "
           "against exact and the one field's (%% of v0); chain: the lumped-mass "
           "chain of N elements; contact start (h of closing travel), duration and "
           "the one field's parting against 2L/c (%%); energy change and the one "
           "field's swing (%%)\n");
    printf("  %-4s %-6s %-5s %9s %9s %9s %8s %8s %8s %9s %8s\n", "N", "scheme", "cfl",
           "rebound", "one fld", "chain", "start", "dur", "parts", "energy", "swing");
    char list[256];
    snprintf(list, sizeof list, "%s", cells);
    for (char *sv = NULL, *t = strtok_r(list, " ", &sv); t; t = strtok_r(NULL, " ", &sv)) {
        int n = atoi(t);
        assert_true(n >= 20 && n <= 640 && n % 20 == 0);
        double h = 10.0 / n;
        char g[7][96];
        snprintf(g[0], sizeof g[0], "grid.cell_size=[%.17e, %.17e]", h, h);
        snprintf(g[1], sizeof g[1], "grid.cells=[%d, 4]", (int)lround(26.0 / h));
        snprintf(g[2], sizeof g[2], "grid.origin=[-13.0, %.17e]", -h);
        snprintf(g[3], sizeof g[3], "bodies.[0].rectangle.max=[-0.5, %.17e]", 2 * h);
        snprintf(g[4], sizeof g[4], "bodies.[1].rectangle.max=[10.5, %.17e]", 2 * h);
        snprintf(g[5], sizeof g[5], "bodies.[0].rectangle.max=[0.0, %.17e]", 2 * h);
        snprintf(g[6], sizeof g[6], "bodies.[1].rectangle.max=[10.0, %.17e]", 2 * h);
        const char *gap[] = {g[0], g[1], g[2], g[3], g[4], NULL};
        const char *one[] = {g[0], g[1], g[2], g[5], g[6], NULL};
        char sl[128];
        snprintf(sl, sizeof sl, "%s", schemes);
        for (char *s1 = NULL, *sch = strtok_r(sl, " ", &s1); sch;
             sch = strtok_r(NULL, " ", &s1)) {
            if (!has_scheme("tests/4-contact/scenes/bars_gap.cfg", sch))
                continue;
            char cl[128];
            snprintf(cl, sizeof cl, "%s", cfls);
            for (char *s2 = NULL, *cf = strtok_r(cl, " ", &s2); cf;
                 cf = strtok_r(NULL, " ", &s2)) {
                double cfl = atof(cf);
                Impact r;
                impact(&c, "tests/4-contact/scenes/bars_gap.cfg", sch, cfl, gap, one, &r, NULL);
                printf("  %-4d %-6s %-5.2f %8.2f%% %8.2f%% %8.2f%% %+8.3f %+7.2f%% %+7.2f%% "
                       "%+8.3f%% %7.3f%%%s%s\n", n, sch, cfl, 100 * r.miss,
                       100 * r.ref_miss, 100 * (1 - chain_rebound(n, cfl)), r.start,
                       100 * r.dur, 100 * r.ref_part, 100 * r.dE, 100 * r.swing,
                       r.miss <= 0.02 ? "  rebound within 2 %" : "",
                       r.stable ? "" : "  UNSTABLE");
                fflush(stdout);
            }
        }
    }
    tk_bounds_finish(&c);
}

/** USL alone, one bar in free flight (bar_flying.cfg: no contact, a rigid
 *  motion): unstable at cfl 0.5, the reason the bars' energy bound is not
 *  asked of USL. */
static void usl_cannot_carry_a_free_bar(void **state)
{
    (void)state;
    Sim *sim = tk_load_file("tests/4-contact/scenes/bar_flying.cfg", NULL);
    int rc = 0;
    while (sim->step < sim->nsteps && !(rc = sim_advance(sim)))
        ;
    printf("  usl cfl 0.5, one bar in free flight: %s at step %ld of %ld\n",
           rc ? "unstable" : "stable", sim->step, sim->nsteps);
    assert_int_not_equal(rc, 0);
    tk_free(sim);
}

int main(void)
{
    if (getenv("BARS_CELLS")) {                 /* make fig-bars: the study only */
        const struct CMUnitTest study[] = {cmocka_unit_test(cell_study)};
        return cmocka_run_group_tests(study, NULL, NULL);
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(identical_bars_from_a_gap),
        cmocka_unit_test(identical_bars_touching),
        cmocka_unit_test(impedances_one_to_two),
        cmocka_unit_test(corners_part_with_the_faces),
        cmocka_unit_test(rebound_converges_with_the_cell),
        cmocka_unit_test(usl_cannot_carry_a_free_bar),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
