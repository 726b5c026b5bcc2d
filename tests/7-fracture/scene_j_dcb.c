/**
 * @file scene_j_dcb.c
 * @brief Chapter 7: J at the tip of the static DCB of chapter 2 against the
 *        energy release rate of a converged Q4 finite element analysis,
 *        G = P^2 / (2 B) dC/da, and J's path independence.
 *
 * CRAMP runs tests/7-fracture/scenes/dcb_j.cfg (the chapter-2 beam on
 * cells of half the size, at a load in the linear range, damped to rest)
 * and gives J on the domains of 4, 6 and 8 cells about the tip; the same
 * beam on the chapter-2 grid (2, 3 and 4 cells: the same mm) is printed
 * beside it, for the convergence with the cell.
 * The FEA (tests/support/q4.c) models the upper arm and the ligament with
 * the symmetry condition on the ligament, carries the MPM's own point loads
 * (the loaded points' forces at their places), and gives the load-point
 * compliance C = delta / P, delta the opening that the loads work through
 * (sum f_k u_y(x_k) / P, both arms), at a - 1, a and a + 1 mm: G by the
 * central difference. The mesh is laid along the beam's y so that LAPACK's
 * band is the arm's depth; its element is refined 1, 0.5, 0.25 mm.
 * Bounds, fixed before the first run: |J - G| <= 2 % of G on every contour
 * (G of the finest mesh), spread of the three J <= 1 %, on the finer
 * grid; the chapter-2 grid's numbers are printed, not bounded, and so
 * is (K_I^2 + K_II^2) / E' from chapter 7's interaction integral.
 */
#include "testkit.h"

#include <stdio.h>
#include <stdlib.h>

#include "j_integral.h"
#include "q4.h"

#define A_TIP 50.0        /* crack length, mm */
#define DA 1.0            /* central difference step in a, mm */
#define ARM 18.0          /* arm depth, mm */
#define LENGTH 100.0      /* beam length, mm */
#define NLOAD_MAX 128     /* loaded points of the upper arm */

/** The upper arm's loaded points: their places and forces. */
typedef struct ArmLoad {
    int n;
    double x[NLOAD_MAX], y[NLOAD_MAX], fy[NLOAD_MAX];
    double P;             /* their total */
} ArmLoad;

/** Load-point compliance of the beam with crack length @p a on elements
 *  of size @p h (plane stress, E, nu, thickness 1): the opening the loads
 *  work through, over P. Mesh x = beam y, mesh y = beam x. */
static double compliance(const ArmLoad *L, double a, double h, double E, double nu)
{
    Q4Model q;
    int nx = (int)lround(ARM / h), ny = (int)lround(LENGTH / h);
    assert_int_equal(q4_init(&q, nx, ny, 0.0, 0.0, h, h, 1.0, E, nu), 0);
    for (int j = 0; j <= ny; j++)
        if (j * h >= a - 1e-9)                      /* ligament: symmetry */
            q.fix[2 * q4_node(&q, 0, j)] = 1;
    q.fix[2 * q4_node(&q, 0, ny) + 1] = 1;           /* no rigid beam-x motion */
    for (int k = 0; k < L->n; k++)
        q4_point_force(&q, L->y[k], L->x[k], L->fy[k], 0.0);
    assert_int_equal(q4_solve(&q), 0);
    double work = 0.0;
    for (int k = 0; k < L->n; k++) {
        double u[2];
        q4_displacement(&q, L->y[k], L->x[k], u);
        work += L->fy[k] * u[0];
    }
    q4_free(&q);
    return 2.0 * work / (L->P * L->P);              /* both arms: 2 delta / P */
}

/** G = P^2 / (2 B) dC/da by the central difference, elements of size h. */
static double fea_G(const ArmLoad *L, double h, double E, double nu)
{
    double cm = compliance(L, A_TIP - DA, h, E, nu);
    double cp = compliance(L, A_TIP + DA, h, E, nu);
    return L->P * L->P / 2.0 * (cp - cm) / (2.0 * DA);
}

/** Run the DCB (with @p overrides) to rest; J per contour into @p J,
 *  the upper arm's loads into @p L (may be NULL). */
