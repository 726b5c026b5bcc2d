/**
 * @file mirror.c
 * @brief The mirror: a symmetry plane on a grid line for wide stencils.
 *        A point of the kept half whose domain crosses the plane weights
 *        the node row beyond it; in the whole body that row holds the
 *        mirror image of the row inside. Each of the point sums of the
 *        step (mass, momentum, force) is folded: the ghost row's sums are
 *        added to the row inside with the normal component reversed, and
 *        the ghost takes the mirror image of the total (chapter 8, "The
 *        mirror").
 */
#include "mirror.h"

#include <math.h>
#include <stdlib.h>

#include "cpdi.h"
#include "field_table.h"
#include "gimp.h"
#include "scene_read.h"
#include "step.h"

static void mirror_release(void *state)
{
    Mirror *M = state;
    free(M->ghost);
    free(M->node);
    free(M->pair_of);
    free(M->use);
    free(M);
}

/** Fold the sums @p t (along the plane) and @p n (normal) of the pairs
 *  reached through the segment: the node inside gets its mirror image's
 *  share, the ghost the image of the total; a node on the plane is its
 *  own image (t doubles, n is 0). */
static void fold(const Mirror *M, double *t, double *n)
{
    for (int k = 0; k < M->n; k++) {
        int g = M->ghost[k], i = M->node[k];
        if (g == i) {                       /* on the plane */
            t[i] += t[i];
            n[i] = 0.0;
            continue;
        }
        if (M->use[k] != 1)
            continue;
        t[i] += t[g];
        n[i] -= n[g];
        t[g] = t[i];
        n[g] = -n[i];
    }
}

/** v = p / m at the nodes of the folded pairs, the held directions held. */
static void velocities(const Mirror *M, Grid *g)
{
    for (int k = 0; k < M->n; k++)
        for (int j = 0; j < 2 && (M->use[k] == 1 || M->ghost[k] == M->node[k]); j++) {
            int s = j ? M->node[k] : M->ghost[k];
            unsigned fix = g->fixed[s];
            if (fix & GRID_FIX_X)
                g->px[s] = 0.0;
            if (fix & GRID_FIX_Y)
                g->py[s] = 0.0;
            g->vx[s] = g->m[s] > 0.0 ? g->px[s] / g->m[s] : 0.0;
            g->vy[s] = g->m[s] > 0.0 ? g->py[s] / g->m[s] : 0.0;
        }
}

/// [mirror_key_fields]
/** Task 1: a point's pair to a node beyond the plane that crosses the
 *  plane on the segment is the image of a pair of the other half: it stays
 *  in the node's field 0, which the mirror folds (Mirror::use). One that
 *  crosses the plane elsewhere (over a crack) is not: it gets a field of
 *  its own, as the crack would give it (eq. 2). Stop the run when a point
 *  reached the plane or a pair reaches past the ghost row. */
static int mirror_key_fields(Sim *sim, void *state, Seam seam)
{
    Mirror *M = state;
    const Grid *g = &sim->grid;
    double d = M->axis ? g->dy : g->dx, tol = 1e-9 * d;
    const double *c = M->axis ? sim->pts.y : sim->pts.x;
    const double *t = M->axis ? sim->pts.x : sim->pts.y;
    (void)seam;
    for (int k = 0; k < M->n; k++)
        M->use[k] = 0;
    for (int p = 0; p < sim->pts.n; p++) {
        double dist = (c[p] - M->at) * M->side;
        if (dist >= d)
            continue;                       /* reaches no node beyond */
        if (!(dist > 0.0))
            return step_stop(sim, p, "mirror (a point reached the plane)", c[p]);
        Stencil st;
        sim->scene.run.stencil(sim, p, &st);        /* nodes, field 0 */
        for (int a = 0; a < st.n; a++) {
            int node = st.slot[a], k = M->pair_of[node];
            double cn = M->axis ? grid_node_y(g, node) : grid_node_x(g, node);
            double tn = M->axis ? grid_node_x(g, node) : grid_node_y(g, node);
            double beyond = (M->at - cn) * M->side;
            if (beyond < tol)
                continue;
            double tc = t[p] + (tn - t[p]) * dist / (dist + beyond);
            int inside = tc >= M->lo - tol && tc <= M->hi + tol;
            if (beyond > d + tol || (inside && k < 0))
                return step_stop(sim, p, "mirror (a pair reaches past the "
                                 "ghost nodes)", tc);
            if (inside)
                M->use[k] = 1;
            else if (fields_key_wide(sim, p, a, M->key))
                return -1;
        }
    }
    return 0;
}
/// [mirror_key_fields]

/// [mirror_step]
/** Task 2 (the first of its seams that runs): masses and momenta; at
 *  Task 2's contact seam the forces of Task 1 (or USF's Task 3); Task 6c:
 *  the re-extrapolated momenta. Task 4 needs nothing: a ghost with the
 *  image of its node's m, p and f, and its held directions, gets the
 *  image of p + dt f bit for bit (no gravity along the normal). */
