/**
 * @file crack_read.c
 * @brief The scene's "cracks" section: polylines checked on input, and the
 *        hooks stage 2 installs when a scene has a crack.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cracks.h"
#include "scene_read.h"
#include "shape.h"

/** Read the list of points of one crack into @p c (checked afterwards by
 *  crack_check_points()). */
static int read_points(SceneReader *r, const config_setting_t *l, Crack *c)
{
    int n = config_setting_length(l);
    if (config_setting_type(l) != CONFIG_TYPE_LIST || n < 2)
        return scene_error(r, l, "points", "expected a list of at least two "
                           "points ( [x, y], [x, y], ... )");
    if (crack_alloc_points(c, n))
        return scene_error(r, l, "points", "out of memory");
    for (int k = 0; k < n; k++) {
        const config_setting_t *e = config_setting_get_elem(l, (unsigned)k);
        double xy[2];
        int t = config_setting_type(e);
        if ((t != CONFIG_TYPE_ARRAY && t != CONFIG_TYPE_LIST) ||
            config_setting_length(e) != 2)
            return scene_error(r, e, "points", "point %d: expected [x, y]", k);
        for (int j = 0; j < 2; j++) {
            int rc = scene_value(r, config_setting_get_elem(e, (unsigned)j),
                                 "points", &xy[j]);
            if (rc)
                return rc < 0 ? -1 : scene_error(r, e, "points", "point %d: "
                                                 "expected [x, y]", k);
        }
        c->x[k] = xy[0];
        c->y[k] = xy[1];
    }
    return 0;
}

int crack_alloc_points(Crack *c, int n)
{
    free(c->x);
    free(c->y);
    c->n = n;
    c->x = malloc(sizeof(double) * (size_t)n);
    c->y = malloc(sizeof(double) * (size_t)n);
    return c->x && c->y ? 0 : -1;
}

int crack_reserve_points(Crack *c, int cap)
{
    if (cap < c->n)
        return 0;
    double *x = realloc(c->x, sizeof(double) * (size_t)cap);
    if (!x)
        return -1;
    c->x = x;
    double *y = realloc(c->y, sizeof(double) * (size_t)cap);
    if (!y)
        return -1;
    c->y = y;
    return 0;
}

/// [crack_check_points]
int crack_check_points(SceneReader *r, const config_setting_t *s,
                       const char *key, const Scene *sc, Crack *c)
{
    double gx1 = sc->ox + sc->ncx * sc->dx, gy1 = sc->oy + sc->ncy * sc->dy;
    int list = config_setting_type(s) == CONFIG_TYPE_LIST &&
               config_setting_length(s) == c->n;
    for (int k = 0; k < c->n; k++) {
        /* a list of points names the line of the point itself */
        const config_setting_t *e = list ? config_setting_get_elem(s, (unsigned)k) : s;
        if (!(c->x[k] >= sc->ox && c->x[k] < gx1 && c->y[k] >= sc->oy &&
              c->y[k] < gy1))
            return scene_error(r, e, key, "point %d (%g, %g) lies outside "
                               "the grid", k, c->x[k], c->y[k]);
        if (k > 0 && c->x[k] == c->x[k - 1] && c->y[k] == c->y[k - 1])
            return scene_error(r, e, key, "segment %d has zero length at "
                               "(%g, %g)", k - 1, c->x[k], c->y[k]);
    }
    int si, sj, cross = crack_self_crossing(c, &si, &sj);
    if (cross < 0)
        return scene_error(r, s, key, "out of memory");
    if (cross)
        return scene_error(r, s, key, "the crack crosses itself "
                           "(segments %d and %d)", si, sj);
    crack_extent(c);
    return 0;
}
/// [crack_check_points]

void crack_extent(Crack *c)
{
    c->xmin = c->xmax = c->x[0];
    c->ymin = c->ymax = c->y[0];
    for (int j = 1; j < c->n; j++) {
        c->xmin = c->x[j] < c->xmin ? c->x[j] : c->xmin;
        c->xmax = c->x[j] > c->xmax ? c->x[j] : c->xmax;
        c->ymin = c->y[j] < c->ymin ? c->y[j] : c->ymin;
        c->ymax = c->y[j] > c->ymax ? c->y[j] : c->ymax;
    }
}

const char *const crack_keys[] = {"points", NULL};

/** Read one crack: its points, then the keys later stages add to a crack
 *  (which may give the points another way), then check them. */
static int read_crack(Sim *sim, SceneReader *r, const config_setting_t *g,
                      int index, Crack *c)
{
    if (scene_check_open_keys(r, &sim->hooks, "cracks", g, crack_keys, NULL))
        return -1;
    c->line = (int)config_setting_source_line(g);
    const config_setting_t *l = config_setting_get_member(g, "points");
    if (l && read_points(r, l, c))
        return -1;
    if (scene_read_open_keys(sim, r, "cracks", g, index))
        return -1;
    if (c->n == 0)
        return scene_error(r, g, "points", "missing (required)");
    if (l && crack_check_points(r, l, "points", &sim->scene, c))
        return -1;
    return 0;
}

/** Stage 2's state, made by whichever of its keys comes first. */
static Cracks *cracks_make(Sim *sim)
{
    Cracks *C = cracks_of(sim);
    if (C)
        return C;
    C = calloc(1, sizeof *C);
    if (C && sim_attach(sim, "cracks", C, cracks_release)) {
        free(C);
        C = NULL;
    }
    return C;
}

