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
#include <stdio.h>
#include <stdlib.h>

#include "fig2.h"

static void midplane_stress_matches_fea(void **state)
{
    (void)state;
    double mpm[NX + 1], fea[NX + 1], open_mpm, open_fea, h = 100.0 / NX;
    mpm_midplane(mpm, &open_mpm, NULL);
    fea_midplane(fea, &open_fea);
    const char *csv = getenv("FIG2_CSV");
    FILE *out = csv ? fopen(csv, "w") : NULL;
    if (out)
        fprintf(out, "x,sigma_xx_cramp,sigma_xx_fea\n");
    for (int i = 0; out && i <= NX; i++)
        fprintf(out, "%.6f,%.8g,%.8g\n", i * h, mpm[i], fea[i]);
    if (out)
        fclose(out);
    Fig2Ligament L = fig2_ligament(mpm, fea, open_mpm, open_fea, "CRAMP");
    double worst = L.worst, peak_fea = L.peak_fea, peak_mpm = L.peak_mpm;
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
