/*
 * Exercise 5.1, "the averaged update, from the energy" (chapter 5): the
 * energy that a stress-update row conserves on the one-point oscillator,
 * how far the true energy strays from it, and the row that keeps it
 * closest, USAVG.  Copy this file, fill in the three functions, and run
 *     make exercise EX=5-usavg/averaged-update SOLUTION=your_copy.c
 * The contracts are in src/5-usavg/usavg_scheme.h; README.md says what to
 * derive and what is checked.
 */
#include "usavg_scheme.h"

#include <math.h>

UpdateScheme usavg_scheme(void)
{
    /* TODO: the share of dt at Task 2, the share at Task 6, and whether
       Task 6 re-extrapolates the new velocities first (stage1.c registers
       USL, MUSL and USF the same way): the shares your derivation picks */
    return (UpdateScheme){"usavg", 0.0, 0.0, 0};
}

double scheme_modified_energy(double a, double theta, double v, double wu)
{
    /* TODO: the quadratic form in (v, wu) that the step of share a
       conserves.  The stub returns the energy itself, which no row
       conserves exactly. */
    (void)a;
    (void)theta;
    return v * v + wu * wu;
}

double scheme_energy_departure(double a, double theta)
{
    /* TODO: max |E/E0 - 1| on the orbit through (v0, 0), exactly (not
       only its leading term in theta). */
    (void)a;
    (void)theta;
    return 0.0;
}
