/**
 * @file material_contact_read.c
 * @brief The scene's contact between bodies: each body's contact group
 *        (bodies.[k].contact_group, by default its material's name) and
 *        the "contact" section's pairs of groups with their laws.
 */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "material_contact.h"
#include "scene_read.h"

/** The material-contact state, made by the first key that needs it. */
static MaterialContact *material_state(Sim *sim)
{
    MaterialContact *M = sim_state(sim, "material contact");
    if (M)
        return M;
    M = calloc(1, sizeof *M);
    if (!M)
        return NULL;
    if (sim_attach(sim, "material contact", M, material_contact_release)) {
        free(M);
        return NULL;
    }
    return M;
}

int material_group_read(Sim *sim, const config_setting_t *s, int index,
                        SceneReader *r)
{
    const char *name = config_setting_get_string(s);
    if (!name || !name[0] || strlen(name) >= 64)
        return scene_error(r, s, "contact_group", "expected a name (a string "
                           "of 1 to 63 characters)");
    for (const char *c = name; *c; c++)
        if (!isalnum((unsigned char)*c) && *c != '_' && *c != '-')
            return scene_error(r, s, "contact_group", "\"%s\": use letters, "
                               "digits, '_' and '-' only", name);
    MaterialContact *M = material_state(sim);
    if (!M)
        return scene_error(r, s, "contact_group", "out of memory");
    if (index >= M->nbody_group) {
        char (*b)[64] = realloc(M->body_group, sizeof *b * (size_t)(index + 1));
        if (!b)
            return scene_error(r, s, "contact_group", "out of memory");
        memset(b + M->nbody_group, 0, sizeof *b * (size_t)(index + 1 - M->nbody_group));
        M->body_group = b;
        M->nbody_group = index + 1;
    }
    snprintf(M->body_group[index], sizeof M->body_group[index], "%s", name);
    return 0;
}

/** The group of body @p b: its contact_group, or its material's name. */
static const char *group_name(const Sim *sim, const MaterialContact *M, int b)
{
    if (b < M->nbody_group && M->body_group[b][0])
        return M->body_group[b];
    return sim->scene.mat[sim->scene.bodies[b].material].name;
}

/** The index of group @p name, given one (1 ..) when new; 0 when no body
 *  is in it; -1 when there is no room. */
static int group_index(const Sim *sim, MaterialContact *M, const char *name)
{
    int found = 0;
    for (int b = 0; b < sim->scene.nbodies && !found; b++)
        found = strcmp(group_name(sim, M, b), name) == 0;
    if (!found)
        return 0;
    for (int g = 1; g <= M->ngroups; g++)
        if (strcmp(M->name[g], name) == 0)
            return g;
    if (M->ngroups == CONTACT_GROUPS_MAX)
        return -1;
    M->ngroups++;
    snprintf(M->name[M->ngroups], sizeof M->name[0], "%s", name);
    return M->ngroups;
}

/** The two group names of entry @p e's "pair", or -1 with a message. */
static int read_pair(SceneReader *r, const config_setting_t *e,
                     const char *names[2])
{
    const config_setting_t *p = config_setting_get_member(e, "pair");
    if (!p)
        return scene_error(r, e, "pair", "missing (expected pair = "
                           "[\"group\", \"group\"])");
    int type = config_setting_type(p);
    if ((type != CONFIG_TYPE_ARRAY && type != CONFIG_TYPE_LIST) ||
        config_setting_length(p) != 2)
        return scene_error(r, p, "pair", "expected two names [\"group\", \"group\"]");
    for (int k = 0; k < 2; k++) {
        names[k] = config_setting_get_string_elem(p, k);
        if (!names[k])
            return scene_error(r, p, "pair", "expected two names [\"group\", \"group\"]");
    }
    if (strcmp(names[0], names[1]) == 0)
        return scene_error(r, p, "pair", "\"%s\" twice: a group has one "
                           "velocity field, so it cannot contact itself "
                           "(give its bodies contact_group names)", names[0]);
    return 0;
}

const char *const material_contact_keys[] = {"pair", "law", "mu", "detection",
                                             "gap_tolerance", "V_sep",
                                             "V_contact", "normal", NULL};

/// [contact_normal_read]
/** Read entry @p e's "normal" (of law @p law) into @p M (the first
 *  entry's, or the default "gradients", binds the others: the normal is
 *  the node's, one for all pairs). */
static int read_normal(SceneReader *r, const config_setting_t *e, int k,
                       const ContactLaw *law, MaterialContact *M)
{
    const char *name = NULL;
    if (scene_string(r, e, "normal", 0, &name) < 0)
        return -1;
    ContactNormal v = NORMAL_GRADIENTS;
    if (name && strcmp(name, "regression") == 0)
        v = NORMAL_REGRESSION;
    else if (name && strcmp(name, "gradients") != 0)
        return scene_error(r, config_setting_get_member(e, "normal"), "normal",
                           "\"%s\": expected \"gradients\" or \"regression\"",
                           name);
    if (v == NORMAL_REGRESSION && law->detect != DETECT_GAP)
        return scene_error(r, config_setting_get_member(e, "normal"), "normal",
                           "\"regression\" needs detection \"gap\" (the fit "
                           "joins the candidates, and the gap chooses)");
    if (k == 0) {
        M->normal = v;
        const config_setting_t *n = config_setting_get_member(e, "normal");
        M->normal_line = n ? (int)config_setting_source_line(n) : 0;
    }
    else if (v != M->normal)
        return scene_error(r, config_setting_get_member(e, "normal"), "normal",
                           "\"%s\" here but not in the first pair: the normal "
                           "is the node's, one for all pairs", name ? name : "gradients");
    return 0;
}
/// [contact_normal_read]

