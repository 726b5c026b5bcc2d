/**
 * @file cracks.h
 * @brief Explicit cracks (polylines of massless points) and the velocity
 *        fields they create at grid nodes (paper's section 2.1, Tasks 1
 *        and 7).
 */
#ifndef MPM_CRACKS_H
#define MPM_CRACKS_H

#include "sim.h"

/** Index of stage 2's state in Sim::ext. */
#define CRACKS_EXT 2

/** One crack: a polyline whose end points are massless material points. */
typedef struct Crack {
    int n;          /**< number of points (segments + 1) */
    double *x;      /**< point x */
    double *y;      /**< point y */
    double xmin;    /**< extent of the points (Appendix, subtask 1) */
    double xmax;    /**< extent */
    double ymin;    /**< extent */
    double ymax;    /**< extent */
    int line;       /**< scene-file line, for messages */
} Crack;

/// [cracks_state]
/** Stage 2's state: the cracks and this step's field assignment. */
typedef struct Cracks {
    int ncracks;         /**< number of cracks */
    Crack *crack;        /**< the cracks */
    unsigned char *pair; /**< per point: 2 bits per corner a, the field v(p,i) */
    int *node_field;     /**< per node: slot of field 1 and of field 2, or -1 */
    int *touched;        /**< nodes given extra fields this step */
    int ntouched;        /**< how many */
} Cracks;
/// [cracks_state]

/** @brief Stage 2's state of @p sim (NULL when the scene has no crack). */
static inline Cracks *cracks_of(const Sim *sim)
{
    return (Cracks *)sim->ext[CRACKS_EXT];
}

/**
 * @brief Which field the pair (point, node) belongs to: 0 when the segment
 *        from the point to the node crosses no crack, 1 when it crosses a
 *        crack with the point above it, 2 below (eq. 2, Appendix "Line
 *        Crossing Algorithm", subtasks 2-4).
 */
int crack_field(const Cracks *C, double px, double py, double nx, double ny);

/**
 * @brief The crossing test against one crack: +1 above, -1 below, 0 not
 *        crossed (an even number of crossings counts as none).
 */
int crack_crossing(const Crack *c, double px, double py, double nx, double ny);

/** @brief Parse the "cracks" section and install stage 2's hooks. */
int cracks_read(Sim *sim, const config_setting_t *s, char *err, size_t errlen);

/** @brief Task 1: v(p,i) of every pair and the extra slots it needs. */
int cracks_assign_fields(Sim *sim);

/** @brief Map the pairs of point @p p to their field slots. */
void cracks_pair_slots(const Sim *sim, int p, int slot[4]);

/** @brief Task 7: move the crack points with the centre-of-mass velocity. */
int cracks_move(Sim *sim);

/** @brief Nodes that carry more than one velocity field this step. */
int cracks_multi_field_nodes(const Sim *sim);

/** @brief Write crack_NNNNN.vtp and crack_NNNNN.csv with the snapshot. */
void cracks_snapshot(const Sim *sim, const char *dir, int index);

/** @brief history.csv column: number of multi-field nodes. */
void cracks_history(const Sim *sim, char *buf, size_t len, int header);

/** @brief Slots to reserve for fields 1 and 2. */
int cracks_extra_slots(const Sim *sim);

/** @brief Check the cracks against the bodies and allocate the field tables. */
int cracks_prepare(Sim *sim, char *err, size_t errlen);

/** @brief Release stage 2's state. */
void cracks_release(Sim *sim);

#endif
