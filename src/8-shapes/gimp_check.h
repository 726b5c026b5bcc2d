/**
 * @file gimp_check.h
 * @brief What a scene with run.shape = "gimp" may ask for, and the check
 *        that every point's domain stays inside the grid.
 */
#ifndef MPM_GIMP_CHECK_H
#define MPM_GIMP_CHECK_H

#include <stddef.h>

#include "sim.h"

/**
 * @brief SEAM_PREPARE: with run.shape = "gimp", refuse what this stage
 *        does not carry out with it yet (another run.method, keyed
 *        velocity fields: cracks, contact) and a point whose domain is not
 *        inside the grid; subscribe gimp_domains_inside() to Task 7.
 *        Nothing for another shape. @return 0, or -1 with a message.
 */
int gimp_prepare(Sim *sim, void *state, char *err, size_t errlen);

/** @brief SEAM_TASK7: stop the run (Sim::fail) at the first point whose
 *         domain has left the grid. @return 0 or -1. */
int gimp_domains_inside(Sim *sim, void *state, Seam seam);

#endif
