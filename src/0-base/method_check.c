/**
 * @file method_check.c
 * @brief Set-up's check that the scene's method runs every seam the
 *        scene's keys subscribed to and reads every setting it was given.
 */
#include "method_check.h"

#include <stdio.h>
#include <string.h>

/** Is @p name in the NULL-ended @p list (which may be NULL)? */
static int listed(const char *const *list, const char *name)
{
    for (const char *const *a = list; a && *a; a++)
        if (strcmp(*a, name) == 0)
            return 1;
    return 0;
}

/** "cracks.contact" of @p k into @p buf. */
static const char *key_path(KeyAt k, char *buf, size_t len)
{
    snprintf(buf, len, "%s%s%s", k.section, k.section[0] ? "." : "", k.key);
    return buf;
}

/** The step seams of @p mask into @p buf: "Task 2 contact, ...". */
static const char *seam_names(unsigned mask, char *buf, size_t len)
{
    static const struct { Seam seam; const char *name; } names[] = {
        {SEAM_TASK1_FIELDS, "Task 1 fields"},
        {SEAM_TASK2_HELD, "Task 2 held contact"},
        {SEAM_TASK2_CONTACT, "Task 2 contact"},
        {SEAM_TASK4_CONTACT, "Task 4 contact"},
        {SEAM_TASK6_CONTACT, "Task 6 contact"},
        {SEAM_TASK7, "Task 7 crack motion"},
    };
    buf[0] = '\0';
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++)
        if (mask & SEAM_BIT(names[k].seam))
            snprintf(buf + strlen(buf), len - strlen(buf), "%s%s",
                     buf[0] ? ", " : "", names[k].name);
    return buf;
}

/** The methods of this build that run the seams @p mask and read @p key
 *  (NULL: any), quoted, into @p buf. */
static const char *methods_that(const Hooks *h, unsigned mask, const char *key,
                                char *buf, size_t len)
{
    buf[0] = '\0';
    for (int k = 0; k < h->nchoices; k++) {
        const Method *m = h->choices[k].impl;
        if (strcmp(h->choices[k].key, "run.method") != 0 ||
            (m->seams & mask) != mask || (key && !method_reads(m, key)))
            continue;
        snprintf(buf + strlen(buf), len - strlen(buf), "%s\"%s\"",
                 buf[0] ? " or " : "", m->name);
    }
    return buf;
}

/** Did one reading of one key (or, with no key, one stage) ask for both? */
static int same_asker(const Subscriber *a, const Subscriber *b)
{
    if (a->rank != b->rank || !a->by.key || !b->by.key)
        return a->rank == b->rank && a->by.key == b->by.key;
    return a->by.line == b->by.line && strcmp(a->by.section, b->by.section) == 0 &&
           strcmp(a->by.key, b->by.key) == 0;
}

/** The step seams that @p sub's asker subscribed to and @p m does not
 *  run; none when @p m carries that key out itself. */
static unsigned skipped_for(const Hooks *h, const Method *m, const Subscriber *sub)
{
    char path[128];
    if (sub->by.key && listed(m->own_keys, key_path(sub->by, path, sizeof path)))
        return 0;
    unsigned mask = 0;
    for (int s = 0; s < SEAM_COUNT; s++) {
        if (!(SEAMS_OF_STEP & SEAM_BIT(s)) || (m->seams & SEAM_BIT(s)))
            continue;
        for (int k = 0; k < h->seam[s].n; k++)
            if (same_asker(&h->seam[s].at[k], sub))
                mask |= SEAM_BIT(s);
    }
    return mask;
}

/** Has a subscriber before (@p seam, @p k), in seam order, the same asker? */
static int named_before(const Hooks *h, int seam, int k)
{
    for (int s = 0; s <= seam; s++)
        for (int j = 0; j < (s < seam ? h->seam[s].n : k); j++)
            if (same_asker(&h->seam[s].at[j], &h->seam[seam].at[k]))
                return 1;
    return 0;
}

