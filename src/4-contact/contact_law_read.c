/**
 * @file contact_law_read.c
 * @brief Reading a contact law from the scene: the keys a crack's contact
 *        and a pair of contact groups share.
 */
#include <string.h>

#include "contact_settings.h"
#include "scene_read.h"

/// [contact_law_read]
/** Read "detection" into @p out (defaults in contact_law_read()). */
static int read_detection(SceneReader *r, const config_setting_t *s, int crack,
                          int has_volume, ContactLaw *out)
{
    const char *rule = NULL;
    int has_tol = scene_number(r, s, "gap_tolerance", 0, 0.0, &out->gap_tolerance);
    if (has_tol < 0 || scene_string(r, s, "detection", 0, &rule) < 0)
        return -1;
    const config_setting_t *at = config_setting_get_member(s, "detection");
    if (!rule)
        out->detect = has_volume ? DETECT_VOLUME : crack ? DETECT_OPENING : DETECT_GAP;
    else if (strcmp(rule, "opening") == 0 && crack)
        out->detect = DETECT_OPENING;
    else if (strcmp(rule, "volume") == 0)
        out->detect = DETECT_VOLUME;
    else if (strcmp(rule, "approach") == 0)
        out->detect = DETECT_APPROACH;
    else if (strcmp(rule, "gap") == 0 && !crack)
        out->detect = DETECT_GAP;
    else
        return scene_error(r, at, "detection", "\"%s\": expected %s", rule,
                           crack ? "\"opening\", \"volume\" or \"approach\"" :
                           "\"gap\", \"volume\" or \"approach\" (\"opening\" "
                           "is a crack's)");
    if (has_volume && out->detect != DETECT_VOLUME)
        return scene_error(r, at, "detection", "\"%s\" ignores V_sep and "
                           "V_contact (they belong to \"volume\")", rule);
    const config_setting_t *at_tol = config_setting_get_member(s, "gap_tolerance");
    if (has_tol && out->detect != DETECT_GAP)
        return scene_error(r, at_tol, "gap_tolerance", "applies to detection "
                           "\"gap\" only");
    if (!(out->gap_tolerance >= 0))
        return scene_error(r, at_tol, "gap_tolerance", "%g must be >= 0 (a "
                           "length: contact when the gap is at most this)",
                           out->gap_tolerance);
    return 0;
}

int contact_law_read(SceneReader *r, const config_setting_t *s,
                     int crack, ContactLaw *out)
{
    const char *law = "frictionless";
    int has_mu, has_sep, has_contact;
    if (scene_string(r, s, "law", 0, &law) < 0 ||
        (has_mu = scene_number(r, s, "mu", 0, 0.0, &out->mu)) < 0 ||
        (has_sep = scene_number(r, s, "V_sep", 0, 0.9, &out->vsep)) < 0 ||
        (has_contact = scene_number(r, s, "V_contact", 0, 1.1, &out->vcontact)) < 0 ||
        read_detection(r, s, crack, has_sep || has_contact, out))
        return -1;
    const config_setting_t *at_mu = config_setting_get_member(s, "mu");
    if (strcmp(law, "friction") == 0) {
        if (!has_mu)
            return scene_error(r, s, "mu", "missing (law \"friction\" needs "
                               "a coefficient of friction; 0 is frictionless)");
        if (!(out->mu >= 0))
            return scene_error(r, at_mu, "mu", "%g must be >= 0", out->mu);
        out->kind = CONTACT_FRICTION;
    } else if (strcmp(law, "frictionless") == 0 || strcmp(law, "stick") == 0) {
        if (has_mu)
            return scene_error(r, at_mu, "mu", "applies to law \"friction\" "
                               "only (this law is \"%s\")", law);
        out->kind = law[0] == 's' ? CONTACT_STICK : CONTACT_FRICTION;
    } else {
        return scene_error(r, config_setting_get_member(s, "law"), "law",
                           "\"%s\": expected \"frictionless\", \"friction\" "
                           "or \"stick\"", law);
    }
    if (!(out->vsep > 0))
        return scene_error(r, config_setting_get_member(s, "V_sep"), "V_sep",
                           "%g must be > 0", out->vsep);
    if (!(out->vcontact >= out->vsep))
        return scene_error(r, config_setting_get_member(s, "V_contact") ?
                           config_setting_get_member(s, "V_contact") : s,
                           "V_contact", "%g must be >= V_sep (%g)", out->vcontact,
                           out->vsep);
    return 0;
}
/// [contact_law_read]
