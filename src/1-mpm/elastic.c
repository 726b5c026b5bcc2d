/**
 * @file elastic.c
 * @brief Hooke's law in the plane (chapter 1, exercise "Hooke's law"
 *        replaces this file).
 */
#include "step.h"

/// [elastic_stress_increment]
void elastic_stress_increment(const Material *mat, double dexx, double deyy,
                              double dexy, double s[3])
{
    s[0] += mat->c11 * dexx + mat->c12 * deyy;
    s[1] += mat->c12 * dexx + mat->c11 * deyy;
    s[2] += 2.0 * mat->c66 * dexy;
}
/// [elastic_stress_increment]