static int mirror_step(Sim *sim, void *state, Seam seam)
{
    Mirror *M = state;
    Grid *g = &sim->grid;
    double *pt = M->axis ? g->px : g->py, *pn = M->axis ? g->py : g->px;
    if (seam == SEAM_TASK6_CONTACT) {
        fold(M, pt, pn);
        velocities(M, g);
        return 0;
    }
    if (!M->folded) {
        for (int k = 0; k < M->n; k++) {    /* mass: no normal part */
            int gh = M->ghost[k], i = M->node[k];
            if (gh != i && M->use[k] != 1)
                continue;
            g->m[i] += gh == i ? g->m[i] : g->m[gh];
            g->m[gh] = g->m[i];
        }
        fold(M, pt, pn);
        velocities(M, g);
        M->folded = 1;
    }
    if (seam == SEAM_TASK2_CONTACT) {
        fold(M, M->axis ? g->fx : g->fy, M->axis ? g->fy : g->fx);
        M->folded = 0;                      /* the next step folds again */
    }
    return 0;
}
/// [mirror_step]

/** The node on grid line @p j along the normal @p axis, position @p i
 *  along the plane. */
static int node_at(const Grid *g, int axis, int j, int i)
{
    return axis ? j * g->nnx + i : i * g->nnx + j;
}

/** Refuse the mirror where it cannot apply (a message naming the key's
 *  line in @p err): -1, else 0. */
static int refuse(const Sim *sim, const Mirror *M, char *err, size_t errlen)
{
    const Scene *sc = &sim->scene;
    const Boundary *B = &sc->bc[M->bc];
    const Grid *g = &sim->grid;
    char where[SCENE_AT_LEN];
    const char *at = scene_lines_at(sc->lines, sc->file, M->line, where,
                                    SCENE_AT_LEN);
    int k = M->bc;
    if (sc->run.shape != &shape_gimp && sc->run.shape != &shape_cpdi) {
        snprintf(err, errlen, "%s: boundaries.[%d].mirror with run.shape = "
                 "\"%s\": linear shape functions reach no node beyond the "
                 "plane, where the boundary's hold is the mirror already; "
                 "drop mirror (or use run.shape = \"gimp\" or \"cpdi\")", at,
                 k, sc->run.shape ? sc->run.shape->name : "linear");
        return -1;
    }
    const Shape *r = &B->region;
    if (r->kind != SHAPE_RECTANGLE || (r->xmin != r->xmax) == (r->ymin != r->ymax)) {
        snprintf(err, errlen, "%s: boundaries.[%d].mirror: the region "
                 "[%g, %g] - [%g, %g] is not a line: a mirror is a segment "
                 "of a plane x = c or y = c (min and max equal in x or y)",
                 at, k, r->xmin, r->ymin, r->xmax, r->ymax);
        return -1;
    }
    double o = M->axis ? g->oy : g->ox, d = M->axis ? g->dy : g->dx;
    int cells = M->axis ? g->ncy : g->ncx;
    double kf = (M->at - o) / d;
    if (fabs(kf - round(kf)) > 1e-9) {
        snprintf(err, errlen, "%s: boundaries.[%d].mirror: %s = %g is not "
                 "on a grid line (the grid's lines are %g + k %g)", at, k,
                 M->axis ? "y" : "x", M->at, o, d);
        return -1;
    }
    if (!(B->hold.fix & (M->axis ? GRID_FIX_Y : GRID_FIX_X)) || B->moving) {
        snprintf(err, errlen, "%s: boundaries.[%d].mirror: a mirror holds "
                 "the plane's nodes at rest along its normal: fix = \"%s\" "
                 "with no velocity", at, k, M->axis ? "y" : "x");
        return -1;
    }
    if (sim->hooks.seam[SEAM_TASK1_FIELDS].n > 0) {
        snprintf(err, errlen, "%s: boundaries.[%d].mirror with cracks or "
                 "contact: not done (the mirror folds a node's one field)",
                 at, k);
        return -1;
    }
    if ((M->axis ? sc->run.gy : sc->run.gx) != 0.0) {
        snprintf(err, errlen, "%s: boundaries.[%d].mirror: gravity along the "
                 "plane's normal is not symmetric about it", at, k);
        return -1;
    }
    long kk = lround(kf);
    if (M->side == 0 || kk - M->side < 0 || kk - M->side > cells) {
        snprintf(err, errlen, "%s: boundaries.[%d].mirror: %s", at, k,
                 M->side == 0 ? "points lie on both sides of the plane (or on "
                 "it): the mirror keeps one half" : "no node row beyond the "
                 "plane (the grid's edge): add a cell");
        return -1;
    }
    return 0;
}

