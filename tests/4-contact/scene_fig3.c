/**
 * @file scene_fig3.c
 * @brief The paper's Fig. 3 (section 3.2): two disks with central cracks
 *        collide and bounce apart, with frictionless crack contact.
 *
 * A reduced run of figures/fig3/cracked_disks.cfg (the collision and the
 * rebound, 12 ms; the figure's grid and CFL) checks, every step and by the
 * cracks' own geometry (crack_watch.h), that no point crosses its own
 * crack's line; that the crack along the impact axis opens (mode I) while
 * the faces of the crack across it touch; that total momentum stays at its
 * start value to round-off; that contact does no work (frictionless); and
 * it prints the total energy drift, which must stay below the 2.6 % that
 * the reference CRAMP code gains on this scene. The same run with contact
 * switched off lets the right crack's faces cross: the watch can fail.
 *
 * FIG3_OUT=dir runs the full scene instead and writes what `make fig3`
 * draws: openings.csv (time, both openings, contact nodes, energy) and
 * four snapshots snap_K.csv (x, y, sigma_xx, sigma_yy) with cracks_K.csv,
 * at 0, 7, 12 and 18 ms (the paper's frames A-D) or at the four times
 * FIG3_TIMES="t0 t1 t2 t3" gives.
 */
#include "testkit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "crack_contact.h"
#include "crack_watch.h"

static const char *const SCENE = "figures/fig3/cracked_disks.cfg";

/** What one run saw. */
typedef struct Fig3Run {
    long crossings[2];    /* per crack */
    double open_max[2];   /* largest opening during the impact */
    double open_min[2];   /* smallest opening during the impact */
    double right_open_at_left_max; /* right crack's opening then */
    double drift;         /* max |E - E0| / E0 */
    double dp;            /* max |P - P0| / sum m |v0| */
    double work;          /* contact work at the end / E0 */
    int contact_nodes;    /* most nodes in contact in one step */
    double t_end;
} Fig3Run;

/** Write the points (x, y, sxx, syy) and the cracks of snapshot @p k. */
static void write_snapshot(const Sim *sim, const char *dir, int k)
{
    char path[600];
    snprintf(path, sizeof path, "%s/snap_%d.csv", dir, k);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fprintf(f, "# t = %.6g ms\nx,y,sxx,syy\n", sim->t);
    const Particles *P = &sim->pts;
    for (int p = 0; p < P->n; p++)
        fprintf(f, "%.9g,%.9g,%.6g,%.6g\n", P->x[p], P->y[p], P->sxx[p], P->syy[p]);
    assert_int_equal(fclose(f), 0);
    snprintf(path, sizeof path, "%s/cracks_%d.csv", dir, k);
    f = fopen(path, "w");
    assert_non_null(f);
    const Cracks *C = cracks_of(sim);
    for (int c = 0; c < C->ncracks; c++) {
        for (int j = 0; j < C->crack[c].n; j++)
            fprintf(f, "%.9g,%.9g\n", C->crack[c].x[j], C->crack[c].y[j]);
        fprintf(f, "\n");
    }
    assert_int_equal(fclose(f), 0);
}

