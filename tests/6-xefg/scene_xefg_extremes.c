/**
 * @file scene_xefg_extremes.c
 * @brief Cohesive XEFG growth at the extremes (issue 27; chapter 6b,
 *        "Cracks that grow (tests)"): a crack that clips supports by 1e-6
 *        of their radius, or misses them by as much, and tips exactly on
 *        Gauss points. (Tips on nodes, the domain's edge and two tips
 *        meeting are in scene_xefg_growth.c.)
 *
 * Bounds, fixed before the first run:
 * - support_clipped_by_1e_6: the bar of tests/6-xefg/scenes/growth_bar.cfg
 *   (crack on x = 6, to t = 0.24 ms, through its growth) with xefg.support
 *   = 2.5 / (1 - 1e-6), so that the node columns x = 4.75 and 7.25, 1.25
 *   from the crack's line, are at d (1 - 1e-6) from it: their supports
 *   are clipped, by the set-up crack (6 nodes) and by every grown segment
 *   (more); the mirror run with 2.5 / (1 + 1e-6) leaves them at
 *   d (1 + 1e-6), unenriched (0). Both run to their end (no "unstable"),
 *   every velocity, displacement and stress finite, every lumped mass
 *   positive, and every step parameter's mass its node's standard mass
 *   to 1e-12 (the lumping m_I <H^2>, H^2 = 1, xefg_build.c); balance
 *   within 1 %. The stable step with the clips at least 1/sqrt 2 of the
 *   one without, at set-up and after the growth: a clipped step
 *   parameter equals its standard one at every Gauss point (its sliver
 *   holds none), so the two, each of mass m_I, move the node's function
 *   at most as one parameter of mass m_I / 2, which at most doubles
 *   omega^2 (a lumping by the sliver's mass would collapse the step).
 *   The clip changes nothing else: the same number of events, each within
 *   the run's first (longest) step of its mirror's (a run's events are
 *   quantised by its steps: the first may fall a step later, and the
 *   others, a few steps after it, follow), the cracks' ends within 1e-9
 *   mm. (The first run took the step at the run's end, 9.8e-5 ms, shorter
 *   after the growth, and failed: the first event came 1.13e-4 ms, one
 *   early step, later with the clips, and the next three as much.)
 * - tip_on_a_gauss_point: tests/6-xefg/scenes/growth_diagonal.cfg, a
 *   plate with its crack on the diagonal y = x, which holds the Gauss
 *   points (xi, xi) of the 4 x 4 rule of the cells it crosses; the tip
 *   set up on the point (3.335, 3.335) of the node (3.25, 3.25)'s uncut
 *   cell (quad_cell() of the cell without cracks), segments of length
 *   sqrt 2 h, one cell along the diagonal, so that every new tip lands on
 *   the same point of the next cell. To t = 0.2 ms: at least 2 events;
 *   every new tip within 1e-12 h of a point of the 4 x 4 rule of its
 *   cell, which before the event held its 16 points, one of them there
 *   (the cell was uncut); after set-up and every event no Gauss point
 *   within 1e-9 h of the tip (the cut cell is split anew and fanned from
 *   the tip, quad_cell(): no point at r = 0, where branch_functions()
 *   gives 0 and the old point's stress would join the average ahead);
 *   every crack point within 1e-9 h of the diagonal; the run to its end
 *   with everything finite; balance within 1 %.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "balance.h"
#include "cohesive.h"
#include "growth.h"
#include "quadrature.h"
#include "testkit.h"

#define BAR "tests/6-xefg/scenes/growth_bar.cfg"
#define DIAGONAL "tests/6-xefg/scenes/growth_diagonal.cfg"


/** Are the parameters' u, v and the Gauss points' stresses finite? */
static int all_finite(const Xefg *x)
{
    for (int k = 0; k < 2 * x->ndof; k++)
        if (!isfinite(x->u[k]) || !isfinite(x->v[k]))
            return 0;
    for (int k = 0; k < 3 * x->ngauss; k++)
        if (!isfinite(x->gs[k]))
            return 0;
    return 1;
}

/** Every mass positive and finite, and the largest |m_step / m_I - 1|
 *  (-1: a mass not positive). */
static double step_mass_error(const Xefg *x)
{
    double worst = 0.0;
    for (int q = 0; q < x->ndof; q++) {
        if (!(x->mass[q] > 0.0 && isfinite(x->mass[q])))
            return -1.0;
        if (x->dof_kind[q] == DOF_STEP) {
            double m = x->mass[x->node_dof[x->dof_node[q]]];
            worst = fmax(worst, fabs(x->mass[q] / m - 1.0));
        }
    }
    return worst;
}

