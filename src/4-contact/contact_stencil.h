/**
 * @file contact_stencil.h
 * @brief The stencil that contact's scatters read (node volumes, mass
 *        gradients, areas, reaches): the point's own, as Task 1 keyed it,
 *        the cell's four nodes or a wider row of run.shape (chapter 8).
 *
 * Each scatter is compiled twice from one inline body: with @p wide a
 * constant NULL (the cell's four nodes, the code of the paper's linear
 * shape functions) and with run.shape's stencil function, so that a scene
 * without a wider stencil runs the loops it ran before chapter 8.
 */
#ifndef MPM_CONTACT_STENCIL_H
#define MPM_CONTACT_STENCIL_H

#include "stencil.h"
#include "strip_scatter.h"

/** @brief Point @p p's bilinear stencil of this step: the one stored at
 *         Task 0 (stencils.h), or, with none stored, computed into
 *         @p buf. */
static inline StencilRow contact_stencil_linear(const Sim *sim, int p,
                                                Stencil *buf)
{
    if (sim->stencils.linear)
        return stencil_stored(sim, p);
    stencil_linear(sim, p, buf);
    buf->n = STENCIL_NODES;
    return stencil_row(buf);
}

/// [contact_stencil]
/** @brief Point @p p's stencil for contact, when one of its nodes carries
 *         extra fields this step (FieldTable::first): its nodes in
 *         @p node and its S_ip, G_ip and field slots in @p row, through
 *         @p wide (run.shape's stencil function, computed into @p buf) or,
 *         NULL, the cell's four nodes (the stencil stored at Task 0 with
 *         Task 1's fields, stencils.h: the same numbers). @return the
 *         nodes in use, or 0 when none of them has extra fields (@p row
 *         is then not set) */
static inline __attribute__((always_inline)) int
contact_stencil(const Sim *sim, StencilFn wide, int p, int node[STENCIL_MAX],
                Stencil *buf, StencilRow *row)
{
    const FieldTable *F = &sim->fields;
    int near = 0;
    if (wide) {                            /* another row of run.shape */
        wide(sim, p, buf);
        for (int a = 0; a < buf->n; a++) {
            node[a] = buf->slot[a];        /* field 0: the nodes */
            near |= F->first[node[a]] >= 0;
        }
        if (!near)
            return 0;
        stencil_fields(sim, p, buf);
        *row = stencil_row(buf);
        return buf->n;
    }
    stencil_nodes(sim, p, node);
    for (int a = 0; a < STENCIL_NODES; a++)
        near |= F->first[node[a]] >= 0;
    if (!near)
        return 0;
    *row = contact_stencil_linear(sim, p, buf);
    return STENCIL_NODES;
}
/// [contact_stencil]

/** @brief A wide-stencil scatter of contact (chapter 8): @p fn for every
 *         point, on the strips of Task 0 when there are some, else on one
 *         thread in point order (own NULL). Each scatter calls it from a
 *         function of its own, so that @p fn is inlined there. */
static inline __attribute__((always_inline)) void
contact_scatter_wide(Sim *sim, StripPointFn fn, void *ctx)
{
    if (sim->strips.n > 0)
        strip_scatter(sim, fn, ctx);
    else
        for (int p = 0, np = sim->pts.n; p < np; p++)
            fn(sim, ctx, p, NULL);
}

#endif
