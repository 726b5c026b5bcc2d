/**
 * @file scene_read.h
 * @brief Reading a scene from a parsed libconfig tree, with messages that
 *        name the file, the line and the key.
 */
#ifndef MPM_SCENE_READ_H
#define MPM_SCENE_READ_H

#include <libconfig.h>
#include <stddef.h>

#include "sim.h"

/** Where messages go while a scene is read. */
typedef struct SceneReader {
    const char *file;  /**< scene file name */
    char *err;         /**< message buffer */
    size_t errlen;     /**< its size */
    const SceneLines *lines; /**< where the tree's lines came from (NULL:
                                  from the scene file itself) */
} SceneReader;

/**
 * @brief Write "file:line: key: message" into the reader's buffer.
 *
 * The file and line are those the setting @p s came from (an @@include
 * file's own, with " (included from scene.cfg:3)" after the message); a
 * setting an override set is named by the override as typed:
 * "scene.cfg: override \"materials.[0].E=-1\": E: message".
 * @return -1, for the caller to return.
 */
int scene_error(SceneReader *r, const config_setting_t *s, const char *key,
                const char *fmt, ...) __attribute__((format(printf, 4, 5)));

/** @brief The number setting @p e holds (integer or real) into *out.
 *  @return 0; 1 when @p e is not a number (no message: the caller says
 *          what it expected); -1 with a message naming @p key when it is
 *          written in hexadecimal (not for physical quantities). */
int scene_value(SceneReader *r, const config_setting_t *e, const char *key,
                double *out);

/** @brief A number (integer or real) under @p key of @p group.
 *  @return 1 found, 0 absent (with *out = def), -1 wrong type or absent and
 *          required. */
int scene_number(SceneReader *r, const config_setting_t *group,
                 const char *key, int required, double def, double *out);

/** @brief @p n (1 to 4) finite numbers [a, b, ...] under @p key into @p out; same
 *         returns as scene_number() (@p out untouched when absent). */
int scene_numbers(SceneReader *r, const config_setting_t *group, const char *key,
                  int n, int required, double *out);

/** @brief A pair of numbers [a, b] under @p key; same returns as
 *         scene_number(). */
int scene_pair(SceneReader *r, const config_setting_t *group, const char *key,
               int required, double out[2]);

/** @brief A string under @p key; same returns as scene_number(). */
int scene_string(SceneReader *r, const config_setting_t *group,
                 const char *key, int required, const char **out);

/** @brief Refuse any member of @p group not named in @p allowed (NULL-ended). */
int scene_check_keys(SceneReader *r, const config_setting_t *group,
                     const char *const *allowed);

/**
 * @brief Refuse any member of @p group (an entry of scene section
 *        @p section) that is neither in @p core or @p more (NULL-ended,
 *        either may be NULL) nor registered for @p section by a stage of
 *        this build; a key a later stage adds is refused naming the stage.
 */
int scene_check_open_keys(SceneReader *r, const Hooks *h, const char *section,
                          const config_setting_t *group,
                          const char *const *core, const char *const *more);

/** @brief Call the parser of every key the stages registered for
 *         @p section that @p group (entry @p index) holds, as its stage
 *         and marking what it subscribes with the key and its line
 *         (hooks_begin_key()). @return 0 or -1. */
int scene_read_open_keys(Sim *sim, SceneReader *r, const char *section,
                         const config_setting_t *group, int index);

/**
 * @brief Read a shape: exactly one of rectangle, disk or polygon in @p group.
 * @return 0 or -1.
 */
int scene_shape(SceneReader *r, const config_setting_t *group, Shape *out);

/**
 * @brief The row @p name of the table chosen by @p section.@p key (a
 *        method, a material law, ...) into *out; refused with the names
 *        of the rows this build has, or the stage that adds @p name.
 * @return 0 or -1.
 */
int scene_choice(SceneReader *r, const Hooks *h, const config_setting_t *group,
                 const char *section, const char *key, const char *name,
                 const void **out);

/** @brief Fill sim->scene from @p cfg and call the stages' scene sections.
 *  @return 0, or -1 with a message. */
int scene_read(Sim *sim, const config_t *cfg, SceneReader *r);

/** @brief Apply "a.b.c=value" to @p cfg. @return 0, or -1 with a message. */
int scene_override(config_t *cfg, const char *assignment, char *err,
                   size_t errlen);

#endif
