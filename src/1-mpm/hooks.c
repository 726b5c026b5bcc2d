/**
 * @file hooks.c
 * @brief The registries of a build and the ordered subscriber lists of
 *        its seams.
 */
#include "hooks.h"

#include <string.h>

#include "sim.h"

void hooks_begin_stage(Hooks *h, int rank)
{
    h->rank = rank;
}

void hooks_begin_key(Hooks *h, KeyAt key)
{
    h->reading = key;
}

int hooks_add_scheme(Hooks *h, const char *name, double before, double after,
                     int reextrapolate)
{
    if (h->nschemes == HOOKS_MAX)
        return h->overflow = -1;
    h->scheme_rank[h->nschemes] = h->rank;
    h->schemes[h->nschemes++] =
        (UpdateScheme){name, before, after, reextrapolate};
    return 0;
}

int hooks_add_key(Hooks *h, const char *section, const char *key,
                  int (*parse)(struct Sim *, const config_setting_t *, int,
                               struct SceneReader *),
                  const char *const *keys)
{
    if (h->nkeys == HOOKS_MAX)
        return h->overflow = -1;
    h->keys[h->nkeys++] = (SceneKey){section, key, parse, keys, h->rank};
    return 0;
}

const SceneKey *hooks_find_key(const Hooks *h, const char *section,
                               const char *key)
{
    for (int k = 0; k < h->nkeys; k++)
        if (strcmp(h->keys[k].section, section) == 0 &&
            strcmp(h->keys[k].key, key) == 0)
            return &h->keys[k];
    return NULL;
}

int hooks_add_refusal(Hooks *h, const char *key, const char *value,
                      const char *stage)
{
    if (h->nrefusals == HOOKS_MAX)
        return h->overflow = -1;
    h->refusals[h->nrefusals++] = (Refusal){key, value, stage};
    return 0;
}

int hooks_add_outputs(Hooks *h, const char *text)
{
    if (h->noutputs == HOOKS_MAX_OUTPUTS)
        return h->overflow = -1;
    h->outputs[h->noutputs++] = text;
    return 0;
}

const Refusal *hooks_find_refusal(const Hooks *h, const char *key,
                                  const char *value)
{
    for (int k = 0; k < h->nrefusals; k++) {
        const Refusal *r = &h->refusals[k];
        if (strcmp(r->key, key) != 0)
            continue;
        if (!r->value || (value && strcmp(r->value, value) == 0))
            return r;
    }
    return NULL;
}

int hooks_add_choice(Hooks *h, const char *key, const char *name,
                     const void *impl)
{
    if (h->nchoices == HOOKS_MAX)
        return h->overflow = -1;
    h->choices[h->nchoices++] = (Choice){key, name, impl, h->rank};
    return 0;
}

const void *hooks_find_choice(const Hooks *h, const char *key,
                              const char *name)
{
    const void *found = NULL;
    for (int k = 0; k < h->nchoices; k++)
        if (strcmp(h->choices[k].key, key) == 0 &&
            (!name || strcmp(h->choices[k].name, name) == 0))
            found = h->choices[k].impl;
    return found;
}

void hooks_list_choices(const Hooks *h, const char *key, char *buf, size_t len)
{
    buf[0] = '\0';
    for (int k = 0; k < h->nchoices; k++) {
        if (strcmp(h->choices[k].key, key) != 0)
            continue;
        if (buf[0])
            strncat(buf, ", ", len - strlen(buf) - 1);
        strncat(buf, h->choices[k].name, len - strlen(buf) - 1);
    }
}

int hooks_add_field_key(Hooks *h, const char *name, int bits)
{
    int shift = 0;
    for (int k = 0; k < h->nfield_keys; k++)
        shift += h->field_keys[k].bits;
    if (h->nfield_keys == HOOKS_MAX || bits < 1 || shift + bits > 31)
        return h->overflow = -1;
    h->field_keys[h->nfield_keys++] = (FieldKey){name, shift, bits};
    return shift;
}

