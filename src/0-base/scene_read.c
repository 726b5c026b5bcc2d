/**
 * @file scene_read.c
 * @brief The scene file: keys, types, physical ranges, and refusals of
 *        features that later stages add.
 */
#include "scene_read.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "energy_guard.h"
#include "scene_keys.h"
#include "shape.h"
#include "scene_text.h"

/** The override that set @p s or a setting holding it (its text, kept as
 *  the setting's hook by scene_override()), or NULL. */
static const char *override_of(const config_setting_t *s)
{
    for (; s && config_setting_source_line(s) == 0; s = config_setting_parent(s))
        if (config_setting_get_hook(s))
            return config_setting_get_hook(s);
    return NULL;
}

int scene_error(SceneReader *r, const config_setting_t *s, const char *key,
                const char *fmt, ...)
{
    int line = s ? (int)config_setting_source_line(s) : 0;
    const char *file = r->file, *over = override_of(s);
    char chain[512] = "";
    int used;
    if (line > 0) {
        int part = scene_lines_find(r->lines, line, &file, &line);
        if (part >= 0)        /* an @include'd file names it, and the chain */
            scene_lines_chain(r->lines, part, chain, sizeof chain);
        else if (config_setting_source_file(s))
            file = config_setting_source_file(s);
        used = snprintf(r->err, r->errlen, "%s:%d: %s: ", file, line, key);
    } else if (over)
        used = snprintf(r->err, r->errlen, "%s: override \"%s\": %s: ", r->file,
                        over, key);
    else if (s && !config_setting_is_root(s))  /* added on the command line */
        used = snprintf(r->err, r->errlen, "%s: %s (set on the command line): ",
                        r->file, key);
    else
        used = snprintf(r->err, r->errlen, "%s: %s: ", r->file, key);
    if (used < 0 || (size_t)used >= r->errlen)
        return -1;
    va_list ap;
    va_start(ap, fmt);
    int more = vsnprintf(r->err + used, r->errlen - (size_t)used, fmt, ap);
    va_end(ap);
    if (more >= 0 && (size_t)used + (size_t)more < r->errlen)
        snprintf(r->err + used + more, r->errlen - (size_t)(used + more), "%s",
                 chain);
    return -1;
}

static int is_number(const config_setting_t *s)
{
    int t = config_setting_type(s);
    return t == CONFIG_TYPE_INT || t == CONFIG_TYPE_INT64 ||
           t == CONFIG_TYPE_FLOAT;
}

static double number_of(const config_setting_t *s)
{
    int t = config_setting_type(s);
    if (t == CONFIG_TYPE_FLOAT)
        return config_setting_get_float(s);
    if (t == CONFIG_TYPE_INT64)
        return (double)config_setting_get_int64(s);
    return (double)config_setting_get_int(s);
}

int scene_value(SceneReader *r, const config_setting_t *e, const char *key,
                double *out)
{
    if (!is_number(e))
        return 1;
    if (config_setting_get_format(e) == CONFIG_FORMAT_HEX)
        return scene_error(r, e, key, "0x%llx is hexadecimal; write numbers in "
                           "decimal", config_setting_type(e) == CONFIG_TYPE_INT ?
                           (unsigned long long)(unsigned)config_setting_get_int(e) :
                           (unsigned long long)config_setting_get_int64(e));
    *out = number_of(e);
    return 0;
}

int scene_number(SceneReader *r, const config_setting_t *group,
                 const char *key, int required, double def, double *out)
{
    const config_setting_t *s = config_setting_get_member(group, key);
    *out = def;
    if (!s)
        return required ? scene_error(r, group, key, "missing (required)") : 0;
    int rc = scene_value(r, s, key, out);
    if (rc)
        return rc < 0 ? -1 : scene_error(r, s, key, "expected a number");
    if (!isfinite(*out))
        return scene_error(r, s, key, "value %g is not finite", *out);
    return 1;
}

int scene_numbers(SceneReader *r, const config_setting_t *group, const char *key,
                  int n, int required, double *out)
{
    static const char *const form[] = {"", "one number [a]", "two numbers [a, b]",
                                       "three numbers [a, b, c]",
                                       "four numbers [a, b, c, d]"};
    const config_setting_t *s = config_setting_get_member(group, key);
    if (!s)
        return required ? scene_error(r, group, key, "missing (required)") : 0;
    int t = config_setting_type(s);
    if ((t != CONFIG_TYPE_ARRAY && t != CONFIG_TYPE_LIST) ||
        config_setting_length(s) != n)
        return scene_error(r, s, key, "expected %s", form[n]);
    for (int k = 0; k < n; k++) {
        const config_setting_t *e = config_setting_get_elem(s, (unsigned)k);
        int rc = scene_value(r, e, key, &out[k]);
        if (rc)
            return rc < 0 ? -1 : scene_error(r, s, key, "expected %s", form[n]);
        if (!isfinite(out[k]))
            return scene_error(r, s, key, "value %g is not finite", out[k]);
    }
    return 1;
}

int scene_pair(SceneReader *r, const config_setting_t *group, const char *key,
               int required, double out[2])
{
    return scene_numbers(r, group, key, 2, required, out);
}

int scene_string(SceneReader *r, const config_setting_t *group,
                 const char *key, int required, const char **out)
{
    const config_setting_t *s = config_setting_get_member(group, key);
    if (!s)
        return required ? scene_error(r, group, key, "missing (required)") : 0;
    if (config_setting_type(s) != CONFIG_TYPE_STRING)
        return scene_error(r, s, key, "expected a string in quotes");
    *out = config_setting_get_string(s);
    return 1;
}

