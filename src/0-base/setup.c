/**
 * @file setup.c
 * @brief From a scene to a ready simulation: material points from shapes,
 *        grid boundary conditions and loaded points.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "setup.h"

/// [fill_body]
/** Fill body @p b with k x k points per cell at the centres of the
 *  sub-cells, with its velocity field, its stress and strain @p e0. */
static int fill_body(Sim *sim, int b, const double e0[3])
{
    const Scene *sc = &sim->scene;
    const Body *B = &sc->bodies[b];
    const Material *mat = &sc->mat[B->material];
    int k = B->ppc;
    double hx = sc->dx / k, hy = sc->dy / k;
    double vol = hx * hy * B->thickness;                /* area x thickness */
    int i0 = (int)floor((B->shape.xmin - sc->ox) / sc->dx);
    int i1 = (int)ceil((B->shape.xmax - sc->ox) / sc->dx);
    int j0 = (int)floor((B->shape.ymin - sc->oy) / sc->dy);
    int j1 = (int)ceil((B->shape.ymax - sc->oy) / sc->dy);
    for (int j = j0 * k; j < j1 * k; j++)
        for (int i = i0 * k; i < i1 * k; i++) {
            double x = sc->ox + (i + 0.5) * hx, y = sc->oy + (j + 0.5) * hy;
            if (!shape_contains(&B->shape, x, y))
                continue;
            int p = particles_add(&sim->pts, x, y, mat->rho * vol, vol,
                                  B->material, b);
            if (p < 0)
                return -1;
            double rx = x - B->cx, ry = y - B->cy;
            sim->pts.vx[p] = B->vx + B->L[0] * rx + B->L[1] * ry;
            sim->pts.vy[p] = B->vy + B->L[2] * rx + B->L[3] * ry;
            sim->pts.sxx[p] = B->stress[0];
            sim->pts.syy[p] = B->stress[1];
            sim->pts.sxy[p] = B->stress[2];
            sim->pts.exx[p] = e0[0];
            sim->pts.eyy[p] = e0[1];
            sim->pts.exy[p] = e0[2];
        }
    return 0;
}
/// [fill_body]

/** "file:line" of body @p B into @p at (SCENE_AT_LEN). */
static const char *body_at(const Scene *sc, const Body *B, char *at)
{
    return scene_lines_at(sc->lines, sc->file, B->line, at, SCENE_AT_LEN);
}

/** The strain @p e that carries body @p b's initial stress, checked
 *  against the range of a small-strain law: principal strains in (-1, 1),
 *  so that no point's area (1 + e1)(1 + e2) A vanishes. */
static int initial_strain(const Scene *sc, int b, double e[3], char *err,
                          size_t errlen)
{
    const Body *B = &sc->bodies[b];
    const Material *mat = &sc->mat[B->material];
    const double *s = B->stress;
    char at[SCENE_AT_LEN];
    e[0] = e[1] = e[2] = 0.0;
    if (s[0] == 0.0 && s[1] == 0.0 && s[2] == 0.0)
        return 0;
    if (!mat->law->strain) {
        snprintf(err, errlen, "%s: stress: material \"%s\" (law \"%s\") "
                 "takes no initial stress", body_at(sc, B, at), mat->name,
                 mat->law->name);
        return -1;
    }
    mat->law->strain(mat, s, e);
    double mean = 0.5 * (e[0] + e[1]);
    double rad = sqrt(0.25 * (e[0] - e[1]) * (e[0] - e[1]) + e[2] * e[2]);
    if (!(mean + rad < 1.0 && mean - rad > -1.0)) {
        snprintf(err, errlen, "%s: stress: [%g, %g, %g] %s is outside the "
                 "range of material \"%s\": its principal strains %g and %g "
                 "must lie in (-1, 1)", body_at(sc, B, at), s[0], s[1], s[2],
                 sc->run.units->stress, mat->name, mean + rad, mean - rad);
        return -1;
    }
    return 0;
}

/** A point's mass in body @p b, rho x (cell / k)^2 x thickness, and its
 *  volume in the range whose sums and m v^2 stay finite: [1e-300, 1e300]. */
static int check_point_mass(const Scene *sc, int b, char *err, size_t errlen)
{
    const Body *B = &sc->bodies[b];
    double rho = sc->mat[B->material].rho;
    double vol = (sc->dx / B->ppc) * (sc->dy / B->ppc) * B->thickness;
    double m = rho * vol;
    if (m >= 1e-300 && m <= 1e300 && vol >= 1e-300 && vol <= 1e300)
        return 0;
    char at[SCENE_AT_LEN];
    snprintf(err, errlen, "%s: body \"%s\": a point's mass rho x volume = %g "
             "x %g = %g: %s is outside [1e-300, 1e300]: check rho, thickness "
             "and cell_size", body_at(sc, B, at), B->name, rho, vol, m,
             m >= 1e-300 && m <= 1e300 ? "the volume" : "the mass");
    return -1;
}