/** Where @p s was asked for, into @p buf: as a message begins ("file:line:
 *  key") when @p lead, else "key at file:line"; a stage's own subscriber
 *  is named by its stage, a key set on the command line by its file. */
static const char *asker_at(const Sim *sim, const Subscriber *s, int lead,
                            char *buf, size_t len)
{
    char at[SCENE_AT_LEN], path[160];
    snprintf(at, sizeof at, "%s", sim->scene.file);
    if (!s->by.key)
        snprintf(path, sizeof path, "stage %d", s->rank);
    else if (s->by.line > 0) {
        scene_lines_at(sim->scene.lines, sim->scene.file, s->by.line, at,
                       sizeof at);
        key_path(s->by, path, sizeof path);
    } else {
        key_path(s->by, path, sizeof path);
        strncat(path, " (set on the command line)", sizeof path - strlen(path) - 1);
    }
    if (lead)
        snprintf(buf, len, "%s: %s", at, path);
    else
        snprintf(buf, len, "%s at %s", path, at);
    return buf;
}

/** The message's first part: @p who asked for @p mask, which @p m skips,
 *  and what to do instead. */
static void refuse_first(const Hooks *h, const Method *m, const Subscriber *sub,
                         unsigned mask, const char *who, SceneReader *r)
{
    char seams[128], others[128];
    methods_that(h, mask, NULL, others, sizeof others);
    const char *fix = others[0] ?
        (sub->by.key ? ": remove it, or choose run.method = " :
                       ": choose run.method = ") :
        (sub->by.key ? ": remove it" : "");
    snprintf(r->err, r->errlen, "%s: run.method \"%s\" does not run the seams "
             "where it acts (%s), so it would be ignored%s%s", who, m->name,
             seam_names(mask, seams, sizeof seams), fix, others);
}

/// [method_check_seams]
/** Subscribers at seams the method does not run: the first key that asked
 *  for them leads the message (its file and line), any others follow. */
static int check_seams(const Sim *sim, const Method *m, SceneReader *r)
{
    const Hooks *h = &sim->hooks;
    int named = 0;
    for (int s = 0; s < SEAM_COUNT; s++)
        for (int k = 0; k < h->seam[s].n; k++) {
            const Subscriber *sub = &h->seam[s].at[k];
            unsigned mask = skipped_for(h, m, sub);
            if (!mask || named_before(h, s, k))
                continue;
            char who[SCENE_AT_LEN + 192], seams[128];
            asker_at(sim, sub, named == 0, who, sizeof who);
            if (named++ == 0) {
                refuse_first(h, m, sub, mask, who, r);
                continue;
            }
            size_t used = strlen(r->err);
            if (used + 1 < r->errlen)
                snprintf(r->err + used, r->errlen - used, "; so would %s (%s)",
                         who, seam_names(mask, seams, sizeof seams));
        }
    return named ? -1 : 0;
}
/// [method_check_seams]

/** A setting the method does not read, given in the scene: name it. */
static int check_ignored(const Sim *sim, const Method *m, const config_t *cfg,
                         SceneReader *r)
{
    for (const char *const *key = m->ignored_keys; key && *key; key++) {
        const config_setting_t *s = config_lookup(cfg, *key);
        if (!s)
            continue;                       /* its default: nothing asked */
        char others[128];
        methods_that(&sim->hooks, 0, *key, others, sizeof others);
        return scene_error(r, s, *key, "run.method \"%s\" does not read it, "
                           "so it would be ignored: remove it%s%s", m->name,
                           others[0] ? ", or choose run.method = " : "", others);
    }
    return 0;
}

int method_check_scene(const Sim *sim, const config_t *cfg, SceneReader *r)
{
    const Method *m = sim->scene.run.method;
    if (!m)
        return 0;
    return check_seams(sim, m, r) || check_ignored(sim, m, cfg, r) ? -1 : 0;
}
