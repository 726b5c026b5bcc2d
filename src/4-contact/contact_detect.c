/**
 * @file contact_detect.c
 * @brief Contact detection by relative nodal volume and approach
 *        (section 2.2, eq. 10-12).
 */
#include "contact_law.h"

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
