/**
 * @file scene_load.c
 * @brief Loading a scene into a simulation: expand the text, read the
 *        tree and the overrides, then build points, grid, loads, the
 *        stages' set-up and the time step.
 */
#include "scene_load.h"

#include <libconfig.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "checkpoint.h"
#include "scene_include.h"
#include "footprint.h"
#include "energy_guard.h"
#include "method_check.h"
#include "scene_read.h"
#include "setup.h"

/** Set-up after points and grid exist: the field table and the arrays the
 *  seams need, then the stages' own checks (SEAM_PREPARE, in order). */
static int prepare_stages(Sim *sim, const char *name, char *err, size_t errlen)
{
    const Hooks *h = &sim->hooks;
    if ((h->seam[SEAM_TASK1_FIELDS].n && fields_enable(sim)) ||
        (h->seam[SEAM_TASK4_CONTACT].n &&
         (grid_want(&sim->grid, &sim->grid.qx) ||
          grid_want(&sim->grid, &sim->grid.qy)))) {
        snprintf(err, errlen, "%s: out of memory for the velocity fields", name);
        return -1;
    }
    const SeamList *l = &h->seam[SEAM_PREPARE];
    for (int k = 0; k < l->n; k++)
        if (l->at[k].fn.prepare(sim, l->at[k].state, err, errlen))
            return -1;
    return 0;
}

/** Read the tree, then build points, grid, loads and the time step. */
static int load_config(Sim *sim, config_t *cfg, const char *name, char *err,
                       size_t errlen)
{
    SceneReader r = {name, err, errlen, sim->scene.lines};
    if (sim->hooks.overflow) {
        snprintf(err, errlen, "%s: this build's stages register more than "
                 "HOOKS_MAX (%d) entries in one table (raise it in hooks.h)",
                 name, HOOKS_MAX);
        return -1;
    }
    if (scene_read(sim, cfg, &r))
        return -1;
    /* the scene's threads win over OMP_NUM_THREADS (OpenMP's default);
       known before the stages prepare, which may size for them */
    sim->threads = sim->scene.run.threads ? sim->scene.run.threads
                                          : omp_get_max_threads();
    const config_setting_t *grid = config_lookup(cfg, "grid");
    if (footprint_check(&sim->scene, sim->memory_limit,
                        grid ? (int)config_setting_source_line(grid) : 0, err, errlen))
        return -1;
    if (setup_points(sim, err, errlen) || setup_grid(sim, err, errlen) ||
        setup_loads(sim, err, errlen) || setup_held_points(sim, err, errlen) ||
        setup_check_totals(sim, err, errlen) || prepare_stages(sim, name, err, errlen) ||
        method_check_scene(sim, cfg, &r) ||     /* all subscribers are in */
        energy_guard_check(sim, cfg, &r))
        return -1;
    sim->bodyke = calloc((size_t)sim->scene.nbodies, sizeof(double));
    if (!sim->bodyke) {
        snprintf(err, errlen, "%s: out of memory", name);
        return -1;
    }
    if (strips_init(sim)) {           /* who writes which nodes (strips.h) */
        snprintf(err, errlen, "%s: out of memory for the threads' strips", name);
        return -1;
    }
    if (stencils_init(sim)) {         /* one stencil per point (stencils.h) */
        snprintf(err, errlen, "%s: out of memory for the points' stencils", name);
        return -1;
    }
    sim_set_time_step(sim);
    return sim_check_time_step(sim, err, errlen);
}

/** libconfig's refusal at its line of the expanded text, in the file and
 *  line it came from ("syntax error", "duplicate setting name", ...). */
static int syntax_error(const config_t *cfg, const SceneLines *m,
                        const char *name, char *err, size_t errlen)
{
    const char *file = name;
    int line = config_error_line(cfg);
    char chain[512] = "";
    int part = scene_lines_find(m, line, &file, &line);
    if (part >= 0)
        scene_lines_chain(m, part, chain, sizeof chain);
    const char *text = config_error_text(cfg);
    const char *hint = strcmp(text, "mismatched element type in array") == 0 ?
        " (an array holds integers only or reals only: 2.0, not 2, beside 0.5)" : "";
    snprintf(err, errlen, "%s:%d: %s%s%s", file, line, text, hint, chain);
    return -1;
}

/** Read the expanded @p text (or the error of its expansion, @p rc) and
 *  the overrides into a tree, then load it. */
static int load_text(Sim *sim, int rc, const char *text, const char *name,
                     int noverrides, char *const *overrides, char *err,
                     size_t errlen)
{
    config_t cfg;
    config_init(&cfg);
    if (rc == 0 && config_read_string(&cfg, text) != CONFIG_TRUE)
        rc = syntax_error(&cfg, sim->scene.lines, name, err, errlen);
    for (int k = 0; rc == 0 && k < noverrides; k++)
        rc = scene_override(&cfg, overrides[k], err, errlen);
    sim->source = name;                /* what a checkpoint names */
    sim->noverrides = noverrides;
    sim->overrides = overrides;
    sim->scene_hash = checkpoint_fingerprint(&cfg);
    if (rc == 0)
        rc = load_config(sim, &cfg, name, err, errlen);
    config_destroy(&cfg);
    return rc;
}

int sim_load_file(Sim *sim, const char *path, int noverrides,
                  char *const *overrides, char *err, size_t errlen)
{
    /* @include "other.cfg" is read relative to the file that names it */
    char *text = NULL;
    scene_lines_free(sim->scene.lines);
    sim->scene.lines = NULL;
    int rc = scene_expand_file(path, &text, &sim->scene.lines, err, errlen);
    rc = load_text(sim, rc, text, path, noverrides, overrides, err, errlen);
    free(text);
    return rc;
}

int sim_load_string(Sim *sim, const char *text, const char *name, char *err,
                    size_t errlen)
{
    char *all = NULL;
    scene_lines_free(sim->scene.lines);
    sim->scene.lines = NULL;
    int rc = scene_expand_string(text, name, &all, &sim->scene.lines, err, errlen);
    rc = load_text(sim, rc, all, name, 0, NULL, err, errlen);
    free(all);
    return rc;
}
