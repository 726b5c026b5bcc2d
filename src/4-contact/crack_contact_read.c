/**
 * @file crack_contact_read.c
 * @brief The scene's per-crack contact settings (cracks.[k].contact) and
 *        the hooks stage 4 subscribes when a crack has contact.
 */
#include <stdlib.h>
#include <string.h>

#include "crack_contact.h"
#include "scene_read.h"

/** Stage 4's crack-contact state, made (and subscribed) by the first
 *  crack that has contact; NULL when out of memory or seams. */
static ContactState *contact_state(Sim *sim)
{
    ContactState *S = sim_state(sim, "crack contact");
    if (S)
        return S;
    S = calloc(1, sizeof *S);
    if (!S)
        return NULL;
    if (sim_attach(sim, "crack contact", S, crack_contact_release)) {
        free(S);
        return NULL;
    }
    Hooks *h = &sim->hooks;
    if (hooks_on_prepare(h, crack_contact_prepare, S) ||
        hooks_on_step(h, SEAM_TASK2_HELD, crack_contact_task, S) ||
        hooks_on_step(h, SEAM_TASK2_CONTACT, crack_contact_task, S) ||
        hooks_on_step(h, SEAM_TASK4_CONTACT, crack_contact_task, S) ||
        hooks_on_step(h, SEAM_TASK6_CONTACT, crack_contact_task, S) ||
        hooks_on_history(h, crack_contact_history, S) ||
        hooks_on_energy(h, crack_contact_energy, S) ||
        hooks_on_checkpoint(h, crack_contact_checkpoint, S))
        return NULL;
    return S;
}

const char *const crack_contact_keys[] = {"law", "mu", "detection", "V_sep",
                                          "V_contact", NULL};

/// [crack_contact_read]
int crack_contact_read(Sim *sim, const config_setting_t *s, int index,
                       SceneReader *r)
{
    if (config_setting_type(s) != CONFIG_TYPE_GROUP)
        return scene_error(r, s, "contact", "expected a group { law = "
                           "\"frictionless\" | \"friction\" | \"stick\"; ... }");
    ContactState *S = contact_state(sim);
    if (!S)
        return scene_error(r, s, "contact", "out of memory");
    if (index >= S->ncracks) {
        CrackContact *c = realloc(S->crack, sizeof *c * (size_t)(index + 1));
        if (!c)
            return scene_error(r, s, "contact", "out of memory");
        memset(c + S->ncracks, 0, sizeof *c * (size_t)(index + 1 - S->ncracks));
        S->crack = c;
        S->ncracks = index + 1;
    }
    CrackContact *c = &S->crack[index];
    c->line = (int)config_setting_source_line(s);
    return scene_check_keys(r, s, crack_contact_keys) || contact_law_read(r, s, 1, &c->law);
}
/// [crack_contact_read]

void crack_contact_release(void *state)
{
    ContactState *S = state;
    free(S->crack);
    crack_normals_free(&S->normals);
    free(S->vnode);
    free(S->node_work);
    free(S->x0);
    free(S->y0);
    free(S->ux);
    free(S->uy);
    contact_decision_free(&S->decision);
    free(S);
}
