/**
 * @file xefg_build.c
 * @brief From a loaded scene to the XEFG discretisation: nodes and their
 *        supports, the enrichment of each node (eq. 1-2), the parameters,
 *        the Gauss points of every node's cell with their shape functions,
 *        the lumped masses (section 2.5) and the nodes' own rows.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cohesive.h"
#include "cracks.h"
#include "footprint.h"
#include "growth.h"
#include "quadrature.h"
#include "xefg.h"
#include "xefg_gather.h"

/** "file:line" of a scene line into @p at. */
static const char *line_at(const Sim *sim, int line, char *at)
{
    return scene_lines_at(sim->scene.lines, sim->scene.file, line, at,
                          SCENE_AT_LEN);
}

/** Is (px, py) strictly inside a body: inside with a margin all round? */
static int inside_a_body(const Scene *sc, double px, double py, double eps)
{
    for (int b = 0; b < sc->nbodies; b++) {
        const Shape *s = &sc->bodies[b].shape;
        if (shape_contains(s, px - eps, py - eps) &&
            shape_contains(s, px + eps, py - eps) &&
            shape_contains(s, px - eps, py + eps) &&
            shape_contains(s, px + eps, py + eps))
            return 1;
    }
    return 0;
}

/** The cracks of stage 2 as lines; an end inside a body is a tip. */
static int crack_lines(Xefg *x, const Sim *sim)
{
    const Cracks *C = cracks_of(sim);
    if (!C)
        return 0;
    x->crack = calloc((size_t)C->ncracks, sizeof(CrackLine));
    if (!x->crack)
        return -1;
    x->ncrack = C->ncracks;
    double eps = 1e-9 * fmin(sim->scene.dx, sim->scene.dy);
    for (int c = 0; c < C->ncracks; c++) {
        const Crack *k = &C->crack[c];
        CrackLine *l = &x->crack[c];
        l->n = k->n;
        l->x = k->x;
        l->y = k->y;
        l->tip[0] = inside_a_body(&sim->scene, k->x[0], k->y[0], eps);
        l->tip[1] = inside_a_body(&sim->scene, k->x[k->n - 1], k->y[k->n - 1], eps);
    }
    return 0;
}

/** Nodes: the points, their cells (half sides) and supports d = a h. */
static int nodes(Xefg *x, const Sim *sim)
{
    const Scene *sc = &sim->scene;
    const Particles *P = &sim->pts;
    int n = P->n;
    x->nnode = n;
    x->X = malloc(sizeof(double) * (size_t)n);
    x->Y = malloc(sizeof(double) * (size_t)n);
    x->d = malloc(sizeof(double) * (size_t)n);
    x->hx = malloc(sizeof(double) * (size_t)n);
    x->hy = malloc(sizeof(double) * (size_t)n);
    if (!x->X || !x->Y || !x->d || !x->hx || !x->hy)
        return -1;
    for (int p = 0; p < n; p++) {
        const Body *B = &sc->bodies[P->body[p]];
        x->X[p] = P->x[p];
        x->Y[p] = P->y[p];
        x->hx[p] = 0.5 * sc->dx / B->ppc;
        x->hy[p] = 0.5 * sc->dy / B->ppc;
        x->d[p] = x->set.support * 2.0 * fmax(x->hx[p], x->hy[p]);
    }
    return 0;
}

/** Parameters: a standard one per node, a step one per crack that cuts
 *  its support through, branch ones per tip its support holds (eq. 1). */
