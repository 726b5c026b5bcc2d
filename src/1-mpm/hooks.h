/**
 * @file hooks.h
 * @brief The seams of the time step where later stages add behaviour, and
 *        the registries a build fills before it reads a scene.
 *
 * Two kinds of things live here:
 * - **registries**, filled by the stages' installers: update schemes,
 *   methods (the run loop's step), material laws, scene sections and keys
 *   nested in core sections, field keys, named choices, and refusals of
 *   what later stages add;
 * - **seams**: ordered lists of subscribers (a function and its own state)
 *   at named places of the step and of the output. A stage subscribes when
 *   a scene needs it (stage 2 only when the scene has a crack), so a scene
 *   that needs nothing costs what conventional MPM costs. Subscribers run
 *   in stage order; nothing assigns over another stage's subscriber.
 */
#ifndef MPM_HOOKS_H
#define MPM_HOOKS_H

#include <libconfig.h>
#include <stddef.h>
#include <stdio.h>

#include "scene.h"

struct Sim;
struct SceneReader;

/** Most entries of each registry and subscribers of each seam. */
#define HOOKS_MAX 32
/** How many stages may describe their output files (Hooks::outputs). */
#define HOOKS_MAX_OUTPUTS 8

/// [seams]
/** The named seams. Step seams follow the paper's Tasks (Appendix). */
typedef enum Seam {
    SEAM_PREPARE,        /**< after points and grid exist: checks, set-up */
    SEAM_TASK1_FIELDS,   /**< Task 1: key each pair's velocity field */
    SEAM_TASK2_HELD,     /**< Task 2, before a stress update (USF, USAVG):
                              the contact the last step decided, where it
                              still holds */
    SEAM_TASK2_CONTACT,  /**< Task 2: adjust momenta (contact) */
    SEAM_TASK4_CONTACT,  /**< Task 4: adjust momenta after p += dt f */
    SEAM_TASK6_CONTACT,  /**< Task 6: adjust re-extrapolated momenta */
    SEAM_TASK7,          /**< Task 7: move cracks, end-of-step work */
    SEAM_SNAPSHOT,       /**< write extra files with each snapshot */
    SEAM_HISTORY,        /**< write extra columns of history.csv */
    SEAM_REPORT,         /**< end of a run: print a summary (stdout) */
    SEAM_CHECKPOINT,     /**< save or restore state a restart needs */
    SEAM_ENERGY,         /**< energy a stage has taken out of the run */
    SEAM_ENERGY_IN,      /**< energy put into the run so far (the start's
                              and the work of gravity and loads), where a
                              stage counts it: the energy guard's measure */
    SEAM_COUNT           /**< number of seams */
} Seam;

/** The bit of seam @p s in a Method's mask of the seams it runs. */
#define SEAM_BIT(s) (1u << (s))
/** The seams a step runs (Tasks 1-7); the others belong to the program
 *  around it (set-up, output, checkpoint) and run under every method. */
#define SEAMS_OF_STEP                                                     \
    (SEAM_BIT(SEAM_TASK1_FIELDS) | SEAM_BIT(SEAM_TASK2_HELD) |            \
     SEAM_BIT(SEAM_TASK2_CONTACT) | SEAM_BIT(SEAM_TASK4_CONTACT) |         \
     SEAM_BIT(SEAM_TASK6_CONTACT) | SEAM_BIT(SEAM_TASK7))

/** The scene key whose reading subscribed (section "" for a top-level
 *  one), and the line of its setting; key NULL: a subscriber not made by
 *  a key (an installer's, or one a set-up subscriber adds). */
typedef struct KeyAt {
    const char *section;  /**< "cracks" of "cracks.contact", or "" */
    const char *key;      /**< "contact" */
    int line;             /**< line of the scene text (scene_lines_at()) */
} KeyAt;

/** A step seam's subscriber: non-zero (with Sim::fail filled) stops the run. */
typedef int (*StepHook)(struct Sim *sim, void *state, Seam seam);
/** A set-up subscriber: write a message and return non-zero to refuse. */
typedef int (*PrepareHook)(struct Sim *sim, void *state, char *err,
                           size_t errlen);
/** A snapshot subscriber: write files for snapshot @p index (@p times:
 *  the times of snapshots 0 .. index, for a series file); 0 or -1. */
typedef int (*SnapshotHook)(const struct Sim *sim, void *state,
                            const char *dir, int index, const double *times);
/** A history subscriber: write ",name..." (header) or ",value..."; 0 or -1. */
typedef int (*HistoryHook)(const struct Sim *sim, void *state, FILE *f,
                           int header);
/** A report subscriber: print lines about the finished run to @p f; 0 or -1. */
typedef int (*ReportHook)(const struct Sim *sim, void *state, FILE *f);

/** A checkpoint subscriber: save (@p save = 1) or restore (0) the state
 *  that lasts from step to step, with checkpoint_io(); 0 or -1. */
