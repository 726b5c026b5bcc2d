/**
 * @file hooks.h
 * @brief The seams of the time step where later stages add behaviour.
 *
 * Stage 1 leaves every function pointer NULL: one velocity field, no
 * contact, no cracks.  Each later stage's installer fills the hooks it needs
 * and registers its scene sections and update schemes; the time step calls a
 * hook only when it is set, so a scene that needs none costs what
 * conventional MPM costs.
 */
#ifndef MPM_HOOKS_H
#define MPM_HOOKS_H

#include <libconfig.h>
#include <stddef.h>

#include "scene.h"

struct Sim;

/** Most update schemes, scene sections and refusals a build registers. */
#define HOOKS_MAX 16

/** A top-level scene key handled by a stage (for example "cracks"). */
typedef struct SceneSection {
    const char *key;    /**< top-level key */
    /** Parse the setting into the stage's state; write a message and return
     *  non-zero on error. */
    int (*parse)(struct Sim *sim, const config_setting_t *s, char *err,
                 size_t errlen);
} SceneSection;

/** A scene feature this build does not have, and the stage that adds it. */
typedef struct Refusal {
    const char *key;    /**< top-level key, or "run.update" for a scheme */
    const char *value;  /**< the refused value, NULL for any */
    const char *stage;  /**< words naming the stage that adds it */
} Refusal;

/// [hooks]
/** Hook table of one build. */
typedef struct Hooks {
    UpdateScheme schemes[HOOKS_MAX];  /**< registered stress-update schemes */
    int nschemes;                     /**< how many */
    SceneSection sections[HOOKS_MAX]; /**< registered scene sections */
    int nsections;                    /**< how many */
    Refusal refusals[HOOKS_MAX];      /**< features of later stages */
    int nrefusals;                    /**< how many */
    /** Grid slots to reserve beyond one per node (extra velocity fields). */
    int (*extra_slots)(const struct Sim *sim);
    /** Checks and set-up after the points and the grid exist; write a
     *  message and return non-zero to refuse the scene. */
    int (*prepare)(struct Sim *sim, char *err, size_t errlen);
    /** Task 1: assign a velocity field to every particle-node pair;
     *  non-zero (with Sim::fail filled) stops the run. */
    int (*assign_fields)(struct Sim *sim);
    /** Map the four pairs of point p (nodes in slot[]) to their field slots. */
    void (*pair_slots)(const struct Sim *sim, int p, int slot[4]);
    /** Tasks 2, 4 and 6: adjust nodal momenta for contact; non-zero stops
     *  the run. */
    int (*contact)(struct Sim *sim, int task);
    /** Task 7: move the cracks with the centre-of-mass grid velocity;
     *  non-zero stops the run. */
    int (*move_cracks)(struct Sim *sim);
    /** Extra columns of history.csv: header (row = NULL) or values. */
    void (*history_columns)(const struct Sim *sim, char *buf, size_t len,
                            int header);
    /** Extra output written with every snapshot. */
    void (*snapshot)(const struct Sim *sim, const char *dir, int index);
    /** Release the stages' state. */
    void (*release)(struct Sim *sim);
} Hooks;
/// [hooks]

/** @brief Register a stress-update scheme. @return 0, or -1 when full. */
int hooks_add_scheme(Hooks *h, const char *name, double before, double after,
                     int reextrapolate);

/** @brief Register a top-level scene section. @return 0, or -1 when full. */
int hooks_add_section(Hooks *h, const char *key,
                      int (*parse)(struct Sim *, const config_setting_t *,
                                   char *, size_t));

/** @brief Record a feature this build refuses, naming its stage. */
int hooks_add_refusal(Hooks *h, const char *key, const char *value,
                      const char *stage);

/** @brief The scheme called @p name, or NULL. */
const UpdateScheme *hooks_find_scheme(const Hooks *h, const char *name);

/** @brief The refusal for @p key (and @p value, if it has one), or NULL. */
const Refusal *hooks_find_refusal(const Hooks *h, const char *key,
                                  const char *value);

#endif