static int parameters(Xefg *x)
{
    int nb = x->set.tip == BRANCH_LEFM ? 4 : 1;
    int n = x->nnode, cap = n + 16;
    x->node_dof = malloc(sizeof(int) * (size_t)(n + 1));
    x->dof_node = malloc(sizeof(int) * (size_t)cap);
    x->dof_kind = malloc(sizeof(int) * (size_t)cap);
    x->dof_crack = malloc(sizeof(int) * (size_t)cap);
    x->dof_end = malloc(sizeof(int) * (size_t)cap);
    x->dof_frame = malloc(4 * sizeof(double) * (size_t)cap);
    x->dof_line = malloc(2 * sizeof(int) * (size_t)cap);
    if (!x->node_dof || !x->dof_node || !x->dof_kind || !x->dof_crack ||
        !x->dof_end || !x->dof_frame || !x->dof_line)
        return -1;
    int q = 0;
    for (int I = 0; I < n; I++) {
        x->node_dof[I] = q;
        int kinds[1 + 2 * 16], crack[1 + 2 * 16], end[1 + 2 * 16], m = 0;
        kinds[m] = DOF_STANDARD, crack[m] = -1, end[m++] = 0;
        for (int c = 0; c < x->ncrack && m + nb < 32; c++) {
            int e = 0;
            SupportCut cut = crack_line_cut(&x->crack[c], x->X[I], x->Y[I],
                                            x->d[I], &e);
            if (cut == SUPPORT_CUT) {                  /* W_b */
                kinds[m] = DOF_STEP, crack[m] = c, end[m++] = 0;
                x->nstep++;
            } else if (cut == SUPPORT_TIP)             /* W_s */
                for (int b = 0; b < nb; b++) {
                    kinds[m] = DOF_BRANCH + b, crack[m] = c, end[m++] = e;
                    x->nbranch++;
                }
        }
        if (q + m > cap) {
            cap = 2 * (q + m);
            if (xefg_grow((void **)&x->dof_node, sizeof(int), cap) ||
                xefg_grow((void **)&x->dof_kind, sizeof(int), cap) ||
                xefg_grow((void **)&x->dof_crack, sizeof(int), cap) ||
                xefg_grow((void **)&x->dof_end, sizeof(int), cap) ||
                xefg_grow((void **)&x->dof_frame, 4 * sizeof(double), cap) ||
                xefg_grow((void **)&x->dof_line, 2 * sizeof(int), cap))
                return -1;
        }
        for (int k = 0; k < m; k++, q++) {
            x->dof_node[q] = I;
            x->dof_kind[q] = kinds[k];
            x->dof_crack[q] = crack[k];
            x->dof_end[q] = end[k];
            double *fr = x->dof_frame + 4 * q;      /* the tip it enriches */
            fr[0] = fr[1] = fr[2] = fr[3] = 0.0;
            if (kinds[k] >= DOF_BRANCH)
                crack_line_tip(&x->crack[crack[k]], end[k], fr, fr + 2);
            x->dof_line[2 * q] = 0;                 /* the whole line */
            x->dof_line[2 * q + 1] = crack[k] >= 0 ? x->crack[crack[k]].n : 0;
        }
    }
    x->node_dof[n] = q;
    x->ndof = q;
    return 0;
}

/** Refuse a crack whose line cuts no node's support: it lies outside
 *  every body. */
static int cracks_in_bodies(const Xefg *x, const Sim *sim, char *err,
                            size_t errlen)
{
    const Cracks *C = cracks_of(sim);
    for (int c = 0; c < x->ncrack; c++) {
        int used = 0;
        for (int q = 0; q < x->ndof && !used; q++)
            used = x->dof_crack[q] == c;
        if (!used) {
            char at[SCENE_AT_LEN];
            snprintf(err, errlen, "%s: crack %d, from (%g, %g) to (%g, %g), "
                     "cuts no body: it lies outside every body's points and "
                     "their supports", line_at(sim, C->crack[c].line, at), c,
                     x->crack[c].x[0], x->crack[c].y[0],
                     x->crack[c].x[x->crack[c].n - 1],
                     x->crack[c].y[x->crack[c].n - 1]);
            return -1;
        }
    }
    return 0;
}