/** Is @p name one of the NULL-ended @p list (which may be NULL)? */
static int in_list(const char *const *list, const char *name)
{
    for (const char *const *a = list; a && *a; a++)
        if (strcmp(*a, name) == 0)
            return 1;
    return 0;
}

/** Append the NULL-ended @p list to the comma-separated @p buf. */
static void append_list(char *buf, size_t len, const char *const *list)
{
    for (const char *const *a = list; a && *a; a++) {
        if (buf[0])
            strncat(buf, ", ", len - strlen(buf) - 1);
        strncat(buf, *a, len - strlen(buf) - 1);
    }
}

/// [scene_check_open_keys]
int scene_check_open_keys(SceneReader *r, const Hooks *h, const char *section,
                          const config_setting_t *group,
                          const char *const *core, const char *const *more)
{
    int n = config_setting_length(group);
    for (int k = 0; k < n; k++) {
        const config_setting_t *s = config_setting_get_elem(group, (unsigned)k);
        const char *name = config_setting_name(s);
        if (!name)
            return scene_error(r, s, "?", "expected key = value");
        if (in_list(core, name) || in_list(more, name) ||
            (h && hooks_find_key(h, section, name)))
            continue;
        char path[128];
        snprintf(path, sizeof path, "%s.%s", section, name);
        const Refusal *why = h ? hooks_find_refusal(h, path, NULL) : NULL;
        if (why)
            return scene_error(r, s, name, "this key needs %s; this build "
                               "does not have it", why->stage);
        char list[512] = "";
        append_list(list, sizeof list, core);
        append_list(list, sizeof list, more);
        for (int j = 0; h && j < h->nkeys; j++)
            if (strcmp(h->keys[j].section, section) == 0) {
                const char *one[] = {h->keys[j].key, NULL};
                append_list(list, sizeof list, one);
            }
        return scene_error(r, s, name, "unknown key (expected one of: %s)", list);
    }
    return 0;
}
/// [scene_check_open_keys]

int scene_check_keys(SceneReader *r, const config_setting_t *group,
                     const char *const *allowed)
{
    return scene_check_open_keys(r, NULL, "", group, allowed, NULL);
}

int scene_read_open_keys(Sim *sim, SceneReader *r, const char *section,
                         const config_setting_t *group, int index)
{
    const Hooks *h = &sim->hooks;
    /* sim->hooks.keys does not change while it is read */
    for (int k = 0; k < h->nkeys; k++) {
        const SceneKey *key = &h->keys[k];
        if (strcmp(key->section, section) != 0)
            continue;
        const config_setting_t *s = config_setting_get_member(group, key->key);
        if (!s)
            continue;
        int rank = sim->hooks.rank;        /* it subscribes as its stage, */
        KeyAt was = sim->hooks.reading;    /* for this key at this line */
        hooks_begin_stage(&sim->hooks, key->rank);
        hooks_begin_key(&sim->hooks, (KeyAt){key->section, key->key,
                                             (int)config_setting_source_line(s)});
        int rc = key->parse(sim, s, index, r);
        hooks_begin_key(&sim->hooks, was);
        hooks_begin_stage(&sim->hooks, rank);
        if (rc)
            return -1;
    }
    return 0;
}

static const config_setting_t *group_of(SceneReader *r,
                                        const config_setting_t *parent,
                                        const char *key, int required,
                                        int *status)
{
    const config_setting_t *s = config_setting_get_member(parent, key);
    *status = 0;
    if (!s) {
        if (required)
            *status = scene_error(r, parent, key, "missing (required)");
        return NULL;
    }
    if (config_setting_type(s) != CONFIG_TYPE_GROUP) {
        *status = scene_error(r, s, key, "expected a group { ... }");
        return NULL;
    }
    return s;
}

static int read_rectangle(SceneReader *r, const config_setting_t *g, Shape *sh)
{
    double lo[2], hi[2];
    if (scene_check_keys(r, g, scene_rectangle_keys) ||
        scene_pair(r, g, "min", 1, lo) < 0 || scene_pair(r, g, "max", 1, hi) < 0)
        return -1;
    if (!(hi[0] >= lo[0] && hi[1] >= lo[1]))   /* a line of nodes is fine */
        return scene_error(r, g, "rectangle",
                           "max [%g, %g] must not be below min [%g, %g]", hi[0],
                           hi[1], lo[0], lo[1]);
    sh->kind = SHAPE_RECTANGLE;
    sh->xmin = lo[0];
    sh->ymin = lo[1];
    sh->xmax = hi[0];
    sh->ymax = hi[1];
    return 0;
}

static int read_disk(SceneReader *r, const config_setting_t *g, Shape *sh)
{
    double c[2];
    if (scene_check_keys(r, g, scene_disk_keys) ||
        scene_pair(r, g, "center", 1, c) < 0 ||
        scene_number(r, g, "radius", 1, 0, &sh->r) < 0 ||
        scene_number(r, g, "inner_radius", 0, 0, &sh->rin) < 0)
        return -1;
    if (!(sh->r > 0))
        return scene_error(r, config_setting_get_member(g, "radius"), "radius",
                           "%g must be > 0", sh->r);
    if (!(sh->rin >= 0 && sh->rin < sh->r))
        return scene_error(r, config_setting_get_member(g, "inner_radius"),
                           "inner_radius", "%g must be in [0, radius)", sh->rin);
    sh->kind = SHAPE_DISK;
    sh->cx = c[0];
    sh->cy = c[1];
    sh->xmin = c[0] - sh->r;
    sh->xmax = c[0] + sh->r;
    sh->ymin = c[1] - sh->r;
    sh->ymax = c[1] + sh->r;
    return 0;
}

