/**
 * @file growth_reserve.c
 * @brief Set-up of the cracks that grow: the checks that need the whole
 *        scene (a cohesive law on every crack that grows), the defaults,
 *        and the room every growth event may use, reserved once, so that
 *        no time step allocates (xefg_build.c sizes its arrays to what the
 *        stationary crack needs; a growing crack needs more).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cohesive.h"
#include "cracks.h"
#include "growth.h"

/** pi, rounded up: the sizes below are upper bounds. */
#define PI_UP 3.1416

/** Most cuts (segments and tips) a cell split during a run may have. */
#define QUAD_CUTS 32

/** "file:line" of a scene line into @p at. */
static const char *line_at(const Sim *sim, int line, char *at)
{
    return scene_lines_at(sim->scene.lines, sim->scene.file, line, at,
                          SCENE_AT_LEN);
}

/** Refuse growth on a crack without a cohesive law: only a cohesive crack
 *  grows (the new segment starts on the law's elastic branch). */
static int check_cohesive(const Growth *g, const Xefg *x, const Sim *sim,
                          char *err, size_t errlen)
{
    for (int k = 0; k < g->ncrack; k++) {
        if (!g->set[k].on)
            continue;
        const Cohesive *c = x->coh;
        if (k < x->ncrack && c && k < c->ncrack && c->set[k].on)
            continue;
        char at[SCENE_AT_LEN];
        snprintf(err, errlen, "%s: growth: crack %d has no cohesive law: only "
                 "a cohesive crack grows (its new segments start on the law's "
                 "elastic branch); add cohesive = { f_t = ...; G_f = ...; } to "
                 "the crack, or remove its growth group",
                 line_at(sim, g->set[k].line, at), k);
        return -1;
    }
    return 0;
}

/** Entries for @p n things, and one more (never zero). */
static size_t room(int n)
{
    return (size_t)(n > 0 ? n : 0) + 1;
}

/** Grow every per-parameter array of @p x to @p cap parameters. */
static int reserve_parameters(Xefg *x, int cap)
{
    size_t d = sizeof(double);
    return xefg_grow((void **)&x->dof_node, sizeof(int), cap) ||
           xefg_grow((void **)&x->dof_kind, sizeof(int), cap) ||
           xefg_grow((void **)&x->dof_crack, sizeof(int), cap) ||
           xefg_grow((void **)&x->dof_end, sizeof(int), cap) ||
           xefg_grow((void **)&x->dof_frame, 4 * d, cap) ||
           xefg_grow((void **)&x->dof_line, 2 * sizeof(int), cap) ||
           xefg_grow((void **)&x->mass, d, cap) ||
           xefg_grow((void **)&x->load, d, cap) ||
           xefg_grow((void **)&x->u, 2 * d, cap) ||
           xefg_grow((void **)&x->v, 2 * d, cap) ||
           xefg_grow((void **)&x->a, 2 * d, cap) ||
           xefg_grow((void **)&x->f, 2 * d, cap) ? -1 : 0;
}

/** Room for @p nrow rows and @p nent entries in @p R. */
static int reserve_rows(ShapeRows *R, int nrow, int nent, int grad)
{
    if (nrow > R->ncap) {
        if (xefg_grow((void **)&R->start, sizeof(int), nrow + 1))
            return -1;
        if (R->ncap == 0)
            R->start[0] = 0;
        R->ncap = nrow;
    }
    if (nent > R->cap) {
        if (xefg_grow((void **)&R->dof, sizeof(int), nent) ||
            xefg_grow((void **)&R->N, sizeof(double), nent) ||
            (grad && (xefg_grow((void **)&R->Nx, sizeof(double), nent) ||
                      xefg_grow((void **)&R->Ny, sizeof(double), nent))))
            return -1;
        R->cap = nent;
    }
    return 0;
}

