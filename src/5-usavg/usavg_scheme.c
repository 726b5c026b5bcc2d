/**
 * @file usavg_scheme.c
 * @brief The USAVG row of the update-scheme table (section 2.3), and why
 *        its shares are a half each: the energy that a row's step conserves
 *        on the one-point oscillator (exercise 5.1,
 *        exercises/5-usavg/averaged-update).
 *
 * With y = (v, omega u) and theta = omega dt, the row of share a is the
 * drift D(a theta), the kick K(theta), the drift D((1 - a) theta), where
 * D(t): omega u += t v and K(t): v -= t omega u. MUSL (a = 0) is K then
 * D(theta), symplectic Euler, which conserves Q = v^2 + (omega u)^2 -
 * theta v omega u (det 1; chapter 1's test_oscillator.c has its trace).
 * The row of share a is D(a theta)^-1 MUSL D(a theta), so it conserves
 * Q(D(a theta) y), the form below. Its cross term, first order in theta,
 * vanishes only at a = 1/2: the symmetric composition of USF's and MUSL's
 * half steps, Stoermer-Verlet, whose energy error is second order.
 */
#include "usavg_scheme.h"

#include <math.h>

/// [usavg_scheme]
UpdateScheme usavg_scheme(void)
{
    /* half of dt at Task 2 from the start-of-step momenta (USF's), half at
       Task 6 from the re-extrapolated new velocities (MUSL's), eq. 31 */
    return (UpdateScheme){"usavg", 0.5, 0.5, 1};
}
/// [usavg_scheme]

double scheme_modified_energy(double a, double theta, double v, double wu)
{
    return (1.0 - a * (1.0 - a) * theta * theta) * v * v + wu * wu
           + (2.0 * a - 1.0) * theta * v * wu;
}

double scheme_energy_departure(double a, double theta)
{
    /* On the ellipse y^T B y = H0 (B the form above, H0 its value at the
     * start (1, 0), where E0 = 1), E = |y|^2 lies between H0 / lambda_max
     * and H0 / lambda_min, B's eigenvalues: trace 2 - c theta^2 and
     * determinant 1 - theta^2 / 4 for every a, with c = a (1 - a). */
    double c = a * (1.0 - a), t2 = theta * theta;
    double h0 = 1.0 - c * t2;
    double root = theta * sqrt((1.0 - 2.0 * a) * (1.0 - 2.0 * a) + c * c * t2);
    double lo = 0.5 * (2.0 - c * t2 - root), hi = 0.5 * (2.0 - c * t2 + root);
    return fmax(h0 / lo - 1.0, 1.0 - h0 / hi);
}