static int read_polygon(SceneReader *r, const config_setting_t *s, Shape *sh)
{
    int n = config_setting_length(s);
    if (config_setting_type(s) != CONFIG_TYPE_LIST || n < 3)
        return scene_error(r, s, "polygon",
                           "expected a list of at least 3 points ( [x, y], ... )");
    sh->kind = SHAPE_POLYGON;
    sh->nv = n;
    sh->v = malloc(2 * (size_t)n * sizeof(double));
    if (!sh->v)
        return scene_error(r, s, "polygon", "out of memory");
    sh->xmin = sh->ymin = INFINITY;
    sh->xmax = sh->ymax = -INFINITY;
    for (int k = 0; k < n; k++) {
        const config_setting_t *e = config_setting_get_elem(s, (unsigned)k);
        int t = config_setting_type(e), rc = 1;
        double x, y;
        if ((t == CONFIG_TYPE_ARRAY || t == CONFIG_TYPE_LIST) &&
            config_setting_length(e) == 2 &&
            (rc = scene_value(r, config_setting_get_elem(e, 0), "polygon", &x)) == 0)
            rc = scene_value(r, config_setting_get_elem(e, 1), "polygon", &y);
        if (rc < 0)
            return -1;
        if (rc)
            return scene_error(r, e, "polygon", "point %d: expected [x, y]", k);
        sh->v[2 * k] = x;
        sh->v[2 * k + 1] = y;
        sh->xmin = fmin(sh->xmin, x);
        sh->xmax = fmax(sh->xmax, x);
        sh->ymin = fmin(sh->ymin, y);
        sh->ymax = fmax(sh->ymax, y);
    }
    if (!(sh->xmax > sh->xmin && sh->ymax > sh->ymin))
        return scene_error(r, s, "polygon", "the points enclose no area");
    return 0;
}

int scene_shape(SceneReader *r, const config_setting_t *group, Shape *out)
{
    static const char *const kinds[] = {"rectangle", "disk", "polygon"};
    const config_setting_t *found = NULL;
    int which = -1;
    for (int k = 0; k < 3; k++) {
        const config_setting_t *s = config_setting_get_member(group, kinds[k]);
        if (!s)
            continue;
        if (found)
            return scene_error(r, s, kinds[k],
                               "give one shape only (also found %s)", kinds[which]);
        found = s;
        which = k;
    }
    memset(out, 0, sizeof *out);
    if (!found)
        return scene_error(r, group, "shape",
                           "missing: give one of rectangle, disk or polygon");
    if (which < 2 && config_setting_type(found) != CONFIG_TYPE_GROUP)
        return scene_error(r, found, kinds[which], "expected a group { ... }");
    if (which == 0)
        return read_rectangle(r, found, out);
    if (which == 1)
        return read_disk(r, found, out);
    return read_polygon(r, found, out);
}

int scene_choice(SceneReader *r, const Hooks *h, const config_setting_t *group,
                 const char *section, const char *key, const char *name,
                 const void **out)
{
    char path[128];
    snprintf(path, sizeof path, "%s.%s", section, key);
    *out = hooks_find_choice(h, path, name);
    if (*out)
        return 0;
    const config_setting_t *s = config_setting_get_member(group, key);
    const Refusal *why = hooks_find_refusal(h, path, name);
    if (why)
        return scene_error(r, s ? s : group, key, "\"%s\" is added by %s; this "
                           "build does not have it", name, why->stage);
    char list[256];
    hooks_list_choices(h, path, list, sizeof list);
    return scene_error(r, s ? s : group, key, "\"%s\" is not known (expected "
                       "one of: %s)", name, list);
}

static int read_grid(Sim *sim, SceneReader *r, const config_setting_t *root)
{
    int st;
    const config_setting_t *g = group_of(r, root, "grid", 1, &st);
    Scene *sc = &sim->scene;
    double o[2] = {0, 0}, n[2], h[2];
    if (!g || scene_check_keys(r, g, scene_grid_keys) ||
        scene_pair(r, g, "origin", 0, o) < 0 ||
        scene_pair(r, g, "cells", 1, n) < 0 || scene_pair(r, g, "cell_size", 1, h) < 0)
        return -1;
    const config_setting_t *cs = config_setting_get_member(g, "cells");
    if (n[0] != floor(n[0]) || n[1] != floor(n[1]) || n[0] < 1 || n[1] < 1 ||
        n[0] * n[1] > 1e8)
        return scene_error(r, cs, "cells", "[%g, %g] must be whole numbers >= 1 "
                           "(and at most 1e8 cells)", n[0], n[1]);
    if (!(h[0] > 0 && h[1] > 0))
        return scene_error(r, config_setting_get_member(g, "cell_size"), "cell_size",
                           "[%g, %g] must be > 0", h[0], h[1]);
    sc->ox = o[0];
    sc->oy = o[1];
    sc->ncx = (int)n[0];
    sc->ncy = (int)n[1];
    sc->dx = h[0];
    sc->dy = h[1];
    return 0;
}