/** Grow every Gauss point array of @p x to @p cap points. */
static int reserve_gauss(Xefg *x, int cap)
{
    size_t d = sizeof(double);
    return xefg_grow((void **)&x->gx, d, cap) ||
           xefg_grow((void **)&x->gy, d, cap) ||
           xefg_grow((void **)&x->gw, d, cap) ||
           xefg_grow((void **)&x->gnode, sizeof(int), cap) ||
           xefg_grow((void **)&x->gs, 3 * d, cap) ||
           xefg_grow((void **)&x->ge, 3 * d, cap) ? -1 : 0;
}

/** Grow every cohesive point array to @p cap points. */
static int reserve_cohesive(Cohesive *c, int cap)
{
    double **d[] = {&c->px, &c->py, &c->w, &c->tx, &c->ty, &c->dmax, &c->dn,
                    &c->ds, &c->tn, &c->ts, &c->stored};
    for (size_t k = 0; k < sizeof d / sizeof d[0]; k++)
        if (xefg_grow((void **)d[k], sizeof(double), cap))
            return -1;
    return xefg_grow((void **)&c->crack, sizeof(int), cap);
}

/** The longest row of @p R. */
static int longest_row(const ShapeRows *R)
{
    int m = 0;
    for (int r = 0; r < R->n; r++)
        m = R->start[r + 1] - R->start[r] > m ? R->start[r + 1] - R->start[r] : m;
    return m;
}

/** The material at end @p e of crack @p k: its nearest node's. */
static const Material *tip_material(const Xefg *x, const Sim *sim, int k,
                                    int e)
{
    double tip[2], dir[2], best = INFINITY;
    crack_line_tip(&x->crack[k], e, tip, dir);
    int near = 0;
    for (int I = 0; I < x->nnode; I++) {
        double d = hypot(x->X[I] - tip[0], x->Y[I] - tip[1]);
        if (d < best)
            best = d, near = I;
    }
    return &sim->scene.mat[sim->pts.mat[near]];
}

/** The averaging radius, the elastic tangent and the bulk's softening
 *  modulus at each end of crack @p k (XefgGrowthSettings); -1 with a
 *  message where, under criterion = "average", the band of width h
 *  softens faster than the elastic modulus (a snap-back: the Rankine
 *  tangent's stability test no longer holds, acoustic_tensor.h). */
static int tip_laws(Growth *g, const Xefg *x, const Sim *sim, int k,
                    double h, char *err, size_t errlen)
{
    XefgGrowthSettings *set = &g->set[k];
    const CohesiveLaw *L = &x->coh->set[k].law;
    PlaneKind plane = sim->scene.run.plane;
    /* the crack band (Bazant and Oh): a strain over h opens the crack h eps */
    set->softening = h * cohesive_softening_slope(L);
    for (int e = 0; e < 2; e++) {
        const Material *m = tip_material(x, sim, k, e);
        double Ep = plane == PLANE_STRAIN ? m->E / (1.0 - m->nu * m->nu) : m->E;
        set->tip_radius[e] = set->radius > 0.0
                                 ? set->radius
                                 : growth_default_radius(h, Ep, L);
        acoustic_elastic_tangent(m->E, m->nu, plane, set->tangent[e]);
        double h0 = set->tangent[e][0][0];         /* m : C : m, isotropic */
        if (!set->tip && !(set->softening > -h0)) {  /* "tip" asks no tangent */
            char at[SCENE_AT_LEN];
            snprintf(err, errlen, "%s: growth: the bulk's softening over a "
                     "node spacing, h |dt / d delta| of the law = %g, is "
                     "not below the elastic modulus %g (a snap-back, which "
                     "the stability check of the Rankine tangent does not "
                     "cover): refine the spacing h = %g or raise G_f",
                     scene_lines_at(sim->scene.lines, sim->scene.file,
                                    set->line, at, SCENE_AT_LEN),
                     -set->softening, h0, h);
            return -1;
        }
    }
    return 0;
}

