/**
 * @file fig2.h
 * @brief The paper's Fig. 2 (stages 2 and 8): sigma_xx along the
 *        mid-plane of the cracked DCB after damping to the static state,
 *        from the MPM and from a static Q4 finite element analysis on the
 *        same grid, sampled alike (tests/2-fields/scene_fig2.c says how).
 */
#ifndef MPM_TEST_FIG2_H
#define MPM_TEST_FIG2_H

#include <math.h>
#include <stdio.h>

#include "output.h"
#include "q4.h"
#include "shape.h"
#include "stencil.h"
#include "testkit.h"

#define NX 51                     /**< elements along the 100 mm beam */
#define NY 9                      /**< elements through the 18 mm arm */

/** MPM: sigma_xx at the mid-plane nodes after damping to the static
 *  state, and the crack's opening at the loaded end, from
 *  figures/fig1/dcb_full.cfg with @p overrides (NULL-ended, or NULL). */
static inline void mpm_midplane(double sxx[NX + 1], double *opening,
                                const char *const *overrides)
{
    Sim *sim = tk_load_file("figures/fig1/dcb_full.cfg", overrides);
    int tip = -1;
    for (int p = 0; p < sim->pts.n; p++)      /* upper arm, loaded end, face */
        if (sim->pts.y[p] > 0 && (tip < 0 || sim->pts.x[p] < sim->pts.x[tip] ||
            (sim->pts.x[p] == sim->pts.x[tip] && sim->pts.y[p] < sim->pts.y[tip])))
            tip = p;
    double y0 = sim->pts.y[tip];
    tk_steps(sim, sim->nsteps);
    Totals t = sim_totals(sim);
    assert_true(t.kinetic < 1e-3 * t.strain);  /* static enough */
    *opening = 2 * (sim->pts.y[tip] - y0);
    assert_int_equal(output_make_dir("build/test-out"), 0);
    assert_int_equal(output_grid_csv(sim, "build/test-out", "fig2_grid.csv"), 0);
    FILE *f = fopen("build/test-out/fig2_grid.csv", "r");
    assert_non_null(f);
    char line[512];
    for (int i = 0; i <= NX; i++)
        sxx[i] = NAN;
    assert_non_null(fgets(line, sizeof line, f));            /* # t = ... */
    assert_int_equal(line[0], '#');
    assert_non_null(fgets(line, sizeof line, f));            /* header */
    while (fgets(line, sizeof line, f)) {
        double x, y, m, s[3];
        if (sscanf(line, "%lf,%lf,%lf,%lf,%lf,%lf", &x, &y, &m, &s[0], &s[1],
                   &s[2]) != 6 || fabs(y) > 1e-9)
            continue;
        int i = (int)lround(x / (100.0 / NX));
        if (i >= 0 && i <= NX)
            sxx[i] = s[0];
    }
    fclose(f);
    tk_free(sim);
}

/** FEA of the upper half, sampled like the MPM. */
static inline void fea_midplane(double sxx[NX + 1], double *opening)
{
    Sim *sim = tk_load_file("figures/fig1/dcb_half.cfg", NULL);
    const Particles *P = &sim->pts;
    const Material *mat = &sim->scene.mat[0];
    Q4Model q;
    double h = 100.0 / NX;
    assert_int_equal(q4_init(&q, NX, NY, 0.0, 0.0, h, 2.0, 1.0, mat->E, mat->nu), 0);
    for (int i = 0; i <= NX; i++)
        if (i * h > 50.0)
            q.fix[2 * q4_node(&q, i, 0) + 1] = 1;     /* ligament: symmetry */
    q.fix[2 * q4_node(&q, NX, 0)] = 1;                /* no rigid x motion */
    const Load *L = &sim->scene.loads[0];
    for (int k = 0; k < L->count; k++)
        q4_point_force(&q, P->x[L->points[k]], P->y[L->points[k]],
                       L->fx / L->count, L->fy / L->count);
    assert_int_equal(q4_solve(&q), 0);
    double u[2];
    q4_displacement(&q, 0.0, 0.0, u);
    *opening = 2 * u[1];
    /* stresses at the points, extrapolated to the nodes as in the MPM */
    double w[NX + 1] = {0};
    for (int i = 0; i <= NX; i++)
        sxx[i] = 0;
    for (int p = 0; p < P->n; p++) {
        double s[3];
        Stencil st;
        if (P->y[p] > 2.0)
            continue;                                 /* first row of cells */
        q4_stress(&q, P->x[p], P->y[p], s);
        stencil_at(&sim->grid, P->x[p], P->y[p], &st);
        const double *S = st.S;
        int i = (int)floor(P->x[p] / h);
        sxx[i] += S[0] * s[0];
        w[i] += S[0];
        sxx[i + 1] += S[1] * s[0];
        w[i + 1] += S[1];
    }
    for (int i = 0; i <= NX; i++)
        sxx[i] /= w[i];
    q4_free(&q);
    tk_free(sim);
}


/** What Fig. 2 compares on the ligament (x > 50 mm). */
typedef struct Fig2Ligament {
    double peak_fea;   /**< the FEA's peak sigma_xx */
    double peak_mpm;   /**< the MPM's peak sigma_xx */
    double x_peak;     /**< where the FEA peaks (mm) */
    double worst;      /**< largest |MPM - FEA| */
} Fig2Ligament;

/** Compare the curves @p mpm and @p fea on the ligament and print the
 *  openings and the peaks, the MPM named @p name. */
static inline Fig2Ligament fig2_ligament(const double mpm[NX + 1],
                                         const double fea[NX + 1],
                                         double open_mpm, double open_fea,
                                         const char *name)
{
    Fig2Ligament L = {0, 0, 0, 0};
    double h = 100.0 / NX;
    for (int i = 0; i <= NX; i++)
        if (i * h > 50.0) {
            if (fea[i] > L.peak_fea) {
                L.peak_fea = fea[i];
                L.x_peak = i * h;
            }
            L.peak_mpm = fmax(L.peak_mpm, mpm[i]);
            L.worst = fmax(L.worst, fabs(mpm[i] - fea[i]));
        }
    printf("crack opening: %s %.5g mm, FEA %.5g mm (%.2f %%)\n", name, open_mpm,
           open_fea, 100 * (open_mpm / open_fea - 1));
    printf("ligament: peak sigma_xx %s %.5g, FEA %.5g MPa at x = %.3g mm "
           "(%.2f %%); largest difference %.3g MPa = %.2f %% of the peak\n",
           name, L.peak_mpm, L.peak_fea, L.x_peak,
           100 * (L.peak_mpm / L.peak_fea - 1), L.worst, 100 * L.worst / L.peak_fea);
    return L;
}

#endif
