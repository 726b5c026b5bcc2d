/**
 * @file material_contact.c
 * @brief Contact between bodies at the nodes (Bardenhagen et al. 2001, the
 *        paper's Fig. 4): one field per contact group where groups meet,
 *        the normal from the fields' mass gradients, detection by approach
 *        (and relative volume when the pair asks), the shared adjustment.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact_law.h"
#include "checkpoint.h"
#include "material_contact.h"
#include "output.h"
#include "step.h"

int material_contact_prepare(Sim *sim, void *state, char *err, size_t errlen)
{
    MaterialContact *M = state;
    const Hooks *h = &sim->hooks;
    const FieldKey *group = hooks_find_field_key(h, "contact group");
    const FieldKey *side = hooks_find_field_key(h, "crack side");
    int nn = sim->grid.nnodes;
    M->shift = group ? group->shift : -1;
    M->group_mask = group ? (1u << group->bits) - 1u : 0u;
    M->side_mask = side ? ((1u << side->bits) - 1u) << side->shift : 0u;
    M->cell_groups = calloc((size_t)nn, sizeof(unsigned));
    M->mixed = calloc((size_t)nn, 1);
    M->near = calloc((size_t)nn, 1);
    M->area = calloc((size_t)nn, sizeof(double));
    M->held = calloc((size_t)nn, sizeof(unsigned));
    if (M->shift < 0 || fields_enable(sim) || !M->cell_groups || !M->mixed ||
        !M->near || !M->area || !M->held) {
        snprintf(err, errlen, "%s: out of memory (or field-key bits) for "
                 "contact between bodies", sim->scene.file);
        return -1;
    }
    return 0;
}

/// [material_key_fields]
int material_key_fields(Sim *sim, void *state, Seam seam)
{
    MaterialContact *M = state;
    const Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    int nx = g->nnx;
    (void)seam;
    memset(M->cell_groups, 0, sizeof(unsigned) * (size_t)g->nnodes);
    for (int p = 0; p < P->n; p++)              /* the groups in each cell */
        M->cell_groups[P->cell[p]] |= 1u << M->group_of_body[P->body[p]];
    for (int j = 0; j < g->nny; j++)            /* a node: its four cells */
        for (int i = 0; i < nx; i++) {
            int n = j * nx + i;
            unsigned seen = M->cell_groups[n];
            if (i > 0)
                seen |= M->cell_groups[n - 1];
            if (j > 0)
                seen |= M->cell_groups[n - nx] | (i > 0 ? M->cell_groups[n - nx - 1] : 0u);
            M->mixed[n] = (seen & (seen - 1)) != 0;  /* more than one group */
        }
    for (int p = 0; p < P->n; p++) {
        int node[STENCIL_NODES], group = M->group_of_body[P->body[p]];
        int c = P->cell[p];
        if (group == 0 || !(M->mixed[c] | M->mixed[c + 1] | M->mixed[c + nx] |
                            M->mixed[c + nx + 1]))
            continue;                           /* field 0, or one group */
        stencil_nodes(sim, p, node);
        for (int a = 0; a < STENCIL_NODES; a++)
            if (M->mixed[node[a]] &&
                fields_key(sim, p, a, (unsigned)group << M->shift))
                return -1;
    }
    return 0;
}
/// [material_key_fields]

/** Room for the per-slot gradients (grown with the grid's slots). */
static int reserve_gradients(Sim *sim, MaterialContact *M)
{
    int cap = sim->grid.capacity;
    if (cap <= M->cap)
        return 0;
    double *x = realloc(M->gx, sizeof(double) * (size_t)cap);
    if (x)
        M->gx = x;
    double *y = realloc(M->gy, sizeof(double) * (size_t)cap);
    if (y)
        M->gy = y;
    if (!x || !y)
        return step_fail(sim, 0, "memory for contact normals", cap);
    M->cap = cap;
    return 0;
}

/** Set @p flag in the cells (by lower-left node) of which a touched node
 *  is a corner. */
static void mark_cells_around(unsigned char *cells, const FieldTable *F,
                              int nx, unsigned char flag)
{
    for (int k = 0; k < F->ntouched; k++) {
        int n = F->touched[k];
        cells[n] = flag;
        if (n >= 1)
            cells[n - 1] = flag;
        if (n >= nx)
            cells[n - nx] = flag;
        if (n >= nx + 1)
            cells[n - nx - 1] = flag;
    }
}

/// [mass_gradients]
/** Task 2: at the nodes with several fields, each field's mass gradient
 *  sum_p m_p grad S_ip and the node's area sum_p A_p S_ip (A_p: the
 *  point's current volume over its body's thickness). A point in a cell
 *  none of whose corners has several fields costs one test. */
