/**
 * @file crack_growth.c
 * @brief When and where a CRAMP tip grows (chapter 7, "Growth"): J
 *        against G_c, the kink of maximum hoop stress, and the new point
 *        handed to stages 2-4 as a moved point is.
 */
#include <math.h>
#include <string.h>

#include "checkpoint.h"
#include "crack_growth.h"
#include "cracks.h"
#include "step.h"

/** Degrees to radians. */
static const double DEGREE = 3.14159265358979323846 / 180.0;

/// [growth_parameters]
void growth_parameters(const JState *S, const JTip *T, double *J, double *KI,
                       double *KII)
{
    int n = S->set[T->crack].ncontours;
    *J = *KI = *KII = 0.0;
    for (int m = 0; m < n; m++) {
        *J += T->J[m] / n;
        *KI += T->KI[m] / n;
        *KII += T->KII[m] / n;
    }
}
/// [growth_parameters]

/** Does (x, y) lie in a body of the scene? */
static int in_a_body(const Scene *sc, double x, double y)
{
    for (int b = 0; b < sc->nbodies; b++)
        if (shape_contains(&sc->bodies[b].shape, x, y))
            return 1;
    return 0;
}

/** Does the square of @p cells cells about (x, y) lie in the grid? */
static int domain_in_grid(const Grid *g, double x, double y, int cells)
{
    double hx = cells * g->dx, hy = cells * g->dy;
    return x - hx >= g->ox && x + hx <= g->ox + g->ncx * g->dx &&
           y - hy >= g->oy && y + hy <= g->oy + g->ncy * g->dy;
}

/** Does any segment of a crack meet the segment from (x0, y0) to
 *  (x1, y1), which starts at point @p i of crack @p k (whose segments
 *  through that point are left out)? @return the crack, or -1. */
static int meets_a_crack(const Cracks *C, int k, int i, double x0, double y0,
                         double x1, double y1)
{
    double a[2] = {x0, y0}, b[2] = {x1, y1};
    for (int j = 0; j < C->ncracks; j++) {
        const Crack *o = &C->crack[j];
        for (int s = 0; s + 1 < o->n; s++) {
            if (j == k && (s == i || s + 1 == i))
                continue;
            double c[2] = {o->x[s], o->y[s]}, d[2] = {o->x[s + 1], o->y[s + 1]};
            if (crack_segments_meet(a, b, c, d))
                return j;
        }
    }
    return -1;
}

/** Does the square of half-side @p cells cells about (x, y) reach out
 *  of every body? Its sides are tested every half cell. */
static int domain_leaves_body(const Sim *sim, double x, double y, int cells)
{
    const Grid *g = &sim->grid;
    double hx = cells * g->dx, hy = cells * g->dy;
    int n = 4 * cells;                  /* half cells along a side */
    for (int k = 0; k <= n; k++) {
        double f = -1.0 + 2.0 * k / n;
        if (!in_a_body(&sim->scene, x + f * hx, y - hy) ||
            !in_a_body(&sim->scene, x + f * hx, y + hy) ||
            !in_a_body(&sim->scene, x - hx, y + f * hy) ||
            !in_a_body(&sim->scene, x + hx, y + f * hy))
            return 1;
    }
    return 0;
}

/** Does a segment of a crack other than @p k reach into the square of
 *  half-side @p cells cells about (x, y)? @return the crack, or -1. */
static int domain_holds_crack(const Sim *sim, const Cracks *C, int k, double x,
                              double y, int cells)
{
    const Grid *g = &sim->grid;
    double hx = cells * g->dx, hy = cells * g->dy;
    double q[5][2] = {{x - hx, y - hy}, {x + hx, y - hy}, {x + hx, y + hy},
                      {x - hx, y + hy}, {x - hx, y - hy}};
    for (int j = 0; j < C->ncracks; j++) {
        const Crack *o = &C->crack[j];
        for (int s = 0; j != k && s + 1 < o->n; s++) {
            double c[2] = {o->x[s], o->y[s]}, d[2] = {o->x[s + 1], o->y[s + 1]};
            if (fabs(c[0] - x) < hx && fabs(c[1] - y) < hy)
                return j;               /* a point inside */
            for (int e = 0; e < 4; e++)
                if (crack_segments_meet(q[e], q[e + 1], c, d))
                    return j;           /* across a side */
        }
    }
    return -1;
}

/// [grow_tip]
/** The new point of tip @p T: @p len along the tip's direction turned by
 *  @p theta towards its left normal. */
static void new_point(const JTip *T, double theta, double len, double *x,
                      double *y)
{
    double ct = cos(theta), st = sin(theta);
    *x = T->x + len * (ct * T->ex - st * T->ey);
    *y = T->y + len * (st * T->ex + ct * T->ey);
}

