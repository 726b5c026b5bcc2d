/**
 * @file crack_normals.h
 * @brief The crack's normal at a node's fields (section 2.2), for crack
 *        contact: per pair of the field table, the normal of the crossing
 *        Task 1 found and the crack it belongs to; per extra slot, their
 *        sum and the lowest crack.
 *
 * Stage 2's Task 1 hands every crossing to its subscribers
 * (cracks_on_crossed()); crack_normals_crossed() keeps the normal in the
 * pair's row.
 * Once Task 1 has given every pair its slot, crack_normals_sum() adds the
 * rows into the slots, in the order of the rows. Only a scene with a crack
 * that has contact has any of this.
 */
#ifndef MPM_CRACK_NORMALS_H
#define MPM_CRACK_NORMALS_H

#include "cracks.h"

/// [crack_normals]
/** Crack normals per pair row and per extra slot of the field table. */
typedef struct CrackNormals {
    double *row_nx;   /**< FieldTable::width per row: crack normal sum x
                           of the pair */
    double *row_ny;   /**< the same per row: crack normal sum y */
    int *row_tag;     /**< the same per row: lowest tag (crack index), or -1 */
    int rows;         /**< rows of this Task 1 set to zero so far */
    int row_cap;      /**< rows allocated */
    double *nx;       /**< per extra slot: sum of its pairs' normals, x */
    double *ny;       /**< per extra slot: the same, y */
    int *tag;         /**< per extra slot: lowest tag of its pairs, or -1 */
    int slot_cap;     /**< extra slots allocated */
} CrackNormals;
/// [crack_normals]

/** @brief Room for the field table's rows and extra slots as they are
 *         now (set-up). @return 0, or -1 when memory is exhausted. */
int crack_normals_alloc(CrackNormals *N, const Sim *sim);

/**
 * @brief Task 1, a subscriber to stage 2's crossings (cracks_on_crossed();
 *        @p state: the CrackNormals): add the unit normal of
 *        the crossed segment, from above the crack to below, to pair
 *        (@p p, @p a), with the crack's index as its tag; a pair keeps the
 *        lowest tag it is given.
 * @return 0, or -1 when memory is exhausted (Sim::fail filled).
 */
int crack_normals_crossed(Sim *sim, const Cracks *C, int p, int a,
                          const CrackHit *hit, void *state);

/**
 * @brief As crack_normals_crossed(), for rows of FieldTable::width pairs
 *        (a wider run.shape, chapter 8).
 * @return 0, or -1 when memory is exhausted (Sim::fail filled).
 */
int crack_normals_crossed_wide(Sim *sim, const Cracks *C, int p, int a,
                               const CrackHit *hit, void *state);

/**
 * @brief After Task 1 (fields_resolve() gave every pair its slot): each
 *        extra slot's normal is the sum of its pairs' normals, its tag the
 *        lowest of theirs (-1: none). Call once per step; the next Task 1
 *        starts from empty rows.
 * @return 0, or -1 when memory is exhausted (Sim::fail filled).
 */
int crack_normals_sum(Sim *sim, CrackNormals *N);

/** @brief Release what the normals hold. */
void crack_normals_free(CrackNormals *N);

#endif