/** Step parameters of the nodes 1.25 mm from x = 6 (the columns the
 *  support radius 1.25 (1 -+ 1e-6) clips or misses), and the range of
 *  their nodes' distance to the crack over d in @p r (every node of the
 *  columns that the crack passes, when @p all). */
static int clipped(const Xefg *x, int all, double r[2])
{
    int n = 0;
    r[0] = INFINITY, r[1] = -INFINITY;
    for (int I = 0; I < x->nnode; I++) {
        if (fabs(fabs(x->X[I] - 6.0) - 1.25) > 1e-9)
            continue;
        const CrackLine *l = &x->crack[0];
        double d;
        crack_line_side(l, x->X[I], x->Y[I], &d);
        int steps = 0;
        for (int q = x->node_dof[I]; q < x->node_dof[I + 1]; q++)
            steps += x->dof_kind[q] == DOF_STEP;
        n += steps;
        if (steps || (all && fabs(d - 1.25) < 1e-9)) {
            r[0] = fmin(r[0], d / x->d[I]);
            r[1] = fmax(r[1], d / x->d[I]);
        }
    }
    return n;
}

/** What a clip run saw. */
typedef struct Clip {
    int at_start, at_end;    /**< clipped step parameters */
    double ratio[2];         /**< distance / d of the columns' nodes */
    double dt0, dt1;         /**< stable step at set-up, at the end */
    double dt;               /**< the step the run used at its end */
    double mass;             /**< worst |m_step / m_I - 1| (-1: bad) */
    double worst;            /**< worst balance error */
    int finite;              /**< everything finite at the end */
    int events;              /**< growth events */
    double t_event[16];      /**< their times */
    double dt_start;         /**< the step the run used first, its longest */
    double end[2];           /**< the crack's last point */
} Clip;

/** The bar to t = 0.24 ms with the support d = 1.25 / (1 + @p rel). */
static void clip_run(double rel, Clip *c)
{
    char support[64];
    snprintf(support, sizeof support, "xefg={support=%.17g;}", 2.5 / (1 + rel));
    const char *const over[] = {"run.time=0.24", support, NULL};
    Sim *s = tk_load_file(BAR, over);
    Xefg *x = xefg_of(s);
    memset(c, 0, sizeof *c);
    double r[2];
    c->at_start = clipped(x, 1, c->ratio);
    c->dt0 = x->stable_step;
    c->dt_start = s->dt;
    while (s->step < s->nsteps) {
        int n0 = x->grow->nevent;
        tk_steps(s, 1);
        if (x->grow->nevent > n0 || s->step % 100 == 0)
            c->worst = fmax(c->worst, xefg_balance(s));
    }
    c->worst = fmax(c->worst, xefg_balance(s));
    c->at_end = clipped(x, 0, r);
    if (c->at_end) {
        c->ratio[0] = fmin(c->ratio[0], r[0]);
        c->ratio[1] = fmax(c->ratio[1], r[1]);
    }
    c->dt1 = x->stable_step;
    c->dt = s->dt;
    c->mass = step_mass_error(x);
    c->finite = all_finite(x);
    c->events = x->grow->nevent;
    for (int e = 0; e < c->events && e < 16; e++)
        c->t_event[e] = x->grow->event[e].t;
    const CrackLine *l = &x->crack[0];
    c->end[0] = l->x[l->n - 1];
    c->end[1] = l->y[l->n - 1];
    printf("    d (1 %+g): %d clipped step parameters at set-up, %d at the "
           "end; their nodes at %.9f to %.9f d; stable step %.6g ms at "
           "set-up, %.6g at the end (step used %.6g); worst |m_step / m_I - "
           "1| %.2g; %d events, the crack to (%g, %g); worst balance error "
           "%.2e\n", rel, c->at_start, c->at_end, c->ratio[0], c->ratio[1],
           c->dt0, c->dt1, c->dt, c->mass, c->events, c->end[0], c->end[1],
           c->worst);
    tk_free(s);
}

/** A crack clipping supports by 1e-6 of their radius, and missing them
 *  by as much. */
