/**
 * @file setup.h
 * @brief Steps that turn a read scene into a simulation ready to run.
 */
#ifndef MPM_SETUP_H
#define MPM_SETUP_H

#include <stddef.h>

#include "sim.h"

/** @brief Generate the material points of every body. @return 0 or -1. */
int setup_points(Sim *sim, char *err, size_t errlen);

/** @brief Allocate the grid (one field slot per node; the field table
 *         adds more when a step needs them) and mark the fixed nodes.
 *  @return 0 or -1. */
int setup_grid(Sim *sim, char *err, size_t errlen);

/** @brief Find the points each load acts on. @return 0 or -1. */
int setup_loads(Sim *sim, char *err, size_t errlen);

/** @brief Select the points of each point_velocities box and give them its
 *         velocity at t = 0. @return 0, or -1 with a message (a box that
 *         holds no point, out of memory) in @p err. */
int setup_held_points(Sim *sim, char *err, size_t errlen);

/** @brief Refuse a scene whose points' energies or momentum, the sums
 *         history.csv writes, are not finite at t = 0, naming the body.
 *  @return 0, or -1 with a message in @p err. */
int setup_check_totals(const Sim *sim, char *err, size_t errlen);

#endif