const FieldKey *hooks_find_field_key(const Hooks *h, const char *name)
{
    for (int k = 0; k < h->nfield_keys; k++)
        if (strcmp(h->field_keys[k].name, name) == 0)
            return &h->field_keys[k];
    return NULL;
}

const UpdateScheme *hooks_find_scheme(const Hooks *h, const char *name)
{
    for (int k = 0; k < h->nschemes; k++)
        if (strcmp(h->schemes[k].name, name) == 0)
            return &h->schemes[k];
    return NULL;
}

/// [subscribe]
/** Insert @p s into seam @p seam's list after every subscriber of the same
 *  or an earlier stage: the list stays in stage order whenever a stage
 *  subscribes. It carries the stage and the scene key being read now. */
static int subscribe(Hooks *h, Seam seam, Subscriber s)
{
    SeamList *l = &h->seam[seam];
    s.rank = h->rank;
    s.by = h->reading;
    if (l->n == HOOKS_MAX)
        return -1;                  /* the caller reports it */
    int k = l->n;
    while (k > 0 && l->at[k - 1].rank > s.rank) {
        l->at[k] = l->at[k - 1];
        k--;
    }
    l->at[k] = s;
    l->n++;
    return 0;
}
/// [subscribe]

int hooks_on_step(Hooks *h, Seam seam, StepHook fn, void *state)
{
    Subscriber s = {.fn.step = fn, .state = state};
    if (seam < SEAM_TASK1_FIELDS || seam > SEAM_TASK7)
        return -1;
    return subscribe(h, seam, s);
}

int hooks_on_prepare(Hooks *h, PrepareHook fn, void *state)
{
    Subscriber s = {.fn.prepare = fn, .state = state};
    return subscribe(h, SEAM_PREPARE, s);
}

int hooks_on_snapshot(Hooks *h, SnapshotHook fn, void *state)
{
    Subscriber s = {.fn.snapshot = fn, .state = state};
    return subscribe(h, SEAM_SNAPSHOT, s);
}

int hooks_on_history(Hooks *h, HistoryHook fn, void *state)
{
    Subscriber s = {.fn.history = fn, .state = state};
    return subscribe(h, SEAM_HISTORY, s);
}

int hooks_on_report(Hooks *h, ReportHook fn, void *state)
{
    Subscriber s = {.fn.report = fn, .state = state};
    return subscribe(h, SEAM_REPORT, s);
}

int hooks_on_checkpoint(Hooks *h, CheckpointHook fn, void *state)
{
    Subscriber s = {.fn.checkpoint = fn, .state = state};
    return subscribe(h, SEAM_CHECKPOINT, s);
}

int hooks_on_energy(Hooks *h, EnergyHook fn, void *state)
{
    Subscriber s = {.fn.energy = fn, .state = state};
    return subscribe(h, SEAM_ENERGY, s);
}

int hooks_on_energy_in(Hooks *h, EnergyHook fn, void *state)
{
    Subscriber s = {.fn.energy = fn, .state = state};
    return subscribe(h, SEAM_ENERGY_IN, s);
}

int hooks_run_report(const struct Sim *sim, FILE *f)
{
    const SeamList *l = &sim->hooks.seam[SEAM_REPORT];
    int rc = 0;
    for (int k = 0; k < l->n; k++)
        rc |= l->at[k].fn.report(sim, l->at[k].state, f);
    return rc ? -1 : 0;
}

int hooks_run_step(Sim *sim, Seam seam)
{
    const SeamList *l = &sim->hooks.seam[seam];
    for (int k = 0; k < l->n; k++) {
        int rc = l->at[k].fn.step(sim, l->at[k].state, seam);
        if (rc)
            return rc;
    }
    return 0;
}

int method_reads(const Method *m, const char *key)
{
    for (const char *const *k = m->ignored_keys; k && *k; k++)
        if (strcmp(*k, key) == 0)
            return 0;
    return 1;
}
