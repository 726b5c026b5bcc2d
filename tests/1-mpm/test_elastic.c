/**
 * @file test_elastic.c
 * @brief Hooke's law in the plane (chapter 1, exercise "Hooke's law"):
 *        elastic_stress_increment() against stresses derived by hand from
 *        isotropic elasticity, in plane stress and in plane strain, and the
 *        wave speed that the time step is built on.
 *
 * Every expected value below is a closed-form consequence of 3D isotropic
 * Hooke's law, eps = ((1 + nu) sigma - nu tr(sigma) I) / E, with
 * sigma_zz = 0 (plane stress) or eps_zz = 0 (plane strain).  The code under
 * test does a handful of multiplications and additions, so its rounding
 * error is a few units in the last place; the tolerance REL = 1e-12
 * (relative to the stress scale E |eps|) leaves a wide margin for that and
 * is still ten orders of magnitude below any wrong coefficient (a missing
 * factor 2 on the shear, a plane-stress modulus used in plane strain: those
 * differ by 10 % or more for the Poisson ratios used here).
 */
#include <stdlib.h>
#include <string.h>

#include "step.h"
#include "testkit.h"

/** Relative tolerance: rounding of a few operations, see the file comment. */
#define REL 1e-12

/** Delrin of the paper's beam impact (Fig. 5): E in MPa, rho in g/mm^3. */
static const double E0 = 2900.0, NU0 = 0.33, RHO0 = 1.5e-3;

static Material make(double E, double nu, double rho, PlaneKind plane)
{
    Material m;
    memset(&m, 0, sizeof m);
    m.E = E;
    m.nu = nu;
    m.rho = rho;
    material_prepare(&m, plane);
    return m;
}

/** Stress from zero after one increment. */
static void from_zero(const Material *m, double exx, double eyy, double exy,
                      double s[3])
{
    s[0] = s[1] = s[2] = 0.0;
    elastic_stress_increment(m, exx, eyy, exy, s);
}

static void check_stress(const double s[3], double sxx, double syy, double sxy,
                         double scale)
{
    assert_close(s[0], sxx, REL * scale);
    assert_close(s[1], syy, REL * scale);
    assert_close(s[2], sxy, REL * scale);
}

/* Plane stress, sigma_yy = 0: then eps_yy = -nu eps_xx and sigma_xx = E eps_xx
 * (the tensile test). */
static void plane_stress_uniaxial_stress(void **state)
{
    (void)state;
    Material m = make(E0, NU0, RHO0, PLANE_STRESS);
    double e = 1e-3, s[3];
    from_zero(&m, e, -NU0 * e, 0.0, s);
    check_stress(s, E0 * e, 0.0, 0.0, E0 * e);
}

/* Plane stress, eps_yy = 0: sigma_xx = E/(1-nu^2) eps, sigma_yy = nu sigma_xx. */
static void plane_stress_uniaxial_strain(void **state)
{
    (void)state;
    Material m = make(E0, NU0, RHO0, PLANE_STRESS);
    double e = -2e-4, s[3];
    from_zero(&m, e, 0.0, 0.0, s);
    double sxx = E0 * e / (1.0 - NU0 * NU0);
    check_stress(s, sxx, NU0 * sxx, 0.0, E0 * fabs(e));
    /* the same along y */
    from_zero(&m, 0.0, e, 0.0, s);
    check_stress(s, NU0 * sxx, sxx, 0.0, E0 * fabs(e));
}

/* Plane strain, eps_yy = eps_zz = 0: the P-wave modulus
 * sigma_xx = E (1-nu) / ((1+nu)(1-2nu)) eps, sigma_yy = E nu / ((1+nu)(1-2nu)) eps. */
