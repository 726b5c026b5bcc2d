/**
 * @file growth_read.c
 * @brief A cohesive crack's `growth` group (cracks.[k].cohesive.growth,
 *        read by cohesive_read()), checked on input: the length of a new
 *        segment and the most segments the crack may add. It sits in the
 *        law's group, so a growing crack has a law (growth_build() checks
 *        again at set-up); and where a tip grows, direction = "hoop"
 *        (the default: the largest hoop stress of K_I, K_II) or
 *        "principal" (normal to sigma_1); and when, criterion = "average"
 *        (the default) or "tip" (growth_tip_zone()); and how fast at
 *        most, max_speed (growth_after_step()); and over how far ahead
 *        criterion = "average" averages, radius. CRAMP's
 *        `cracks.[k].growth` is stage 7's.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "growth.h"
#include "scene_read.h"

const char *const growth_keys[] = {"length", "max_segments", "direction",
                                   "criterion", "max_speed", "radius", NULL};

static void growth_release(void *state)
{
    growth_free(state);
    free(state);
}

/** The state of @p sim with room for crack @p index, made when missing. */
static Growth *growth_make(Sim *sim, int index)
{
    Growth *g = growth_of(sim);
    if (!g) {
        if (!(g = calloc(1, sizeof *g)))
            return NULL;
        if (sim_attach(sim, "xefg growth", g, growth_release)) {
            free(g);
            return NULL;
        }
        /* subscribed here, before the parameters' section is
         * (xefg_prepare()): at restore the events are replayed first */
        if (hooks_on_checkpoint(&sim->hooks, growth_checkpoint, g))
            return NULL;
    }
    if (index >= g->ncrack) {
        XefgGrowthSettings *s = realloc(g->set, sizeof *s * (size_t)(index + 1));
        if (!s)
            return NULL;
        memset(s + g->ncrack, 0, sizeof *s * (size_t)(index + 1 - g->ncrack));
        g->set = s;
        g->ncrack = index + 1;
    }
    return g;
}

/** The member @p key of @p s, or @p s when it is absent (for a line). */
static const config_setting_t *at(const config_setting_t *s, const char *key)
{
    const config_setting_t *m = config_setting_get_member(s, key);
    return m ? m : s;
}

/// [growth_read]
int growth_read(Sim *sim, const config_setting_t *s, int index,
                SceneReader *r)
{
    if (config_setting_type(s) != CONFIG_TYPE_GROUP)
        return scene_error(r, s, "growth", "expected a group { length = 0.5; "
                           "max_segments = 20; direction = \"hoop\"; } (all "
                           "optional)");
    if (scene_check_keys(r, s, growth_keys))
        return -1;
    Growth *g = growth_make(sim, index);
    if (!g)
        return scene_error(r, s, "growth", "out of memory");
    XefgGrowthSettings *set = &g->set[index];
    double length = 0.0, most = 0.0, speed = 0.0, radius = 0.0;
    const char *direction = "hoop", *criterion = "average";
    *set = (XefgGrowthSettings){.on = 1,
                                .line = (int)config_setting_source_line(s)};
    int has_length = scene_number(r, s, "length", 0, 0.0, &length);
    int has_most = scene_number(r, s, "max_segments", 0, 0.0, &most);
    int has_speed = scene_number(r, s, "max_speed", 0, 0.0, &speed);
    int has_radius = scene_number(r, s, "radius", 0, 0.0, &radius);
    if (has_length < 0 || has_most < 0 || has_speed < 0 || has_radius < 0 ||
        scene_string(r, s, "direction", 0, &direction) < 0 ||
        scene_string(r, s, "criterion", 0, &criterion) < 0)
        return -1;
    if (strcmp(criterion, "tip") == 0)
        set->tip = 1;
    else if (strcmp(criterion, "average") != 0)
        return scene_error(r, at(s, "criterion"), "criterion", "\"%s\": "
                           "expected \"average\" (the default: sigma_1 "
                           "averaged over a half disk ahead of the tip) or "
                           "\"tip\" "
                           "(the cohesive zone's own tip reaches the last "
                           "segment)", criterion);
    if (strcmp(direction, "hoop") == 0)
        set->hoop = 1;
    else if (strcmp(direction, "principal") != 0)
        return scene_error(r, at(s, "direction"), "direction", "\"%s\": "
                           "expected \"hoop\" (the default: the largest hoop "
                           "stress of K_I, K_II at the tip) or \"principal\" "
                           "(normal to sigma_1)", direction);
    if (has_length && !(length > 0.0 && isfinite(length)))
        return scene_error(r, at(s, "length"), "length", "%g: the length of a "
                           "new segment must be positive (leave it out for "
                           "one node spacing)", length);
    if (has_most && !(most >= 1.0 && most <= 100000.0 && most == floor(most)))
        return scene_error(r, at(s, "max_segments"), "max_segments", "%g: the "
                           "most segments a crack may add must be a whole "
                           "number from 1 to 100000 (room for them is kept "
                           "at set-up)", most);
    if (has_speed && !(speed > 0.0 && isfinite(speed)))
        return scene_error(r, at(s, "max_speed"), "max_speed", "%g: the "
                           "largest speed of a tip must be positive (leave "
                           "it out for no limit)", speed);
    if (has_radius && !(radius > 0.0 && isfinite(radius)))
        return scene_error(r, at(s, "radius"), "radius", "%g: the radius of "
                           "the half disk ahead of a tip whose stress is "
                           "averaged must be positive (leave it out for "
                           "L / 2 of the material, within 0.5 to 1.5 node "
                           "spacings)", radius);
    if (has_radius && set->tip)
        return scene_error(r, at(s, "radius"), "radius", "%g: criterion = "
                           "\"tip\" averages nothing (the radius is the "
                           "half disk of criterion = \"average\")", radius);
    set->length = length;
    set->radius = radius;
    set->max_segments = (int)most;
    set->max_speed = speed;
    return 0;
}
/// [growth_read]
