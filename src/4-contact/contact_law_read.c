/**
 * @file contact_law_read.c
 * @brief Reading a contact law from the scene: the keys a crack's contact
 *        and a pair of contact groups share.
 */
#include <string.h>

#include "contact_settings.h"
#include "scene_read.h"

/// [contact_law_read]
int contact_law_read(SceneReader *r, const config_setting_t *s,
                     int volume_test, ContactLaw *out)
{
    const char *law = "frictionless";
    int has_mu, has_sep, has_contact;
    if (scene_string(r, s, "law", 0, &law) < 0 ||
        (has_mu = scene_number(r, s, "mu", 0, 0.0, &out->mu)) < 0 ||
        (has_sep = scene_number(r, s, "V_sep", 0, 0.9, &out->vsep)) < 0 ||
        (has_contact = scene_number(r, s, "V_contact", 0, 1.1, &out->vcontact)) < 0)
        return -1;
    out->volume_test = volume_test || has_sep || has_contact;
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