static void plane_strain_uniaxial_strain(void **state)
{
    (void)state;
    Material m = make(E0, NU0, RHO0, PLANE_STRAIN);
    double e = 5e-4, s[3], d = (1.0 + NU0) * (1.0 - 2.0 * NU0);
    from_zero(&m, e, 0.0, 0.0, s);
    check_stress(s, E0 * (1.0 - NU0) * e / d, E0 * NU0 * e / d, 0.0, E0 * e);
}

/* Plane strain, sigma_yy = 0: sigma_zz = nu sigma_xx, so
 * eps_yy = -nu/(1-nu) eps_xx and sigma_xx = E/(1-nu^2) eps_xx. */
static void plane_strain_uniaxial_stress(void **state)
{
    (void)state;
    Material m = make(E0, NU0, RHO0, PLANE_STRAIN);
    double e = 1e-3, s[3];
    from_zero(&m, e, -NU0 / (1.0 - NU0) * e, 0.0, s);
    check_stress(s, E0 * e / (1.0 - NU0 * NU0), 0.0, 0.0, E0 * e);
}

/* Equal biaxial strain: plane stress sigma = E/(1-nu) eps, plane strain
 * sigma = E/((1+nu)(1-2nu)) eps, in both in-plane directions. */
static void equal_biaxial_strain(void **state)
{
    (void)state;
    double e = 3e-4, s[3];
    Material ps = make(E0, NU0, RHO0, PLANE_STRESS);
    from_zero(&ps, e, e, 0.0, s);
    check_stress(s, E0 * e / (1.0 - NU0), E0 * e / (1.0 - NU0), 0.0, E0 * e);
    Material pe = make(E0, NU0, RHO0, PLANE_STRAIN);
    double d = (1.0 + NU0) * (1.0 - 2.0 * NU0);
    from_zero(&pe, e, e, 0.0, s);
    check_stress(s, E0 * e / d, E0 * e / d, 0.0, E0 * e);
}

/* Pure shear, same in both idealisations: with the tensor shear strain
 * eps_xy (half the engineering strain gamma), sigma_xy = 2 G eps_xy =
 * E/(1+nu) eps_xy.  The same state rotated by 45 degrees is eps_xx = -eps_yy
 * = g, which must give sigma_xx = -sigma_yy = 2 G g (isotropy). */
static void pure_shear(void **state)
{
    (void)state;
    const PlaneKind planes[2] = {PLANE_STRESS, PLANE_STRAIN};
    for (int k = 0; k < 2; k++) {
        Material m = make(E0, NU0, RHO0, planes[k]);
        double g = 7e-4, s[3], twoG = E0 / (1.0 + NU0);
        from_zero(&m, 0.0, 0.0, g, s);
        check_stress(s, 0.0, 0.0, twoG * g, E0 * g);
        from_zero(&m, g, -g, 0.0, s);
        check_stress(s, twoG * g, -twoG * g, 0.0, E0 * g);
    }
}

/* Invert with the compliance of 3D Hooke's law at random strains and Poisson
 * ratios (including negative ones):
 *   plane stress: eps_xx = (s_xx - nu s_yy) / E, eps_xy = (1+nu) s_xy / E;
 *   plane strain (s_zz = nu (s_xx + s_yy)):
 *                 eps_xx = ((1-nu^2) s_xx - nu (1+nu) s_yy) / E. */
