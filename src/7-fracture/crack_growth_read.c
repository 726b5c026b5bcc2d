/**
 * @file crack_growth_read.c
 * @brief A crack's `growth` settings (cracks.[k].growth), the hooks growth
 *        subscribes, and the set-up that reserves room for new points.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "crack_growth.h"
#include "cracks.h"
#include "scene_read.h"

const char *const crack_growth_keys[] = {"G_c", "length", "max_segments", "average",
                                             NULL};

/** Most segments a crack may reserve room for. */
#define GROWTH_MAX_SEGMENTS 10000000

/** The growth state, made (and subscribed) by the first crack that
 *  grows; NULL when out of memory or seams. */
static CrackGrowth *growth_state(Sim *sim)
{
    CrackGrowth *G = sim_state(sim, "crack-growth");
    if (G)
        return G;
    G = calloc(1, sizeof *G);
    if (!G)
        return NULL;
    if (sim_attach(sim, "crack-growth", G, crack_growth_release)) {
        free(G);
        return NULL;
    }
    Hooks *h = &sim->hooks;
    if (hooks_on_prepare(h, crack_growth_prepare, G) ||
        hooks_on_history(h, crack_growth_history, G) ||
        hooks_on_report(h, crack_growth_report, G) ||
        hooks_on_checkpoint(h, crack_growth_checkpoint, G))
        return NULL;
    return G;
}

/** Make room for crack @p index in @p G. @return 0 or -1. */
static int growth_fit(CrackGrowth *G, int index)
{
    if (index < G->ncracks)
        return 0;
    GrowthSettings *s = realloc(G->set, sizeof *s * (size_t)(index + 1));
    if (!s)
        return -1;
    G->set = s;
    GrowthEnd *e = realloc(G->end, sizeof *e * 2 * (size_t)(index + 1));
    if (!e)
        return -1;
    G->end = e;
    memset(s + G->ncracks, 0, sizeof *s * (size_t)(index + 1 - G->ncracks));
    for (int k = 2 * G->ncracks; k < 2 * (index + 1); k++)
        e[k] = (GrowthEnd){.last_step = -1, .by = -1};
    G->ncracks = index + 1;
    return 0;
}

/// [crack_growth_read]
int crack_growth_read(Sim *sim, const config_setting_t *s, int index,
                      SceneReader *r)
{
    if (config_setting_type(s) != CONFIG_TYPE_GROUP)
        return scene_error(r, s, "growth", "expected a group { G_c = 1e-4; "
                           "length = 0.5; }");
    if (scene_check_keys(r, s, crack_growth_keys))
        return -1;
    /* J decides when a tip grows, and K_I, K_II where: the same crack
       must ask for them (in any order of its keys) */
    if (!config_setting_get_member(config_setting_parent(s), "j_integral"))
        return scene_error(r, s, "growth", "needs j_integral on the same "
                           "crack (J and K decide when and where it grows)");
    CrackGrowth *G = growth_state(sim);
    if (!G || growth_fit(G, index))
        return scene_error(r, s, "growth", "out of memory");
    GrowthSettings *g = &G->set[index];
    const Scene *sc = &sim->scene;
    int line = (int)config_setting_source_line(s);
    *g = (GrowthSettings){.on = 1, .line = line, .max_line = line};
    double max = 0.0;
    if (scene_number(r, s, "G_c", 1, 0.0, &g->G_c) < 0 ||
        scene_number(r, s, "length", 0, 0.5 * fmin(sc->dx, sc->dy),
                     &g->length) < 0 ||
        scene_number(r, s, "max_segments", 0, 0.0, &max) < 0 ||
        scene_number(r, s, "average", 0, 0.0, &g->average) < 0)
        return -1;
    if (!(g->G_c > 0.0 && isfinite(g->G_c)))
        return scene_error(r, config_setting_get_member(s, "G_c"), "G_c",
                           "%g: the toughness must be positive", g->G_c);
    if (!(g->average >= 0.0 && isfinite(g->average)))
        return scene_error(r, config_setting_get_member(s, "average"), "average",
                           "%g: a time >= 0 (0: each evaluation alone)",
                           g->average);
    if (!(g->length > 0.0 && isfinite(g->length)))
        return scene_error(r, config_setting_get_member(s, "length"), "length",
                           "%g: a new segment's length must be positive",
                           g->length);
    const config_setting_t *m = config_setting_get_member(s, "max_segments");
    if (m) {
        if (!(max >= 1 && max <= GROWTH_MAX_SEGMENTS && max == floor(max)))
            return scene_error(r, m, "max_segments", "%g: expected a whole "
                               "number from 1 to %d", max, GROWTH_MAX_SEGMENTS);
        g->max_segments = (int)max;
        g->max_line = (int)config_setting_source_line(m);
    }
    return 0;
}
/// [crack_growth_read]

/// [crack_growth_prepare]
int crack_growth_prepare(Sim *sim, void *state, char *err, size_t errlen)
{
    CrackGrowth *G = state;
    Cracks *C = cracks_of(sim);
    const Scene *sc = &sim->scene;
    const Grid *g = &sim->grid;
    char at[SCENE_AT_LEN];
    for (int k = 0; k < G->ncracks && C && k < C->ncracks; k++) {
        GrowthSettings *s = &G->set[k];
        Crack *c = &C->crack[k];
        if (!s->on)
            continue;
        scene_lines_at(sc->lines, sc->file, s->max_line, at, sizeof at);
        /* by default: room to cross the grid's diagonal once more */
        if (s->max_segments == 0) {
            double diag = hypot(g->ncx * g->dx, g->ncy * g->dy);
            double more = fmin(ceil(diag / s->length), GROWTH_MAX_SEGMENTS);
            s->max_segments = c->n - 1 + (int)more;
        }
        if (s->max_segments < c->n - 1) {
            snprintf(err, errlen, "%s: max_segments: %d is fewer than the "
                     "%d segments crack %d has", at, s->max_segments, c->n - 1, k);
            return -1;
        }
        snprintf(s->full, sizeof s->full, "segments of crack %d, all the "
                 "room reserved (cracks.[%d].growth.max_segments, %s)", k, k,
                 scene_lines_at(sc->lines, sc->file, s->line, at, sizeof at));
        if (crack_reserve_points(c, s->max_segments + 1)) {
            snprintf(err, errlen, "%s: growth: out of memory for %d segments",
                     at, s->max_segments);
            return -1;
        }
    }
    return 0;
}
/// [crack_growth_prepare]

void crack_growth_release(void *state)
{
    CrackGrowth *G = state;
    free(G->set);
    free(G->end);
    free(G);
}
