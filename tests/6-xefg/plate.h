/**
 * @file plate.h
 * @brief The stage-6 tests' plate: 10 x 6 nodes at spacing 1 (the cells
 *        [1, 11] x [1, 7], one point per cell), run by XEFG.
 */
#ifndef MPM_TEST_PLATE_H
#define MPM_TEST_PLATE_H

#include <stdio.h>

#include "testkit.h"

/** @brief Load the plate with @p extra scene text (a crack, settings). */
static inline Sim *plate(const char *extra)
{
    char text[4096];
    snprintf(text, sizeof text,
             "grid = { origin = [0.0, 0.0]; cells = [12, 8]; cell_size = [1.0, 1.0]; };\n"
             "run = { time = 0.01; method = \"xefg\"; snapshots = 0; };\n"
             "materials = ( { name = \"m\"; E = 1000.0; nu = 0.3; rho = 1e-3; } );\n"
             "bodies = ( { name = \"plate\"; material = \"m\"; points_per_cell = 1;\n"
             "             rectangle = { min = [1.0, 1.0]; max = [11.0, 7.0]; }; } );\n"
             "%s\n", extra);
    return tk_load(text);
}

#endif
