/**
 * @file crack_growth.h
 * @brief Crack growth at CRAMP tips (chapter 7, "Growth"): a tip whose J
 *        reaches the toughness G_c gains a segment in the direction of
 *        the largest hoop stress (Erdogan and Sih 1963), from K_I and K_II.
 */
#ifndef MPM_CRACK_GROWTH_H
#define MPM_CRACK_GROWTH_H

#include <libconfig.h>

#include "hoop_angle.h"
#include "j_integral.h"
#include "scene_include.h"

struct SceneReader;

/** One crack's `growth` settings, as the scene gave them. */
typedef struct GrowthSettings {
    int on;               /**< the crack has the key */
    double G_c;           /**< toughness: J at which a tip grows (N/mm) */
    double length;        /**< length of a new segment (mm) */
    int max_segments;     /**< room reserved, in segments (0: default) */
    double average;       /**< J decides as its mean over consecutive
                               blocks of evaluations spanning this time
                               (ms), and K_I, K_II as theirs; 0: each
                               evaluation alone */
    int line;             /**< line of the key (scene_lines_at()) */
    int max_line;         /**< line of max_segments (or of the key) */
    /** "the segments of crack k (...)": Sim::fail's quantity when full */
    char full[SCENE_AT_LEN + 96];
} GrowthSettings;

/** Why a tip grows no more (GrowthEnd::stop), besides cutting through. */
typedef enum GrowthStop {
    GROWTH_ON = 0,        /**< it may grow */
    GROWTH_AT_CRACK,      /**< its next segment would cross or touch a crack */
    GROWTH_DOMAIN_EDGE,   /**< its widest J domain reaches out of the body */
    GROWTH_DOMAIN_CRACK   /**< its widest J domain holds another crack */
} GrowthStop;

/** What one crack end has done (index 2 crack + end). */
typedef struct GrowthEnd {
    long events;          /**< segments it has gained */
    long last_step;       /**< steps taken at its latest event, -1: none */
    double J;             /**< the J that decided the latest event */
    double theta;         /**< its kink angle (rad, from ex, ey towards
                               the left normal -ey, ex) */
    int through;          /**< 1 once it grew out of every body: no more */
    int stop;             /**< GrowthStop: why it grows no more */
    int by;               /**< the crack that stopped it (or -1) */
    long negative;        /**< decisions with J < -G_c / 10 (J does not
                               hold on its domain: a kink, shut faces, an
                               edge) */
    double Jsum;          /**< sum of J over the block so far */
    double Ksum[2];       /**< sums of K_I and K_II over it */
    long nsum;            /**< evaluations in it */
} GrowthEnd;

/// [crack_growth_state]
/** Stage 7's growth state: the settings per crack and what each end did. */
typedef struct CrackGrowth {
    int ncracks;          /**< entries of set (and 2 ncracks of end) */
    GrowthSettings *set;  /**< per crack (on = 0 without the key) */
    GrowthEnd *end;       /**< per crack end, 2 crack + end */
} CrackGrowth;
/// [crack_growth_state]

/** The keys of a crack's growth group (NULL-ended). */
extern const char *const crack_growth_keys[];

/** @brief J, K_I and K_II that decide growth at tip @p T: the means over
 *         its contours. */
void growth_parameters(const JState *S, const JTip *T, double *J, double *KI,
                       double *KII);

/** @brief Read `cracks.[index].growth` (G_c, length, max_segments); it
 *         needs `j_integral` on the same crack. Subscribes the set-up,
 *         history, report and checkpoint of growth.
 *  @return 0, or -1 with the message in @p r. */
int crack_growth_read(Sim *sim, const config_setting_t *s, int index,
                      struct SceneReader *r);

/** @brief Set-up: reserve room for each growing crack's points, so that
 *         a step allocates none. @return 0, or -1 with "file:line: ..." in
 *         @p err. */
int crack_growth_prepare(Sim *sim, void *state, char *err, size_t errlen);

/**
 * @brief Grow the tips whose fresh J (just evaluated) reaches G_c: at
 *        most one segment per tip, of GrowthSettings::length, at
 *        hoop_angle() from the tip's direction (K_I < 0 counts as 0:
 *        faces cannot pass through each other); then bring the crossing
 *        search and the J tips up to date, as after the cracks move.
 *        A tip stops for good (GrowthEnd::stop) when its next segment
 *        would cross or touch a crack (none is added), or when its new
 *        widest J domain reaches out of the body or holds another crack
 *        (J is then not path independent).
 * @return 0, or -1 with Sim::fail filled (no room left, a new point or
 *         its J domain outside the grid, search memory).
 */
int crack_growth_step(Sim *sim, CrackGrowth *G, JState *S);

/** @brief history.csv: per growing tip, its events and its place
 *         (events_crack0_last, tipx_crack0_last, tipy_crack0_last). */
int crack_growth_history(const Sim *sim, void *state, FILE *f, int header);

/** @brief The end of a run: events and the tip per growing crack end. */
int crack_growth_report(const Sim *sim, void *state, FILE *f);

/** @brief Save or restore the events; on restore, reserve the room again
 *         (stage 2 restores the points). */
int crack_growth_checkpoint(Sim *sim, void *state, FILE *f, int save);

/** @brief Release the growth state. */
void crack_growth_release(void *state);

#endif