static int read_run(Sim *sim, SceneReader *r, const config_setting_t *root)
{
    int st;
    const config_setting_t *g = group_of(r, root, "run", 1, &st);
    RunSettings *run = &sim->scene.run;
    double gr[2] = {0, 0}, snaps, hist, ckpt, threads;
    const char *update = "musl", *plane = "stress", *method = "mpm";
    const char *rate = "unrotated", *precision = "usual", *units = "mm-g-ms";
    const char *output = "ascii";
    const char *shape = "linear";
    if (!g ||
        scene_check_open_keys(r, &sim->hooks, "run", g, scene_run_keys, NULL) ||
        scene_number(r, g, "time", 1, 0, &run->time) < 0 ||
        scene_number(r, g, "cfl", 0, 0.5, &run->cfl) < 0 ||
        scene_number(r, g, "damping", 0, 0.0, &run->damping) < 0 ||
        scene_pair(r, g, "gravity", 0, gr) < 0 ||
        scene_number(r, g, "gravity_ramp", 0, 0.0, &run->gravity_ramp) < 0 ||
        scene_number(r, g, "snapshots", 0, 10, &snaps) < 0 ||
        scene_number(r, g, "history_every", 0, 0, &hist) < 0 ||
        scene_number(r, g, "checkpoint_every", 0, 0, &ckpt) < 0 ||
        scene_number(r, g, "threads", 0, 0, &threads) < 0 ||
        scene_number(r, g, "energy_limit", 0, ENERGY_LIMIT_DEFAULT,
                     &run->energy_limit) < 0 ||
        scene_string(r, g, "update", 0, &update) < 0 ||
        scene_string(r, g, "method", 0, &method) < 0 ||
        scene_string(r, g, "plane", 0, &plane) < 0 ||
        scene_string(r, g, "stress_rate", 0, &rate) < 0 ||
        scene_string(r, g, "precision", 0, &precision) < 0 ||
        scene_string(r, g, "units", 0, &units) < 0 ||
        scene_string(r, g, "output", 0, &output) < 0 ||
        scene_string(r, g, "shape", 0, &shape) < 0)
        return -1;
    run->units = units_find(units);
    if (!run->units)
        return scene_error(r, config_setting_get_member(g, "units"), "units",
                           "\"%s\": expected \"mm-g-ms\" (the default) or \"SI\"",
                           units);
    if (strcmp(precision, "usual") == 0 || strcmp(precision, "full") == 0)
        run->full_precision = precision[0] == 'f';
    else
        return scene_error(r, config_setting_get_member(g, "precision"),
                           "precision", "\"%s\": expected \"usual\" (10 "
                           "significant digits) or \"full\" (17)", precision);
    if (config_setting_get_member(g, "threads") &&
        !(threads >= 1 && threads <= 1024 && threads == floor(threads)))
        return scene_error(r, config_setting_get_member(g, "threads"), "threads",
                           "%g: expected a whole number of threads from 1 to "
                           "1024 (leave it out for OMP_NUM_THREADS, or every "
                           "core)", threads);
    run->threads = (int)threads;
    if (strcmp(output, "ascii") == 0 || strcmp(output, "binary") == 0)
        run->binary = output[0] == 'b';
    else
        return scene_error(r, config_setting_get_member(g, "output"),
                           "output", "\"%s\": expected \"ascii\" (text: "
                           "particles_NNNNN.vtu, grid_NNNNN.csv and "
                           "particles_final.csv) or \"binary\" (binary "
                           ".vtu for all three)", output);
    if (scene_choice(r, &sim->hooks, g, "run", "method", method,
                     (const void **)&run->method) ||
        scene_choice(r, &sim->hooks, g, "run", "shape", shape,
                     (const void **)&run->shape))
        return -1;
    run->stencil = run->shape->stencil;
    const config_setting_t *ins = config_setting_get_member(g, "allow_cfl_above_one");
    if (ins && config_setting_type(ins) != CONFIG_TYPE_BOOL)
        return scene_error(r, ins, "allow_cfl_above_one", "expected true or false");
    run->allow_cfl_above_one = ins ? config_setting_get_bool(ins) : 0;
    run->gx = gr[0];
    run->gy = gr[1];
    if (!(run->time > 0))
        return scene_error(r, config_setting_get_member(g, "time"), "time",
                           "%g must be > 0", run->time);
    if (!(run->cfl > 0))
        return scene_error(r, config_setting_get_member(g, "cfl"), "cfl",
                           "%g must be > 0", run->cfl);
    if (run->cfl > 1 && !run->allow_cfl_above_one)
        return scene_error(r, config_setting_get_member(g, "cfl"), "cfl",
                           "%g exceeds 1, the explicit stability limit; set "
                           "allow_cfl_above_one = true to insist", run->cfl);
    if (!(run->gravity_ramp >= 0))
        return scene_error(r, config_setting_get_member(g, "gravity_ramp"),
                           "gravity_ramp", "%g must be >= 0 (a time; 0: gravity "
                           "at once)", run->gravity_ramp);
    if (!(run->damping >= 0))
        return scene_error(r, config_setting_get_member(g, "damping"), "damping",
                           "%g must be >= 0", run->damping);
    if (!(run->energy_limit == 0 || (run->energy_limit > 1 && isfinite(run->energy_limit))))
        return scene_error(r, config_setting_get_member(g, "energy_limit"),
                           "energy_limit", "%g: expected a finite factor above 1 "
                           "(stop a run whose energy passes that many times the "
                           "energy put in; default %g) or 0 (never)",
                           run->energy_limit, ENERGY_LIMIT_DEFAULT);
    if (snaps < 0 || snaps != floor(snaps) || snaps > 100000)
        return scene_error(r, config_setting_get_member(g, "snapshots"), "snapshots",
                           "%g must be a whole number in [0, 100000]", snaps);
    if (hist < 0 || hist != floor(hist) || hist > 1e9)
        return scene_error(r, config_setting_get_member(g, "history_every"),
                           "history_every", "%g must be a whole number >= 0", hist);
    if (ckpt < 0 || ckpt != floor(ckpt) || ckpt > 1e15)
        return scene_error(r, config_setting_get_member(g, "checkpoint_every"),
                           "checkpoint_every", "%g must be a whole number >= 0",
                           ckpt);
    run->snapshots = (int)snaps;
    run->history_every = (int)hist;
    run->checkpoint_every = (long)ckpt;
    if (strcmp(plane, "stress") == 0)
        run->plane = PLANE_STRESS;
    else if (strcmp(plane, "strain") == 0)
        run->plane = PLANE_STRAIN;
    else
        return scene_error(r, config_setting_get_member(g, "plane"), "plane",
                           "\"%s\": expected \"stress\" or \"strain\"", plane);
    if (strcmp(rate, "unrotated") == 0 || strcmp(rate, "jaumann") == 0)
        run->objective = rate[0] == 'j';
    else
        return scene_error(r, config_setting_get_member(g, "stress_rate"),
                           "stress_rate", "\"%s\": expected \"unrotated\" (the "
                           "paper's) or \"jaumann\" (rotated with the spin)", rate);
    run->scheme = hooks_find_scheme(&sim->hooks, update);
    if (!run->scheme) {
        const config_setting_t *u = config_setting_get_member(g, "update");
        const Refusal *why = hooks_find_refusal(&sim->hooks, "run.update", update);
        if (why)
            return scene_error(r, u, "update", "\"%s\" is added by %s; this "
                               "build does not have it", update, why->stage);
        char list[128] = "";
        for (int k = 0; k < sim->hooks.nschemes; k++) {
            strncat(list, sim->hooks.schemes[k].name, sizeof list - strlen(list) - 1);
            if (k + 1 < sim->hooks.nschemes)
                strncat(list, ", ", sizeof list - strlen(list) - 1);
        }
        return scene_error(r, u, "update", "\"%s\" is not a stress-update "
                           "scheme (expected one of: %s)", update, list);
    }
    return scene_read_open_keys(sim, r, "run", g, 0);
}

