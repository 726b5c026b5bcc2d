/**
 * @file rankine_tangent.c
 * @brief Tangents to try the stability criterion on: isotropic elasticity
 *        in plane strain or plane stress, and the softening tangent of a
 *        Rankine (maximum principal stress) law with associated flow
 *        (de Borst et al., "Nonlinear finite element analysis of solids
 *        and structures", 2nd ed., ch. 7; the derivation is in
 *        acoustic_tensor.h).
 */
#include <math.h>

#include "acoustic_tensor.h"

static const double PI = 3.14159265358979323846;

void acoustic_elastic_tangent(double E, double nu, PlaneKind plane,
                              double C[3][3])
{
    double mu = E / (2.0 * (1.0 + nu)), lambda;
    if (plane == PLANE_STRAIN)
        lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    else  /* sigma_zz = 0 condensed out: lambda' = E nu / (1 - nu^2) */
        lambda = E * nu / (1.0 - nu * nu);
    double c[3][3] = {{lambda + 2.0 * mu, lambda, 0.0},
                      {lambda, lambda + 2.0 * mu, 0.0},
                      {0.0, 0.0, mu}};
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++)
            C[a][b] = c[a][b];
}

double acoustic_principal_angle(const double s[3])
{
    /* tan 2 phi1 = 2 sxy / (sxx - syy), the branch that gives sigma_1 */
    double phi = 0.5 * atan2(2.0 * s[2], s[0] - s[1]);
    return phi < 0.0 ? phi + PI : phi;
}

/// [rankine_tangent]
double acoustic_rankine_tangent(const double C[3][3], const double s[3],
                                double H, double Ct[3][3])
{
    double phi = acoustic_principal_angle(s);
    double c = cos(phi), sn = sin(phi);
    /* m = df/dsigma = n1 (x) n1, strain-like: the shear entry doubled */
    double m[3] = {c * c, sn * sn, 2.0 * c * sn};
    double Cm[3], mC[3], h0 = 0.0;
    for (int a = 0; a < 3; a++) {
        Cm[a] = mC[a] = 0.0;
        for (int b = 0; b < 3; b++) {
            Cm[a] += C[a][b] * m[b];   /* C m: the stress of the flow */
            mC[a] += m[b] * C[b][a];   /* m C: the rate of sigma_1 */
        }
    }
    for (int a = 0; a < 3; a++)
        h0 += m[a] * Cm[a];            /* m : C : m */
    /* d kappa = m C d eps / (h0 + H), d sigma = C (d eps - d kappa m) */
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++)
            Ct[a][b] = C[a][b] - Cm[a] * mC[b] / (h0 + H);
    return h0;
}
/// [rankine_tangent]
