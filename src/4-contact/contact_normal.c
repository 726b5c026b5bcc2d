/**
 * @file contact_normal.c
 * @brief The normal between two bodies' fields at a node, from their mass
 *        gradients (chapter 4, "the normal").
 */
#include <math.h>

#include "contact_law.h"

/// [contact_interface_normal]
int contact_interface_normal(const double ga[2], const double gb[2], double n[2])
{
    /* sum_p m_p grad S_ip = integral of rho grad S_i = the integral of
       S_i n over the body's surface: it points out of the body. The two
       unit vectors are averaged so that each surface counts alike,
       whatever the densities and thicknesses of the bodies. */
    double la = sqrt(ga[0] * ga[0] + ga[1] * ga[1]);
    double lb = sqrt(gb[0] * gb[0] + gb[1] * gb[1]);
    double x = 0.0, y = 0.0;
    if (la > 0) {
        x += ga[0] / la;
        y += ga[1] / la;
    }
    if (lb > 0) {
        x -= gb[0] / lb;
        y -= gb[1] / lb;
    }
    double l = sqrt(x * x + y * y);
    if (!(l > 0))
        return 0;                   /* no direction: no contact */
    n[0] = x / l;
    n[1] = y / l;
    return 1;
}
/// [contact_interface_normal]
