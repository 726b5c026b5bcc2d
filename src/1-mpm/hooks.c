/**
 * @file hooks.c
 * @brief Registration of update schemes, scene sections and refusals.
 */
#include "hooks.h"

#include <string.h>

int hooks_add_scheme(Hooks *h, const char *name, double before, double after,
                     int reextrapolate)
{
    if (h->nschemes == HOOKS_MAX)
        return -1;
    h->schemes[h->nschemes++] =
        (UpdateScheme){name, before, after, reextrapolate};
    return 0;
}

int hooks_add_section(Hooks *h, const char *key,
                      int (*parse)(struct Sim *, const config_setting_t *,
                                   char *, size_t))
{
    if (h->nsections == HOOKS_MAX)
        return -1;
    h->sections[h->nsections++] = (SceneSection){key, parse};
    return 0;
}

int hooks_add_refusal(Hooks *h, const char *key, const char *value,
                      const char *stage)
{
    if (h->nrefusals == HOOKS_MAX)
        return -1;
    h->refusals[h->nrefusals++] = (Refusal){key, value, stage};
    return 0;
}

const UpdateScheme *hooks_find_scheme(const Hooks *h, const char *name)
{
    for (int k = 0; k < h->nschemes; k++)
        if (strcmp(h->schemes[k].name, name) == 0)
            return &h->schemes[k];
    return NULL;
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