static void support_clipped_by_1e_6(void **state)
{
    (void)state;
    Clip in, out;
    printf("  the bar's crack 1.25 mm from two node columns, support radius "
           "d = 1.25 / (1 -+ 1e-6):\n");
    clip_run(-1e-6, &in);
    clip_run(+1e-6, &out);
    double dt0 = in.dt0 / out.dt0, dt1 = in.dt1 / out.dt1, late = 0.0;
    double step = fmax(in.dt_start, out.dt_start);
    int n = in.events < 16 ? in.events : 16;
    for (int e = 0; e < n && in.events == out.events; e++)
        late = fmax(late, fabs(in.t_event[e] - out.t_event[e]));
    printf("    stable step clipped / missed %.6f at set-up, %.6f at the end "
           "(1/sqrt 2 = 0.707107); events at most %.4g ms apart, %.3f of the "
           "first step %.4g ms\n", dt0, dt1, late, late / step, step);
    TkBounds b = {0, 0};
    const Clip *c[2] = {&in, &out};
    for (int k = 0; k < 2; k++) {
        const char *w = k ? "missed" : "clipped";
        tk_bound(&b, 4, c[k]->finite, "%s: a field not finite", w);
        tk_bound(&b, 4, c[k]->mass >= 0.0 && c[k]->mass <= 1e-12,
                 "%s: step masses off m_I by %.3g", w, c[k]->mass);
        tk_bound(&b, 4, c[k]->events > 0, "%s: no growth", w);
        tk_bound(&b, 4, c[k]->worst <= 0.01, "%s: balance off by %.3g", w,
                 c[k]->worst);
    }
    tk_bound(&b, 4, in.at_start == 6 && in.at_end > in.at_start,
             "clipped: %d and %d step parameters", in.at_start, in.at_end);
    tk_bound(&b, 4, fabs(in.ratio[0] - (1 - 1e-6)) < 1e-12 &&
             fabs(in.ratio[1] - (1 - 1e-6)) < 1e-12, "clipped at %.12f d",
             in.ratio[0]);
    tk_bound(&b, 4, out.at_start == 0 && out.at_end == 0,
             "missed: %d and %d step parameters", out.at_start, out.at_end);
    tk_bound(&b, 4, fabs(out.ratio[0] - (1 + 1e-6)) < 1e-12,
             "missed at %.12f d", out.ratio[0]);
    tk_bound(&b, 4, dt0 >= 1 / sqrt(2.0) && dt1 >= 1 / sqrt(2.0),
             "stable step fell to %.3g, %.3g of the missed one's", dt0, dt1);
    tk_bound(&b, 4, in.events == out.events && late <= step * (1 + 1e-9),
             "events %d and %d, %.3g ms apart", in.events, out.events, late);
    tk_bound(&b, 4, hypot(in.end[0] - out.end[0], in.end[1] - out.end[1]) <=
             1e-9, "the cracks end apart");
    tk_bounds_finish(&b);
}

/** The smallest distance of a Gauss point from (px, py). */
static double nearest_point(const Xefg *x, double px, double py)
{
    double d = INFINITY;
    for (int p = 0; p < x->ngauss; p++)
        d = fmin(d, hypot(x->gx[p] - px, x->gy[p] - py));
    return d;
}

/** The node whose cell holds (px, py) strictly, or -1. */
static int cell_of(const Xefg *x, double px, double py)
{
    for (int I = 0; I < x->nnode; I++)
        if (fabs(px - x->X[I]) < x->hx[I] && fabs(py - x->Y[I]) < x->hy[I])
            return I;
    return -1;
}

/** The distance of (px, py) from the nearest point of the 4 x 4 rule of
 *  node @p I's cell uncut. */
static double off_rule(const Xefg *x, int I, double px, double py)
{
    QuadPoint q[16];
    int m = quad_cell(NULL, 0, x->X[I] - x->hx[I], x->Y[I] - x->hy[I],
                      x->X[I] + x->hx[I], x->Y[I] + x->hy[I], 4, q, 16);
    double d = INFINITY;
    for (int k = 0; k < m && k < 16; k++)
        d = fmin(d, hypot(q[k].x - px, q[k].y - py));
    return d;
}

