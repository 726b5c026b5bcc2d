/**
 * @file scene_keys.h
 * @brief The keys of the scene's core sections, one table per section:
 *        the reader checks a scene against these tables, and `mpm --keys`
 *        prints them with the keys, sections and choices that the stages of
 *        the build register, so that the book's scene reference
 *        (chapters/scene-reference.md) is checked against the same lists.
 */
#ifndef MPM_SCENE_KEYS_H
#define MPM_SCENE_KEYS_H

#include <stddef.h>
#include <stdio.h>

#include "hooks.h"

/** The core top-level sections (NULL-ended; each table below is NULL-ended). */
extern const char *const scene_section_keys[];
/** The keys of `grid`. */
extern const char *const scene_grid_keys[];
/** The keys of `run`. */
extern const char *const scene_run_keys[];
/** The keys of a material (and those of its law, MaterialLaw::keys). */
extern const char *const scene_material_keys[];
/** The keys of a body, its three shapes among them. */
extern const char *const scene_body_keys[];
/** The keys of a hold: an entry of `boundaries` or of `point_velocities`. */
extern const char *const scene_hold_keys[];
/** The keys of an entry of `loads`. */
extern const char *const scene_load_keys[];
/** The keys of a `rectangle` shape. */
extern const char *const scene_rectangle_keys[];
/** The keys of a `disk` shape. */
extern const char *const scene_disk_keys[];

/**
 * @brief Print every key a scene may have in this build, one a line:
 *        "PATH STAGE", PATH the key's place in the scene ("grid.cells",
 *        "bodies.disk.radius", a section alone: "cracks"), STAGE the stage
 *        that adds it; then the values of the stages' tables as
 *        "KEY=VALUE STAGE" ("run.update=usavg 5"). A first line
 *        "# mpm stage N ..." names the build.
 * @return 0, or -1 when a write failed.
 */
int scene_keys_print(const Hooks *h, int stage, FILE *f);

/** @brief The top-level sections of this build, comma separated, into
 *         @p buf: the core ones, then those the stages add. */
void scene_sections_list(const Hooks *h, char *buf, size_t len);

#endif
