/**
 * @file material.h
 * @brief Materials and the table of constitutive laws; stage 1 registers
 *        isotropic linear elasticity (Hooke's law) in plane stress or
 *        plane strain.
 */
#ifndef MPM_MATERIAL_H
#define MPM_MATERIAL_H

#include <libconfig.h>

struct SceneReader;
struct MaterialLaw;

/** Parameters a material law added by a later stage may keep. */
#define MATERIAL_PARAMS 8

/** Two-dimensional idealisation of the third direction. */
typedef enum { PLANE_STRESS = 0, PLANE_STRAIN = 1 } PlaneKind;

/** A material: its law, density, and the law's parameters. */
typedef struct Material {
    char name[64];  /**< name used by bodies in the scene */
    const struct MaterialLaw *law; /**< its constitutive law (materials.law) */
    double E;       /**< Young's modulus (MPa) */
    double nu;      /**< Poisson's ratio */
    double rho;     /**< density (g/mm^3) */
    double c11;     /**< plane stiffness d sigma_xx / d eps_xx */
    double c12;     /**< plane stiffness d sigma_xx / d eps_yy */
    double c66;     /**< shear modulus G: d sigma_xy = 2 G d eps_xy */
    double czz;     /**< plane strain: sigma_zz = czz (eps_xx + eps_yy); 0 otherwise */
    double ezz;     /**< plane stress: eps_zz = ezz (eps_xx + eps_yy); 0 otherwise */
    double wave;    /**< fastest (dilatational) plane wave speed sqrt(c11 / rho) */
    double par[MATERIAL_PARAMS]; /**< parameters of other laws */
} Material;

/// [material_law]
/** A row of the constitutive-law table (materials.law = "name"). */
typedef struct MaterialLaw {
    const char *name;              /**< value of materials.law */
    const char *const *keys;       /**< its keys in a material, NULL-ended */
    /** Read and check its keys of material group @p g; 0 or -1. */
    int (*read)(struct SceneReader *r, const config_setting_t *g, Material *m);
    /** Derived constants and Material::wave for the plane idealisation. */
    void (*prepare)(Material *m, PlaneKind plane);
    /** Stress increment for a strain increment (eq. 36): s += ... */
    void (*stress)(const Material *m, double dexx, double deyy, double dexy,
                   double s[3]);
    /** The strain e[3] (xx, yy, tensor xy) that carries stress s[3] from
     *  zero, for a body's initial stress; NULL: the law takes none. */
    void (*strain)(const Material *m, const double s[3], double e[3]);
} MaterialLaw;
/// [material_law]

/** @brief Hooke's law, the row stage 1 registers as "hooke". */
extern const MaterialLaw material_hooke;

/** @brief Fill the derived stiffnesses and wave speed of @p mat for @p plane. */
void material_prepare(Material *mat, PlaneKind plane);

/**
 * @brief Elastic strain energy density 1/2 sigma : eps of one point,
 *        with the out-of-plane terms of the chosen plane idealisation.
 */
double material_energy_density(double sxx, double syy, double sxy,
                               double exx, double eyy, double exy);

#endif