/** Tips exactly on Gauss points, set up and grown. */
static void tip_on_a_gauss_point(void **state)
{
    (void)state;
    QuadPoint q[16];                    /* the rule of the uncut cell */
    assert_int_equal(quad_cell(NULL, 0, 3.0, 3.0, 3.5, 3.5, 4, q, 16), 16);
    char points[128], length[96];
    snprintf(points, sizeof points, "cracks.[0].points=([0.5, 0.5], "
             "[%.17g, %.17g])", q[10].x, q[10].y);
    snprintf(length, sizeof length, "cracks.[0].cohesive.growth.length=%.17g",
             hypot(0.5, 0.5));
    const char *const over[] = {"run.time=0.2", points, length, NULL};
    Sim *s = tk_load_file(DIAGONAL, over);
    Xefg *x = xefg_of(s);
    Growth *g = x->grow;
    const CrackLine *l = &x->crack[0];
    double h = g->h, worst = 0.0, land = 0.0, clear;
    clear = nearest_point(x, l->x[l->n - 1], l->y[l->n - 1]);
    printf("  tip on the Gauss point (%.17g, %.17g) of the cell of (3.25, "
           "3.25); nearest Gauss point after set-up %.3g h\n", q[10].x,
           q[10].y, clear / h);
    int *gnode = malloc(sizeof(int) * (size_t)g->gauss_cap);
    double *gx = malloc(sizeof(double) * (size_t)g->gauss_cap);
    double *gy = malloc(sizeof(double) * (size_t)g->gauss_cap);
    assert_true(gnode && gx && gy);
    int uncut = 0, was_there = 0;
    while (s->step < s->nsteps) {
        int n0 = g->nevent, ng = x->ngauss;
        memcpy(gnode, x->gnode, sizeof(int) * (size_t)ng);
        memcpy(gx, x->gx, sizeof(double) * (size_t)ng);
        memcpy(gy, x->gy, sizeof(double) * (size_t)ng);
        tk_steps(s, 1);
        if (s->step % 100 == 0)
            worst = fmax(worst, xefg_balance(s));
        if (g->nevent == n0)
            continue;
        const GrowthEvent *ev = &g->event[g->nevent - 1];
        int I = cell_of(x, ev->x1, ev->y1), held = 0;
        double off = I >= 0 ? off_rule(x, I, ev->x1, ev->y1) : INFINITY;
        double there = INFINITY;
        for (int p = 0; p < ng; p++)
            if (gnode[p] == I) {
                held++;
                there = fmin(there, hypot(gx[p] - ev->x1, gy[p] - ev->y1));
            }
        double near = nearest_point(x, ev->x1, ev->y1);
        uncut += held == 16;
        was_there += there <= 1e-12 * h;
        land = fmax(land, off);
        clear = fmin(clear, near);
        worst = fmax(worst, xefg_balance(s));
        printf("    event %d at step %ld: (%.17g, %.17g), %.3g h off the rule "
               "of its cell, which held %d points before, the nearest %.3g h "
               "from it; nearest Gauss point now %.3g h\n", g->nevent, s->step,
               ev->x1, ev->y1, off / h, held, there / h, near / h);
    }
    double diag = 0.0;
    for (int i = 0; i < l->n; i++)
        diag = fmax(diag, fabs(l->x[i] - l->y[i]));
    int ok = all_finite(x);
    worst = fmax(worst, xefg_balance(s));
    printf("    %d events, %d into an uncut cell, %d onto a point it held; "
           "largest distance off the rule %.3g h; nearest Gauss point to a "
           "tip %.3g h; largest |x - y| of the crack %.3g h; fields %s; "
           "worst balance error %.2e\n", g->nevent, uncut, was_there,
           land / h, clear / h, diag / h, ok ? "finite" : "NOT finite",
           worst);
    TkBounds b = {0, 0};
    tk_bound(&b, 4, g->nevent >= 2, "%d events", g->nevent);
    tk_bound(&b, 4, land <= 1e-12 * h, "a tip %.3g h off the rule", land / h);
    tk_bound(&b, 4, uncut == g->nevent && was_there == g->nevent,
             "%d of %d cells uncut, %d with the point", uncut, g->nevent,
             was_there);
    tk_bound(&b, 4, clear > 1e-9 * h, "a Gauss point %.3g h from a tip",
             clear / h);
    tk_bound(&b, 4, diag <= 1e-9 * h, "crack off the diagonal by %.3g h",
             diag / h);
    tk_bound(&b, 4, ok, "a field not finite");
    tk_bound(&b, 4, worst <= 0.01, "balance off by %.3g", worst);
    tk_bounds_finish(&b);
    free(gnode), free(gx), free(gy);
    tk_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(support_clipped_by_1e_6),
        cmocka_unit_test(tip_on_a_gauss_point),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
