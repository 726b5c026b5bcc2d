/**
 * @file material.c
 * @brief Plane stiffnesses of isotropic linear elasticity.
 */
#include "material.h"

#include <math.h>

void material_prepare(Material *mat, PlaneKind plane)
{
    double E = mat->E, nu = mat->nu;
    mat->c66 = E / (2.0 * (1.0 + nu));
    if (plane == PLANE_STRESS) {
        mat->c11 = E / (1.0 - nu * nu);
        mat->c12 = nu * mat->c11;
        mat->czz = 0.0;
        mat->ezz = -nu / (1.0 - nu);
    } else {
        double lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
        mat->c11 = lambda + 2.0 * mat->c66;
        mat->c12 = lambda;
        mat->czz = lambda;
        mat->ezz = 0.0;
    }
    mat->wave = sqrt(mat->c11 / mat->rho);
}

double material_energy_density(double sxx, double syy, double sxy,
                               double exx, double eyy, double exy)
{
    /* sigma_zz eps_zz = 0 in both plane stress and plane strain */
    return 0.5 * (sxx * exx + syy * eyy + 2.0 * sxy * exy);
}