/** The message for a place whose row could not be made (@p rc). */
static int row_error(const Xefg *x, const Sim *sim, int node, double px,
                     double py, int rc, char *err, size_t errlen)
{
    const Body *B = &sim->scene.bodies[sim->pts.body[node]];
    char at[SCENE_AT_LEN];
    if (rc == -2) {
        snprintf(err, errlen, "%s: out of memory for the shape functions",
                 sim->scene.file);
        return -1;
    }
    const char *where = x->set.line ? line_at(sim, x->set.line, at)
                                    : line_at(sim, B->line, at);
    if (rc == -3)
        snprintf(err, errlen, "%s: xefg.support = %g: the point at (%g, %g) of "
                 "body \"%s\" lies in the supports of more than 512 nodes; "
                 "lower xefg.support", where, x->set.support, px, py, B->name);
    else
        snprintf(err, errlen, "%s: xefg.support = %g: the point at (%g, %g) of "
                 "body \"%s\" (in the cell of the node at (%g, %g)) lies in the "
                 "supports of fewer than three nodes not on one line, too few "
                 "for the linear basis (eq. 15); raise xefg.support (2 to 3 is "
                 "usual)", where, x->set.support, px, py, B->name, x->X[node],
                 x->Y[node]);
    return -1;
}

/** Gauss points of every node's cell, with their shape functions; the
 *  lumped masses and body-force integrals on the way. */
static int gauss_points(Xefg *x, const Sim *sim, const CellList *cl,
                        char *err, size_t errlen)
{
    const Scene *sc = &sim->scene;
    const Particles *P = &sim->pts;
    int n = x->set.gauss, cap = 64 * n * n;
    QuadPoint *q = malloc(sizeof(QuadPoint) * (size_t)cap);
    x->mass = calloc((size_t)x->ndof, sizeof(double));
    x->load = calloc((size_t)x->ndof, sizeof(double));
    x->cell_w = calloc((size_t)x->nnode, sizeof(double));
    if (!q || !x->mass || !x->load || !x->cell_w) {
        free(q);
        return -1;
    }
    int gcap = 0;
    double *diag = calloc((size_t)x->ndof, sizeof(double));
    if (!diag) {
        free(q);
        return -1;
    }
    for (int I = 0; I < x->nnode; I++) {
        int m = quad_cell(x->crack, x->ncrack, x->X[I] - x->hx[I],
                          x->Y[I] - x->hy[I], x->X[I] + x->hx[I],
                          x->Y[I] + x->hy[I], n, q, cap);
        if (m > cap) {                               /* room, and again */
            cap = m;
            QuadPoint *r = realloc(q, sizeof(QuadPoint) * (size_t)cap);
            if (!r)
                break;
            q = r;
            m = quad_cell(x->crack, x->ncrack, x->X[I] - x->hx[I],
                          x->Y[I] - x->hy[I], x->X[I] + x->hx[I],
                          x->Y[I] + x->hy[I], n, q, cap);
        }
        if (m < 0)
            break;
        if (x->ngauss + m > gcap) {
            gcap = 2 * (x->ngauss + m);
            if (xefg_grow((void **)&x->gx, sizeof(double), gcap) ||
                xefg_grow((void **)&x->gy, sizeof(double), gcap) ||
                xefg_grow((void **)&x->gw, sizeof(double), gcap) ||
                xefg_grow((void **)&x->gnode, sizeof(int), gcap))
                break;
        }
        const Body *B = &sc->bodies[P->body[I]];
        double rho = sc->mat[B->material].rho;
        for (int k = 0; k < m; k++) {
            int g = x->ngauss++;
            x->gx[g] = q[k].x;
            x->gy[g] = q[k].y;
            x->gw[g] = q[k].w * B->thickness;
            x->gnode[g] = I;
            x->cell_w[I] += x->gw[g];
            int rc = xefg_shape_row(x, cl, P->body, P->body[I], q[k].x,
                                    q[k].y, 1, &x->gauss);
            if (rc) {
                double px = q[k].x, py = q[k].y;
                free(q);
                free(diag);
                return row_error(x, sim, I, px, py, rc, err, errlen);
            }
            for (int e = x->gauss.start[g]; e < x->gauss.start[g + 1]; e++) {
                int d = x->gauss.dof[e];
                double rw = rho * x->gw[g], N = x->gauss.N[e], E = 1.0, Ex, Ey;
                if (x->dof_kind[d] != DOF_STANDARD)
                    xefg_enrichment(x, d, q[k].x, q[k].y, &E, &Ex, &Ey);
                else
                    x->mass[d] += rw * N;           /* row sum: int rho Phi_I */
                diag[d] += rw * E * E;              /* int_supp rho E^2 */
                x->load[d] += rw * N;
            }
        }
    }
    free(q);
    /// [xefg_lumping]
    /* section 2.5: an enriched parameter gets the row-sum mass of its node
     * times the mean of E^2 over the node's support, m_I <E^2> (after
     * Elguedj et al.): H^2 = 1 gives a step parameter m_I whatever the cut,
     * so the stable step cannot collapse when a crack clips a support */
    for (int d = 0; d < x->ndof; d++) {
        int s0 = x->node_dof[x->dof_node[d]];
        if (d != s0)
            x->mass[d] = x->mass[s0] * diag[d] / diag[s0];
    }
    /// [xefg_lumping]
    free(diag);
    if (x->nnode && x->gauss.n != x->ngauss) {
        snprintf(err, errlen, "%s: out of memory for the Gauss points",
                 sim->scene.file);
        return -1;
    }
    return 0;
}

