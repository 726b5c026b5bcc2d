/**
 * @file method_check.h
 * @brief A scene asks of its method only what the method does: what a
 *        method would skip is refused at set-up, not ignored in silence.
 */
#ifndef MPM_METHOD_CHECK_H
#define MPM_METHOD_CHECK_H

#include <libconfig.h>

#include "scene_read.h"
#include "sim.h"

/** @brief Refuse a loaded scene that asks its method (run.method) for
 *         what the method does not do: a subscriber at a step seam the
 *         method does not run (Method::seams), unless a key the method
 *         carries out itself asked for it (Method::own_keys), or a setting
 *         the method does not read (Method::ignored_keys) that the scene
 *         @p cfg gives. Each is named by its scene key, file and line.
 *  @return 0, or -1 with the message in @p r. */
int method_check_scene(const Sim *sim, const config_t *cfg, SceneReader *r);

#endif
