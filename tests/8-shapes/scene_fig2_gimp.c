/**
 * @file scene_fig2_gimp.c
 * @brief The paper's Fig. 1 and 2 with uGIMP and CPDI beside linear (chapter 8,
 *        "Cracks with GIMP"): the crack's opening and sigma_xx along the
 *        ligament of the cracked DCB after damping to the static state,
 *        against the static Q4 FEA of tests/2-fields/scene_fig2.c (same
 *        grid, same sampling: tests/support/fig2.h).
 *
 * Bounds fixed before the first GIMP run, and the same for CPDI before its
 * first run: linear's own (scene_fig2.c),
 * that is the largest difference on the ligament and the peak each within
 * 5 % of the FEA's peak; and the opening within 5 % of the FEA's.
 * uGIMP and CPDI run on the grid widened by a cell on the left, with the crack's
 * mouth on the new edge node (scene_crack_gimp.c says why); linear runs
 * the figure's scene as it is.
 * The three runs damp 400 ms each (about 5 s of CPU on one thread).
 */
#include <stdio.h>

#include "fig2.h"

/** The bounds (fixed before the runs): linear's, and the opening. */
static void assert_bounds(const Fig2Ligament *G, double o_mpm, double o_fea)
{
    assert_true(G->worst <= 0.05 * G->peak_fea);
    assert_true(fabs(G->peak_mpm - G->peak_fea) <= 0.05 * G->peak_fea);
    assert_true(fabs(o_mpm - o_fea) <= 0.05 * o_fea);
}

static void gimp_and_cpdi_beside_linear(void **state)
{
    (void)state;
    static const char *const gimp[] = {
        "run.shape=\"gimp\"", "grid.origin=[-3.9215686274509802, -20.0]",
        "grid.cells=[54, 20]",
        "cracks.[0].points=([-3.9215686274509802, 0.0], [50.0, 0.0])", NULL};
    static const char *const cpdi[] = {
        "run.shape=\"cpdi\"", "grid.origin=[-3.9215686274509802, -20.0]",
        "grid.cells=[54, 20]",
        "cracks.[0].points=([-3.9215686274509802, 0.0], [50.0, 0.0])", NULL};
    double lin[NX + 1], gmp[NX + 1], cpd[NX + 1], fea[NX + 1];
    double o_lin, o_gmp, o_cpd, o_fea;
    fea_midplane(fea, &o_fea);
    mpm_midplane(lin, &o_lin, NULL);
    Fig2Ligament L = fig2_ligament(lin, fea, o_lin, o_fea, "linear");
    mpm_midplane(gmp, &o_gmp, gimp);
    Fig2Ligament G = fig2_ligament(gmp, fea, o_gmp, o_fea, "uGIMP");
    mpm_midplane(cpd, &o_cpd, cpdi);
    Fig2Ligament C = fig2_ligament(cpd, fea, o_cpd, o_fea, "CPDI");
    (void)L;
    assert_bounds(&G, o_gmp, o_fea);
    assert_bounds(&C, o_cpd, o_fea);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(gimp_and_cpdi_beside_linear),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