int setup_points(Sim *sim, char *err, size_t errlen)
{
    Scene *sc = &sim->scene;
    if (particles_init(&sim->pts, 1024)) {
        snprintf(err, errlen, "%s: out of memory for the points", sc->file);
        return -1;
    }
    for (int b = 0; b < sc->nbodies; b++) {
        int before = sim->pts.n;
        double e0[3];
        if (check_point_mass(sc, b, err, errlen) || initial_strain(sc, b, e0, err, errlen))
            return -1;
        if (fill_body(sim, b, e0)) {
            if (sim->pts.n == INT_MAX)
                snprintf(err, errlen, "%s:%d: body \"%s\": more than %d points "
                         "(lower points_per_cell or the cell count)", sc->file,
                         sc->bodies[b].line, sc->bodies[b].name, INT_MAX);
            else
                snprintf(err, errlen, "%s: out of memory for the points", sc->file);
            return -1;
        }
        if (sim->pts.n == before) {
            char at[SCENE_AT_LEN];
            snprintf(err, errlen, "%s: body \"%s\" holds no material point "
                     "(shape smaller than a point spacing?)",
                     body_at(sc, &sc->bodies[b], at), sc->bodies[b].name);
            return -1;
        }
    }
    return 0;
}

int setup_grid(Sim *sim, char *err, size_t errlen)
{
    Scene *sc = &sim->scene;
    Grid *g = &sim->grid;
    if (grid_init(g, sc->ox, sc->oy, sc->dx, sc->dy, sc->ncx, sc->ncy)) {
        snprintf(err, errlen, "%s: out of memory for the grid", sc->file);
        return -1;
    }
    double tol = 1e-9 * fmin(sc->dx, sc->dy);
    int *owner = malloc(sizeof(int) * (size_t)g->nnodes);  /* the boundary */
    if (!owner) {
        snprintf(err, errlen, "%s: out of memory for the grid", sc->file);
        return -1;
    }
    for (int n = 0; n < g->nnodes; n++)
        owner[n] = -1;
    for (int k = 0; k < sc->nbc; k++) {
        const Boundary *B = &sc->bc[k];
        Shape r = B->region;                 /* nodes on its edges count */
        r.xmin -= tol;
        r.ymin -= tol;
        r.xmax += tol;
        r.ymax += tol;
        for (int n = 0; n < g->nnodes; n++) {
            if (!shape_contains(&r, grid_node_x(g, n), grid_node_y(g, n)))
                continue;
            int o = owner[n];
            if (o >= 0 && (B->moving || sc->bc[o].moving)) {
                char at[SCENE_AT_LEN], other[SCENE_AT_LEN];
                const char *f1 = sc->file, *f2 = sc->file;
                int l1 = B->line, l2 = sc->bc[o].line;
                scene_lines_find(sc->lines, B->line, &f1, &l1);
                scene_lines_find(sc->lines, sc->bc[o].line, &f2, &l2);
                if (strcmp(f1, f2) == 0)           /* "line 9", or "a.cfg:9" */
                    snprintf(other, sizeof other, "line %d", l2);
                else
                    snprintf(other, sizeof other, "%s:%d", f2, l2);
                snprintf(err, errlen, "%s: boundaries: the node at (%g, %g) is "
                         "also held by the boundary at %s; a prescribed "
                         "velocity and another hold on one node contradict",
                         scene_lines_at(sc->lines, sc->file, B->line, at, sizeof at),
                         grid_node_x(g, n), grid_node_y(g, n), other);
                free(owner);
                return -1;
            }
            g->fixed[n] |= (unsigned char)B->hold.fix;
            owner[n] = k;
            sim->nmoving += B->moving;
        }
    }
    sim->moving = malloc(sizeof(int) * (size_t)(sim->nmoving + 1));
    sim->moving_bc = malloc(sizeof(int) * (size_t)(sim->nmoving + 1));
    if (!sim->moving || !sim->moving_bc) {
        snprintf(err, errlen, "%s: out of memory for the grid", sc->file);
        free(owner);
        return -1;
    }
    int m = 0;
    for (int n = 0; n < g->nnodes; n++)
        if (owner[n] >= 0 && sc->bc[owner[n]].moving) {
            sim->moving[m] = n;
            sim->moving_bc[m++] = owner[n];
        }
    free(owner);
    return 0;
}

/** The points inside @p region, into a new array @p *points (the caller
 *  frees it); their number, or -1 out of memory. */
static int points_in(const Particles *P, const Shape *region, int **points)
{
    *points = malloc(sizeof(int) * ((size_t)P->n + 1));
    if (!*points)
        return -1;
    int count = 0;
    for (int p = 0; p < P->n; p++)
        if (shape_contains(region, P->x[p], P->y[p]))
            (*points)[count++] = p;
    return count;
}

