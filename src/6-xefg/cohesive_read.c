/**
 * @file cohesive_read.c
 * @brief A crack's `cohesive` group (cracks.[k].cohesive), read and checked
 *        on input: the law, its strength, its fracture energy, its penalty
 *        and its shear weight.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cohesive.h"
#include "scene_read.h"

const char *const cohesive_keys[] = {"law", "f_t", "G_f", "penalty", "shear",
                                     "notch_segments", NULL};

static void cohesive_release(void *state)
{
    cohesive_free(state);
    free(state);
}

/** The state of @p sim with room for crack @p index, made when missing. */
static Cohesive *cohesive_make(Sim *sim, int index)
{
    Cohesive *c = cohesive_of(sim);
    if (!c) {
        if (!(c = calloc(1, sizeof *c)))
            return NULL;
        if (sim_attach(sim, "xefg cohesive", c, cohesive_release)) {
            free(c);
            return NULL;
        }
    }
    if (index >= c->ncrack) {
        CohesiveSettings *s = realloc(c->set, sizeof *s * (size_t)(index + 1));
        if (!s)
            return NULL;
        memset(s + c->ncrack, 0, sizeof *s * (size_t)(index + 1 - c->ncrack));
        c->set = s;
        c->ncrack = index + 1;
    }
    return c;
}

/** The member @p key of @p s, or @p s when it is absent (for a line). */
static const config_setting_t *at(const config_setting_t *s, const char *key)
{
    const config_setting_t *m = config_setting_get_member(s, key);
    return m ? m : s;
}

/// [cohesive_read]
int cohesive_read(Sim *sim, const config_setting_t *s, int index,
                  SceneReader *r)
{
    if (config_setting_type(s) != CONFIG_TYPE_GROUP)
        return scene_error(r, s, "cohesive", "expected a group { law = "
                           "\"linear\"; f_t = 3.0; G_f = 0.1; }");
    if (scene_check_open_keys(r, &sim->hooks, "cracks.cohesive", s,
                              cohesive_keys, NULL))
        return -1;
    Cohesive *c = cohesive_make(sim, index);
    if (!c)
        return scene_error(r, s, "cohesive", "out of memory");
    const Units *u = sim->scene.run.units ? sim->scene.run.units : units_default();
    CohesiveSettings *set = &c->set[index];
    CohesiveLaw *L = &set->law;
    const char *law = "linear";
    double notch = 0.0;
    *set = (CohesiveSettings){1, {COHESIVE_LINEAR, 0, 0, 0, 0}, 0,
                              (int)config_setting_source_line(s)};
    if (scene_string(r, s, "law", 0, &law) < 0 ||
        scene_number(r, s, "f_t", 1, 0.0, &L->f_t) < 0 ||
        scene_number(r, s, "G_f", 1, 0.0, &L->G_f) < 0 ||
        scene_number(r, s, "penalty", 0, 0.0, &L->K) < 0 ||
        scene_number(r, s, "shear", 0, 0.0, &L->beta) < 0 ||
        scene_number(r, s, "notch_segments", 0, 0.0, &notch) < 0)
        return -1;
    if (!(notch >= 0.0 && notch <= 1e6 && notch == floor(notch)))
        return scene_error(r, at(s, "notch_segments"), "notch_segments",
                           "%g: the number of the crack's first segments "
                           "left traction-free (a notch) must be a whole "
                           "number >= 0", notch);
    set->notch = (int)notch;
    if (strcmp(law, "linear") == 0)
        L->kind = COHESIVE_LINEAR;
    else if (strcmp(law, "exponential") == 0)
        L->kind = COHESIVE_EXPONENTIAL;
    else
        return scene_error(r, at(s, "law"), "law", "\"%s\": expected \"linear\" "
                           "(f_t (1 - delta / delta_c), delta_c = 2 G_f / f_t) "
                           "or \"exponential\" (f_t exp(-f_t delta / G_f))", law);
    if (!(L->f_t > 0.0))
        return scene_error(r, at(s, "f_t"), "f_t", "%g: the tensile strength "
                           "(%s) must be positive", L->f_t, u->stress);
    if (!(L->G_f > 0.0))
        return scene_error(r, at(s, "G_f"), "G_f", "%g: the fracture energy "
                           "(%s/%s^2) must be positive", L->G_f, u->energy,
                           u->length);
    if (config_setting_get_member(s, "penalty") &&
        !(L->K > L->f_t * L->f_t / (2.0 * L->G_f)))
        return scene_error(r, at(s, "penalty"), "penalty", "%g: the penalty "
                           "stiffness (%s/%s) must exceed f_t^2 / (2 G_f) = %g, "
                           "for the elastic branch to hold less than G_f (ten "
                           "or more times that is usual; leave it out for the "
                           "default 10 E / h)", L->K, u->stress, u->length,
                           L->f_t * L->f_t / (2.0 * L->G_f));
    if (!(L->beta >= 0.0))
        return scene_error(r, at(s, "shear"), "shear", "%g: the weight of "
                           "sliding in the effective opening must be >= 0 "
                           "(0: normal opening alone)", L->beta);
    /* keys registered in the law's group: growth (growth.h) */
    if (scene_read_open_keys(sim, r, "cracks.cohesive", s, index))
        return -1;
    return 0;
}
/// [cohesive_read]
