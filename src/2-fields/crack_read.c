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

/** Do segments (a, b) and (c, d) share a point? (closed segments) */
static int segments_meet(const double *a, const double *b, const double *c,
                         const double *d)
{
    double d1 = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    double d2 = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
    double d3 = (d[0] - c[0]) * (a[1] - c[1]) - (d[1] - c[1]) * (a[0] - c[0]);
    double d4 = (d[0] - c[0]) * (b[1] - c[1]) - (d[1] - c[1]) * (b[0] - c[0]);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) &&
        ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return 1;
    /* collinear touching */
    const double *p[4][3] = {{a, b, c}, {a, b, d}, {c, d, a}, {c, d, b}};
    double dd[4] = {d1, d2, d3, d4};
    for (int k = 0; k < 4; k++)
        if (dd[k] == 0 &&
            fmin(p[k][0][0], p[k][1][0]) <= p[k][2][0] &&
            p[k][2][0] <= fmax(p[k][0][0], p[k][1][0]) &&
            fmin(p[k][0][1], p[k][1][1]) <= p[k][2][1] &&
            p[k][2][1] <= fmax(p[k][0][1], p[k][1][1]))
            return 1;
    return 0;
}

/** Read one crack's points and check them. */
static int read_crack(SceneReader *r, const Scene *sc, const config_setting_t *g,
                      Crack *c)
{
    static const char *const keys[] = {"points", NULL};
    if (scene_check_keys(r, g, keys))
        return -1;
    const config_setting_t *l = config_setting_get_member(g, "points");
    if (!l)
        return scene_error(r, g, "points", "missing (required)");
    int n = config_setting_length(l);
    if (config_setting_type(l) != CONFIG_TYPE_LIST || n < 2)
        return scene_error(r, l, "points", "expected a list of at least two "
                           "points ( [x, y], [x, y], ... )");
    c->n = n;
    c->line = (int)config_setting_source_line(g);
    c->x = malloc(sizeof(double) * (size_t)n);
    c->y = malloc(sizeof(double) * (size_t)n);
    if (!c->x || !c->y)
        return scene_error(r, l, "points", "out of memory");
    double gx1 = sc->ox + sc->ncx * sc->dx, gy1 = sc->oy + sc->ncy * sc->dy;
    for (int k = 0; k < n; k++) {
        const config_setting_t *e = config_setting_get_elem(l, (unsigned)k);
        double xy[2];
        int t = config_setting_type(e);
        if ((t != CONFIG_TYPE_ARRAY && t != CONFIG_TYPE_LIST) ||
            config_setting_length(e) != 2)
            return scene_error(r, e, "points", "point %d: expected [x, y]", k);
        for (int j = 0; j < 2; j++) {
            const config_setting_t *v = config_setting_get_elem(e, (unsigned)j);
            int vt = config_setting_type(v);
            if (vt == CONFIG_TYPE_FLOAT)
                xy[j] = config_setting_get_float(v);
            else if (vt == CONFIG_TYPE_INT || vt == CONFIG_TYPE_INT64)
                xy[j] = (double)config_setting_get_int64(v);
            else
                return scene_error(r, e, "points", "point %d: expected [x, y]", k);
        }
        if (!(xy[0] >= sc->ox && xy[0] < gx1 && xy[1] >= sc->oy && xy[1] < gy1))
            return scene_error(r, e, "points", "point %d (%g, %g) lies outside "
                               "the grid", k, xy[0], xy[1]);
        c->x[k] = xy[0];
        c->y[k] = xy[1];
        if (k > 0 && c->x[k] == c->x[k - 1] && c->y[k] == c->y[k - 1])
            return scene_error(r, e, "points", "segment %d has zero length at "
                               "(%g, %g)", k - 1, xy[0], xy[1]);
    }
    for (int i = 0; i + 1 < n; i++)
        for (int j = i + 2; j + 1 < n; j++) {
            double a[2] = {c->x[i], c->y[i]}, b[2] = {c->x[i + 1], c->y[i + 1]};
            double cc[2] = {c->x[j], c->y[j]}, d[2] = {c->x[j + 1], c->y[j + 1]};
            if (segments_meet(a, b, cc, d))
                return scene_error(r, l, "points", "the crack crosses itself "
                                   "(segments %d and %d)", i, j);
        }
    c->xmin = c->xmax = c->x[0];
    c->ymin = c->ymax = c->y[0];
    for (int k = 1; k < n; k++) {
        c->xmin = fmin(c->xmin, c->x[k]);
        c->xmax = fmax(c->xmax, c->x[k]);
        c->ymin = fmin(c->ymin, c->y[k]);
        c->ymax = fmax(c->ymax, c->y[k]);
    }
    return 0;
}

