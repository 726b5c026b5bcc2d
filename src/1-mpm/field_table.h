/**
 * @file field_table.h
 * @brief The velocity fields of the grid nodes (Task 1, eq. 2): one table
 *        keyed by what the stages contribute.
 *
 * Every node owns slot n, its field with key 0. A pair (point p, node i)
 * whose key is not 0 (a crack between them, from stage 2; a material or
 * contact group, from stage 4) uses the node's slot of that key, created
 * the first time a step needs it. The extra slots of a node form a short
 * list sorted by key. A point whose four pairs all have key 0 has no row
 * in the pair table and costs what it costs in conventional MPM (so does a
 * point of a wider stencil, chapter 8, whose pairs all have key 0); a scene
 * whose stages key nothing has no table at all.
 *
 * The table grows by doubling when a step needs more room, during Task 1,
 * before anything is extrapolated to the grid.
 */
#ifndef MPM_FIELD_TABLE_H
#define MPM_FIELD_TABLE_H

#include "grid.h"

struct Sim;

/// [field_table]
/** Velocity fields of the nodes and the field of every pair. */
typedef struct FieldTable {
    int *first;        /**< per node: first extra slot, -1; NULL: no table */
    int *next;         /**< per extra slot: next of the same node, or -1 */
    unsigned *key;     /**< per extra slot: its key */
    int extra_cap;     /**< room of next, key */
    int *touched;      /**< nodes given extra slots this step */
    int ntouched;      /**< how many */
    int *row_of;       /**< per point: its pair row, or -1 */
    int *row_point;    /**< per row: the point */
    unsigned *row_key; /**< width per row: key of each pair */
    int *row_slot;     /**< width per row: slot of each pair (after Task 1) */
    int width;         /**< pairs per row: the most nodes a point of
                            run.shape reaches (4 linear, 9 uGIMP) */
    int nrows;         /**< rows in use this step */
    int row_cap;       /**< rows allocated */
} FieldTable;
/// [field_table]

/** @brief Give the scene a field table (idempotent). @return 0 or -1. */
int fields_enable(struct Sim *sim);

/** @brief Task 1 begins: forget the last step's rows and extra slots. */
void fields_begin_step(struct Sim *sim);

/**
 * @brief The pair row of point @p p, made (every key 0) when it has none:
 *        rows come in the order of these calls. One thread at a time; the
 *        keys of distinct rows may then be set on threads (fields_row_key()).
 * @return the row, or -1 when memory is exhausted (Sim::fail filled).
 */
int fields_row(struct Sim *sim, int p);

/** @brief Add @p key bits to pair @p a of row @p r, made by fields_row():
 *         a row is its point's alone, so threads may key distinct rows. */
static inline void fields_row_key(FieldTable *F, int r, int a, unsigned key)
{
    F->row_key[F->width * r + a] |= key;
}

/**
 * @brief Add @p key bits to the key of pair (point @p p, corner @p a) of a
 *        table of linear rows (FieldTable::width == STENCIL_NODES: stage 8
 *        keys a wider run.shape with fields_key_wide()).
 * @return 0, or -1 when memory is exhausted (Sim::fail filled).
 */
int fields_key(struct Sim *sim, int p, int a, unsigned key);

/**
 * @brief As fields_key(), for pair @p a of a wider stencil's rows
 *        (FieldTable::width pairs each: uGIMP, chapter 8).
 * @return 0, or -1 when memory is exhausted (Sim::fail filled).
 */
int fields_key_wide(struct Sim *sim, int p, int a, unsigned key);

/**
 * @brief Task 1 ends: give every keyed pair the slot of its key at its
 *        node, creating slots as needed.
 * @return 0, or -1 when memory is exhausted (Sim::fail filled).
 */
int fields_resolve(struct Sim *sim);

/** @brief The slot after @p s at the same node, or -1. Start from s = n
 *         (the node's field 0): for (s = n; s >= 0; s = field_next(..)). */
static inline int field_next(const FieldTable *F, const Grid *g, int s)
{
    if (s < g->nnodes)
        return F->first ? F->first[s] : -1;
    return F->next[s - g->nnodes];
}

/** @brief Key of slot @p s (0 for a node's own slot). */
static inline unsigned field_key(const FieldTable *F, const Grid *g, int s)
{
    return s < g->nnodes ? 0u : F->key[s - g->nnodes];
}

/** @brief Nodes where more than one field has mass this step. */
int fields_multi_field_nodes(const struct Sim *sim);

/** @brief Release the table. */
void fields_free(FieldTable *F);

#endif