/** Run the scene (reduced unless @p out), contact on or off. */
static Fig3Run run_fig3(int contact, const char *out, const char *const *overrides)
{
    Sim *sim = tk_load_file(SCENE, overrides);
    Cracks *C = cracks_of(sim);
    ContactState *S = sim_state(sim, "crack contact");
    assert_non_null(C);
    assert_non_null(S);
    assert_int_equal(C->ncracks, 2);
    if (!contact)
        for (int k = 0; k < S->ncracks; k++)
            S->crack[k].law.kind = CONTACT_NONE;
    CrackWatch w[2];
    for (int k = 0; k < 2; k++)          /* crack k lies in body k */
        watch_start(&w[k], sim, k, C->crack[k].x, C->crack[k].y, C->crack[k].n,
                    0.75 * sim->grid.dy, 0.6);
    Totals t0 = sim_totals(sim);
    double e0 = t0.kinetic + t0.strain, mv = 0;
    for (int p = 0; p < sim->pts.n; p++)
        mv += sim->pts.m[p] * hypot(sim->pts.vx[p], sim->pts.vy[p]);
    Fig3Run r;
    memset(&r, 0, sizeof r);
    r.open_min[0] = r.open_min[1] = INFINITY;
    r.open_max[0] = r.open_max[1] = -INFINITY;
    FILE *f = NULL;
    double snap_at[4] = {0.0, 7.0, 12.0, 18.0};   /* frames A-D (ms) */
    int snap = 0;
    if (out) {
        char path[600];
        snprintf(path, sizeof path, "%s/openings.csv", out);
        f = fopen(path, "w");
        assert_non_null(f);
        fprintf(f, "time,open_left,open_right,contact_nodes,energy\n");
        const char *times = getenv("FIG3_TIMES");
        if (times)
            sscanf(times, "%lf %lf %lf %lf", &snap_at[0], &snap_at[1], &snap_at[2],
                   &snap_at[3]);
    }
    while (sim->step < sim->nsteps) {
        if (out && snap < 4 && sim->t + 0.5 * sim->dt >= snap_at[snap])
            write_snapshot(sim, out, snap++);
        tk_steps(sim, 1);
        double open[2];
        for (int k = 0; k < 2; k++) {
            const Crack *c = &C->crack[k];
            watch_check(&w[k], sim, c->x, c->y, c->n);
            open[k] = watch_opening(&w[k], sim, c->x, c->y, c->n);
        }
        if (sim->t < 12.0) {              /* the impact and the rebound */
            if (open[0] > r.open_max[0])
                r.right_open_at_left_max = open[1];
            for (int k = 0; k < 2; k++) {
                r.open_max[k] = fmax(r.open_max[k], open[k]);
                r.open_min[k] = fmin(r.open_min[k], open[k]);
            }
        }
        Totals t = sim_totals(sim);
        double e = t.kinetic + t.strain;
        r.drift = fmax(r.drift, fabs(e - e0) / e0);
        r.dp = fmax(r.dp, hypot(t.px - t0.px, t.py - t0.py) / mv);
        if (S->nodes > r.contact_nodes)
            r.contact_nodes = S->nodes;
        if (f)
            fprintf(f, "%.6g,%.6g,%.6g,%d,%.9g\n", sim->t, open[0], open[1],
                    S->nodes, e);
    }
    while (out && snap < 4)
        write_snapshot(sim, out, snap++);
    if (f)
        assert_int_equal(fclose(f), 0);
    r.work = S->work / e0;
    r.t_end = sim->t;
    for (int k = 0; k < 2; k++) {
        r.crossings[k] = w[k].crossings;
        if (w[k].first_p >= 0)
            printf("  crack %d: point %d crossed at step %ld\n", k, w[k].first_p,
                   w[k].first_step);
        watch_free(&w[k]);
    }
    tk_free(sim);
    return r;
}

static void print_run(const char *what, const Fig3Run *r)
{
    printf("  %s (to %.3g ms): crossings %ld and %ld; opening of the left crack "
           "%.4f to %.4f mm, of the right %.4f to %.4f mm (%.4f when the left "
           "is widest); most contact nodes %d; energy drift %.3f %%; momentum "
           "%.2e of sum m|v|; contact work %.2e of E0\n", what, r->t_end,
           r->crossings[0], r->crossings[1], r->open_min[0], r->open_max[0],
           r->open_min[1], r->open_max[1], r->right_open_at_left_max,
           r->contact_nodes, 100 * r->drift, r->dp, r->work);
}

static const char *const reduced[] = {"run.time=12.0", NULL};

static void collision_with_contact(void **state)
{
    (void)state;
    Fig3Run r = run_fig3(1, NULL, reduced);
    print_run("frictionless contact", &r);
    double h = 1.0;                          /* the scene's cell size (mm) */
    assert_int_equal(r.crossings[0], 0);     /* no point crosses its crack */
    assert_int_equal(r.crossings[1], 0);
    assert_true(r.open_max[0] > 0.5 * h);    /* mode I: the left crack opens */
    /* the right crack is closed then: its faces' points no further apart
       than at the start, give or take a tenth of a cell */
    assert_true(fabs(r.right_open_at_left_max) < 0.1 * h);
    assert_true(r.contact_nodes > 0);
    assert_true(r.dp < 1e-12);               /* momentum: round-off */
    assert_true(fabs(r.work) < 1e-12);       /* frictionless: no work */
    assert_true(r.drift < 0.026);            /* the reference code: 2.6-3.3 % */
}

static void collision_without_contact(void **state)
{
    (void)state;
    Fig3Run r = run_fig3(0, NULL, reduced);
    print_run("contact off", &r);
    assert_true(r.crossings[1] > 0);         /* the watch sees faces cross */
    assert_int_equal(r.contact_nodes, 0);
}

int main(void)
{
    const char *out = getenv("FIG3_OUT");
    if (out) {
        Fig3Run r = run_fig3(1, out, NULL);
        print_run("full run, frictionless contact", &r);
        return 0;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(collision_with_contact),
        cmocka_unit_test(collision_without_contact),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