typedef int (*CheckpointHook)(struct Sim *sim, void *state, FILE *f, int save);
/** An energy subscriber: the energy its stage has dissipated since the run
 *  began (>= 0 when taken out), named for the report in *@p name. */
typedef double (*EnergyHook)(const struct Sim *sim, void *state,
                             const char **name);
/** One subscriber: its function (of the seam's type) and its own state. */
typedef struct Subscriber {
    union {
        StepHook step;         /**< SEAM_TASK* */
        PrepareHook prepare;   /**< SEAM_PREPARE */
        SnapshotHook snapshot; /**< SEAM_SNAPSHOT */
        HistoryHook history;   /**< SEAM_HISTORY */
        ReportHook report;     /**< SEAM_REPORT */
        CheckpointHook checkpoint; /**< SEAM_CHECKPOINT */
        EnergyHook energy;     /**< SEAM_ENERGY, SEAM_ENERGY_IN */
    } fn;                      /**< the function */
    void *state;               /**< passed back to it */
    int rank;                  /**< stage order of its installer */
    KeyAt by;                  /**< the scene key that asked for it */
} Subscriber;

/** The subscribers of one seam, in stage order. */
typedef struct SeamList {
    int n;                        /**< how many */
    Subscriber at[HOOKS_MAX];     /**< in the order they run */
} SeamList;
/// [seams]

/** A scene section (top level) or a key nested in one ("materials",
 *  "bodies", "run", or a stage's section such as "cracks"). */
typedef struct SceneKey {
    const char *section;  /**< "" for a top-level section */
    const char *key;      /**< the key */
    /** Read the setting @p s (of entry @p index of a list section, else 0);
     *  return non-zero with a message in the reader. */
    int (*parse)(struct Sim *sim, const config_setting_t *s, int index,
                 struct SceneReader *r);
    /** The keys inside it when it is a group or a list of groups
     *  (NULL-ended; its parser checks against the same list), else NULL. */
    const char *const *keys;
    int rank;             /**< stage order */
} SceneKey;

/** A scene feature this build does not have, and the stage that adds it. */
typedef struct Refusal {
    const char *key;    /**< "cracks", "materials.friction", "run.update" */
    const char *value;  /**< the refused value, NULL for any */
    const char *stage;  /**< words naming the stage that adds it */
} Refusal;

/** A named implementation a scene key chooses from ("run.method" = "mpm",
 *  "materials.law" = "hooke", "run.crack_search" = "plain"). */
typedef struct Choice {
    const char *key;    /**< the scene key that chooses */
    const char *name;   /**< the value that names this row */
    const void *impl;   /**< the row: a Method, a MaterialLaw, ... */
    int rank;           /**< stage order of the stage that added it */
} Choice;

/// [method]
/** A row of the method table: how the run loop advances one step, and
 *  which of the scene's requests it honours (method_check_scene()). */
typedef struct Method {
    const char *name;                /**< run.method */
    int (*step)(struct Sim *sim);    /**< one step; non-zero stops the run */
    /** The method's stable time step for the loaded scene, before the
     *  scene's run.cfl factor; NULL: the MPM rule (a cell crossed by the
     *  fastest wave, sim_set_time_step()). */
    double (*stable_step)(const struct Sim *sim);
    unsigned seams;                  /**< SEAM_BITs of the step seams it runs */
    /** Scene keys it carries out itself, so that their subscribers at
     *  seams it does not run are not refused (NULL-ended, or NULL). */
    const char *const *own_keys;
    /** Settings ("run.update") it does not read: refused when the scene
     *  gives them (NULL-ended, or NULL). */
    const char *const *ignored_keys;
} Method;
/// [method]

/** @brief Does method @p m read the setting @p key ("run.update"), that
 *         is, is it not among its Method::ignored_keys? */
int method_reads(const Method *m, const char *key);

/** A part of the field key that a stage contributes (bits of a key). */
typedef struct FieldKey {
    const char *name;   /**< "crack side", "material", ... */
    int shift;          /**< its lowest bit */
    int bits;           /**< its width */
} FieldKey;

/// [hooks]
/** Registries and seams of one build (and, once a scene is read, of that
 *  scene). */
typedef struct Hooks {
    UpdateScheme schemes[HOOKS_MAX]; /**< stress-update schemes */
    int scheme_rank[HOOKS_MAX];      /**< the stage order of each */
    int nschemes;                    /**< how many */
    SceneKey keys[HOOKS_MAX];        /**< sections and nested keys */
    int nkeys;                       /**< how many */
    Refusal refusals[HOOKS_MAX];     /**< features of later stages */
    int nrefusals;                   /**< how many */
    Choice choices[HOOKS_MAX];       /**< methods, laws, searches */
    int nchoices;                    /**< how many */
    FieldKey field_keys[HOOKS_MAX];  /**< parts of the field key */
    int nfield_keys;                 /**< how many */
    const char *outputs[HOOKS_MAX_OUTPUTS]; /**< files stages add (--help) */
    int noutputs;                    /**< how many */
    SeamList seam[SEAM_COUNT];       /**< subscribers of each seam */
    int rank;                        /**< stage order of what is added now */
    int build_stage;                 /**< the build's last stage (stages.c) */
    KeyAt reading;                   /**< the scene key read now, if any */
    int overflow;                    /**< -1 once a registry was full */
} Hooks;
/// [hooks]

