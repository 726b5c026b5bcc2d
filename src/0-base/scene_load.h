/**
 * @file scene_load.h
 * @brief From a scene file (or text) to a simulation ready to step.
 */
#ifndef MPM_SCENE_LOAD_H
#define MPM_SCENE_LOAD_H

#include "sim.h"

/**
 * @brief Read a scene file, apply "key.path=value" overrides, generate the
 *        points and prepare the grid and the time step. A scene whose
 *        estimated memory exceeds Sim::memory_limit is refused before
 *        anything is allocated for its points and grid.
 * @return 0, or non-zero with a message "file:line: ..." in @p err.
 */
int sim_load_file(Sim *sim, const char *path, int noverrides,
                  char *const *overrides, char *err, size_t errlen);

/** @brief As sim_load_file() for a scene held in a string named @p name. */
int sim_load_string(Sim *sim, const char *text, const char *name,
                    char *err, size_t errlen);

#endif