static int mass_gradients(Sim *sim, MaterialContact *M)
{
    const FieldTable *F = &sim->fields;
    const Grid *g = &sim->grid;
    const Particles *P = &sim->pts;
    const Body *bodies = sim->scene.bodies;
    int nx = g->nnx;
    if (reserve_gradients(sim, M))
        return -1;
    for (int k = 0; k < F->ntouched; k++) {     /* the nodes with several fields */
        int n = F->touched[k];
        M->area[n] = 0.0;
        for (int s = n; s >= 0; s = field_next(F, g, s))
            M->gx[s] = M->gy[s] = 0.0;
    }
    mark_cells_around(M->near, F, nx, 1);       /* and the cells around them */
    for (int p = 0; p < P->n; p++) {
        if (!M->near[P->cell[p]])
            continue;
        int node[STENCIL_NODES];
        Stencil st;
        stencil_nodes(sim, p, node);
        stencil_of_point(sim, p, &st);
        double mp = P->m[p];
        double area = (1.0 + P->exx[p]) * (1.0 + P->eyy[p]) * P->vol[p] /
                      bodies[P->body[p]].thickness;
        for (int a = 0; a < STENCIL_NODES; a++)
            if (F->first[node[a]] >= 0) {
                M->gx[st.slot[a]] += mp * st.Gx[a];
                M->gy[st.slot[a]] += mp * st.Gy[a];
                M->area[node[a]] += area * st.S[a];
            }
    }
    mark_cells_around(M->near, F, nx, 0);       /* clean for the next step */
    return 0;
}
/// [mass_gradients]

/// [material_contact_task]
int material_contact_task(Sim *sim, void *state, Seam seam)
{
    MaterialContact *M = state;
    const FieldTable *F = &sim->fields;
    Grid *g = &sim->grid;
    unsigned gmask = M->group_mask;
    if (seam == SEAM_TASK2_CONTACT) {           /* a new step */
        M->nodes = 0;
        if (mass_gradients(sim, M))
            return -1;
    }
    M->task_nodes = 0;
    double cell = g->dx * g->dy;
    for (int k = 0; k < F->ntouched; k++) {
        int n = F->touched[k], adjusted = 0, pair = 0;
        double vrel = M->area[n] / cell;        /* eq. 10, per unit thickness */
        if (seam == SEAM_TASK4_CONTACT)
            M->held[n] = 0;
        for (int a = n; a >= 0; a = field_next(F, g, a)) {
            unsigned ka = field_key(F, g, a);
            for (int b = field_next(F, g, a); b >= 0 && g->m[a] > 0;
                 b = field_next(F, g, b)) {
                unsigned kb = field_key(F, g, b);
                int ga = (int)((ka >> M->shift) & gmask);
                int gb = (int)((kb >> M->shift) & gmask);
                if (g->m[b] <= 0 || ga == gb || (ka & M->side_mask) != (kb & M->side_mask))
                    continue;                   /* same body, or across a crack */
                unsigned bit = pair < 32 ? 1u << pair : 0u;
                pair++;
                const ContactLaw *law = material_law(M, ga, gb);
                double nrm[2] = {0.0, 0.0};
                double grad_a[2] = {M->gx[a], M->gy[a]}, grad_b[2] = {M->gx[b], M->gy[b]};
                if (law->kind != CONTACT_BONDED &&
                    !contact_interface_normal(grad_a, grad_b, nrm))
                    continue;
                if (seam == SEAM_TASK6_CONTACT) {   /* the step's decision */
                    if (!(M->held[n] & bit))
                        continue;
                } else if (!contact_pair_detected(g, a, b, nrm, vrel, law)) {
                    continue;
                } else if (seam == SEAM_TASK4_CONTACT) {
                    M->held[n] |= bit;
                }
                M->work += contact_adjust(g, a, b, nrm, law);
                adjusted |= law->kind != CONTACT_BONDED;
            }
        }
        M->task_nodes += adjusted;
    }
    if (M->task_nodes > M->nodes)
        M->nodes = M->task_nodes;
    return 0;
}
/// [material_contact_task]

/// [material_contact_history]
int material_contact_history(const Sim *sim, void *state, FILE *f, int header)
{
    const MaterialContact *M = state;
    const Particles *P = &sim->pts;
    const Scene *sc = &sim->scene;
    if (header) {
        if (fprintf(f, ",material_contact_nodes,material_contact_work") < 0)
            return -1;
        for (int b = 0; b < sc->nbodies; b++)
            if (fprintf(f, ",momentum_x_%s,momentum_y_%s", sc->bodies[b].name,
                        sc->bodies[b].name) < 0)
                return -1;
        return 0;
    }
    if (fprintf(f, ",%d,%.*g", M->nodes, output_digits(sim, 10), M->work) < 0)
        return -1;
    for (int b = 0; b < sc->nbodies; b++) {    /* each body's momentum */
        double px = 0.0, py = 0.0;
        for (int p = 0; p < P->n; p++)
            if (P->body[p] == b) {
                px += P->m[p] * P->vx[p];
                py += P->m[p] * P->vy[p];
            }
        if (fprintf(f, ",%.*g,%.*g", output_digits(sim, 10), px,
                    output_digits(sim, 10), py) < 0)
            return -1;
    }
    return 0;
}
/// [material_contact_history]

int material_contact_checkpoint(Sim *sim, void *state, FILE *f, int save)
{
    (void)sim;
    MaterialContact *M = state;
    return checkpoint_io(f, &M->work, sizeof M->work, save) ||
           checkpoint_io(f, &M->nodes, sizeof M->nodes, save) ? -1 : 0;
}