/// [read_materials]
static int read_materials(Sim *sim, SceneReader *r, const config_setting_t *root)
{
    const config_setting_t *l = config_setting_get_member(root, "materials");
    Scene *sc = &sim->scene;
    if (!l)
        return scene_error(r, root, "materials", "missing (required)");
    if (config_setting_type(l) != CONFIG_TYPE_LIST || config_setting_length(l) < 1)
        return scene_error(r, l, "materials", "expected a list ( { ... }, ... )");
    sc->nmat = config_setting_length(l);
    sc->mat = calloc((size_t)sc->nmat, sizeof(Material));
    if (!sc->mat)
        return scene_error(r, l, "materials", "out of memory");
    for (int k = 0; k < sc->nmat; k++) {
        const config_setting_t *g = config_setting_get_elem(l, (unsigned)k);
        Material *m = &sc->mat[k];
        const char *name, *law = "hooke";
        if (config_setting_type(g) != CONFIG_TYPE_GROUP)
            return scene_error(r, g, "materials", "entry %d: expected a group", k);
        if (scene_string(r, g, "law", 0, &law) < 0 ||
            scene_choice(r, &sim->hooks, g, "materials", "law", law,
                         (const void **)&m->law) ||
            scene_check_open_keys(r, &sim->hooks, "materials", g,
                                  scene_material_keys,
                                  m->law->keys) ||
            scene_string(r, g, "name", 1, &name) < 0 ||
            scene_number(r, g, "rho", 1, 0, &m->rho) < 0 || m->law->read(r, g, m))
            return -1;
        snprintf(m->name, sizeof m->name, "%s", name);
        for (int j = 0; j < k; j++)
            if (strcmp(sc->mat[j].name, m->name) == 0)
                return scene_error(r, g, "name", "material \"%s\" defined twice", name);
        if (!(m->rho > 0))
            return scene_error(r, config_setting_get_member(g, "rho"), "rho",
                               "%g: density must be > 0 (g/mm^3)", m->rho);
        m->law->prepare(m, sc->run.plane);
        if (scene_read_open_keys(sim, r, "materials", g, k))
            return -1;
    }
    return 0;
}
/// [read_materials]

static int inside_grid(const Scene *sc, const Shape *s)
{
    return s->xmin >= sc->ox && s->ymin >= sc->oy &&
           s->xmax <= sc->ox + sc->ncx * sc->dx &&
           s->ymax <= sc->oy + sc->ncy * sc->dy;
}

