/**
 * @file contact_detect.c
 * @brief Contact detection: the paper's relative nodal volume and
 *        approach (section 2.2, eq. 10-12), and the rules of a law (the
 *        gap, the crack's opening, approach alone). Chapter 4's exercise
 *        "contact detection" replaces this file.
 */
#include "contact_law.h"
#include "contact_settings.h"

/// [contact_detected]
int contact_detected(double vrel, double vsep, double vcontact, double dvn)
{
    if (vrel < vsep)
        return 0;                  /* separated */
    if (vrel > vcontact)
        return 1;                  /* in contact */
    return dvn > 0.0;              /* grey zone: only when approaching (eq. 12) */
}
/// [contact_detected]

/// [contact_pair_detected]
int contact_pair_detected(const Grid *g, int a, int b, const double n[2],
                          double vrel, double gap, double dt,
                          const ContactLaw *law)
{
    if (law->kind == CONTACT_BONDED)
        return 1;
    double dvn = (g->px[a] / g->m[a] - g->px[b] / g->m[b]) * n[0] +
                 (g->py[a] / g->m[a] - g->py[b] / g->m[b]) * n[1];
    switch (law->detect) {
    case DETECT_VOLUME:
        return contact_detected(vrel, law->vsep, law->vcontact, dvn);
    case DETECT_GAP:                         /* the gap at the step's end */
        return dvn > 0.0 && gap - dt * dvn <= law->gap_tolerance;
    case DETECT_OPENING:                     /* the opening at the step's end */
        return dvn > 0.0 && gap - dt * dvn <= 0.0;
    default:
        return dvn > 0.0;                    /* approach alone */
    }
}
/// [contact_pair_detected]
