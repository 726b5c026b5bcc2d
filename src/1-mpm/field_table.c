/**
 * @file field_table.c
 * @brief The field table: pair rows filled by the stages' keys in Task 1,
 *        node slots found or created for them (eq. 2).
 */
#include "field_table.h"

#include <stdlib.h>
#include <string.h>

#include "sim.h"
#include "stencil.h"
#include "step.h"

/** Grow *a (of @p size bytes per element) from @p old to @p cap elements. */
static int grow(void **a, size_t size, int old, int cap)
{
    void *q = realloc(*a, (size_t)cap * size);
    if (!q)
        return -1;
    memset((char *)q + (size_t)old * size, 0, (size_t)(cap - old) * size);
    *a = q;
    return 0;
}

/** Make room for @p rows pair rows. */
static int reserve_rows(FieldTable *F, int rows)
{
    if (rows <= F->row_cap)
        return 0;
    int cap = F->row_cap > 0 ? F->row_cap : 64, n = F->width;
    while (cap < rows)
        cap *= 2;
    if (grow((void **)&F->row_point, sizeof(int), F->row_cap, cap) ||
        grow((void **)&F->row_key, n * sizeof(unsigned), F->row_cap, cap) ||
        grow((void **)&F->row_slot, n * sizeof(int), F->row_cap, cap))
        return -1;
    F->row_cap = cap;
    return 0;
}

/** Make room for @p extra extra slots, in the grid and in the table. */
static int reserve_slots(Grid *g, FieldTable *F, int extra)
{
    if (extra <= F->extra_cap)
        return 0;
    int cap = F->extra_cap > 0 ? F->extra_cap : 64;
    while (cap < extra)
        cap *= 2;
    if (grid_reserve(g, g->nnodes + cap) ||
        grow((void **)&F->next, sizeof(int), F->extra_cap, cap) ||
        grow((void **)&F->key, sizeof(unsigned), F->extra_cap, cap))
        return -1;
    F->extra_cap = cap;
    return 0;
}

int fields_enable(Sim *sim)
{
    FieldTable *F = &sim->fields;
    int nn = sim->grid.nnodes, np = sim->pts.n;
    if (F->first)
        return 0;
    F->width = sim->scene.run.shape ? sim->scene.run.shape->nodes : STENCIL_NODES;
    F->first = malloc(sizeof(int) * (size_t)nn);
    F->touched = malloc(sizeof(int) * (size_t)nn);
    F->row_of = malloc(sizeof(int) * ((size_t)np + 1));
    if (!F->first || !F->touched || !F->row_of)
        return -1;
    for (int n = 0; n < nn; n++)
        F->first[n] = -1;
    for (int p = 0; p < np; p++)
        F->row_of[p] = -1;
    return reserve_rows(F, 64) || reserve_slots(&sim->grid, F, 64) ? -1 : 0;
}

void fields_begin_step(Sim *sim)
{
    FieldTable *F = &sim->fields;
    for (int r = 0; r < F->nrows; r++)
        F->row_of[F->row_point[r]] = -1;
    for (int k = 0; k < F->ntouched; k++)
        F->first[F->touched[k]] = -1;
    F->nrows = 0;
    F->ntouched = 0;
    sim->grid.nslots = sim->grid.nnodes;
}

/// [fields_key]
int fields_row(Sim *sim, int p)
{
    FieldTable *F = &sim->fields;
    int r = F->row_of[p];
    if (r < 0) {                             /* the point's first keyed pair */
        if (reserve_rows(F, F->nrows + 1))
            return step_fail(sim, p, "memory for the pair table", F->nrows);
        r = F->nrows++;
        F->row_of[p] = r;
        F->row_point[r] = p;
        memset(&F->row_key[F->width * r], 0, (size_t)F->width * sizeof(unsigned));
    }
    return r;
}

/** Add @p key to pair (@p p, @p a) in rows of @p n pairs (a constant
 *  STENCIL_NODES for linear rows, FieldTable::width for wider ones). */
