/**
 * @file scene_fig2.c
 * @brief The paper's Fig. 2: sigma_xx along the mid-plane of the cracked
 *        DCB from CRAMP against a static finite element analysis on the same
 *        grid of 4-node elements.
 *
 * The FEA (tests/support/q4.c) models the upper half with the symmetry
 * condition on the ligament, takes the same nodal forces as the MPM load
 * (the points' loads spread by the shape functions) and is sampled as the
 * MPM is: stresses at the material points' initial positions, extrapolated
 * to the nodes with the same mass-weighted sums (all points of the DCB have
 * equal masses).  The two therefore differ only by what each method solves.
 * With FIG2_CSV=path in the environment the curves are written there.
 */
#include "stencil.h"
#include "testkit.h"

#include <stdio.h>
#include <stdlib.h>

#include "output.h"
#include "q4.h"
#include "shape.h"

#define NX 51                     /* elements along the 100 mm beam */
#define NY 9                      /* elements through the 18 mm arm */

/** MPM: sigma_xx at the mid-plane nodes after damping to the static state. */
static void mpm_midplane(double sxx[NX + 1], double *opening)
{
    Sim *sim = tk_load_file("figures/fig1/dcb_full.cfg", NULL);
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
static void fea_midplane(double sxx[NX + 1], double *opening)
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

static void midplane_stress_matches_fea(void **state)
{
    (void)state;
    double mpm[NX + 1], fea[NX + 1], open_mpm, open_fea, h = 100.0 / NX;
    mpm_midplane(mpm, &open_mpm);
    fea_midplane(fea, &open_fea);
    const char *csv = getenv("FIG2_CSV");
    FILE *out = csv ? fopen(csv, "w") : NULL;
    if (out)
        fprintf(out, "x,sigma_xx_cramp,sigma_xx_fea\n");
    double peak_fea = 0, peak_mpm = 0, worst = 0;
    int ipeak = 0;
    for (int i = 0; i <= NX; i++) {
        if (out)
            fprintf(out, "%.6f,%.8g,%.8g\n", i * h, mpm[i], fea[i]);
        if (i * h > 50.0 && fea[i] > peak_fea) {
            peak_fea = fea[i];
            ipeak = i;
        }
    }
    if (out)
        fclose(out);
    for (int i = 0; i <= NX; i++)
        if (i * h > 50.0) {
            peak_mpm = fmax(peak_mpm, mpm[i]);
            worst = fmax(worst, fabs(mpm[i] - fea[i]));
        }
    printf("crack opening: CRAMP %.5g mm, FEA %.5g mm (%.2f %%)\n", open_mpm,
           open_fea, 100 * (open_mpm / open_fea - 1));
    printf("ligament: peak sigma_xx CRAMP %.5g, FEA %.5g MPa at x = %.3g mm "
           "(%.2f %%); largest difference %.3g MPa = %.2f %% of the peak\n",
           peak_mpm, peak_fea, ipeak * h, 100 * (peak_mpm / peak_fea - 1), worst,
           100 * worst / peak_fea);
    assert_true(worst <= 0.05 * peak_fea);
    assert_true(fabs(peak_mpm - peak_fea) <= 0.05 * peak_fea);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(midplane_stress_matches_fea),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