int cracks_read_search(Sim *sim, const config_setting_t *s, int index,
                       SceneReader *r)
{
    const char *name = config_setting_get_string(s);
    Cracks *C = cracks_make(sim);
    (void)index;
    if (!name)
        return scene_error(r, s, "crack_search", "expected a string in quotes");
    if (!C)
        return scene_error(r, s, "crack_search", "out of memory");
    return scene_choice(r, &sim->hooks, config_setting_parent(s), "run",
                        "crack_search", name, (const void **)&C->search);
}

/// [cracks_read]
int cracks_read(Sim *sim, const config_setting_t *s, int index, SceneReader *r)
{
    int n = config_setting_length(s);
    (void)index;
    if (config_setting_type(s) != CONFIG_TYPE_LIST)
        return scene_error(r, s, "cracks", "expected a list ( { points = ...; }, ... )");
    if (n == 0)
        return 0;                        /* no crack: stage 1's behaviour */
    Cracks *C = cracks_make(sim);
    if (!C || !(C->crack = calloc((size_t)n, sizeof(Crack))))
        return scene_error(r, s, "cracks", "out of memory");
    for (int k = 0; k < n; k++) {
        const config_setting_t *g = config_setting_get_elem(s, (unsigned)k);
        if (config_setting_type(g) != CONFIG_TYPE_GROUP)
            return scene_error(r, g, "cracks", "entry %d: expected a group", k);
        C->ncracks = k + 1;
        if (read_crack(sim, r, g, k, &C->crack[k]))
            return -1;
    }
    if (!C->search)                      /* the latest stage's search */
        C->search = hooks_find_choice(&sim->hooks, "run.crack_search", NULL);
    C->side_shift = hooks_find_field_key(&sim->hooks, "crack side")->shift;
    /* subscribed only for a scene with cracks (Task 1, 7, output) */
    Hooks *h = &sim->hooks;
    if (hooks_on_prepare(h, cracks_prepare, C) ||
        hooks_on_step(h, SEAM_TASK1_FIELDS, cracks_key_fields, C) ||
        hooks_on_step(h, SEAM_TASK7, cracks_task7, C) ||
        hooks_on_snapshot(h, cracks_snapshot, C) ||
        hooks_on_history(h, cracks_history, C) ||
        hooks_on_checkpoint(h, cracks_checkpoint, C))
        return scene_error(r, s, "cracks", "too many subscribers at a seam");
    return 0;
}
/// [cracks_read]

int cracks_prepare(Sim *sim, void *state, char *err, size_t errlen)
{
    Cracks *C = state;
    const Scene *sc = &sim->scene;
    /* an edge crack may start outside the body, and a crack may cut a
       body through from outside to outside, but every crack must meet a
       body: its segments are walked in steps of an eighth of a cell (a
       body thinner than that holds no point anyway) */
    double step = 0.125 * fmin(sim->grid.dx, sim->grid.dy);
    for (int k = 0; k < C->ncracks; k++) {
        const Crack *c = &C->crack[k];
        int inside = 0;
        for (int j = 0; j < c->n && !inside; j++) {
            double ex = j + 1 < c->n ? c->x[j + 1] - c->x[j] : 0.0;
            double ey = j + 1 < c->n ? c->y[j + 1] - c->y[j] : 0.0;
            double len = sqrt(ex * ex + ey * ey);
            long n = len > 0 ? (long)ceil(len / step) : 0;
            for (long i = 0; i <= n && !inside; i++) {
                double f = n > 0 ? (double)i / (double)n : 0.0;
                for (int b = 0; b < sc->nbodies && !inside; b++)
                    inside = shape_contains(&sc->bodies[b].shape, c->x[j] + f * ex,
                                            c->y[j] + f * ey);
            }
        }
        if (!inside) {
            char at[SCENE_AT_LEN];
            snprintf(err, errlen, "%s: cracks: crack %d lies outside every "
                     "body", scene_lines_at(sc->lines, sc->file, c->line, at,
                                            sizeof at), k);
            return -1;
        }
    }
    C->reach = sc->run.shape && sc->run.shape->nodes > STENCIL_NODES;
    size_t np = (size_t)sim->pts.n + 1;                          /* Task 1 */
    if (!(C->pair_field = malloc((size_t)sim->fields.width * np)) ||
        !(C->keyed = malloc(sizeof(int) * np)) ||
        !(C->keyed_end = malloc(sizeof(int) * (size_t)sim->threads))) {
        snprintf(err, errlen, "%s: cracks: out of memory for Task 1", sc->file);
        return -1;
    }
    if (C->search->update && C->search->update(C, &sim->grid)) {
        snprintf(err, errlen, "%s: cracks: out of memory for the crossing "
                 "search \"%s\"", sc->file, C->search->name);
        return -1;
    }
    return 0;
}

void cracks_release(void *state)
{
    Cracks *C = state;
    if (C->search && C->search->release)
        C->search->release(C);
    for (int k = 0; k < C->ncracks; k++) {
        free(C->crack[k].x);
        free(C->crack[k].y);
    }
    free(C->crack);
    free(C->pair_field);
    free(C->pair_hit);
    free(C->keyed);
    free(C->keyed_end);
    free(C);
}