/** @brief Mark what is registered or subscribed from now on as the
 *         @p rank-th stage's (stage order; stages.c alone calls it). */
void hooks_begin_stage(Hooks *h, int rank);

/** @brief Mark what is subscribed from now on as asked for by scene key
 *         @p key (the scene reader calls it around a key's parser). */
void hooks_begin_key(Hooks *h, KeyAt key);

/** @brief Say, for `mpm --help`, which files a stage adds to the output
 *         folder and when (a sentence's clause). @return 0, or -1 when
 *         full. */
int hooks_add_outputs(Hooks *h, const char *text);

/** @brief Register a stress-update scheme. @return 0, or -1 when full. */
int hooks_add_scheme(Hooks *h, const char *name, double before, double after,
                     int reextrapolate);

/** @brief Register a top-level scene section (@p section = "") or a key
 *         nested in @p section, read by @p parse; @p keys (NULL-ended, or
 *         NULL) are the keys of the group it holds, for `mpm --keys`.
 *  @return 0, or -1 when full. */
int hooks_add_key(Hooks *h, const char *section, const char *key,
                  int (*parse)(struct Sim *, const config_setting_t *, int,
                               struct SceneReader *),
                  const char *const *keys);

/** @brief The registered key @p key of @p section, or NULL. */
const SceneKey *hooks_find_key(const Hooks *h, const char *section,
                               const char *key);

/** @brief Record a feature this build refuses, naming its stage. */
int hooks_add_refusal(Hooks *h, const char *key, const char *value,
                      const char *stage);

/** @brief The refusal for @p key (and @p value, if it has one), or NULL. */
const Refusal *hooks_find_refusal(const Hooks *h, const char *key,
                                  const char *value);

/** @brief Register row @p name of the table chosen by scene key @p key. */
int hooks_add_choice(Hooks *h, const char *key, const char *name,
                     const void *impl);

/** @brief The row @p name of table @p key, or NULL; @p name NULL gives the
 *         last registered row (the latest stage's). */
const void *hooks_find_choice(const Hooks *h, const char *key,
                              const char *name);

/** @brief Write the names of table @p key, comma separated, into @p buf. */
void hooks_list_choices(const Hooks *h, const char *key, char *buf,
                        size_t len);

/** @brief Reserve @p bits bits of the field key for @p name.
 *  @return the shift of the part, or -1 when the key has no room. */
int hooks_add_field_key(Hooks *h, const char *name, int bits);

/** @brief The part of the field key called @p name, or NULL. */
const FieldKey *hooks_find_field_key(const Hooks *h, const char *name);

/** @brief The scheme called @p name, or NULL. */
const UpdateScheme *hooks_find_scheme(const Hooks *h, const char *name);

/** @brief Subscribe @p fn with @p state to step seam @p seam. @return 0/-1. */
int hooks_on_step(Hooks *h, Seam seam, StepHook fn, void *state);

/** @brief Subscribe to SEAM_PREPARE. @return 0 or -1. */
int hooks_on_prepare(Hooks *h, PrepareHook fn, void *state);

/** @brief Subscribe to SEAM_SNAPSHOT. @return 0 or -1. */
int hooks_on_snapshot(Hooks *h, SnapshotHook fn, void *state);

/** @brief Subscribe to SEAM_HISTORY. @return 0 or -1. */
int hooks_on_history(Hooks *h, HistoryHook fn, void *state);

/** @brief Subscribe to SEAM_REPORT. @return 0 or -1. */
int hooks_on_report(Hooks *h, ReportHook fn, void *state);

/** @brief Subscribe to SEAM_CHECKPOINT. @return 0 or -1. */
int hooks_on_checkpoint(Hooks *h, CheckpointHook fn, void *state);

/** @brief Subscribe to SEAM_ENERGY. @return 0 or -1. */
int hooks_on_energy(Hooks *h, EnergyHook fn, void *state);

/** @brief Subscribe to SEAM_ENERGY_IN (one subscriber: the first counts).
 *  @return 0 or -1. */
int hooks_on_energy_in(Hooks *h, EnergyHook fn, void *state);
/** @brief Print the end-of-run lines of every SEAM_REPORT subscriber to
 *         @p f. @return 0, or -1 when a write failed. */
int hooks_run_report(const struct Sim *sim, FILE *f);

/** @brief Run the subscribers of step seam @p seam in order; stop at the
 *         first that fails. @return 0 or its non-zero value. */
int hooks_run_step(struct Sim *sim, Seam seam);

#endif