static int read_bodies(Sim *sim, SceneReader *r, const config_setting_t *root)
{
    const config_setting_t *l = config_setting_get_member(root, "bodies");
    Scene *sc = &sim->scene;
    if (!l)
        return scene_error(r, root, "bodies", "missing (required)");
    if (config_setting_type(l) != CONFIG_TYPE_LIST || config_setting_length(l) < 1)
        return scene_error(r, l, "bodies", "expected a list ( { ... }, ... )");
    int n = config_setting_length(l);
    sc->bodies = calloc((size_t)n, sizeof(Body));
    if (!sc->bodies)
        return scene_error(r, l, "bodies", "out of memory");
    for (int k = 0; k < n; k++) {
        const config_setting_t *g = config_setting_get_elem(l, (unsigned)k);
        Body *b = &sc->bodies[k];
        const char *name = NULL, *mat;
        double v[2] = {0, 0}, centre[2] = {0, 0}, ppc, w = 0;
        int has_w, has_L, has_c;
        if (config_setting_type(g) != CONFIG_TYPE_GROUP)
            return scene_error(r, g, "bodies", "entry %d: expected a group", k);
        sc->nbodies = k + 1;
        b->line = (int)config_setting_source_line(g);
        if (scene_check_open_keys(r, &sim->hooks, "bodies", g, scene_body_keys,
                                  NULL) ||
            scene_string(r, g, "name", 0, &name) < 0 ||
            scene_string(r, g, "material", 1, &mat) < 0 ||
            scene_number(r, g, "thickness", 0, sc->run.units->mm, &b->thickness) < 0 ||
            scene_pair(r, g, "velocity", 0, v) < 0 ||
            (has_w = scene_number(r, g, "angular_velocity", 0, 0, &w)) < 0 ||
            (has_L = scene_numbers(r, g, "velocity_gradient", 4, 0, b->L)) < 0 ||
            (has_c = scene_pair(r, g, "center", 0, centre)) < 0 ||
            scene_numbers(r, g, "stress", 3, 0, b->stress) < 0 ||
            scene_number(r, g, "points_per_cell", 0, 2, &ppc) < 0 ||
            scene_shape(r, g, &b->shape) < 0)
            return -1;
        if (name)
            snprintf(b->name, sizeof b->name, "%s", name);
        else
            snprintf(b->name, sizeof b->name, "body%d", k);
        for (const char *c = b->name; *c; c++)
            if (!isalnum((unsigned char)*c) && *c != '_' && *c != '-')
                return scene_error(r, g, "name", "\"%s\": use letters, digits, "
                                   "'_' and '-' only", b->name);
        b->material = -1;
        for (int j = 0; j < sc->nmat; j++)
            if (strcmp(sc->mat[j].name, mat) == 0)
                b->material = j;
        if (b->material < 0)
            return scene_error(r, config_setting_get_member(g, "material"), "material",
                               "\"%s\" is not defined under materials", mat);
        if (!(b->thickness > 0))
            return scene_error(r, config_setting_get_member(g, "thickness"),
                               "thickness", "%g must be > 0", b->thickness);
        if (ppc != floor(ppc) || ppc < 1 || ppc > 16)
            return scene_error(r, config_setting_get_member(g, "points_per_cell"),
                               "points_per_cell", "%g must be a whole number in "
                               "[1, 16]", ppc);
        b->ppc = (int)ppc;
        if ((has_w || has_L) && !has_c)
            return scene_error(r, config_setting_get_member(g, has_w ?
                               "angular_velocity" : "velocity_gradient"),
                               has_w ? "angular_velocity" : "velocity_gradient",
                               "needs the centre it turns about: center = [x, y] "
                               "(the point that moves with velocity)");
        if (has_c && !has_w && !has_L)
            return scene_error(r, config_setting_get_member(g, "center"), "center",
                               "is the centre of angular_velocity or "
                               "velocity_gradient; the body gives neither");
        b->vx = v[0];
        b->vy = v[1];
        b->cx = centre[0];
        b->cy = centre[1];
        b->L[1] -= w;                           /* spin w: [0 -w; w 0] */
        b->L[2] += w;
        if (!inside_grid(sc, &b->shape))
            return scene_error(r, g, b->name, "the body [%g, %g] x [%g, %g] lies "
                               "outside the grid [%g, %g] x [%g, %g]",
                               b->shape.xmin, b->shape.xmax, b->shape.ymin,
                               b->shape.ymax, sc->ox, sc->ox + sc->ncx * sc->dx,
                               sc->oy, sc->oy + sc->ncy * sc->dy);
        if (scene_read_open_keys(sim, r, "bodies", g, k))
            return -1;
    }
    return 0;
}

static int read_regions(SceneReader *r, const config_setting_t *root,
                        const char *key, int *count, void **items, size_t size)
{
    const config_setting_t *l = config_setting_get_member(root, key);
    if (!l)
        return 0;
    if (config_setting_type(l) != CONFIG_TYPE_LIST)
        return scene_error(r, l, key, "expected a list ( { ... }, ... )");
    *count = config_setting_length(l);
    *items = calloc((size_t)*count + 1, size);
    if (!*items)
        return scene_error(r, l, key, "out of memory");
    for (int k = 0; k < *count; k++)
        if (config_setting_type(config_setting_get_elem(l, (unsigned)k)) !=
            CONFIG_TYPE_GROUP)
            return scene_error(r, config_setting_get_elem(l, (unsigned)k), key,
                               "entry %d: expected a group", k);
    return 1;
}

/** "x", "y" or "xy" into GRID_FIX_ bits; 0 for anything else. */
static unsigned fix_bits(const char *fix)
{
    return strcmp(fix, "x") == 0 ? GRID_FIX_X : strcmp(fix, "y") == 0 ? GRID_FIX_Y
         : strcmp(fix, "xy") == 0 ? GRID_FIX_X | GRID_FIX_Y : 0u;
}

/** The table of group @p g, "table = ( [t, vx, vy], ... )" with t
 *  increasing, into @p h (its velocity: the largest |value|, so that a
 *  table that moves is moving). */
static int read_hold_table(SceneReader *r, const config_setting_t *g, Hold *h,
                           double v[2])
{
    const config_setting_t *t = config_setting_get_member(g, "table");
    if (config_setting_type(t) != CONFIG_TYPE_LIST || config_setting_length(t) < 1)
        return scene_error(r, t, "table", "expected a list of rows ( [t, vx, vy], ... )");
    h->nrows = config_setting_length(t);
    h->table = malloc(sizeof(double) * 3 * (size_t)h->nrows);
    if (!h->table)
        return scene_error(r, t, "table", "out of memory");
    for (int k = 0; k < h->nrows; k++) {
        const config_setting_t *row = config_setting_get_elem(t, (unsigned)k);
        double *x = h->table + 3 * k;
        int n = config_setting_type(row) == CONFIG_TYPE_ARRAY ? config_setting_length(row) : 0;
        for (int j = 0; j < 3 && n == 3; j++) {
            int rc = scene_value(r, config_setting_get_elem(row, (unsigned)j),
                                 "table", &x[j]);
            if (rc < 0)
                return -1;
            n = rc ? 0 : n;
        }
        if (n != 3 || !isfinite(x[0] + x[1] + x[2]))
            return scene_error(r, row, "table", "row %d: expected three finite "
                               "numbers [t, vx, vy]", k);
        if (k > 0 && !(x[0] > x[-3]))
            return scene_error(r, row, "table", "row %d: time %g does not follow "
                               "%g", k, x[0], x[-3]);
        for (int j = 0; j < 2; j++)
            if (fabs(x[1 + j]) > fabs(v[j]))
                v[j] = x[1 + j];
    }
    return 0;
}