/** Add point (x, y) at tip @p T of crack @p c. The first point grows by
 *  shifting the points up one place (the room is reserved, and the crack
 *  keeps its direction, so its sides keep their names). */
static void grow_tip(Crack *c, const JTip *T, double x, double y)
{
    if (T->end) {
        c->x[c->n] = x;
        c->y[c->n] = y;
    } else {
        memmove(c->x + 1, c->x, sizeof(double) * (size_t)c->n);
        memmove(c->y + 1, c->y, sizeof(double) * (size_t)c->n);
        c->x[0] = x;
        c->y[0] = y;
    }
    c->n++;
    crack_extent(c);
}
/// [grow_tip]

/// [crack_growth_step]
int crack_growth_step(Sim *sim, CrackGrowth *G, JState *S)
{
    Cracks *C = cracks_of(sim);
    const Grid *g = &sim->grid;
    int grown = 0;
    for (int t = 0; t < S->ntips; t++) {
        const JTip *T = &S->tip[t];
        if (T->crack >= G->ncracks || !G->set[T->crack].on)
            continue;
        const GrowthSettings *s = &G->set[T->crack];
        GrowthEnd *e = &G->end[2 * T->crack + T->end];
        Crack *c = &C->crack[T->crack];
        double J, KI, KII;
        growth_parameters(S, T, &J, &KI, &KII);
        if (e->through || e->stop)
            continue;
        if (s->average > 0.0) {             /* the block's means decide */
            e->Jsum += J;
            e->Ksum[0] += KI;
            e->Ksum[1] += KII;
            e->nsum++;
            if (e->nsum * S->every * sim->dt < s->average)
                continue;
            J = e->Jsum / e->nsum;
            KI = e->Ksum[0] / e->nsum;
            KII = e->Ksum[1] / e->nsum;
            e->Jsum = e->Ksum[0] = e->Ksum[1] = 0.0;
            e->nsum = 0;
        }
        /* an elastic tip has J >= 0: below -G_c / 10 is no round-off */
        e->negative += J < -0.1 * s->G_c;
        if (!(J >= s->G_c))
            continue;                       /* when: J reaches G_c */
        if (c->n - 1 >= s->max_segments)
            return step_stop(sim, -1, s->full, s->max_segments);
        /* faces cannot pass through each other: K_I < 0 is shut faces
           (with contact, the pressure that the interaction integral, made
           for traction-free faces, reads as K_I) or faces that overlap
           (without); the angle is K_I = 0's, |theta| <= 70.53 degrees */
        if (KI < 0.0)
            KI = 0.0;
        double theta = hoop_angle(KI, KII); /* where: the largest hoop stress */
        double x, y;
        new_point(T, theta, s->length, &x, &y);
        int i = T->end ? c->n - 1 : 0;
        int hit = meets_a_crack(C, T->crack, i, c->x[i], c->y[i], x, y);
        if (hit >= 0) {                     /* it would cross: it stops */
            e->stop = GROWTH_AT_CRACK;
            e->by = hit;
            continue;
        }
        grow_tip(c, T, x, y);
        i = T->end ? c->n - 1 : 0;
        if (!(c->x[i] >= g->ox && c->x[i] < g->ox + g->ncx * g->dx &&
              c->y[i] >= g->oy && c->y[i] < g->oy + g->ncy * g->dy))
            return step_stop(sim, -1, "crack point (grew out of the grid)",
                             c->x[i]);
        int widest = 0, out = !in_a_body(&sim->scene, c->x[i], c->y[i]);
        for (int m = 0; m < S->set[T->crack].ncontours; m++)
            widest = S->set[T->crack].contour[m] > widest
                         ? S->set[T->crack].contour[m] : widest;
        if (!out && !domain_in_grid(g, c->x[i], c->y[i], widest))
            return step_stop(sim, -1, "crack tip (its J domain grew out of "
                             "the grid)", c->x[i]);
        /* J holds only on a domain whose boundaries across x1 are the
           crack's own faces: a free edge or another crack in it stops it */
        if (!out && domain_leaves_body(sim, c->x[i], c->y[i], widest))
            e->stop = GROWTH_DOMAIN_EDGE;
        else if (!out && (hit = domain_holds_crack(sim, C, T->crack, c->x[i],
                                                   c->y[i], widest)) >= 0) {
            e->stop = GROWTH_DOMAIN_CRACK;
            e->by = hit;
        }
        e->events++;
        e->last_step = sim->step + 1;
        e->J = J;
        e->theta = theta;
        e->through = out;                   /* cut through: no more growth */
        grown = 1;
    }
    if (!grown)
        return 0;
    /* as after Task 7's motion: the search and the J tips follow */
    if (C->search->update && C->search->update(C, &sim->grid))
        return step_fail(sim, -1, "memory for the crossing search", 0);
    j_integral_tips(sim, S);
    return 0;
}
/// [crack_growth_step]

