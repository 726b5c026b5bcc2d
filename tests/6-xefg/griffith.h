/**
 * @file griffith.h
 * @brief Griffith's inclined centre crack for the stage-6 tests
 *        (scene_centre_crack.c, scene_growth_direction.c): a square XEFG
 *        plate whose edges carry the exact stress of the infinite plate
 *        (griffith_stress(), tests/support/westergaard.h), so that the
 *        finite plate holds the infinite plate's state.
 */
#ifndef MPM_TEST_GRIFFITH_H
#define MPM_TEST_GRIFFITH_H

#include <complex.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "testkit.h"
#include "westergaard.h"

#define HALF 7.5                  /* b: the plate is [-b, b]^2 (mm) */
#define CRACK 1.5                 /* a: half the crack's length (mm) */
#define SPACING 0.375             /* h (mm) */
#define SIGMA 1.0                 /* the remote tension, along y (MPa) */
#define RHO 1e-3                  /* g/mm^3 */

/** The force on edge point (px, py) of the plate: the exact traction of
 *  the edges it lies on (top/bottom when @p top_bottom, left/right when
 *  @p sides), times h (unit thickness). */
static inline void edge_force(double beta, double px, double py,
                              int top_bottom, int sides, double f[2])
{
    double s[3];
    f[0] = f[1] = 0.0;
    if (top_bottom) {                       /* t = sigma . (0, +-1) */
        double ny = py > 0 ? 1.0 : -1.0;
        griffith_stress(SIGMA, beta, CRACK, px, ny * HALF, s);
        f[0] += s[2] * ny * SPACING;
        f[1] += s[1] * ny * SPACING;
    }
    if (sides) {                            /* t = sigma . (+-1, 0) */
        double nx = px > 0 ? 1.0 : -1.0;
        griffith_stress(SIGMA, beta, CRACK, nx * HALF, py, s);
        f[0] += s[0] * nx * SPACING;
        f[1] += s[2] * nx * SPACING;
    }
}

/**
 * The scene text (malloc'd) of the plate [-HALF, HALF]^2, points at
 * spacing SPACING, plane strain, E = 1000 MPa, nu = 0.3, the LEFM tip
 * functions, with the crack of half length CRACK at @p beta through its
 * centre, written from its lower-left tip (or from the other, @p reverse),
 * its edges loaded by Griffith's tractions for SIGMA (one load per edge
 * point, traction x h). @p crack is added to the crack's group (" cohesive
 * = {...};" or ""), @p load to every load (" ramp = 1.0;" or "").
 */
static inline char *griffith_plate(double beta, int reverse, double time,
                                   double damping, const char *crack,
                                   const char *load)
{
    int n = (int)(HALF / SPACING + 0.5);            /* points per half side */
    double h = SPACING, ca = CRACK * cos(beta), sa = CRACK * sin(beta);
    double sgn = reverse ? -1.0 : 1.0;
    Text t = {malloc(4096), 0, 4096};
    assert_non_null(t.s);
    /* points sit at cell centres, the body's edge h/2 beyond the outermost;
     * the crack's middle is a cell corner */
    text_add(&t,
             "grid = { origin = [%#.17g, %#.17g]; cells = [%d, %d]; cell_size = [%#.17g, %#.17g]; };\n"
             "run = { time = %#.17g; method = \"xefg\"; snapshots = 0; plane = \"strain\";\n"
             "        damping = %#.17g; };\n"
             "materials = ( { name = \"m\"; E = 1000.0; nu = 0.3; rho = %#.17g; } );\n"
             "bodies = ( { name = \"plate\"; material = \"m\"; points_per_cell = 1;\n"
             "             rectangle = { min = [%#.17g, %#.17g]; max = [%#.17g, %#.17g]; }; } );\n"
             "xefg = { tip = \"lefm\"; };\n"
             "cracks = ( { points = ( [%#.17g, %#.17g], [%#.17g, %#.17g] );%s } );\n"
             "loads = (\n",
             -HALF - h, -HALF - h, 2 * n + 2, 2 * n + 2, h, h, time, damping, RHO,
             -HALF, -HALF, HALF, HALF, -sgn * ca, -sgn * sa, sgn * ca, sgn * sa,
             crack);
    const char *sep = "  ";
    for (int i = 0; i < 2 * n; i++)
        for (int j = 0; j < 2 * n; j++) {
            int tb = j == 0 || j == 2 * n - 1, lr = i == 0 || i == 2 * n - 1;
            if (!tb && !lr)
                continue;
            double px = -HALF + (i + 0.5) * h, py = -HALF + (j + 0.5) * h, f[2];
            edge_force(beta, px, py, tb, lr, f);
            text_add(&t, "%s{ rectangle = { min = [%#.17g, %#.17g]; max = [%#.17g, %#.17g]; };\n"
                     "    force = [%#.17g, %#.17g];%s }\n", sep, px - 0.25 * h,
                     py - 0.25 * h, px + 0.25 * h, py + 0.25 * h, f[0], f[1],
                     load);
            sep = ", ";
        }
    text_add(&t, ");\n");
    return t.s;
}

#endif