/** Every parameter's lumped mass must be positive and finite. */
static int check_masses(const Xefg *x, const Sim *sim, char *err,
                        size_t errlen)
{
    for (int q = 0; q < x->ndof; q++)
        if (!(x->mass[q] > 0.0 && isfinite(x->mass[q]))) {
            int I = x->dof_node[q];
            snprintf(err, errlen, "%s: the node at (%g, %g) has a %s "
                     "parameter of lumped mass %g: raise xefg.support or "
                     "xefg.gauss", sim->scene.file, x->X[I], x->Y[I],
                     x->dof_kind[q] == DOF_STANDARD ? "standard"
                     : x->dof_kind[q] == DOF_STEP ? "step" : "branch",
                     x->mass[q]);
            return -1;
        }
    return 0;
}

/** State at t = 0: velocities of the bodies' linear fields on the standard
 *  parameters (MLS reproduces them exactly), the points' stress and strain
 *  at the Gauss points of their cells. */
static int initial_state(Xefg *x, const Sim *sim)
{
    const Particles *P = &sim->pts;
    size_t n2 = 2 * (size_t)x->ndof;
    x->u = calloc(n2, sizeof(double));
    x->v = calloc(n2, sizeof(double));
    x->f = calloc(n2, sizeof(double));
    x->a = calloc(n2, sizeof(double));
    x->gs = malloc(3 * sizeof(double) * (size_t)x->ngauss);
    x->ge = malloc(3 * sizeof(double) * (size_t)x->ngauss);
    if (!x->u || !x->v || !x->f || !x->a || !x->gs || !x->ge)
        return -1;
    for (int I = 0; I < x->nnode; I++) {
        x->v[2 * x->node_dof[I]] = P->vx[I];
        x->v[2 * x->node_dof[I] + 1] = P->vy[I];
    }
    for (int g = 0; g < x->ngauss; g++) {
        int I = x->gnode[g];
        x->gs[3 * g] = P->sxx[I];
        x->gs[3 * g + 1] = P->syy[I];
        x->gs[3 * g + 2] = P->sxy[I];
        x->ge[3 * g] = P->exx[I];
        x->ge[3 * g + 1] = P->eyy[I];
        x->ge[3 * g + 2] = P->exy[I];
    }
    return 0;
}

/** Refuse a discretisation that would not fit in memory, before its rows
 *  are built: each of the gauss^2 points of a node's cell keeps a row of
 *  about pi (d/h)^2 nodes' parameters (value and gradient, 28 bytes each). */
