/**
 * @file material.h
 * @brief Isotropic linear elasticity in plane stress or plane strain.
 */
#ifndef MPM_MATERIAL_H
#define MPM_MATERIAL_H

/** Two-dimensional idealisation of the third direction. */
typedef enum { PLANE_STRESS = 0, PLANE_STRAIN = 1 } PlaneKind;

/** An isotropic elastic material and its derived plane stiffnesses. */
typedef struct Material {
    char name[64];  /**< name used by bodies in the scene */
    double E;       /**< Young's modulus (MPa) */
    double nu;      /**< Poisson's ratio */
    double rho;     /**< density (g/mm^3) */
    double c11;     /**< plane stiffness d sigma_xx / d eps_xx */
    double c12;     /**< plane stiffness d sigma_xx / d eps_yy */
    double c66;     /**< shear modulus G: d sigma_xy = 2 G d eps_xy */
    double czz;     /**< plane strain: sigma_zz = czz (eps_xx + eps_yy); 0 otherwise */
    double ezz;     /**< plane stress: eps_zz = ezz (eps_xx + eps_yy); 0 otherwise */
    double wave;    /**< fastest (dilatational) plane wave speed sqrt(c11 / rho) */
} Material;

/** @brief Fill the derived stiffnesses and wave speed of @p mat for @p plane. */
void material_prepare(Material *mat, PlaneKind plane);

/**
 * @brief Elastic strain energy density 1/2 sigma : eps of one point,
 *        with the out-of-plane terms of the chosen plane idealisation.
 */
double material_energy_density(double sxx, double syy, double sxy,
                               double exx, double eyy, double exy);

#endif
