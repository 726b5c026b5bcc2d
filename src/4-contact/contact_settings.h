/**
 * @file contact_settings.h
 * @brief A contact law as a scene states it (for a crack, or for a pair of
 *        contact groups), how it is read, and how it changes the momenta
 *        of two fields at a node: the one adjustment that crack contact and
 *        contact between bodies share (section 2.2, eq. 13-19).
 */
#ifndef MPM_CONTACT_SETTINGS_H
#define MPM_CONTACT_SETTINGS_H

#include <libconfig.h>

#include "grid.h"

struct SceneReader;

/** The contact laws. */
typedef enum ContactLawKind {
    CONTACT_NONE,        /**< no contact: the fields pass (a crack without it) */
    CONTACT_FRICTION,    /**< frictional sliding, mu >= 0 (eq. 14-19) */
    CONTACT_STICK,       /**< stick (eq. 13) while in contact */
    CONTACT_BONDED       /**< always stick, no detection: two groups no pair
                              names move as one field would */
} ContactLawKind;

/** How two fields at a node are found in contact. */
typedef enum ContactDetection {
    DETECT_GAP,          /**< approach and a gap <= gap_tolerance, the gap
                              from the fields' points (bodies' default) */
    DETECT_VOLUME,       /**< the paper's relative volume (eq. 10-12) and
                              approach (chosen by V_sep or V_contact) */
    DETECT_APPROACH,     /**< approach alone (fires at a distance) */
    DETECT_OPENING       /**< approach and a crack opening <= 0, the
                              opening from the two sides' displacements
                              (cracks' default) */
} ContactDetection;

/// [contact_law_settings]
/** A contact law and its detection settings. */
typedef struct ContactLaw {
    ContactLawKind kind; /**< which law */
    double mu;           /**< coefficient of friction (0: frictionless) */
    ContactDetection detect; /**< the detection rule */
    double gap_tolerance; /**< DETECT_GAP: contact when the gap is at most
                              this (length, >= 0; default 0) */
    double vsep;         /**< V_sep: below it, separated (default 0.9) */
    double vcontact;     /**< V_contact: above it, in contact (default 1.1) */
} ContactLaw;
/// [contact_law_settings]

/**
 * @brief Read a law from group @p s: law = "frictionless" | "friction"
 *        (with mu >= 0) | "stick"; detection = "gap" | "opening" |
 *        "volume" | "approach"; gap_tolerance; V_sep, V_contact. The keys of @p s
 *        are not checked here (the caller knows its other keys).
 * @param r            the scene reader (messages name file and line)
 * @param s            the group
 * @param crack        1: a crack's contact (detection "opening",
 *                     "volume" or "approach"; default "opening", or
 *                     "volume" when V_sep or V_contact is given, with 0.9
 *                     and 1.1 for the one not given); 0: a pair of bodies
 *                     ("gap", "volume" or "approach"; default "gap", or
 *                     "volume" when V_sep or V_contact is given)
 * @param out          the law read
 * @return 0, or -1 with a message in @p r.
 */
int contact_law_read(struct SceneReader *r, const config_setting_t *s,
                     int crack, ContactLaw *out);

/**
 * @brief Change the momenta of fields (slots) @p a and @p b, found in
 *        contact, by @p law, with @p n the unit normal from a to b; b gets
 *        exactly minus a's change, so momentum is conserved to round-off.
 * @param g   the grid (momenta and masses of the slots)
 * @param a   slot of field a
 * @param b   slot of field b
 * @param n   unit normal from a to b
 * @param law the pair's contact law
 * @param dp  a's momentum change (out)
 * @return 1 when the fields slide under friction (the change is not
 *         stick's), else 0.
 */
int contact_adjust(Grid *g, int a, int b, const double n[2],
                   const ContactLaw *law, double dp[2]);

/**
 * @brief The work of the friction at Task 4: the tangential part of a's
 *        momentum change @p dp on the relative velocity v_a - v_b the step
 *        started from, (q - dt f) / m, with q the momenta before Task 4's
 *        contact and f the forces of the update (zero for frictionless,
 *        usually < 0). The velocity after the update is no measure: where
 *        a field's mass is tiny, f dt / m is far above any point's speed.
 * @param g  the grid, after the update and before Task 4's contact
 *           changed the forces (q and f as Task 4 left them)
 * @param a  slot of field a
 * @param b  slot of field b
 * @param n  unit normal from a to b
 * @param dp a's momentum change (contact_adjust())
 * @param dt the step
 */
double contact_friction_work(const Grid *g, int a, int b, const double n[2],
                             const double dp[2], double dt);

/**
 * @brief Are fields @p a and @p b in contact? The approach velocity
 *        (v_a - v_b) . n > 0 and, by the law's rule, a @p gap at most the
 *        tolerance or the relative volume @p vrel (eq. 10-12); a bonded
 *        pair always is.
 * @param g    the grid (momenta and masses of the slots)
 * @param a    slot of field a
 * @param b    slot of field b
 * @param n    unit normal from a to b
 * @param vrel relative nodal volume (DETECT_VOLUME)
 * @param gap  the surfaces' separation along @p n at the start of the step
 *             (DETECT_GAP; negative: overlap), or the crack's opening
 *             (DETECT_OPENING)
 * @param dt   the step: the gap the end of the step would have,
 *             gap - dt (v_a - v_b) . n, is tested (Tasks 2 and 4 pass the
 *             step; 0 tests the gap now)
 * @param law  the pair's law
 */
int contact_pair_detected(const Grid *g, int a, int b, const double n[2],
                          double vrel, double gap, double dt,
                          const ContactLaw *law);

#endif