/** The J tips (found at set-up: a crack's ends inside a body). */
static const JState *j_tips(const Sim *sim)
{
    return sim_state(sim, "j-integral");
}

int crack_growth_history(const Sim *sim, void *state, FILE *f, int header)
{
    const CrackGrowth *G = state;
    const JState *S = j_tips(sim);
    for (int t = 0; S && t < S->ntips; t++) {
        const JTip *T = &S->tip[t];
        if (T->crack >= G->ncracks || !G->set[T->crack].on)
            continue;
        const GrowthEnd *e = &G->end[2 * T->crack + T->end];
        const char *name = T->end ? "last" : "first";
        int k = T->crack;
        int rc = header ? fprintf(f, ",events_crack%d_%s,tipx_crack%d_%s,"
                                  "tipy_crack%d_%s", k, name, k, name, k, name)
                        : fprintf(f, ",%ld,%.9g,%.9g", e->events, T->x, T->y);
        if (rc < 0)
            return -1;
    }
    return 0;
}

int crack_growth_report(const Sim *sim, void *state, FILE *f)
{
    const CrackGrowth *G = state;
    const JState *S = j_tips(sim);
    const Units *u = sim->scene.run.units;
    for (int t = 0; S && t < S->ntips; t++) {
        const JTip *T = &S->tip[t];
        if (T->crack >= G->ncracks || !G->set[T->crack].on)
            continue;
        const GrowthSettings *s = &G->set[T->crack];
        const GrowthEnd *e = &G->end[2 * T->crack + T->end];
        if (fprintf(f, "mpm: crack growth, crack %d, %s point: %ld segments "
                    "of %g %s added, tip now (%.6g, %.6g)%s", T->crack,
                    T->end ? "last" : "first", e->events, s->length, u->length,
                    T->x, T->y, e->through ? ", through the body" : "") < 0)
            return -1;
        if (e->events &&
            fprintf(f, "; the latest after step %ld, J %.6g %s/%s^2 (G_c %g), "
                    "kink %.3g degrees", e->last_step, e->J, u->energy,
                    u->length, s->G_c, e->theta / DEGREE) < 0)
            return -1;
        static const char *const why[] = {
            "", "; stopped: its next segment would cross crack %d",
            "; stopped: its J domain reaches out of the body",
            "; stopped: its J domain holds crack %d"};
        if (e->stop && fprintf(f, why[e->stop], e->by) < 0)
            return -1;
        if (e->negative && fprintf(f, "; J < -G_c/10 at %ld of its decisions (J does "
                                   "not hold on its domain: a kink, shut "
                                   "faces, an edge?)", e->negative) < 0)
            return -1;
        if (fputc('\n', f) == EOF)
            return -1;
    }
    return 0;
}

/// [crack_growth_checkpoint]
int crack_growth_checkpoint(Sim *sim, void *state, FILE *f, int save)
{
    CrackGrowth *G = state;
    Cracks *C = cracks_of(sim);
    int n = G->ncracks, m = n;
    if (checkpoint_io(f, &m, sizeof m, save) || m != n)
        return -1;
    for (int k = 0; k < 2 * n; k++) {
        GrowthEnd *e = &G->end[k];
        if (checkpoint_io(f, &e->events, sizeof e->events, save) ||
            checkpoint_io(f, &e->last_step, sizeof e->last_step, save) ||
            checkpoint_io(f, &e->J, sizeof e->J, save) ||
            checkpoint_io(f, &e->theta, sizeof e->theta, save) ||
            checkpoint_io(f, &e->through, sizeof e->through, save) ||
            checkpoint_io(f, &e->stop, sizeof e->stop, save) ||
            checkpoint_io(f, &e->by, sizeof e->by, save) ||
            checkpoint_io(f, &e->negative, sizeof e->negative, save) ||
            checkpoint_io(f, &e->Jsum, sizeof e->Jsum, save) ||
            checkpoint_io(f, e->Ksum, sizeof e->Ksum, save) ||
            checkpoint_io(f, &e->nsum, sizeof e->nsum, save))
            return -1;
    }
    /* stage 2 restored the points (a grown crack with exactly as many
       as it had): the room for more is reserved again */
    for (int k = 0; !save && k < n && k < C->ncracks; k++)
        if (G->set[k].on &&
            crack_reserve_points(&C->crack[k], G->set[k].max_segments + 1))
            return -1;
    return 0;
}
/// [crack_growth_checkpoint]
