/**
 * @file scene_keys.c
 * @brief The tables of the core sections' keys, and `mpm --keys`.
 */
#include "scene_keys.h"

#include <string.h>

#include "material.h"

const char *const scene_section_keys[] = {"grid", "run", "materials", "bodies",
    "boundaries", "loads", "point_velocities", NULL};
const char *const scene_grid_keys[] = {"origin", "cells", "cell_size", NULL};
const char *const scene_run_keys[] = {"time", "cfl", "allow_cfl_above_one",
    "update", "method", "damping", "plane", "gravity", "gravity_ramp", "snapshots",
    "history_every", "stress_rate", "precision", "units", "checkpoint_every",
    "output", "threads", "shape", "energy_limit", NULL};
const char *const scene_material_keys[] = {"name", "law", "rho", NULL};
const char *const scene_body_keys[] = {"name", "material", "thickness",
    "velocity", "angular_velocity", "velocity_gradient", "center", "stress",
    "points_per_cell", "rectangle", "disk", "polygon", NULL};
const char *const scene_hold_keys[] = {"rectangle", "fix", "velocity", "ramp",
    "table", NULL};
const char *const scene_load_keys[] = {"rectangle", "force", "ramp", NULL};
const char *const scene_rectangle_keys[] = {"min", "max", NULL};
const char *const scene_disk_keys[] = {"center", "radius", "inner_radius", NULL};

/** A group of the scene and the table of its keys. */
typedef struct KeyTable {
    const char *path;           /**< where the group is: "bodies.disk" */
    const char *const *keys;    /**< its keys */
} KeyTable;

/** Every core group, the shapes inside the sections that take them. */
static const KeyTable core[] = {
    {"", scene_section_keys},
    {"grid", scene_grid_keys},
    {"run", scene_run_keys},
    {"materials", scene_material_keys},
    {"bodies", scene_body_keys},
    {"bodies.rectangle", scene_rectangle_keys},
    {"bodies.disk", scene_disk_keys},
    {"boundaries", scene_hold_keys},
    {"boundaries.rectangle", scene_rectangle_keys},
    {"loads", scene_load_keys},
    {"loads.rectangle", scene_rectangle_keys},
    {"point_velocities", scene_hold_keys},
    {"point_velocities.rectangle", scene_rectangle_keys},
};

/** Print "PATH.KEY STAGE" for every key of @p keys (PATH "" at the top). */
static void print_keys(FILE *f, const char *path, const char *const *keys,
                       int stage)
{
    for (const char *const *k = keys; k && *k; k++)
        fprintf(f, "%s%s%s %d\n", path, path[0] ? "." : "", *k, stage);
}

int scene_keys_print(const Hooks *h, int stage, FILE *f)
{
    fprintf(f, "# mpm stage %d: the scene keys it accepts, as \"path stage\" "
               "(the stage that adds it)\n", stage);
    for (size_t t = 0; t < sizeof core / sizeof core[0]; t++)
        print_keys(f, core[t].path, core[t].keys, 1);
    /* a material has its law's keys as well */
    for (int k = 0; k < h->nchoices; k++)
        if (strcmp(h->choices[k].key, "materials.law") == 0) {
            const MaterialLaw *law = h->choices[k].impl;
            print_keys(f, "materials", law->keys, h->choices[k].rank);
        }
    /* the stages' sections and keys, with the keys of the groups they hold */
    for (int k = 0; k < h->nkeys; k++) {
        const SceneKey *s = &h->keys[k];
        char path[128];
        snprintf(path, sizeof path, "%s%s%s", s->section, s->section[0] ? "." : "",
                 s->key);
        fprintf(f, "%s %d\n", path, s->rank);
        print_keys(f, path, s->keys, s->rank);
    }
    /* the values a scene chooses from the stages' tables */
    for (int k = 0; k < h->nschemes; k++)
        fprintf(f, "run.update=%s %d\n", h->schemes[k].name, h->scheme_rank[k]);
    for (int k = 0; k < h->nchoices; k++)
        fprintf(f, "%s=%s %d\n", h->choices[k].key, h->choices[k].name,
                h->choices[k].rank);
    return fflush(f) == 0 && !ferror(f) ? 0 : -1;
}

void scene_sections_list(const Hooks *h, char *buf, size_t len)
{
    buf[0] = '\0';
    for (const char *const *k = scene_section_keys; *k; k++) {
        if (buf[0])
            strncat(buf, ", ", len - strlen(buf) - 1);
        strncat(buf, *k, len - strlen(buf) - 1);
    }
    for (int k = 0; k < h->nkeys; k++)
        if (!h->keys[k].section[0]) {
            strncat(buf, ", ", len - strlen(buf) - 1);
            strncat(buf, h->keys[k].key, len - strlen(buf) - 1);
        }
}