/// [cracks_read]
int cracks_read(Sim *sim, const config_setting_t *s, char *err, size_t errlen)
{
    SceneReader r = {sim->scene.file, err, errlen};
    int n = config_setting_length(s);
    if (config_setting_type(s) != CONFIG_TYPE_LIST)
        return scene_error(&r, s, "cracks", "expected a list ( { points = ...; }, ... )");
    if (n == 0)
        return 0;                        /* no crack: stage 1's behaviour */
    Cracks *C = calloc(1, sizeof *C);
    if (!C)
        return scene_error(&r, s, "cracks", "out of memory");
    sim->ext[CRACKS_EXT] = C;
    sim->hooks.release = cracks_release;
    C->crack = calloc((size_t)n, sizeof(Crack));
    if (!C->crack)
        return scene_error(&r, s, "cracks", "out of memory");
    for (int k = 0; k < n; k++) {
        const config_setting_t *g = config_setting_get_elem(s, (unsigned)k);
        if (config_setting_type(g) != CONFIG_TYPE_GROUP)
            return scene_error(&r, g, "cracks", "entry %d: expected a group", k);
        C->ncracks = k + 1;
        if (read_crack(&r, &sim->scene, g, &C->crack[k]))
            return -1;
    }
    /* the hooks exist only for a scene with cracks (Task 1, 7, output) */
    sim->hooks.extra_slots = cracks_extra_slots;
    sim->hooks.prepare = cracks_prepare;
    sim->hooks.assign_fields = cracks_assign_fields;
    sim->hooks.pair_slots = cracks_pair_slots;
    sim->hooks.move_cracks = cracks_move;
    sim->hooks.snapshot = cracks_snapshot;
    sim->hooks.history_columns = cracks_history;
    return 0;
}
/// [cracks_read]

int cracks_extra_slots(const Sim *sim)
{
    const Cracks *C = cracks_of(sim);
    const Scene *sc = &sim->scene;
    double cells = 0;
    for (int k = 0; k < C->ncracks; k++)
        for (int j = 0; j + 1 < C->crack[k].n; j++)
            cells += fabs(C->crack[k].x[j + 1] - C->crack[k].x[j]) / sc->dx +
                     fabs(C->crack[k].y[j + 1] - C->crack[k].y[j]) / sc->dy + 2;
    /* each cell a crack passes through touches 4 nodes, each with at most
       two extra fields; twice that leaves room for stretching cracks */
    double slots = 2.0 * 4.0 * 2.0 * (cells + 4);
    double all = 2.0 * (sc->ncx + 1.0) * (sc->ncy + 1.0);
    return (int)(slots < all ? slots : all);
}

int cracks_prepare(Sim *sim, char *err, size_t errlen)
{
    Cracks *C = cracks_of(sim);
    const Scene *sc = &sim->scene;
    /* an edge crack may start outside the body, but some point of every
       crack must lie in a body */
    for (int k = 0; k < C->ncracks; k++) {
        const Crack *c = &C->crack[k];
        int inside = 0;
        for (int j = 0; j < c->n && !inside; j++)
            for (int b = 0; b < sc->nbodies && !inside; b++)
                inside = shape_contains(&sc->bodies[b].shape, c->x[j], c->y[j]);
        if (!inside) {
            snprintf(err, errlen, "%s:%d: cracks: crack %d lies outside every "
                     "body", sc->file, c->line, k);
            return -1;
        }
    }
    int nn = sim->grid.nnodes;
    C->pair = calloc((size_t)sim->pts.n + 1, 1);
    C->node_field = malloc(sizeof(int) * 2 * (size_t)nn);
    C->touched = malloc(sizeof(int) * ((size_t)sim->grid.capacity - (size_t)nn + 1));
    if (!C->pair || !C->node_field || !C->touched) {
        snprintf(err, errlen, "%s: out of memory for crack fields", sc->file);
        return -1;
    }
    for (int k = 0; k < 2 * nn; k++)
        C->node_field[k] = -1;
    return 0;
}

void cracks_release(Sim *sim)
{
    Cracks *C = cracks_of(sim);
    if (!C)
        return;
    for (int k = 0; k < C->ncracks; k++) {
        free(C->crack[k].x);
        free(C->crack[k].y);
    }
    free(C->crack);
    free(C->pair);
    free(C->node_field);
    free(C->touched);
    free(C);
    sim->ext[CRACKS_EXT] = NULL;
}