static void mpm_J(const char *const *overrides, double J[3], int *contour,
                  double *cell, ArmLoad *L, double JK[3])
{
    Sim *sim = tk_load_file("tests/7-fracture/scenes/dcb_j.cfg", overrides);
    const Load *ld = &sim->scene.loads[0];
    if (L) {
        assert_true(ld->count <= NLOAD_MAX);
        L->n = ld->count;
        L->P = ld->fy;
        for (int k = 0; k < ld->count; k++) {
            L->x[k] = sim->pts.x[ld->points[k]];
            L->y[k] = sim->pts.y[ld->points[k]];
            L->fy[k] = ld->fy / ld->count;
        }
    }
    tk_steps(sim, sim->nsteps);
    Totals t = sim_totals(sim);
    assert_true(t.kinetic < 1e-3 * t.strain);       /* at rest */
    const JState *S = sim_state(sim, "j-integral");
    assert_non_null(S);
    assert_int_equal(S->ntips, 1);
    assert_int_equal(S->set[0].ncontours, 3);
    double E = sim->scene.mat[0].E;     /* plane stress: E' = E */
    for (int m = 0; m < 3; m++) {
        J[m] = S->tip[0].J[m];
        contour[m] = S->set[0].contour[m];
        JK[m] = (S->tip[0].KI[m] * S->tip[0].KI[m] +
                 S->tip[0].KII[m] * S->tip[0].KII[m]) / E;
    }
    *cell = sim->grid.dx;
    tk_free(sim);
}

/** The chapter-2 grid (cells 100/51 x 2 mm), with the same domains in mm:
 *  2, 3, 4 cells. Its loaded points are one column at x = 0.49 mm, the
 *  finer grid's two columns at 0.25 and 0.74 mm: the same load centre to
 *  0.005 mm, so one G serves both. */
static const char *const coarse[] = {
    "grid.origin=[-1.9607843137254901, -20.0]", "grid.cells=[53,20]",
    "grid.cell_size=[1.9607843137254901, 2.0]",
    "cracks.[0].points=([-1.9607843137254901, 0.0], [50.0, 0.0])",
    "cracks.[0].j_integral.contours=[2,3,4]", NULL};

/** One row per contour: J, and its difference from @p G. */
static void print_J(double cell, double cy, const double J[3],
                    const int contour[3], double G)
{
    for (int m = 0; m < 3; m++)
        printf("    %5.3f x %3.1f   %2d (%4.1f mm)   %.6g   %+7.3f %%\n", cell,
               cy, contour[m], contour[m] * cy, J[m], 100 * (J[m] / G - 1.0));
}

static void j_matches_compliance_G(void **state)
{
    (void)state;
    double J[3], Jc[3], JK[3], JKc[3], cell, cellc;
    int contour[3], contourc[3];
    ArmLoad L;
    mpm_J(NULL, J, contour, &cell, &L, JK);
    const double E = 0.1, nu = 0.33;
    const double hs[3] = {1.0, 0.5, 0.25};
    double G[3];
    printf("  FEA (Q4, plane stress), G = P^2/(2B) dC/da at a = %g mm, da = "
           "+-%g mm, P = %g N:\n", A_TIP, DA, L.P);
    for (int k = 0; k < 3; k++) {
        G[k] = fea_G(&L, hs[k], E, nu);
        printf("    element %5.3f mm: G = %.6g N/mm\n", hs[k], G[k]);
    }
    double order = log((G[1] - G[0]) / (G[2] - G[1])) / log(2.0);
    double Gx = G[2] + (G[2] - G[1]) / (pow(2.0, order) - 1.0);
    printf("    observed order %.2f; extrapolated G = %.6g (the finest %+.3f %% "
           "from it)\n", order, Gx, 100.0 * (G[2] / Gx - 1.0));
    double Gref = G[2];
    mpm_J(coarse, Jc, contourc, &cellc, NULL, JKc);
    printf("  CRAMP, J on square domains about the tip (G of the 0.25 mm mesh):\n");
    printf("    cells (mm)    contour (cells)   J (N/mm)      J/G - 1\n");
    print_J(cellc, 2.0, Jc, contourc, Gref);
    print_J(cell, 1.0, J, contour, Gref);
    printf("  K from the interaction integral, (K_I^2 + K_II^2)/E' against the "
           "same G (printed, not bounded):\n");
    print_J(cellc, 2.0, JKc, contourc, Gref);
    print_J(cell, 1.0, JK, contour, Gref);
    TkBounds b = {0, 0};
    double lo = J[0], hi = J[0];
    for (int m = 0; m < 3; m++) {
        double err = J[m] / Gref - 1.0;
        lo = fmin(lo, J[m]);
        hi = fmax(hi, J[m]);
        tk_bound(&b, 4, fabs(err) <= 0.02, "contour %d: J %.6g vs G %.6g (%+.2f %%, "
                 "bound 2 %%)", contour[m], J[m], Gref, 100 * err);
    }
    double spread = (hi - lo) / (0.5 * (hi + lo));
    printf("    spread over the three contours at %.3f mm: %.3f %% (bound 1 %%)\n",
           cell, 100 * spread);
    tk_bound(&b, 4, spread <= 0.01, "spread %.3f %% over 1 %%", 100 * spread);
    tk_bounds_finish(&b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(j_matches_compliance_G),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
