/*
 * Exercise "Hooke's law" (chapter 1): the elastic stress increment in the
 * plane.  Copy this file, fill in elastic_stress_increment(), and run
 *     make exercise EX=1-mpm/hookes-law SOLUTION=your_copy.c
 * The contract is in src/1-mpm/step.h; the stiffnesses c11, c12, c66 that
 * material_prepare() fills are described in src/1-mpm/material.h.
 */
#include "step.h"

void elastic_stress_increment(const Material *mat, double dexx, double deyy,
                              double dexy, double s[3])
{
    /* TODO: add d sigma = C d eps to s[0] (xx), s[1] (yy) and s[2] (xy).
     * dexy is the tensor shear strain (half the engineering gamma_xy).
     * This stub adds nothing, so the stress never changes and the tests
     * fail until you write it. */
    (void)mat;
    (void)dexx;
    (void)deyy;
    (void)dexy;
    (void)s;
}
