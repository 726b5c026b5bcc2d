/**
 * @file shapes_check.h
 * @brief What a scene with run.shape = "gimp" or "cpdi" may ask for, and
 *        the check that every uGIMP domain stays inside the grid.
 */
#ifndef MPM_SHAPES_CHECK_H
#define MPM_SHAPES_CHECK_H

#include <stddef.h>

#include "sim.h"

/**
 * @brief SEAM_PREPARE: with run.shape = "gimp" or "cpdi", refuse what this
 *        stage does not carry out with them (another run.method) and a
 *        point whose domain is not inside the grid; subscribe each shape's Task-7 work. Nothing for
 *        the linear shape. @return 0, or -1 with a message.
 */
int shapes_prepare(Sim *sim, void *state, char *err, size_t errlen);

/** @brief SEAM_TASK7 (uGIMP): stop the run (Sim::fail) at the first point
 *         whose domain has left the grid. @return 0 or -1. */
int gimp_domains_inside(Sim *sim, void *state, Seam seam);

#endif