/** The hold of group @p g: fix ("x", "y", "xy"; @p fix_default when not
 *  given, NULL: required); velocity (required when @p need_velocity,
 *  unless a table is given) with ramp (>= 0), or a table; only along held
 *  directions. */
static int read_hold(SceneReader *r, const config_setting_t *g,
                     const char *fix_default, int need_velocity, Hold *h)
{
    const char *fix = fix_default;
    double v[2] = {0.0, 0.0};
    int table = config_setting_get_member(g, "table") != NULL;
    if (table && (config_setting_get_member(g, "velocity") ||
                  config_setting_get_member(g, "ramp")))
        return scene_error(r, config_setting_get_member(g, "table"), "table",
                           "gives the velocity in time; velocity and ramp with it "
                           "would contradict it");
    if (scene_string(r, g, "fix", fix_default == NULL, &fix) < 0 ||
        scene_pair(r, g, "velocity", need_velocity && !table, v) < 0 ||
        scene_number(r, g, "ramp", 0, 0.0, &h->ramp) < 0 ||
        (table && read_hold_table(r, g, h, v)))
        return -1;
    h->fix = fix_bits(fix);
    if (!h->fix)
        return scene_error(r, config_setting_get_member(g, "fix"), "fix",
                           "\"%s\": expected \"x\", \"y\" or \"xy\"", fix);
    const char *key = table ? "table" : "velocity";
    if ((v[0] != 0.0 && !(h->fix & GRID_FIX_X)) || (v[1] != 0.0 && !(h->fix & GRID_FIX_Y)))
        return scene_error(r, config_setting_get_member(g, key), key,
                           "[%g, %g] moves a direction that fix = \"%s\" leaves "
                           "free", v[0], v[1], fix);
    if (!(h->ramp >= 0.0))
        return scene_error(r, config_setting_get_member(g, "ramp"), "ramp",
                           "%g must be >= 0", h->ramp);
    h->vx = v[0];
    h->vy = v[1];
    return 0;
}

static int read_boundaries(Sim *sim, SceneReader *r, const config_setting_t *root)
{
    Scene *sc = &sim->scene;
    int st = read_regions(r, root, "boundaries", &sc->nbc, (void **)&sc->bc,
                          sizeof(Boundary));
    if (st <= 0)
        return st;
    const config_setting_t *l = config_setting_get_member(root, "boundaries");
    for (int k = 0; k < sc->nbc; k++) {
        const config_setting_t *g = config_setting_get_elem(l, (unsigned)k);
        Boundary *B = &sc->bc[k];
        B->line = (int)config_setting_source_line(g);
        if (scene_check_open_keys(r, &sim->hooks, "boundaries", g,
                                  scene_hold_keys, NULL) ||
            scene_shape(r, g, &B->region) < 0 ||
            read_hold(r, g, NULL, 0, &B->hold))
            return -1;
        B->moving = B->hold.vx != 0.0 || B->hold.vy != 0.0;
        if (scene_read_open_keys(sim, r, "boundaries", g, k))  /* stage 8's mirror */
            return -1;
    }
    return 0;
}

static int read_loads(Sim *sim, SceneReader *r, const config_setting_t *root)
{
    Scene *sc = &sim->scene;
    int st = read_regions(r, root, "loads", &sc->nloads, (void **)&sc->loads,
                          sizeof(Load));
    if (st <= 0)
        return st;
    const config_setting_t *l = config_setting_get_member(root, "loads");
    for (int k = 0; k < sc->nloads; k++) {
        const config_setting_t *g = config_setting_get_elem(l, (unsigned)k);
        Load *L = &sc->loads[k];
        double f[2];
        L->line = (int)config_setting_source_line(g);
        if (scene_check_keys(r, g, scene_load_keys) ||
            scene_shape(r, g, &L->region) < 0 ||
            scene_pair(r, g, "force", 1, f) < 0 ||
            scene_number(r, g, "ramp", 0, 0.0, &L->ramp) < 0)
            return -1;
        if (!(L->ramp >= 0))
            return scene_error(r, config_setting_get_member(g, "ramp"), "ramp",
                               "%g must be >= 0", L->ramp);
        L->fx = f[0];
        L->fy = f[1];
    }
    return 0;
}

static int read_held_points(Sim *sim, SceneReader *r, const config_setting_t *root)
{
    Scene *sc = &sim->scene;
    int st = read_regions(r, root, "point_velocities", &sc->nheld, (void **)&sc->held,
                          sizeof(HeldPoints));
    if (st <= 0)
        return st;
    const config_setting_t *l = config_setting_get_member(root, "point_velocities");
    for (int k = 0; k < sc->nheld; k++) {
        const config_setting_t *g = config_setting_get_elem(l, (unsigned)k);
        HeldPoints *H = &sc->held[k];
        H->line = (int)config_setting_source_line(g);
        if (scene_check_keys(r, g, scene_hold_keys) ||
            scene_shape(r, g, &H->region) < 0 ||
            read_hold(r, g, "xy", 1, &H->hold))
            return -1;
    }
    return 0;
}

