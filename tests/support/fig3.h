/**
 * @file fig3.h
 * @brief The paper's Fig. 3 (stages 4 and 8): two disks with central
 *        cracks collide and bounce apart with frictionless crack contact;
 *        one run of figures/fig3/cracked_disks.cfg watched every step
 *        (tests/4-contact/scene_fig3.c says what it checks).
 */
#ifndef MPM_TEST_FIG3_H
#define MPM_TEST_FIG3_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "crack_contact.h"
#include "crack_watch.h"
#include "testkit.h"

/** The figure's scene. */
#define FIG3_SCENE "figures/fig3/cracked_disks.cfg"

/** What one run saw. */
typedef struct Fig3Run {
    long crossings[2];    /**< per crack: points seen across it */
    double open_max[2];   /**< largest opening during the impact (mm) */
    double open_min[2];   /**< smallest opening during the impact (mm) */
    double right_open_at_left_max; /**< right crack's opening then (mm) */
    double t_open_max;    /**< when the left crack was widest (ms) */
    double drift;         /**< max |E - E0| / E0 */
    double dp;            /**< max |P - P0| / sum m |v0| */
    double work;          /**< contact work at the end / E0 */
    int contact_nodes;    /**< most nodes in contact in one step */
    double t_end;         /**< the run's last time (ms) */
} Fig3Run;

/** Write the points (x, y, sxx, syy) and the cracks of snapshot @p k. */
static inline void fig3_snapshot(const Sim *sim, const char *dir, int k)
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

/** Run the scene with @p overrides (NULL-ended, or NULL), contact on or
 *  off; with @p out, write openings.csv and the four snapshots there. */
static inline Fig3Run run_fig3(int contact, const char *out,
                               const char *const *overrides)
{
    Sim *sim = tk_load_file(FIG3_SCENE, overrides);
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
            fig3_snapshot(sim, out, snap++);
        tk_steps(sim, 1);
        double open[2];
        for (int k = 0; k < 2; k++) {
            const Crack *c = &C->crack[k];
            watch_check(&w[k], sim, c->x, c->y, c->n);
            open[k] = watch_opening(&w[k], sim, c->x, c->y, c->n);
        }
        if (sim->t < 12.0) {              /* the impact and the rebound */
            if (open[0] > r.open_max[0]) {
                r.right_open_at_left_max = open[1];
                r.t_open_max = sim->t;
            }
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
        fig3_snapshot(sim, out, snap++);
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

/** Print what run @p r saw, headed @p what. */
static inline void fig3_print(const char *what, const Fig3Run *r)
{
    printf("  %s (to %.3g ms): crossings %ld and %ld; opening of the left crack "
           "%.4f to %.4f mm (widest at %.3g ms), of the right %.4f to %.4f mm "
           "(%.4f when the left is widest); most contact nodes %d; energy drift %.3f %%; momentum "
           "%.2e of sum m|v|; contact work %.2e of E0\n", what, r->t_end,
           r->crossings[0], r->crossings[1], r->open_min[0], r->open_max[0],
           r->t_open_max, r->open_min[1], r->open_max[1], r->right_open_at_left_max,
           r->contact_nodes, 100 * r->drift, r->dp, r->work);
}

#endif
