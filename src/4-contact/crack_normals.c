/**
 * @file crack_normals.c
 * @brief The crack normals of crack contact (section 2.2): kept per pair
 *        at Task 1, summed per extra slot once Task 1 has given the slots.
 */
#include "crack_normals.h"

#include <math.h>
#include <stdlib.h>

#include "step.h"

/** Resize *a to @p cap elements of @p size bytes. @return 0 or -1. */
static int resize(void **a, size_t size, int cap)
{
    void *q = realloc(*a, (size_t)cap * size);
    if (!q)
        return -1;
    *a = q;
    return 0;
}

/** Room for as many rows as the field table has (it grows by doubling). */
static int reserve_rows(CrackNormals *N, const FieldTable *F)
{
    int cap = F->row_cap, n = F->width;
    if (cap <= N->row_cap)
        return 0;
    if (resize((void **)&N->row_nx, n * sizeof(double), cap) ||
        resize((void **)&N->row_ny, n * sizeof(double), cap) ||
        resize((void **)&N->row_tag, n * sizeof(int), cap))
        return -1;
    N->row_cap = cap;
    return 0;
}

/** Room for as many extra slots as the field table has. */
static int reserve_slots(CrackNormals *N, const FieldTable *F)
{
    int cap = F->extra_cap;
    if (cap <= N->slot_cap)
        return 0;
    if (resize((void **)&N->nx, sizeof(double), cap) ||
        resize((void **)&N->ny, sizeof(double), cap) ||
        resize((void **)&N->tag, sizeof(int), cap))
        return -1;
    N->slot_cap = cap;
    return 0;
}

/** The rows Task 1 made since the last call, of @p n pairs each, start
 *  with no normal (@p p: the point a failure names). */
static inline __attribute__((always_inline)) int
clear_new_rows(Sim *sim, CrackNormals *N, int p, int n)
{
    const FieldTable *F = &sim->fields;
    if (reserve_rows(N, F))
        return step_fail(sim, p, "memory for crack normals", F->row_cap);
    for (int k = n * N->rows; k < n * F->nrows; k++) {
        N->row_nx[k] = N->row_ny[k] = 0.0;
        N->row_tag[k] = -1;
    }
    N->rows = F->nrows;
    return 0;
}

int crack_normals_alloc(CrackNormals *N, const Sim *sim)
{
    N->rows = 0;
    return reserve_rows(N, &sim->fields) || reserve_slots(N, &sim->fields) ? -1 : 0;
}

/// [crack_normals_crossed]
/** Keep the normal of crossing @p hit in pair (@p p, @p a) of rows of @p n
 *  pairs (a constant STENCIL_NODES for linear rows, FieldTable::width for
 *  wider ones). */
static inline __attribute__((always_inline)) int
normal_crossed(Sim *sim, const Cracks *C, int p, int a, const CrackHit *hit,
               CrackNormals *N, int n)
{
    int r = sim->fields.row_of[p], k = n * r + a;
    if (r >= N->rows && clear_new_rows(sim, N, p, n))
        return -1;
    const Crack *c = &C->crack[hit->crack];  /* above to below: (dy, -dx) */
    double dx = c->x[hit->segment + 1] - c->x[hit->segment];
    double dy = c->y[hit->segment + 1] - c->y[hit->segment];
    double len = sqrt(dx * dx + dy * dy);
    N->row_nx[k] += dy / len;
    N->row_ny[k] += -dx / len;
    if (N->row_tag[k] < 0 || hit->crack < N->row_tag[k])
        N->row_tag[k] = hit->crack;
    return 0;
}

int crack_normals_crossed(Sim *sim, const Cracks *C, int p, int a,
                          const CrackHit *hit, void *state)
{
    return normal_crossed(sim, C, p, a, hit, state, STENCIL_NODES);
}

int crack_normals_crossed_wide(Sim *sim, const Cracks *C, int p, int a,
                               const CrackHit *hit, void *state)
{
    return normal_crossed(sim, C, p, a, hit, state, sim->fields.width);
}
/// [crack_normals_crossed]

/// [crack_normals_sum]
int crack_normals_sum(Sim *sim, CrackNormals *N)
{
    const FieldTable *F = &sim->fields;
    int nn = sim->grid.nnodes, n = F->width;
    if (clear_new_rows(sim, N, 0, n))
        return -1;
    if (reserve_slots(N, F))
        return step_fail(sim, 0, "memory for crack normals", F->extra_cap);
    for (int e = 0; e < sim->grid.nslots - nn; e++) {
        N->nx[e] = N->ny[e] = 0.0;
        N->tag[e] = -1;
    }
    for (int k = 0; k < n * F->nrows; k++) {    /* rows in order, pairs in order */
        int s = F->row_slot[k], tag = N->row_tag[k];
        if (s < nn)
            continue;                        /* field 0: the node's own slot */
        N->nx[s - nn] += N->row_nx[k];
        N->ny[s - nn] += N->row_ny[k];
        if (tag >= 0 && (N->tag[s - nn] < 0 || tag < N->tag[s - nn]))
            N->tag[s - nn] = tag;
    }
    N->rows = 0;                             /* the next Task 1's rows are new */
    return 0;
}
/// [crack_normals_sum]

void crack_normals_free(CrackNormals *N)
{
    free(N->row_nx);
    free(N->row_ny);
    free(N->row_tag);
    free(N->nx);
    free(N->ny);
    free(N->tag);
}