/// [material_contact_read]
int material_contact_read(Sim *sim, const config_setting_t *s, int index,
                          SceneReader *r)
{
    (void)index;
    if (config_setting_type(s) != CONFIG_TYPE_LIST || config_setting_length(s) < 1)
        return scene_error(r, s, "contact", "expected a list of pairs ( { pair = "
                           "[\"a\", \"b\"]; law = \"frictionless\"; }, ... )");
    MaterialContact *M = material_state(sim);
    int n = config_setting_length(s), nb = sim->scene.nbodies;
    if (!M || !(M->name = calloc(CONTACT_GROUPS_MAX + 1, sizeof *M->name)) ||
        !(M->group_of_body = calloc((size_t)nb, sizeof(int))) ||
        !(M->law = calloc((size_t)(2 * n + 1) * (size_t)(2 * n + 1), sizeof(ContactLaw))))
        return scene_error(r, s, "contact", "out of memory");
    snprintf(M->name[0], sizeof M->name[0], "(groups no pair names)");
    int *gi = calloc((size_t)n * 2, sizeof(int));
    ContactLaw *read = calloc((size_t)n, sizeof(ContactLaw));
    if (!gi || !read) {
        free(gi);
        free(read);
        return scene_error(r, s, "contact", "out of memory");
    }
    int rc = 0;
    for (int k = 0; k < n && !rc; k++) {
        const config_setting_t *e = config_setting_get_elem(s, (unsigned)k);
        const char *names[2];
        if (config_setting_type(e) != CONFIG_TYPE_GROUP) {
            rc = scene_error(r, e, "contact", "entry %d: expected a group "
                             "{ pair = [\"a\", \"b\"]; law = ...; }", k);
            break;
        }
        rc = scene_check_keys(r, e, material_contact_keys) || read_pair(r, e, names) ||
             contact_law_read(r, e, 0, &read[k]) || read_normal(r, e, k, &read[k], M);
        double cell = sim->scene.dx < sim->scene.dy ? sim->scene.dx : sim->scene.dy;
        if (!rc && read[k].detect == DETECT_GAP && !(read[k].gap_tolerance < cell))
            rc = scene_error(r, config_setting_get_member(e, "gap_tolerance"),
                             "gap_tolerance", "%g is not below the cell size %g: a "
                             "gap that wide is contact at a distance (detection "
                             "\"approach\" says so)", read[k].gap_tolerance, cell);
        for (int j = 0; j < 2 && !rc; j++) {
            gi[2 * k + j] = group_index(sim, M, names[j]);
            if (gi[2 * k + j] == 0)
                rc = scene_error(r, config_setting_get_member(e, "pair"), "pair",
                                 "\"%s\" is neither a material of a body nor "
                                 "a body's contact_group", names[j]);
            else if (gi[2 * k + j] < 0)
                rc = scene_error(r, e, "pair", "more than %d contact groups",
                                 CONTACT_GROUPS_MAX);
        }
        for (int j = 0; j < k && !rc; j++)
            if ((gi[2 * j] == gi[2 * k] && gi[2 * j + 1] == gi[2 * k + 1]) ||
                (gi[2 * j] == gi[2 * k + 1] && gi[2 * j + 1] == gi[2 * k]))
                rc = scene_error(r, e, "pair", "the pair \"%s\", \"%s\" is "
                                 "listed twice", names[0], names[1]);
    }
    if (!rc) {
        int G = M->ngroups + 1;
        for (int i = 0; i < G * G; i++)
            M->law[i].kind = CONTACT_BONDED;     /* unlisted: as one field */
        for (int k = 0; k < n; k++) {
            M->law[gi[2 * k] * G + gi[2 * k + 1]] = read[k];
            M->law[gi[2 * k + 1] * G + gi[2 * k]] = read[k];
            M->reach |= read[k].detect == DETECT_GAP;
        }
        for (int b = 0; b < nb; b++)
            for (int g = 1; g < G; g++)
                if (strcmp(group_name(sim, M, b), M->name[g]) == 0)
                    M->group_of_body[b] = g;
        Hooks *h = &sim->hooks;
        if (hooks_on_prepare(h, material_contact_prepare, M) ||
            hooks_on_step(h, SEAM_TASK1_FIELDS, material_key_fields, M) ||
            hooks_on_step(h, SEAM_TASK2_HELD, material_contact_task, M) ||
            hooks_on_step(h, SEAM_TASK2_CONTACT, material_contact_task, M) ||
            hooks_on_step(h, SEAM_TASK4_CONTACT, material_contact_task, M) ||
            hooks_on_step(h, SEAM_TASK6_CONTACT, material_contact_task, M) ||
            hooks_on_history(h, material_contact_history, M) ||
            hooks_on_energy(h, material_contact_energy, M) ||
            hooks_on_checkpoint(h, material_contact_checkpoint, M))
            rc = scene_error(r, s, "contact", "too many subscribers to the "
                             "step's seams");
    }
    free(gi);
    free(read);
    return rc ? -1 : 0;
}
/// [material_contact_read]

void material_contact_release(void *state)
{
    MaterialContact *M = state;
    contact_decision_free(&M->decision);
    free(M->name);
    free(M->body_group);
    free(M->group_of_body);
    free(M->law);
    free(M->cell_groups);
    free(M->mixed);
    free(M->mixed_cell);
    free(M->near);
    free(M->keyed);
    free(M->keyed_list);
    free(M->keyed_end);
    free(M->near_list);
    free(M->near_end);
    free(M->node_work);
    free(M->gx);
    free(M->gy);
    free(M->area);
    free(M->va);
    free(M->lo);
    free(M->hi);
    free(M->cx);
    free(M->cy);
    free(M->fit);
    free(M->fit_pair);
    free(M);
}