int scene_read(Sim *sim, const config_t *cfg, SceneReader *r)
{
    const config_setting_t *root = config_root_setting(cfg);
    sim->scene.file = r->file;
    /* every top-level key: ours, a stage's section, a later stage's, or a typo */
    for (int k = 0; k < config_setting_length(root); k++) {
        const config_setting_t *s = config_setting_get_elem(root, (unsigned)k);
        const char *name = config_setting_name(s);
        if (in_list(scene_section_keys, name) ||
            hooks_find_key(&sim->hooks, "", name))
            continue;
        const Refusal *why = hooks_find_refusal(&sim->hooks, name, NULL);
        if (why)
            return scene_error(r, s, name, "this scene needs %s; this build "
                               "does not have it", why->stage);
        char list[256];
        scene_sections_list(&sim->hooks, list, sizeof list);
        return scene_error(r, s, name, "unknown key (expected one of: %s)", list);
    }
    if (read_grid(sim, r, root) || read_run(sim, r, root) ||
        read_materials(sim, r, root) || read_bodies(sim, r, root) ||
        read_boundaries(sim, r, root) || read_loads(sim, r, root) ||
        read_held_points(sim, r, root))
        return -1;
    /* the stages' sections, in stage order */
    return scene_read_open_keys(sim, r, "", root, 0);
}

/* ---- command-line overrides "a.b.c=value" -------------------------------- */

/** Add a copy of @p from to @p parent under @p name (NULL inside an array
 *  or list): scalars (with their format, hexadecimal or not), arrays,
 *  lists and groups. NULL when it cannot. */
static config_setting_t *copy_setting(config_setting_t *parent, const char *name,
                                      const config_setting_t *from)
{
    int type = config_setting_type(from);
    config_setting_t *s = config_setting_add(parent, name, type);
    if (!s)
        return NULL;
    switch (type) {
    case CONFIG_TYPE_INT:
        return config_setting_set_int(s, config_setting_get_int(from)) &&
               config_setting_set_format(s, config_setting_get_format(from)) ? s : NULL;
    case CONFIG_TYPE_INT64:
        return config_setting_set_int64(s, config_setting_get_int64(from)) &&
               config_setting_set_format(s, config_setting_get_format(from)) ? s : NULL;
    case CONFIG_TYPE_FLOAT:
        return config_setting_set_float(s, config_setting_get_float(from)) ? s : NULL;
    case CONFIG_TYPE_BOOL:
        return config_setting_set_bool(s, config_setting_get_bool(from)) ? s : NULL;
    case CONFIG_TYPE_STRING:
        return config_setting_set_string(s, config_setting_get_string(from)) ? s : NULL;
    default:                                  /* array, list, group */
        for (int k = 0; k < config_setting_length(from); k++) {
            const config_setting_t *e = config_setting_get_elem(from, (unsigned)k);
            if (!copy_setting(s, type == CONFIG_TYPE_GROUP ? config_setting_name(e)
                                                           : NULL, e))
                return NULL;
        }
        return s;
    }
}

int scene_override(config_t *cfg, const char *assignment, char *err,
                   size_t errlen)
{
    char path[256];
    const char *eq = strchr(assignment, '=');
    if (!eq || eq == assignment || (size_t)(eq - assignment) >= sizeof path) {
        snprintf(err, errlen, "override \"%s\": expected key.path=value", assignment);
        return -1;
    }
    memcpy(path, assignment, (size_t)(eq - assignment));
    path[eq - assignment] = '\0';
    const char *value = eq + 1;
    char *dot = strrchr(path, '.');
    config_setting_t *parent;
    const char *name;
    if (dot) {
        *dot = '\0';
        parent = config_lookup(cfg, path);
        name = dot + 1;
    } else {
        parent = config_root_setting(cfg);
        name = path;
    }
    if (!parent || config_setting_type(parent) != CONFIG_TYPE_GROUP) {
        snprintf(err, errlen, "override \"%s\": no group \"%s\" in the scene",
                 assignment, path);
        return -1;
    }
    if (config_setting_get_member(parent, name))
        config_setting_remove(parent, name);
    /* the value as libconfig reads it (a number, true, "text", [a, b], ...);
       a bare word that it does not read is a string (run.update=usf) */
    size_t len = strlen(value) + 16;
    char *text = malloc(len);
    config_t one;
    config_init(&one);
    config_setting_t *s = NULL;
    TextScan scan = {TEXT_CODE, ""};
    const char *bad;
    int badlen;
    if (text) {
        snprintf(text, len, "v = %s;", value);
        if (scene_text_scan(text, text + strlen(text), &scan, &bad, &badlen)) {
            char why[256];
            scene_text_range_message(bad, badlen, why, sizeof why);
            snprintf(err, errlen, "override \"%s\": %s: %s", assignment, name, why);
            config_destroy(&one);
            free(text);
            return -1;
        }
        if (*value && config_read_string(&one, text) == CONFIG_TRUE)
            s = copy_setting(parent, name, config_lookup(&one, "v"));
        else if ((s = config_setting_add(parent, name, CONFIG_TYPE_STRING)) != NULL &&
                 !config_setting_set_string(s, value))
            s = NULL;
    }
    config_destroy(&one);
    free(text);
    if (!s) {
        snprintf(err, errlen, "override \"%s\": cannot set \"%s\"", assignment, name);
        return -1;
    }
    /* scene_error() names a value found wrong in it by the override */
    config_setting_set_hook(s, (void *)assignment);
    return 0;
}