static void compliance_inverts_stiffness(void **state)
{
    (void)state;
    srand(2003);
    for (int k = 0; k < 2000; k++) {
        double nu = -0.9 + 1.35 * rand() / (double)RAND_MAX;  /* (-0.9, 0.45) */
        double E = 0.1 + 5000.0 * rand() / (double)RAND_MAX;
        double e[3];
        for (int c = 0; c < 3; c++)
            e[c] = 1e-3 * (2.0 * rand() / (double)RAND_MAX - 1.0);
        double s[3], scale = 1e-3;        /* strain scale of the check */
        /* the stresses reach ~10 E |eps| (1/(1-2 nu) near nu = 0.45) and the
         * compliance sums cancel some of it: allow 100 REL relative */
        Material ps = make(E, nu, 1e-3, PLANE_STRESS);
        from_zero(&ps, e[0], e[1], e[2], s);
        assert_close((s[0] - nu * s[1]) / E, e[0], 100 * REL * scale);
        assert_close((s[1] - nu * s[0]) / E, e[1], 100 * REL * scale);
        assert_close((1.0 + nu) * s[2] / E, e[2], 100 * REL * scale);
        Material pe = make(E, nu, 1e-3, PLANE_STRAIN);
        from_zero(&pe, e[0], e[1], e[2], s);
        double a = 1.0 - nu * nu, b = nu * (1.0 + nu);
        assert_close((a * s[0] - b * s[1]) / E, e[0], 100 * REL * scale);
        assert_close((a * s[1] - b * s[0]) / E, e[1], 100 * REL * scale);
        assert_close((1.0 + nu) * s[2] / E, e[2], 100 * REL * scale);
    }
}

/* The function adds an increment to the stress it is given (eq. 36 is an
 * update, not an assignment); a zero increment leaves the stress alone. */
static void increments_add_to_the_stress(void **state)
{
    (void)state;
    Material m = make(E0, NU0, RHO0, PLANE_STRAIN);
    double inc[3], s[3] = {1.5, -2.25, 0.75};
    from_zero(&m, 2e-4, -1e-4, 3e-4, inc);
    elastic_stress_increment(&m, 2e-4, -1e-4, 3e-4, s);
    check_stress(s, 1.5 + inc[0], -2.25 + inc[1], 0.75 + inc[2], E0 * 1e-3);
    double z[3] = {1.5, -2.25, 0.75};
    elastic_stress_increment(&m, 0.0, 0.0, 0.0, z);
    assert_close(z[0], 1.5, 0.0);
    assert_close(z[1], -2.25, 0.0);
    assert_close(z[2], 0.75, 0.0);
}

/* The time step rests on the fastest wave (chapter 1): a plane longitudinal
 * wave travels at sqrt(M / rho), M = d sigma_xx / d eps_xx at eps_yy = 0.
 * M read off elastic_stress_increment() must give Material::wave and the
 * textbook speeds: plane stress sqrt(E / ((1-nu^2) rho)), plane strain
 * sqrt(E (1-nu) / ((1+nu)(1-2nu) rho)). */
static void wave_speed_from_the_stiffness(void **state)
{
    (void)state;
    double e = 1e-3, s[3];
    Material ps = make(E0, NU0, RHO0, PLANE_STRESS);
    from_zero(&ps, e, 0.0, 0.0, s);
    double c_ps = sqrt(E0 / ((1.0 - NU0 * NU0) * RHO0));
    assert_close(sqrt(s[0] / e / RHO0), c_ps, REL * c_ps);
    assert_close(ps.wave, c_ps, REL * c_ps);
    Material pe = make(E0, NU0, RHO0, PLANE_STRAIN);
    from_zero(&pe, e, 0.0, 0.0, s);
    double c_pe = sqrt(E0 * (1.0 - NU0) / ((1.0 + NU0) * (1.0 - 2.0 * NU0) * RHO0));
    assert_close(sqrt(s[0] / e / RHO0), c_pe, REL * c_pe);
    assert_close(pe.wave, c_pe, REL * c_pe);
    /* plane strain is stiffer than plane stress for nu > 0 */
    assert_true(c_pe > c_ps);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(plane_stress_uniaxial_stress),
        cmocka_unit_test(plane_stress_uniaxial_strain),
        cmocka_unit_test(plane_strain_uniaxial_strain),
        cmocka_unit_test(plane_strain_uniaxial_stress),
        cmocka_unit_test(equal_biaxial_strain),
        cmocka_unit_test(pure_shear),
        cmocka_unit_test(compliance_inverts_stiffness),
        cmocka_unit_test(increments_add_to_the_stress),
        cmocka_unit_test(wave_speed_from_the_stiffness),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
