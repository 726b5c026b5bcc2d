/**
 * @file stage1.c
 * @brief Stage 1 registers the MPM step, Hooke's law and the three
 *        classical stress-update schemes.
 */
#include "stage1.h"

#include "shape.h"
#include "sim.h"

/** The MPM step of the Appendix (Tasks 0-8): the method "mpm"; it runs
 *  every seam of the step and reads every setting. */
static const Method mpm_method = {"mpm", sim_step, NULL, SEAMS_OF_STEP, NULL,
                                  NULL};

/** The paper's bilinear shape functions (Appendix): run.shape "linear",
 *  computed inline by stencil_of_point(), so no stencil function. */
static const ShapeFunctions shape_linear_row = {"linear", STENCIL_NODES, NULL};

/// [stage1_install]
void stage1_install(Hooks *h)
{
    hooks_add_choice(h, "run.method", "mpm", &mpm_method);
    hooks_add_choice(h, "materials.law", "hooke", &material_hooke);
    hooks_add_choice(h, "run.shape", "linear", &shape_linear_row);
    /*                   name    Task 2  Task 6  re-extrapolate (Task 6c) */
    hooks_add_scheme(h, "usl",  0.0,    1.0,    0);  /* Sulsky et al. 1994 */
    hooks_add_scheme(h, "musl", 0.0,    1.0,    1);  /* Sulsky et al. 1995 */
    hooks_add_scheme(h, "usf",  1.0,    0.0,    0);  /* Bardenhagen 2002 */
}
/// [stage1_install]