static inline __attribute__((always_inline)) int
key_pair(Sim *sim, int p, int a, unsigned key, int n)
{
    int r = fields_row(sim, p);
    if (r < 0)
        return -1;
    sim->fields.row_key[n * r + a] |= key;
    return 0;
}

int fields_key(Sim *sim, int p, int a, unsigned key)
{
    return key_pair(sim, p, a, key, STENCIL_NODES);
}

int fields_key_wide(Sim *sim, int p, int a, unsigned key)
{
    return key_pair(sim, p, a, key, sim->fields.width);
}
/// [fields_key]

/** The slot of @p key at node @p n; created (in key order) when missing. */
static inline __attribute__((always_inline)) int node_slot(Sim *sim, int n, unsigned key)
{
    FieldTable *F = &sim->fields;
    Grid *g = &sim->grid;
    int prev = -1, s = F->first[n];
    while (s >= 0 && F->key[s - g->nnodes] < key) {
        prev = s;
        s = F->next[s - g->nnodes];
    }
    if (s >= 0 && F->key[s - g->nnodes] == key)
        return s;
    if (reserve_slots(g, F, g->nslots - g->nnodes + 1))
        return -1;
    int t = g->nslots++, e = t - g->nnodes;
    g->slot_node[e] = n;
    g->m[t] = g->px[t] = g->py[t] = g->fx[t] = g->fy[t] = 0.0;
    F->key[e] = key;
    F->next[e] = s;
    if (F->first[n] < 0)
        F->touched[F->ntouched++] = n;
    if (prev < 0)
        F->first[n] = t;
    else
        F->next[prev - g->nnodes] = t;
    return t;
}

/// [fields_resolve]
/** The slots of every keyed pair, through run.shape's stencil function
 *  @p wide, or NULL for the cell's four nodes. */
static inline __attribute__((always_inline)) int
resolve_rows(Sim *sim, StencilFn wide)
{
    FieldTable *F = &sim->fields;
    int n = F->width;
    for (int r = 0; r < F->nrows; r++) {
        int p = F->row_point[r], node[STENCIL_MAX];
        int reach = stencil_node_list(sim, wide, p, node);
        for (int a = 0; a < reach; a++) {
            unsigned key = F->row_key[n * r + a];
            int s = key ? node_slot(sim, node[a], key) : node[a];
            if (s < 0)
                return step_fail(sim, p, "memory for velocity fields", node[a]);
            F->row_slot[n * r + a] = s;
        }
    }
    return 0;
}

/** The slots through the cell's four nodes, compiled on its own (the
 *  code a scene without a wider stencil ran before chapter 8). */
static __attribute__((noinline)) int resolve_linear(Sim *sim)
{
    return resolve_rows(sim, NULL);
}

/** The slots through run.shape's stencil function (chapter 8). */
static __attribute__((noinline)) int resolve_wide(Sim *sim)
{
    return resolve_rows(sim, sim->scene.run.stencil);
}

int fields_resolve(Sim *sim)
{
    if (sim->scene.run.stencil)              /* another row of run.shape */
        return resolve_wide(sim);
    return resolve_linear(sim);              /* the paper's four nodes */
}
/// [fields_resolve]

int fields_multi_field_nodes(const struct Sim *sim)
{
    const FieldTable *F = &sim->fields;
    const Grid *g = &sim->grid;
    int count = 0;
    for (int k = 0; k < F->ntouched; k++) {
        int fields = 0;
        for (int s = F->touched[k]; s >= 0; s = field_next(F, g, s))
            fields += g->m[s] > 0;
        count += fields > 1;
    }
    return count;
}

void fields_free(FieldTable *F)
{
    free(F->first);
    free(F->next);
    free(F->key);
    free(F->touched);
    free(F->row_of);
    free(F->row_point);
    free(F->row_key);
    free(F->row_slot);
    memset(F, 0, sizeof *F);
}