static int check_memory(const Xefg *x, const Sim *sim, char *err,
                        size_t errlen)
{
    double a = x->set.support, g = x->set.gauss;
    double per_node = (double)x->ndof / (x->nnode ? x->nnode : 1);
    double entries = (double)x->nnode * g * g * (3.2 * a * a + 2.0) * per_node;
    double bytes = entries * 28.0 + (double)x->nnode * g * g * 80.0;
    double limit = sim->memory_limit ? (double)sim->memory_limit
                                     : footprint_available();
    if (bytes <= limit)
        return 0;
    char at[SCENE_AT_LEN];
    snprintf(err, errlen, "%s: the XEFG discretisation needs about %.2g GB "
             "(%d nodes, %.3g Gauss points, %.3g shape-function entries), more "
             "than the %.2g GB available (--max-memory to change; or lower "
             "xefg.gauss or xefg.support)",
             x->set.line ? line_at(sim, x->set.line, at) : sim->scene.file,
             bytes / 1e9, x->nnode, (double)x->nnode * g * g, entries,
             limit / 1e9);
    return -1;
}

/// [xefg_build]
int xefg_build(Xefg *x, const Sim *sim, char *err, size_t errlen)
{
    CellList cl = {0};
    double size = 0.0;
    int rc = -1;
    if (crack_lines(x, sim) || nodes(x, sim) || parameters(x))
        goto oom;
    if (cracks_in_bodies(x, sim, err, errlen) || check_memory(x, sim, err, errlen))
        return -1;
    for (int I = 0; I < x->nnode; I++)
        size = fmax(size, x->d[I]);
    if (cell_list_build(&cl, x->nnode, x->X, x->Y, size))
        goto oom;
    if (gauss_points(x, sim, &cl, err, errlen) ||
        check_masses(x, sim, err, errlen))
        goto done;
    for (int I = 0; I < x->nnode; I++) {          /* rows at the nodes */
        int r = xefg_shape_row(x, &cl, sim->pts.body, sim->pts.body[I],
                               x->X[I], x->Y[I], 0, &x->at_node);
        if (r) {
            row_error(x, sim, I, x->X[I], x->Y[I], r, err, errlen);
            goto done;
        }
    }
    if (initial_state(x, sim))
        goto oom;
    if (xefg_constraints_build(x, sim, &cl, sim->pts.body, err, errlen))
        goto done;
    if ((x->coh = cohesive_of(sim)) &&              /* before the stable step */
        cohesive_build(x->coh, x, sim, &cl, err, errlen))
        goto done;
    if ((x->grow = growth_of(sim)) &&               /* room to grow */
        growth_build(x->grow, x, sim, err, errlen))
        goto done;
    if (xefg_gather_build(x, sim))                  /* sums on threads */
        goto oom;
    if (xefg_power_iteration(x, sim)) {
        snprintf(err, errlen, "%s: the power iteration for the stable time "
                 "step gave no finite frequency (highest %g)", sim->scene.file,
                 x->omega_max);
        goto done;
    }
    xefg_accelerations(x, sim, 0.0);              /* a(0) */
    x->e0 = xefg_kinetic_energy(x) + xefg_strain_energy(x, sim);
    rc = 0;
    goto done;
oom:
    snprintf(err, errlen, "%s: out of memory for the XEFG discretisation",
             sim->scene.file);
done:
    cell_list_free(&cl);
    return rc;
}
/// [xefg_build]

void xefg_free(Xefg *x)
{
    void *arrays[] = {x->X, x->Y, x->d, x->hx, x->hy, x->crack, x->node_dof,
                      x->dof_node, x->dof_kind, x->dof_crack, x->dof_end,
                      x->dof_frame, x->dof_line,
                      x->mass, x->load, x->u, x->v, x->a, x->f, x->gw, x->gx, x->gy,
                      x->gnode, x->gs, x->ge, x->cell_w};
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; k++)
        free(arrays[k]);
    shape_rows_free(&x->gauss);
    shape_rows_free(&x->at_node);
    xefg_gather_free(x->gather);
    for (int k = 0; k < 2; k++) {
        Constraints *c = &x->fix[k];
        free(c->node);
        free(c->hold);
        free(c->S);
        free(c->r);
        shape_rows_free(&c->rows);
    }
    *x = (Xefg){0};
}
