/*
 * Exercise "contact detection" (chapter 4): when are two fields at a node
 * in contact? Copy this file, fill in contact_pair_detected(), and run
 *     make exercise EX=4-contact/contact-detection SOLUTION=your_copy.c
 * The contracts are in src/4-contact/contact_law.h and
 * src/4-contact/contact_settings.h; README.md says what is checked.
 */
#include "contact_law.h"
#include "contact_settings.h"

/* The paper's relative-volume rule (eq. 10-12), given. */
int contact_detected(double vrel, double vsep, double vcontact, double dvn)
{
    if (vrel < vsep)
        return 0;
    if (vrel > vcontact)
        return 1;
    return dvn > 0.0;
}

int contact_pair_detected(const Grid *g, int a, int b, const double n[2],
                          double vrel, double gap, double dt,
                          const ContactLaw *law)
{
    if (law->kind == CONTACT_BONDED)
        return 1;
    double dvn = (g->px[a] / g->m[a] - g->px[b] / g->m[b]) * n[0] +
                 (g->py[a] / g->m[a] - g->py[b] / g->m[b]) * n[1];
    if (law->detect == DETECT_VOLUME)
        return contact_detected(vrel, law->vsep, law->vcontact, dvn);
    /* TODO: approach alone is stage 4's first rule. Use the gap (bodies)
       and the opening (cracks) too, as they will be at the step's end. */
    (void)gap;
    (void)dt;
    return dvn > 0.0;
}
