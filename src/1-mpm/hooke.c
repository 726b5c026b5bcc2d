/**
 * @file hooke.c
 * @brief Hooke's law as a row of the constitutive-law table: its keys E
 *        and nu, their physical ranges, its stiffnesses and its stress
 *        increment (elastic.c).
 */
#include "material.h"
#include "scene_read.h"
#include "step.h"

/** Read E and nu of material group @p g and check their ranges. */
static int hooke_read(SceneReader *r, const config_setting_t *g, Material *m)
{
    if (scene_number(r, g, "E", 1, 0, &m->E) < 0 ||
        scene_number(r, g, "nu", 1, 0, &m->nu) < 0)
        return -1;
    if (!(m->E > 0))
        return scene_error(r, config_setting_get_member(g, "E"), "E",
                           "%g: Young's modulus must be > 0", m->E);
    if (!(m->nu > -1 && m->nu < 0.5))
        return scene_error(r, config_setting_get_member(g, "nu"), "nu",
                           "%g: Poisson's ratio must lie in (-1, 0.5)", m->nu);
    return 0;
}

/** The strain of stress @p s (the inverse of the plane stiffness). */
static void hooke_strain(const Material *m, const double s[3], double e[3])
{
    double det = m->c11 * m->c11 - m->c12 * m->c12;
    e[0] = (m->c11 * s[0] - m->c12 * s[1]) / det;
    e[1] = (m->c11 * s[1] - m->c12 * s[0]) / det;
    e[2] = s[2] / (2.0 * m->c66);
}

/** Keys of Hooke's law in a material. */
static const char *const hooke_keys[] = {"E", "nu", NULL};

/// [material_hooke]
const MaterialLaw material_hooke = {
    "hooke", hooke_keys, hooke_read, material_prepare, elastic_stress_increment,
    hooke_strain,
};
/// [material_hooke]
