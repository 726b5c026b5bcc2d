/**
 * @file j_integral_read.c
 * @brief A crack's `j_integral` settings (cracks.[k].j_integral), the
 *        hooks stage 7 subscribes when a crack has them, and the set-up
 *        that finds the tips and checks the contours against the grid.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cracks.h"
#include "j_integral.h"
#include "scene_read.h"

const char *const j_integral_keys[] = {"every", "contours", NULL};

/** Stage 7's state, made (and subscribed) by the first crack that asks
 *  for J; NULL when out of memory or seams. */
static JState *j_state(Sim *sim)
{
    JState *S = sim_state(sim, "j-integral");
    if (S)
        return S;
    S = calloc(1, sizeof *S);
    if (!S)
        return NULL;
    if (sim_attach(sim, "j-integral", S, j_integral_release)) {
        free(S);
        return NULL;
    }
    Hooks *h = &sim->hooks;
    if (hooks_on_prepare(h, j_integral_prepare, S) ||
        hooks_on_step(h, SEAM_TASK7, j_integral_task7, S) ||
        hooks_on_history(h, j_integral_history, S) ||
        hooks_on_report(h, j_integral_report, S) ||
        hooks_on_checkpoint(h, j_integral_checkpoint, S))
        return NULL;
    return S;
}

/** A whole number >= 1 in @p e (the setting of @p key) into *@p out. */
static int whole(SceneReader *r, const config_setting_t *e, const char *key,
                 const char *what, long *out)
{
    double v;
    int rc = scene_value(r, e, key, &v);
    if (rc < 0)
        return -1;
    if (rc || !(v >= 1 && v <= 1e9 && v == floor(v)))
        return scene_error(r, e, key, "%s: expected a whole number >= 1", what);
    *out = (long)v;
    return 0;
}

/// [j_integral_read]
int j_integral_read(Sim *sim, const config_setting_t *s, int index,
                    SceneReader *r)
{
    if (config_setting_type(s) != CONFIG_TYPE_GROUP)
        return scene_error(r, s, "j_integral", "expected a group { every = "
                           "100; contours = [2, 3, 4]; }");
    if (scene_check_keys(r, s, j_integral_keys))
        return -1;
    JState *S = j_state(sim);
    if (!S)
        return scene_error(r, s, "j_integral", "out of memory");
    if (index >= S->ncracks) {
        JSettings *n = realloc(S->set, sizeof *n * (size_t)(index + 1));
        if (!n)
            return scene_error(r, s, "j_integral", "out of memory");
        memset(n + S->ncracks, 0, sizeof *n * (size_t)(index + 1 - S->ncracks));
        S->set = n;
        S->ncracks = index + 1;
    }
    JSettings *j = &S->set[index];
    *j = (JSettings){1, 100, 3, {2, 3, 4}, (int)config_setting_source_line(s),
                     (int)config_setting_source_line(s)};
    const config_setting_t *e = config_setting_get_member(s, "every");
    if (e && whole(r, e, "every", "steps between evaluations", &j->every))
        return -1;
    const config_setting_t *l = config_setting_get_member(s, "contours");
    if (!l)
        return 0;
    int n = config_setting_length(l), t = config_setting_type(l);
    if ((t != CONFIG_TYPE_ARRAY && t != CONFIG_TYPE_LIST) || n < 1 ||
        n > J_CONTOURS_MAX)
        return scene_error(r, l, "contours", "expected a list of 1 to %d "
                           "half-widths in cells, [2, 3, 4]", J_CONTOURS_MAX);
    j->ncontours = n;
    j->contours_line = (int)config_setting_source_line(l);
    for (int k = 0; k < n; k++) {
        long c;
        if (whole(r, config_setting_get_elem(l, (unsigned)k), "contours",
                  "a half-width in cells", &c))
            return -1;
        if (c > 100000)
            return scene_error(r, l, "contours", "%ld cells: larger than any grid", c);
        j->contour[k] = (int)c;
    }
    return 0;
}
/// [j_integral_read]