/** The side of the plane the points lie on (+1, -1), or 0 when both or on. */
static int body_side(const Sim *sim, const Mirror *M)
{
    const double *c = M->axis ? sim->pts.y : sim->pts.x;
    int above = 0, below = 0;
    for (int p = 0; p < sim->pts.n; p++) {
        above += c[p] > M->at;
        below += !(c[p] > M->at);
    }
    return below == 0 ? 1 : above == 0 ? -1 : 0;
}

/** Set-up: refuse what cannot apply, pair the nodes, subscribe the folds. */
static int mirror_prepare(Sim *sim, void *state, char *err, size_t errlen)
{
    Mirror *M = state;
    const Boundary *B = &sim->scene.bc[M->bc];
    Grid *g = &sim->grid;
    M->axis = B->region.ymin == B->region.ymax;
    M->at = M->axis ? B->region.ymin : B->region.xmin;
    M->lo = M->axis ? B->region.xmin : B->region.ymin;
    M->hi = M->axis ? B->region.xmax : B->region.ymax;
    M->side = body_side(sim, M);
    if (refuse(sim, M, err, errlen))
        return -1;
    double o = M->axis ? g->oy : g->ox, d = M->axis ? g->dy : g->dx;
    double ot = M->axis ? g->ox : g->oy, dt = M->axis ? g->dx : g->dy;
    int k0 = (int)lround((M->at - o) / d), along = M->axis ? g->nnx : g->nny;
    M->ghost = malloc(sizeof(int) * 2 * (size_t)along);
    M->node = malloc(sizeof(int) * 2 * (size_t)along);
    M->use = calloc(2 * (size_t)along, 1);
    M->pair_of = malloc(sizeof(int) * (size_t)g->nnodes);
    if (!M->ghost || !M->node || !M->use || !M->pair_of) {
        snprintf(err, errlen, "%s: out of memory (mirror)", sim->scene.file);
        return -1;
    }
    double tol = 1e-9 * dt;
    for (int nd = 0; nd < g->nnodes; nd++)
        M->pair_of[nd] = -1;
    for (int i = 0; i < along; i++) {
        double t = ot + i * dt;
        if (t >= M->lo - tol && t <= M->hi + tol) {      /* on the plane */
            M->ghost[M->n] = M->node[M->n] = node_at(g, M->axis, k0, i);
            M->n++;
        }
        /* beyond: every node a pair through the segment reaches (a point
           reaches 1 + l <= 1.5 cells along the plane: two cells) */
        if (t >= M->lo - 2.0 * dt - tol && t <= M->hi + 2.0 * dt + tol) {
            M->ghost[M->n] = node_at(g, M->axis, k0 - M->side, i);
            M->node[M->n] = node_at(g, M->axis, k0 + M->side, i);
            g->fixed[M->ghost[M->n]] = g->fixed[M->node[M->n]];
            M->pair_of[M->ghost[M->n]] = M->n;
            M->n++;
        }
    }
    const FieldKey *side = hooks_find_field_key(&sim->hooks, "mirror side");
    M->key = side ? 1u << side->shift : 0u;
    if (!side || fields_enable(sim)) {
        snprintf(err, errlen, "%s: out of memory (or field-key bits) for the "
                 "mirror", sim->scene.file);
        return -1;
    }
    if (hooks_on_step(&sim->hooks, SEAM_TASK1_FIELDS, mirror_key_fields, M) ||
        hooks_on_step(&sim->hooks, SEAM_TASK2_HELD, mirror_step, M) ||
        hooks_on_step(&sim->hooks, SEAM_TASK2_CONTACT, mirror_step, M) ||
        hooks_on_step(&sim->hooks, SEAM_TASK6_CONTACT, mirror_step, M)) {
        snprintf(err, errlen, "%s: too many step hooks", sim->scene.file);
        return -1;
    }
    return 0;
}

int mirror_read(Sim *sim, const config_setting_t *s, int index, SceneReader *r)
{
    if (config_setting_type(s) != CONFIG_TYPE_BOOL)
        return scene_error(r, s, "mirror", "expected true or false");
    if (!config_setting_get_bool(s))
        return 0;
    if (sim_state(sim, MIRROR_STATE))
        return scene_error(r, s, "mirror", "a second mirror: one per scene "
                           "(the corner of two is not done)");
    Mirror *M = calloc(1, sizeof *M);
    if (!M)
        return scene_error(r, s, "mirror", "out of memory");
    if (sim_attach(sim, MIRROR_STATE, M, mirror_release)) {
        free(M);
        return scene_error(r, s, "mirror", "out of memory");
    }
    M->bc = index;
    M->line = (int)config_setting_source_line(s);
    if (hooks_on_prepare(&sim->hooks, mirror_prepare, M))
        return scene_error(r, s, "mirror", "too many set-up hooks");
    return 0;
}
