/**
 * @file sim.c
 * @brief Loading a scene into a simulation, its totals, and its release.
 */
#include "sim.h"

#include <libconfig.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_read.h"
#include "setup.h"

void sim_init(Sim *sim)
{
    memset(sim, 0, sizeof *sim);
}

/** Read the tree, then build points, grid, loads and the time step. */
static int load_config(Sim *sim, config_t *cfg, const char *name, char *err,
                       size_t errlen)
{
    SceneReader r = {name, err, errlen};
    if (scene_read(sim, cfg, &r))
        return -1;
    int extra = sim->hooks.extra_slots ? sim->hooks.extra_slots(sim) : 0;
    if (setup_points(sim, err, errlen) || setup_grid(sim, extra, err, errlen) ||
        setup_loads(sim, err, errlen))
        return -1;
    if (sim->hooks.prepare && sim->hooks.prepare(sim, err, errlen))
        return -1;
    sim->bodyke = calloc((size_t)sim->scene.nbodies, sizeof(double));
    if (!sim->bodyke) {
        snprintf(err, errlen, "%s: out of memory", name);
        return -1;
    }
    sim_set_time_step(sim);
    return 0;
}

static int syntax_error(const config_t *cfg, const char *name, char *err,
                        size_t errlen)
{
    const char *where = config_error_file(cfg) ? config_error_file(cfg) : name;
    if (config_error_type(cfg) == CONFIG_ERR_FILE_IO)
        snprintf(err, errlen, "%s: cannot read the file", where);
    else
        snprintf(err, errlen, "%s:%d: syntax error: %s", where,
                 config_error_line(cfg), config_error_text(cfg));
    return -1;
}

int sim_load_file(Sim *sim, const char *path, int noverrides,
                  char *const *overrides, char *err, size_t errlen)
{
    config_t cfg;
    config_init(&cfg);
    /* @include "other.cfg" is read relative to the scene's folder */
    char dir[1024];
    snprintf(dir, sizeof dir, "%s", path);
    char *slash = strrchr(dir, '/');
    if (slash) {
        *slash = '\0';
        config_set_include_dir(&cfg, dir);
    }
    int rc = 0;
    if (config_read_file(&cfg, path) != CONFIG_TRUE)
        rc = syntax_error(&cfg, path, err, errlen);
    for (int k = 0; rc == 0 && k < noverrides; k++)
        rc = scene_override(&cfg, overrides[k], err, errlen);
    if (rc == 0)
        rc = load_config(sim, &cfg, path, err, errlen);
    config_destroy(&cfg);
    return rc;
}

int sim_load_string(Sim *sim, const char *text, const char *name, char *err,
                    size_t errlen)
{
    config_t cfg;
    config_init(&cfg);
    int rc = 0;
    if (config_read_string(&cfg, text) != CONFIG_TRUE)
        rc = syntax_error(&cfg, name, err, errlen);
    if (rc == 0)
        rc = load_config(sim, &cfg, name, err, errlen);
    config_destroy(&cfg);
    return rc;
}

/// [sim_totals]
Totals sim_totals(const Sim *sim)
{
    const Particles *P = &sim->pts;
    Totals t = {0, 0, 0, 0};
    for (int p = 0; p < P->n; p++) {
        double m = P->m[p];
        t.kinetic += 0.5 * m * (P->vx[p] * P->vx[p] + P->vy[p] * P->vy[p]);
        t.strain += P->vol[p] * material_energy_density(P->sxx[p], P->syy[p],
                        P->sxy[p], P->exx[p], P->eyy[p], P->exy[p]);
        t.px += m * P->vx[p];
        t.py += m * P->vy[p];
    }
    return t;
}
/// [sim_totals]

void sim_free(Sim *sim)
{
    if (sim->hooks.release)
        sim->hooks.release(sim);
    particles_free(&sim->pts);
    grid_free(&sim->grid);
    scene_free(&sim->scene);
    free(sim->bodyke);
    sim->bodyke = NULL;
}