/** "file:line" of line @p line of the scene into @p at. */
static const char *where(const Sim *sim, int line, char at[SCENE_AT_LEN])
{
    return scene_lines_at(sim->scene.lines, sim->scene.file, line, at,
                          SCENE_AT_LEN);
}

/** Does (x, y) lie in a body of the scene? */
static int in_a_body(const Scene *sc, double x, double y)
{
    for (int b = 0; b < sc->nbodies; b++)
        if (shape_contains(&sc->bodies[b].shape, x, y))
            return 1;
    return 0;
}

/// [j_integral_prepare]
int j_integral_prepare(Sim *sim, void *state, char *err, size_t errlen)
{
    JState *S = state;
    const Cracks *C = cracks_of(sim);
    const Grid *g = &sim->grid;
    char at[SCENE_AT_LEN];
    S->ntips = 0;
    free(S->tip);
    if (!(S->tip = calloc(2 * (size_t)S->ncracks + 1, sizeof *S->tip)))
        goto oom;
    S->every = 0;
    for (int k = 0; k < S->ncracks && C && k < C->ncracks; k++) {
        const JSettings *j = &S->set[k];
        const Crack *c = &C->crack[k];
        if (!j->on)
            continue;
        S->every = S->every == 0 || j->every < S->every ? j->every : S->every;
        int found = 0;
        for (int end = 0; end < 2; end++) {
            int i = end ? c->n - 1 : 0;
            if (!in_a_body(&sim->scene, c->x[i], c->y[i]))
                continue;               /* a crack's mouth, not a tip */
            found = 1;
            /* the domain of the widest contour must lie in the grid */
            for (int m = 0; m < j->ncontours; m++) {
                double hx = j->contour[m] * g->dx, hy = j->contour[m] * g->dy;
                if (c->x[i] - hx < g->ox || c->x[i] + hx > g->ox + g->ncx * g->dx ||
                    c->y[i] - hy < g->oy || c->y[i] + hy > g->oy + g->ncy * g->dy) {
                    snprintf(err, errlen, "%s: contours: %d cells about the "
                             "tip of crack %d at (%g, %g) reach outside the "
                             "grid", where(sim, j->contours_line, at),
                             j->contour[m], k, c->x[i], c->y[i]);
                    return -1;
                }
            }
            S->tip[S->ntips++] = (JTip){.crack = k, .end = end};
        }
        if (!found) {
            snprintf(err, errlen, "%s: j_integral: crack %d has no tip (both "
                     "of its ends lie outside every body)", where(sim, j->line, at), k);
            return -1;
        }
    }
    /* the displacement u = x - X is measured from the points as set up */
    S->npoints = sim->pts.n;
    free(S->X);
    free(S->Y);
    S->X = malloc(sizeof(double) * (size_t)(S->npoints + 1));
    S->Y = malloc(sizeof(double) * (size_t)(S->npoints + 1));
    free(S->near);
    S->near = malloc(sizeof(int) * (size_t)(S->npoints + 1));
    if (!S->X || !S->Y || !S->near)
        goto oom;
    memcpy(S->X, sim->pts.x, sizeof(double) * (size_t)S->npoints);
    memcpy(S->Y, sim->pts.y, sizeof(double) * (size_t)S->npoints);
    /* scratch per field slot, as many as the grid holds now; it grows
       with the grid, as the field table's slots do (chapter 1b) */
    free(S->mux);
    free(S->muy);
    free(S->m);
    S->mux = S->muy = S->m = NULL;
    S->cap = 0;
    if (j_integral_fit(S, g->capacity))
        goto oom;
    j_integral_tips(sim, S);             /* J = 0: nothing has moved */
    S->at_step = sim->step;
    S->at_time = sim->t;
    return 0;
oom:
    snprintf(err, errlen, "%s: j_integral: out of memory", sim->scene.file);
    return -1;
}
/// [j_integral_prepare]

void j_integral_release(void *state)
{
    JState *S = state;
    free(S->set);
    free(S->tip);
    free(S->X);
    free(S->Y);
    free(S->near);
    free(S->mux);
    free(S->muy);
    free(S->m);
    free(S);
}