/// [growth_reserve]
int growth_build(Growth *g, Xefg *x, const Sim *sim, char *err, size_t errlen)
{
    if (check_cohesive(g, x, sim, err, errlen))
        return -1;
    Cracks *C = cracks_of(sim);
    Cohesive *coh = x->coh;
    double h = INFINITY, dmax = 0.0;
    for (int I = 0; I < x->nnode; I++) {
        h = fmin(h, 2.0 * fmin(x->hx[I], x->hy[I]));
        dmax = fmax(dmax, x->d[I]);
    }
    g->h = h;
    /* our choice: sigma_1 averaged over the half disk ahead of the tip,
     * at most 1.5 h, about 3.5 cells (some 56 Gauss points of 4 x 4),
     * wide enough to smooth the stress of single points; by default no
     * wider than L / 2 of the material at the tip (chapter 6c) */
    g->radius = 1.5 * h;
    for (int k = 0; k < g->ncrack && k < x->ncrack; k++)
        if (g->set[k].on && tip_laws(g, x, sim, k, h, err, errlen))
            return -1;
    /* our choice: the interaction integral's ring from 2 h to 4 h, as
     * scene_centre_crack.c's r_d = 2 h gave K within 1.6 % of Griffith's */
    g->k_radius = 2.0 * h;
    const Grid *gr = &sim->grid;
    double diag = hypot(gr->ncx * gr->dx, gr->ncy * gr->dy);
    int n = x->set.gauss, nb = x->set.tip == BRANCH_LEFM ? 4 : 1, events = 0;
    double L = 0.0;
    for (int k = 0; k < g->ncrack; k++) {
        XefgGrowthSettings *s = &g->set[k];
        if (!s->on)
            continue;
        if (s->length == 0.0)
            s->length = h;                     /* default: one node spacing */
        if (s->max_segments == 0)              /* default: across the grid */
            s->max_segments = (int)fmin(ceil(diag / s->length), 100000.0);
        events += s->max_segments;
        L = fmax(L, s->length);
    }
    g->point_cap = calloc(room(g->ncrack), sizeof(int));
    g->event = malloc(sizeof(GrowthEvent) * room(events));
    if (!g->point_cap || !g->event)
        goto oom;
    g->event_cap = events;
    for (int k = 0; k < g->ncrack && k < x->ncrack; k++) {
        if (!g->set[k].on)
            continue;
        Crack *ck = &C->crack[k];                 /* room in stage 2's line */
        int cap = ck->n + g->set[k].max_segments;
        if (xefg_grow((void **)&ck->x, sizeof(double), cap) ||
            xefg_grow((void **)&ck->y, sizeof(double), cap))
            goto oom;
        x->crack[k].x = ck->x;
        x->crack[k].y = ck->y;
        g->point_cap[k] = cap;
    }
    /* what one event may touch: the nodes whose supports meet the new
     * segment (within d of it), the places within 2 d of it (their rows
     * hold those nodes), and the cells it cuts (their points split) */
    double zone = 4.0 * dmax * L + PI_UP * 4.0 * dmax * dmax;
    int zone_cells = (int)ceil(zone / (h * h) + 2.0 * PI_UP * 2.0 * dmax / h +
                               2.0 * L / h) + 8;
    int near_nodes = (int)ceil((2.0 * dmax * L + PI_UP * dmax * dmax) / (h * h) +
                               2.0 * PI_UP * dmax / h + 2.0 * L / h) + 8;
    int cut_cells = 2 * ((int)ceil(L / h) + 2);
    int support = (int)ceil(PI_UP * dmax * dmax / (h * h)) + 8;
    double biggest = (double)events * (zone_cells * (double)n * n +
                                       cut_cells * 24.0 * n * n) *
                     (longest_row(&x->gauss) + support * (1.0 + nb));
    if (biggest > 5e8) {                        /* entries of the rows */
        snprintf(err, errlen, "%s: growth: room for %d segments of %g would "
                 "take some %.3g row entries: lower max_segments or raise "
                 "length", sim->scene.file, events, L, biggest);
        return -1;
    }
    int zone_pts = zone_cells * n * n + cut_cells * 24 * n * n;
    int per_row = longest_row(&x->gauss) + support * (1 + nb);
    g->dof_cap = x->ndof + events * near_nodes * (1 + nb);
    g->gauss_cap = x->ngauss + events * cut_cells * 24 * n * n + zone_pts;
    int gauss_ent = x->gauss.len + (events + 1) * zone_pts * per_row +
                    ROW_ROOM;
    int node_ent = x->at_node.len + events * zone_cells * support * (1 + nb) +
                   ROW_ROOM;
    if (reserve_parameters(x, g->dof_cap) || reserve_gauss(x, g->gauss_cap) ||
        reserve_rows(&x->gauss, g->gauss_cap, gauss_ent, 1) ||
        reserve_rows(&x->at_node, x->nnode, node_ent, 0))
        goto oom;
    for (int k = 0; k < 2; k++) {               /* the held places' rows */
        ShapeRows *G = &x->fix[k].rows;
        if (x->fix[k].n > 0 &&
            reserve_rows(G, x->fix[k].n, G->len + (x->fix[k].n < near_nodes ?
                         x->fix[k].n : near_nodes) * support * (1 + nb) *
                         (events < 4 ? events : 4) + ROW_ROOM, 0))
            goto oom;
    }
    int coh_new = ((int)ceil(L / h) + 2) * n;     /* a segment's points */
    int coh_zone = ((int)ceil((L + 4.0 * dmax) / h) + 4) * n;
    g->coh_cap = coh->npt + events * coh_new;
    int coh_row = longest_row(&coh->jump) + support * (1 + nb);
    if (reserve_cohesive(coh, g->coh_cap) ||
        reserve_rows(&coh->jump, g->coh_cap,
                     coh->jump.len + events * (coh_new + coh_zone) * coh_row +
                         ROW_ROOM, 0))
        goto oom;
    /* scratch of one event */
    int marks = g->gauss_cap > x->nnode ? g->gauss_cap : x->nnode;
    marks = marks > g->coh_cap ? marks : g->coh_cap;
    g->add = calloc(room(x->nnode), sizeof(int));
    g->shift = calloc(room(x->nnode), sizeof(int));
    g->mark = calloc(room(marks), sizeof(int));
    g->len = calloc(room(marks), sizeof(int));
    g->diag = calloc(room(g->dof_cap), sizeof(double));
    g->zs = malloc(2 * sizeof(double) * room(g->dof_cap));
    g->kzs = malloc(2 * sizeof(double) * room(g->dof_cap));
    g->gss = malloc(3 * sizeof(double) * room(g->gauss_cap));
    g->quad_cap = 256 * n * n;
    g->quad = malloc(sizeof(QuadPoint) * room(g->quad_cap));
    g->qw = quad_work_new(QUAD_CUTS);
    int rows = zone_cells > coh_zone ? zone_cells : coh_zone;
    if (!g->add || !g->shift || !g->mark || !g->len || !g->diag || !g->zs ||
        !g->kzs || !g->gss || !g->quad || !g->qw ||
        reserve_rows(&g->row, 2, 2 * ROW_ROOM, 1) ||
        reserve_rows(&g->rows, rows + 2, (rows + 2) * per_row + ROW_ROOM, 0))
        goto oom;
    if (cell_list_build(&g->cl, x->nnode, x->X, x->Y, dmax))
        goto oom;
    return 0;
oom:
    snprintf(err, errlen, "%s: out of memory for the room of the growing "
             "cracks", sim->scene.file);
    return -1;
}
/// [growth_reserve]

void growth_free(Growth *g)
{
    void *a[] = {g->set, g->point_cap, g->event, g->add, g->shift, g->mark,
                 g->len, g->diag, g->zs, g->kzs, g->gss, g->quad};
    for (size_t k = 0; k < sizeof a / sizeof a[0]; k++)
        free(a[k]);
    cell_list_free(&g->cl);
    quad_work_free(g->qw);
    shape_rows_free(&g->row);
    shape_rows_free(&g->rows);
    *g = (Growth){0};
}