/** The message for a box (of @p what, at @p line) that holds no point. */
static int no_point_in(const Scene *sc, const char *what, int line,
                       const Shape *r, char *err, size_t errlen)
{
    char at[SCENE_AT_LEN];
    snprintf(err, errlen, "%s: %s: no material point lies in [%g, %g] x "
             "[%g, %g]", scene_lines_at(sc->lines, sc->file, line, at, sizeof at),
             what, r->xmin, r->xmax, r->ymin, r->ymax);
    return -1;
}

int setup_loads(Sim *sim, char *err, size_t errlen)
{
    Scene *sc = &sim->scene;
    for (int l = 0; l < sc->nloads; l++) {
        Load *L = &sc->loads[l];
        L->count = points_in(&sim->pts, &L->region, &L->points);
        if (L->count < 0) {
            snprintf(err, errlen, "%s: out of memory", sc->file);
            return -1;
        }
        if (L->count == 0)
            return no_point_in(sc, "load", L->line, &L->region, err, errlen);
    }
    return 0;
}

int setup_held_points(Sim *sim, char *err, size_t errlen)
{
    Scene *sc = &sim->scene;
    Particles *P = &sim->pts;
    for (int k = 0; k < sc->nheld; k++) {
        HeldPoints *H = &sc->held[k];
        H->count = points_in(P, &H->region, &H->points);
        if (H->count < 0) {
            snprintf(err, errlen, "%s: out of memory", sc->file);
            return -1;
        }
        if (H->count == 0)
            return no_point_in(sc, "point_velocities", H->line, &H->region, err,
                               errlen);
        const Grid *g = &sim->grid;
        for (int j = 0; j < H->count; j++) {    /* its nodes: held by no boundary */
            int p = H->points[j];
            int i0 = (int)floor((P->x[p] - g->ox) / g->dx);
            int j0 = (int)floor((P->y[p] - g->oy) / g->dy);
            for (int a = 0; a < 4; a++) {
                int n = (j0 + a / 2) * g->nnx + i0 + a % 2;
                if (g->fixed[n]) {
                    char at[SCENE_AT_LEN];
                    snprintf(err, errlen, "%s: point_velocities: the point at "
                             "(%g, %g) reaches the node at (%g, %g), which a "
                             "boundary holds; the two holds contradict",
                             scene_lines_at(sc->lines, sc->file, H->line, at,
                                            sizeof at),
                             P->x[p], P->y[p], grid_node_x(g, n),
                             grid_node_y(g, n));
                    return -1;
                }
            }
        }
        double v[2];
        hold_velocity(&H->hold, 0.0, v);
        for (int j = 0; j < H->count; j++) {    /* they start at it */
            if (H->hold.fix & GRID_FIX_X)
                P->vx[H->points[j]] = v[0];
            if (H->hold.fix & GRID_FIX_Y)
                P->vy[H->points[j]] = v[1];
        }
    }
    return 0;
}

/** The sums history.csv writes over body @p b's points, into @p t. */
static void body_totals(const Sim *sim, int b, Totals *t)
{
    const Particles *P = &sim->pts;
    *t = (Totals){0, 0, 0, 0};
    for (int p = 0; p < P->n; p++) {
        if (P->body[p] != b)
            continue;
        double m = P->m[p];
        t->kinetic += 0.5 * m * (P->vx[p] * P->vx[p] + P->vy[p] * P->vy[p]);
        t->strain += P->vol[p] * material_energy_density(P->sxx[p], P->syy[p],
                         P->sxy[p], P->exx[p], P->eyy[p], P->exy[p]);
        t->px += m * P->vx[p];
        t->py += m * P->vy[p];
    }
}

int setup_check_totals(const Sim *sim, char *err, size_t errlen)
{
    Totals t = sim_totals(sim);
    if (isfinite(t.kinetic) && isfinite(t.strain) && isfinite(t.px) && isfinite(t.py))
        return 0;
    const Scene *sc = &sim->scene;
    const char *eu = sc->run.units->energy;
    char at[SCENE_AT_LEN];
    for (int b = 0; b < sc->nbodies; b++) {
        body_totals(sim, b, &t);
        const Body *B = &sc->bodies[b];
        if (!isfinite(t.kinetic) || !isfinite(t.px) || !isfinite(t.py)) {
            snprintf(err, errlen, "%s: body \"%s\": its kinetic energy %g %s or "
                     "momentum (%g, %g) is not finite: rho, thickness and velocity "
                     "are too large together", body_at(sc, B, at), B->name,
                     t.kinetic, eu, t.px, t.py);
            return -1;
        }
        if (!isfinite(t.strain)) {
            snprintf(err, errlen, "%s: body \"%s\": its strain energy %g %s is "
                     "not finite: stress, thickness and cell_size are too large "
                     "together", body_at(sc, B, at), B->name, t.strain, eu);
            return -1;
        }
    }
    snprintf(err, errlen, "%s: the points' energy or momentum summed over the "
             "bodies is not finite (kinetic %g, strain %g %s)", sc->file,
             t.kinetic, t.strain, eu);
    return -1;
}
