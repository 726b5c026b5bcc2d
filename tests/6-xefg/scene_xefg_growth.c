/**
 * @file scene_xefg_growth.c
 * @brief Cohesive XEFG cracks that grow (chapter 6, "Growing cohesive
 *        cracks"): a bar 10 x 5 mm with an edge crack on its symmetry line
 *        x = 6, cohesive (f_t = 1 MPa, G_f = 0.05 N/mm) and free to grow,
 *        pulled apart at its ends (tests/6-xefg/scenes/growth_bar.cfg,
 *        nodes 0.5 mm apart, the crack between two columns of them).
 *
 * Bounds, fixed before the first run:
 * - mode_i_grows_straight (to t = 0.2294 ms, half way up; the first run
 *   stopped at 0.2 ms, before the first event, and failed "it grows"):
 *   it grows; every point of the
 *   crack within 0.05 h (0.025 mm) of x = 6; the number of segments added
 *   equals the number of growth events; at every event the averaged
 *   sigma_1 ahead of the tip that grew (the test's own sum over the Gauss
 *   points) was below f_t the step before, unless that tip was made that
 *   step (one segment per tip per step), and reached f_t at the event
 *   (the event's own record); the energy balance (start + held work =
 *   kinetic + strain + cohesive stored + damped + dissipated) within 1 % of the
 *   energy in at every 100th step and right after every event; the step
 *   the run uses no longer than run.cfl times the stable step that the
 *   power iteration gives for the grown discretisation (the first run
 *   failed it, 9.63e-5 > 0.5 x 1.72e-4 ms, when the code ran the power
 *   iteration only after an event that made a parameter lighter, relative
 *   to its node, than any before; it runs it after every event now, the
 *   bound unchanged); every new
 *   cohesive point closed and never opened right after its event
 *   (delta_max = 0, t_n = 0).
 * - beam_grows_straight (tests/6-xefg/scenes/growth_beam.cfg, a notched
 *   beam in three-point bending, to t = 1.7 ms): at least two events; the
 *   crack within 0.05 h of x = 9; segments = events; sigma_1 below f_t the
 *   step before each event (fresh tips apart) and at f_t at it; balance
 *   within 1 %; new cohesive points closed; the rows of the places held
 *   at the top (which the crack comes within 2 d of) kept equal to their
 *   nodes' rows and holding the crack's parameters; the stable step.
 * - edge_stops_growth (to t = 0.6 ms): the crack reaches the top edge
 *   y = 6 and stops growing: no tip left, no event after it reached the
 *   edge, the run goes on to its end, balance within 1 %.
 * - full_stops_the_run: with max_segments = 3 the run stops with a
 *   diagnostic naming the crack and max_segments, at the fourth event.
 * - tip_on_a_node: the crack on the node column x = 6.25, its tip on the
 *   node (6.25, 2.25), segments of one spacing, so that every new tip is
 *   on a node: the run reaches the edge without instability, every crack
 *   point within 0.25 h of x = 6.25 (the crack is h / 2 off the bar's
 *   symmetry line), balance within 1 %.
 * - inclined_crack_turns: the crack from (5, 0.5) to (6, 2.5), 26.57
 *   degrees from the vertical, in the same bar (to t = 0.6 ms): it grows;
 *   its last segment within 15 degrees of the vertical (normal to the
 *   pull); every new cohesive point closed at its event (the field kept
 *   however the crack turns); balance within 1 %.
 * - tip_at_end_zero: the bar's crack given from its tip to its mouth,
 *   so that it grows at its end 0 (new points go before the first): the
 *   same 7 events to the edge as the other way round, the new points
 *   before the old ones, within 0.05 h of x = 6, no tip left, balance
 *   within 1 %.
 * - both_tips_grow: a crack inside the bar, from (6, 2.5) to (6, 4.5):
 *   both ends grow, a point per event, through to both edges (no tip
 *   left), within 0.05 h of x = 6, balance within 1 %.
 * - two_tips_meeting (issue 27, "two tips meeting"): the bar's edge
 *   crack and its mirror about y = 3.5 from the top edge, tips at 2.5 and
 *   4.5, both growing: by the symmetry the events come in mirrored pairs
 *   (same step, y -> 7 - y within 1e-9 mm) until the tips meet at
 *   (6, 3.5); there the run stops (we lack the junction enrichment, the
 *   paper's eq. 10) with a diagnostic naming both cracks, at the step of
 *   crack 0's last event, before any segment overlaps the other crack
 *   (crack 0 up to y = 3.5, crack 1 down to y = 4, its segment to 3.5
 *   not inserted, within 1e-9 mm), the
 *   balance within 1 % at the stop. (Before growth_meets() the two lines
 *   ran on through each other to the opposite edges, each cohesive on the
 *   same line.)
 * - speed_limit_waits (growth.max_speed, chapter 6c): the bar's crack
 *   to the edge (0.6 ms) with max_speed = c_R of its material (plane
 *   stress, the scene's: Rayleigh's equation with kappa^2 = (1 - nu) / 2,
 *   c_R = xi c_s, c_s = sqrt(E / (2 (1 + nu) rho))): the
 *   tip waited in some step (without the limit it grows faster, 3.5 mm
 *   in 0.002 ms); every two consecutive events at least length /
 *   max_speed apart (to 1e-12 relative); it still reaches the edge
 *   (y = 6, no tip left); within 0.05 h of x = 6; balance within 1 %.
 * - path_in_the_outputs: the program's last cracks_NNNNN.csv of the bar
 *   run to the edge holds the 2 + 7 points of the grown crack, the last
 *   at y = 6; its cracks_NNNNN.vtp the same 9 points in one line, the
 *   last at (6, 6), and cracks.pvd names that file.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "balance.h"
#include "cohesive.h"
#include "cracks.h"
#include "growth.h"
#include "testkit.h"

#define SCENE "tests/6-xefg/scenes/growth_bar.cfg"
#define BEAM "tests/6-xefg/scenes/growth_beam.cfg"


/** The test's own sigma_1 of the stress averaged over the half disk of
 *  radius @p r ahead of the tip at end @p e of crack 0 (-inf: no tip). */
static double sigma1_ahead(const Xefg *x, int e, double r)
{
    const CrackLine *l = &x->crack[0];
    if (!l->tip[e])
        return -INFINITY;
    int i = e ? l->n - 1 : 0, j = e ? l->n - 2 : 1;
    double tx = l->x[i], ty = l->y[i];
    double dx = tx - l->x[j], dy = ty - l->y[j];
    double s[3] = {0, 0, 0}, w = 0;
    for (int g = 0; g < x->ngauss; g++) {
        double px = x->gx[g] - tx, py = x->gy[g] - ty;
        if (hypot(px, py) <= r && px * dx + py * dy >= 0) {
            for (int k = 0; k < 3; k++)
                s[k] += x->gw[g] * x->gs[3 * g + k];
            w += x->gw[g];
        }
    }
    for (int k = 0; k < 3; k++)
        s[k] /= w;
    return 0.5 * (s[0] + s[1]) + hypot(0.5 * (s[0] - s[1]), s[2]);
}

/** What a run saw. */
typedef struct Seen {
    int events;        /**< growth events */
    int fresh;         /**< of them at a tip made the step before */
    int early;         /**< of them where sigma_1 was >= f_t the step before
                            at a tip that was not fresh */
    int late;          /**< events whose recorded sigma_1 was below f_t */
    double before_max; /**< largest sigma_1 / f_t the step before an event */
    double worst;      /**< worst balance error */
    double t_worst;    /**< when */
    long after_edge;   /**< events after the crack went through */
    double xdev;       /**< largest |x - x_line| of a crack point */
    int open_new;      /**< new cohesive points not closed at insertion */
} Seen;

/** Step @p s to its end, watching every event. */
static void watch(Sim *s, double xline, Seen *v)
{
    Xefg *x = xefg_of(s);
    Growth *g = x->grow;
    const CohesiveLaw *L = &x->coh->set[0].law;
    memset(v, 0, sizeof *v);
    long fresh_step = -10, follow = -1;
    int through = 0, p0 = 0, p1 = 0;
    double s_event = 0.0;
    while (s->step < s->nsteps) {
        double before = sigma1_ahead(x, 1, g->set[0].tip_radius[1]);
        int n0 = g->nevent, npt0 = x->coh->npt;
        tk_steps(s, 1);
        if (g->nevent > n0) {
            const GrowthEvent *ev = &g->event[g->nevent - 1];
            v->events++;
            if (through)
                v->after_edge++;
            int was_fresh = fresh_step == s->step - 1;
            const Cohesive *C = x->coh;       /* the new points: closed, */
            for (int p = npt0; p < C->npt; p++)
                if (C->dmax[p] != 0.0 || C->tn[p] != 0.0)   /* never opened */
                    v->open_new++;
            if (was_fresh)
                v->fresh++;
            else if (!(before < L->f_t))
                v->early++;
            v->late += !(ev->sigma1 >= L->f_t);
            v->before_max = fmax(v->before_max, before / L->f_t);
            fresh_step = s->step;
            v->worst = fmax(v->worst, xefg_balance(s));
            printf("    event %d at step %ld (t = %.5f ms): (%.4f, %.4f) -> "
                   "(%.4f, %.4f), sigma_1 %.5f MPa (%.5f the step before%s); "
                   "%d parameters, %d Gauss points, %d cohesive points; "
                   "balance error %.2e\n", v->events, s->step, s->t, ev->x0,
                   ev->y0, ev->x1, ev->y1, ev->sigma1, before,
                   was_fresh ? ", a tip made then" : "", x->ndof, x->ngauss, x->coh->npt, xefg_balance(s));
        }
        if (g->nevent > n0) {             /* follow the new points' traction */
            follow = s->step + 20;
            p0 = npt0;
            p1 = x->coh->npt;
            s_event = g->event[g->nevent - 1].sigma1;
        }
        if (s->step == follow && p1 > p0) {
            const Cohesive *C = x->coh;
            double t = 0.0, w = 0.0, d = 0.0;
            for (int p = p0; p < p1; p++) {
                t += C->w[p] * C->tn[p];
                w += C->w[p];
                d = fmax(d, C->dn[p]);
            }
            printf("      20 steps later: the new segment's mean traction %.4f "
                   "MPa (%.3f of the sigma_1 that grew it), largest opening "
                   "%.3g mm (delta_0 = f_t / K = %.3g)\n", t / w, t / w / s_event,
                   d, cohesive_delta0(&C->set[0].law));
        }
        through = !x->crack[0].tip[0] && !x->crack[0].tip[1];
        if (s->step % 100 == 0 && xefg_balance(s) > v->worst)
            v->worst = xefg_balance(s), v->t_worst = s->t;
    }
    v->worst = fmax(v->worst, xefg_balance(s));
    const CrackLine *l = &x->crack[0];
    for (int i = 0; i < l->n; i++)
        v->xdev = fmax(v->xdev, fabs(l->x[i] - xline));
}

/** The stable step of the grown discretisation against the run's. */
static void stable_step_holds(Sim *s, TkBounds *b)
{
    Xefg *x = xefg_of(s);
    double used = s->dt, before = x->stable_step;
    assert_int_equal(xefg_power_iteration(x, s), 0);
    double cfl = s->scene.run.cfl;
    printf("    step used %.6g ms; stable step after the growth %.6g ms (kept "
           "%.6g; %d power iterations during the run); run.cfl x stable "
           "%.6g\n", used, x->stable_step, before, x->grow->power_runs,
           cfl * x->stable_step);
    tk_bound(b, 4, used <= cfl * x->stable_step * (1.0 + 1e-6),
             "step %.6g above run.cfl x stable step %.6g", used,
             cfl * x->stable_step);
}

/** Mode I: the crack grows straight up the symmetry line. */
static void mode_i_grows_straight(void **state)
{
    (void)state;
    const char *const over[] = {"run.time=0.2294", NULL};
    Sim *s = tk_load_file(SCENE, over);
    Xefg *x = xefg_of(s);
    double h = x->grow->h;
    int n0 = x->crack[0].n;
    Seen v;
    printf("  mode I, averaging radius %g mm = 1.5 h (the bar's L / 2 is "
           "above it), segments of %g mm:\n", x->grow->set[0].tip_radius[1],
           x->grow->set[0].length);
    watch(s, 6.0, &v);
    TkBounds b = {0, 0};
    int added = x->crack[0].n - n0;
    printf("    %d events (%d at a tip made the step before), %d segments "
           "added; largest sigma_1 / f_t the step before an event %.5f; "
           "largest |x - 6| %.3g mm (%.3g h); worst balance error %.2e\n",
           v.events, v.fresh, added, v.before_max, v.xdev, v.xdev / h, v.worst);
    tk_bound(&b, 4, v.events > 0, "no growth");
    tk_bound(&b, 4, v.xdev <= 0.05 * h, "crack off the line by %.3g", v.xdev);
    tk_bound(&b, 4, added == v.events && added == x->grow->nevent,
             "%d segments for %d events", added, v.events);
    tk_bound(&b, 4, v.early == 0, "%d events with sigma_1 >= f_t the step "
             "before", v.early);
    tk_bound(&b, 4, v.late == 0, "%d events below f_t", v.late);
    tk_bound(&b, 4, v.worst <= 0.01, "balance off by %.3g", v.worst);
    tk_bound(&b, 4, v.open_new == 0, "%d new cohesive points not closed",
             v.open_new);
    stable_step_holds(s, &b);
    tk_bounds_finish(&b);
    tk_free(s);
}

/** The crack reaches the edge and stops growing. */
static void edge_stops_growth(void **state)
{
    (void)state;
    const char *const over[] = {"run.time=0.6", NULL};
    Sim *s = tk_load_file(SCENE, over);
    Xefg *x = xefg_of(s);
    Seen v;
    printf("  to the edge:\n");
    watch(s, 6.0, &v);
    const CrackLine *l = &x->crack[0];
    TkBounds b = {0, 0};
    printf("    %d events; the crack ends at (%g, %g); tips %d %d; %ld events "
           "after it went through; t = %g ms of %g; worst balance error "
           "%.2e\n", v.events, l->x[l->n - 1], l->y[l->n - 1], l->tip[0],
           l->tip[1], v.after_edge, s->t, s->scene.run.time, v.worst);
    tk_bound(&b, 4, l->y[l->n - 1] >= 6.0 - 1e-9, "the crack ends inside");
    tk_bound(&b, 4, !l->tip[0] && !l->tip[1], "a tip is left");
    tk_bound(&b, 4, v.after_edge == 0, "%ld events after the edge",
             v.after_edge);
    tk_bound(&b, 4, s->step == s->nsteps, "the run stopped early");
    tk_bound(&b, 4, v.worst <= 0.01, "balance off by %.3g", v.worst);
    tk_bounds_finish(&b);
    tk_free(s);
}

/** max_segments reached: the run stops, naming the crack. */
static void full_stops_the_run(void **state)
{
    (void)state;
    const char *const over[] = {"run.time=0.6",
                                "cracks.[0].cohesive.growth.max_segments=3", NULL};
    Sim *s = tk_load_file(SCENE, over);
    Xefg *x = xefg_of(s);
    int rc = 0;
    while (s->step < s->nsteps && (rc = sim_advance(s)) == 0)
        ;
    printf("  max_segments = 3: stopped at step %ld (t = %g ms) with rc %d: "
           "\"%s = %g\"; %d events\n", s->fail.step, s->t, rc,
           s->fail.quantity ? s->fail.quantity : "(none)", s->fail.value,
           x->grow->nevent);
    assert_true(rc != 0);
    assert_non_null(s->fail.quantity);
    assert_non_null(strstr(s->fail.quantity, "growth of crack 0 stopped"));
    assert_non_null(strstr(s->fail.quantity, "max_segments = 3"));
    assert_int_equal(x->grow->nevent, 3);
    tk_free(s);
}

/** Every new tip on a node. */
static void tip_on_a_node(void **state)
{
    (void)state;
    const char *const over[] = {"run.time=0.6",
                                "cracks.[0].points=([6.25, 0.5], [6.25, 2.25])",
                                NULL};
    Sim *s = tk_load_file(SCENE, over);
    Xefg *x = xefg_of(s);
    double h = x->grow->h;
    Seen v;
    printf("  tips on nodes:\n");
    watch(s, 6.25, &v);
    const CrackLine *l = &x->crack[0];
    TkBounds b = {0, 0};
    printf("    %d events; ends at (%g, %g); largest |x - 6.25| %.3g mm (%.3g "
           "h); worst balance error %.2e\n", v.events, l->x[l->n - 1],
           l->y[l->n - 1], v.xdev, v.xdev / h, v.worst);
    tk_bound(&b, 4, v.events > 0, "no growth");
    tk_bound(&b, 4, s->step == s->nsteps, "the run stopped early");
    tk_bound(&b, 4, v.xdev <= 0.25 * h, "crack off the node column by %.3g",
             v.xdev);
    tk_bound(&b, 4, v.worst <= 0.01, "balance off by %.3g", v.worst);
    tk_bounds_finish(&b);
    tk_free(s);
}

/** Mode I in bending: the notched beam, its crack growing gradually up
 *  the symmetry line, past the held places at the top. */
static void beam_grows_straight(void **state)
{
    (void)state;
    const char *const over[] = {"run.time=1.7", NULL};
    Sim *s = tk_load_file(BEAM, over);
    Xefg *x = xefg_of(s);
    double h = x->grow->h;
    int n0 = x->crack[0].n;
    Seen v;
    printf("  three-point bending:\n");
    watch(s, 9.0, &v);
    TkBounds b = {0, 0};
    int added = x->crack[0].n - n0, held = 0, consistent = 1;
    const Constraints *C = &x->fix[1];
    for (int j = 0; j < C->n; j++) {       /* the rows of the held places */
        int nd = C->node[j];
        const ShapeRows *A = &x->at_node, *G = &C->rows;
        consistent &= A->start[nd + 1] - A->start[nd] ==
                      G->start[j + 1] - G->start[j];
        for (int e = G->start[j]; e < G->start[j + 1]; e++)
            held += x->dof_crack[G->dof[e]] == 0;
    }
    const CrackLine *l = &x->crack[0];
    printf("    %d events, %d segments, tip at (%g, %g); largest sigma_1 / f_t "
           "the step before an event %.5f; largest |x - 9| %.3g mm (%.3g h); "
           "%d entries of the crack's parameters in the held places' rows; "
           "worst balance error %.2e (t = %.4f ms)\n", v.events, added,
           l->x[l->n - 1], l->y[l->n - 1], v.before_max, v.xdev, v.xdev / h,
           held, v.worst, v.t_worst);
    tk_bound(&b, 4, v.events >= 2, "%d events", v.events);
    tk_bound(&b, 4, v.xdev <= 0.05 * h, "crack off the line by %.3g", v.xdev);
    tk_bound(&b, 4, added == v.events, "%d segments for %d events", added,
             v.events);
    tk_bound(&b, 4, v.early == 0, "%d events with sigma_1 >= f_t the step "
             "before", v.early);
    tk_bound(&b, 4, v.late == 0, "%d events below f_t", v.late);
    tk_bound(&b, 4, v.worst <= 0.01, "balance off by %.3g", v.worst);
    tk_bound(&b, 4, v.open_new == 0, "%d new cohesive points not closed",
             v.open_new);
    tk_bound(&b, 4, consistent && held > 0, "held rows %s, %d crack entries",
             consistent ? "kept" : "not kept", held);
    stable_step_holds(s, &b);
    tk_bounds_finish(&b);
    tk_free(s);
}

/** A crack inclined at 63 degrees turns to grow across the pull. */
static void inclined_crack_turns(void **state)
{
    (void)state;
    const char *const over[] = {"run.time=0.6",
                                "cracks.[0].points=([5.0, 0.5], [6.0, 2.5])",
                                NULL};
    Sim *s = tk_load_file(SCENE, over);
    Xefg *x = xefg_of(s);
    int n0 = x->crack[0].n;
    Seen v;
    printf("  an inclined crack:\n");
    watch(s, 6.0, &v);
    const CrackLine *l = &x->crack[0];
    TkBounds b = {0, 0};
    double first = 0.0, last = 0.0;
    if (l->n > n0) {
        first = atan2(l->x[n0] - l->x[n0 - 1], l->y[n0] - l->y[n0 - 1]);
        last = atan2(l->x[l->n - 1] - l->x[l->n - 2],
                     l->y[l->n - 1] - l->y[l->n - 2]);
    }
    double deg = 180.0 / 3.14159265358979;
    printf("    %d events; ends at (%g, %g); the first new segment %.2f and the "
           "last %.2f degrees from the vertical (the crack was at 26.57); %d new "
           "cohesive points not closed; worst balance error %.2e\n", v.events,
           l->x[l->n - 1], l->y[l->n - 1], first * deg, last * deg, v.open_new,
           v.worst);
    tk_bound(&b, 4, v.events > 0, "no growth");
    tk_bound(&b, 4, fabs(last * deg) <= 15.0, "the last segment %.2f degrees "
             "from the vertical", last * deg);
    tk_bound(&b, 4, v.open_new == 0, "%d new cohesive points not closed",
             v.open_new);
    tk_bound(&b, 4, v.worst <= 0.01, "balance off by %.3g", v.worst);
    tk_bounds_finish(&b);
    tk_free(s);
}

/** The same crack given from its tip to its mouth: the tip is its end 0,
 *  and a new segment goes before its first point. */
static void tip_at_end_zero(void **state)
{
    (void)state;
    const char *const over[] = {"run.time=0.6",
                                "cracks.[0].points=([6.0, 2.5], [6.0, 0.5])",
                                NULL};
    Sim *s = tk_load_file(SCENE, over);
    Xefg *x = xefg_of(s);
    double h = x->grow->h;
    printf("  the tip at end 0:\n");
    int events = 0;
    double worst = 0.0;
    while (s->step < s->nsteps) {
        int n0 = x->grow->nevent;
        tk_steps(s, 1);
        events += x->grow->nevent > n0;
        if (s->step % 100 == 0 || x->grow->nevent > n0)
            worst = fmax(worst, xefg_balance(s));
    }
    const CrackLine *l = &x->crack[0];
    double xdev = 0.0;
    for (int i = 0; i < l->n; i++)
        xdev = fmax(xdev, fabs(l->x[i] - 6.0));
    printf("    %d events; %d points, the first (%g, %g), the last (%g, %g); "
           "largest |x - 6| %.3g h; tips %d %d; worst balance error %.2e\n",
           events, l->n, l->x[0], l->y[0], l->x[l->n - 1], l->y[l->n - 1],
           xdev / h, l->tip[0], l->tip[1], worst);
    TkBounds b = {0, 0};
    tk_bound(&b, 4, events == 7 && l->n == 9, "%d events, %d points", events,
             l->n);
    tk_bound(&b, 4, l->y[0] >= 6.0 - 1e-9 && l->y[l->n - 1] == 0.5,
             "the new points not before the first");
    tk_bound(&b, 4, xdev <= 0.05 * h, "crack off the line by %.3g", xdev);
    tk_bound(&b, 4, !l->tip[0] && !l->tip[1], "a tip is left");
    tk_bound(&b, 4, worst <= 0.01, "balance off by %.3g", worst);
    tk_bounds_finish(&b);
    tk_free(s);
}

/** A crack inside the bar: both its ends are tips, and both grow. */
static void both_tips_grow(void **state)
{
    (void)state;
    const char *const over[] = {"run.time=0.6",
                                "cracks.[0].points=([6.0, 2.5], [6.0, 4.5])",
                                NULL};
    Sim *s = tk_load_file(SCENE, over);
    Xefg *x = xefg_of(s);
    double h = x->grow->h, worst = 0.0;
    int ends[2] = {0, 0};
    while (s->step < s->nsteps) {
        int n0 = x->grow->nevent;
        tk_steps(s, 1);
        for (int i = n0; i < x->grow->nevent; i++)
            ends[x->grow->event[i].end]++;
        if (s->step % 100 == 0 || x->grow->nevent > n0)
            worst = fmax(worst, xefg_balance(s));
    }
    const CrackLine *l = &x->crack[0];
    double xdev = 0.0;
    for (int i = 0; i < l->n; i++)
        xdev = fmax(xdev, fabs(l->x[i] - 6.0));
    printf("  both tips: %d events at end 0, %d at end 1; from (%g, %g) to "
           "(%g, %g); largest |x - 6| %.3g h; tips %d %d; worst balance error "
           "%.2e\n", ends[0], ends[1], l->x[0], l->y[0], l->x[l->n - 1],
           l->y[l->n - 1], xdev / h, l->tip[0], l->tip[1], worst);
    TkBounds b = {0, 0};
    tk_bound(&b, 4, ends[0] > 0 && ends[1] > 0, "an end did not grow");
    tk_bound(&b, 4, l->n == 2 + ends[0] + ends[1], "%d points", l->n);
    tk_bound(&b, 4, l->y[0] <= 1.0 + 1e-9 && l->y[l->n - 1] >= 6.0 - 1e-9,
             "not through");
    tk_bound(&b, 4, !l->tip[0] && !l->tip[1], "a tip is left");
    tk_bound(&b, 4, xdev <= 0.05 * h, "crack off the line by %.3g", xdev);
    tk_bound(&b, 4, worst <= 0.01, "balance off by %.3g", worst);
    tk_bounds_finish(&b);
    tk_free(s);
}

/** Two tips growing toward each other on one line: a clean stop where
 *  they meet. */
static void two_tips_meeting(void **state)
{
    (void)state;
    const char *const over[] = {"run.time=0.6", "cracks=("
        "{ points = ([6.0, 0.5], [6.0, 2.5]); cohesive = { law = \"linear\"; "
        "f_t = 1.0; G_f = 0.05; growth = { max_segments = 12; }; }; },"
        "{ points = ([6.0, 6.5], [6.0, 4.5]); cohesive = { law = \"linear\"; "
        "f_t = 1.0; G_f = 0.05; growth = { max_segments = 12; }; }; })", NULL};
    Sim *s = tk_load_file(SCENE, over);
    Xefg *x = xefg_of(s);
    Growth *g = x->grow;
    int rc = 0;
    while (s->step < s->nsteps && (rc = sim_advance(s)) == 0)
        ;
    int pairs = 1, n[2] = {0, 0};
    long last0 = -1;
    for (int e = 0; e < g->nevent; e++) {
        const GrowthEvent *a = &g->event[e];
        n[a->crack]++;
        last0 = a->crack == 0 ? a->step : last0;
        printf("    event %d: crack %d at step %ld, (%g, %g) -> (%g, %g)\n", e,
               a->crack, a->step, a->x0, a->y0, a->x1, a->y1);
    }
    for (int e = 0; e + 1 < g->nevent; e += 2) {  /* mirrored pairs */
        const GrowthEvent *a = &g->event[e], *b = &g->event[e + 1];
        pairs &= a->crack == 0 && b->crack == 1 && a->step == b->step &&
                 fabs(a->y1 - (7.0 - b->y1)) <= 1e-9 &&
                 fabs(a->x1 - b->x1) <= 1e-9;
    }
    double hi0 = -INFINITY, lo1 = INFINITY;
    for (int i = 0; i < x->crack[0].n; i++)
        hi0 = fmax(hi0, x->crack[0].y[i]);
    for (int i = 0; i < x->crack[1].n; i++)
        lo1 = fmin(lo1, x->crack[1].y[i]);
    const char *q = s->fail.quantity ? s->fail.quantity : "(none)";
    printf("  two tips meeting: rc %d at step %ld (t = %g ms), crack 0's last "
           "event at step %ld; %d + %d events; crack 0 up to y = %g, crack 1 "
           "down to y = %g; balance error %.2e\n    \"%s = %g\"\n", rc,
           s->fail.step, s->t, last0, n[0], n[1], hi0, lo1, xefg_balance(s), q,
           s->fail.value);
    TkBounds b = {0, 0};
    tk_bound(&b, 4, rc != 0 && s->fail.quantity, "the run did not stop");
    tk_bound(&b, 4, strstr(q, "growth of crack 1 stopped") &&
             strstr(q, "meets crack 0") && s->fail.value == 0.0,
             "the message does not name both cracks");
    tk_bound(&b, 4, s->fail.step == last0, "stop at step %ld, crack 0's last "
             "event at %ld", s->fail.step, last0);
    tk_bound(&b, 4, pairs && n[0] == n[1] + 1, "events not in mirrored pairs "
             "(%d and %d)", n[0], n[1]);
    tk_bound(&b, 4, fabs(hi0 - 3.5) <= 1e-9 && lo1 >= 3.5 + 0.5 - 1e-9,
             "crack 0 to %g, crack 1 to %g", hi0, lo1);
    tk_bound(&b, 4, xefg_balance(s) <= 0.01, "balance off by %.3g", xefg_balance(s));
    tk_bounds_finish(&b);
    tk_free(s);
}

/** growth.max_speed: the tip waits length / max_speed between events. */
static void speed_limit_waits(void **state)
{
    (void)state;
    double E = 1000.0, nu = 0.2, rho = 1e-3, k2 = (1 - nu) / 2; /* stress */
    double lo = 0.5, hi = 1.0;                 /* Rayleigh's root, bisection */
    for (int i = 0; i < 100; i++) {
        double xi = 0.5 * (lo + hi), x2 = xi * xi;
        if ((2 - x2) * (2 - x2) - 4 * sqrt(1 - x2) * sqrt(1 - k2 * x2) < 0)
            lo = xi;
        else
            hi = xi;
    }
    double cr = lo * sqrt(E / (2 * (1 + nu) * rho));
    char limit[96];
    snprintf(limit, sizeof limit, "cracks.[0].cohesive.growth.max_speed=%.17g",
             cr);
    const char *const over[] = {"run.time=0.6", limit, NULL};
    Sim *s = tk_load_file(SCENE, over);
    Xefg *x = xefg_of(s);
    Growth *g = x->grow;
    double h = g->h, worst = 0.0, gap = INFINITY;
    while (s->step < s->nsteps) {
        int n0 = g->nevent;
        tk_steps(s, 1);
        if (s->step % 100 == 0 || g->nevent > n0)
            worst = fmax(worst, xefg_balance(s));
    }
    for (int e = 1; e < g->nevent; e++)
        gap = fmin(gap, g->event[e].t - g->event[e - 1].t);
    double wait = g->set[0].length / cr, xdev = 0.0;
    const CrackLine *l = &x->crack[0];
    for (int i = 0; i < l->n; i++)
        xdev = fmax(xdev, fabs(l->x[i] - 6.0));
    printf("  max_speed = c_R = %.2f mm/ms: %d events, %ld steps waited; "
           "shortest time between events %.6g ms (length / c_R %.6g); ends "
           "at (%g, %g), tips %d %d; largest |x - 6| %.3g h; worst balance "
           "error %.2e\n", cr, g->nevent, g->waits, gap, wait,
           l->x[l->n - 1], l->y[l->n - 1], l->tip[0], l->tip[1], xdev / h,
           worst);
    TkBounds b = {0, 0};
    tk_bound(&b, 4, g->waits > 0, "the tip never waited");
    tk_bound(&b, 4, g->nevent > 1 && gap >= wait * (1.0 - 1e-12),
             "events %.6g ms apart, below %.6g", gap, wait);
    tk_bound(&b, 4, l->y[l->n - 1] >= 6.0 - 1e-9 && !l->tip[0] && !l->tip[1],
             "not through");
    tk_bound(&b, 4, xdev <= 0.05 * h, "crack off the line by %.3g", xdev);
    tk_bound(&b, 4, worst <= 0.01, "balance off by %.3g", worst);
    tk_bounds_finish(&b);
    tk_free(s);
}

/** The path in the outputs: the program writes the grown crack into the
 *  cracks_NNNNN series of stage 2, point by point. */
static void path_in_the_outputs(void **state)
{
    (void)state;
    char out[8192], path[256];
    int rc = tk_run_mpm(SCENE " -q -o build/test-xefg-growth run.time=0.6 "
                        "run.snapshots=2", out, sizeof out);
    if (rc)
        fail_msg("exit %d: %s", rc, out);
    int last = -1;
    for (int k = 0; k < 100; k++) {
        snprintf(path, sizeof path, "build/test-xefg-growth/cracks_%05d.csv", k);
        FILE *f = fopen(path, "r");
        if (!f)
            break;
        fclose(f);
        last = k;
    }
    assert_true(last >= 1);
    snprintf(path, sizeof path, "build/test-xefg-growth/cracks_%05d.csv", last);
    char *text = tk_slurp(path, NULL);
    int points = 0;
    double y = 0.0;
    for (char *l = strstr(text, "\n0,"); l; l = strstr(l + 1, "\n0,")) {
        int c, j;
        double px;
        if (sscanf(l + 1, "%d,%d,%lf,%lf", &c, &j, &px, &y) == 4)
            points++;
    }
    printf("  %s: %d points, the last at y = %g\n", path, points, y);
    assert_int_equal(points, 9);
    assert_true(fabs(y - 6.0) < 1e-9);
    free(text);
    /* ParaView's: the same path in the last cracks_NNNNN.vtp, one line of
     * 9 points whose last is (6, 6), and the series names that file */
    snprintf(path, sizeof path, "build/test-xefg-growth/cracks_%05d.vtp", last);
    text = tk_slurp(path, NULL);
    char *piece = strstr(text, "NumberOfPoints=\"");
    int np = 0, nl = 0;
    assert_non_null(piece);
    assert_int_equal(sscanf(piece, "NumberOfPoints=\"%d\" NumberOfLines=\"%d\"",
                            &np, &nl), 2);
    char *pts = strstr(piece, "format=\"ascii\">");
    assert_non_null(pts);
    pts += strlen("format=\"ascii\">");
    double vx = NAN, vy = NAN, vz;
    for (int k = 0; k < np && pts; k++) {      /* one point a line */
        assert_int_equal(sscanf(pts, " %lf %lf %lf", &vx, &vy, &vz), 3);
        pts = strchr(pts + 1, '\n');
    }
    printf("  %s: %d points in %d line, the last (%g, %g)\n", path, np, nl, vx, vy);
    assert_int_equal(np, 9);
    assert_int_equal(nl, 1);
    assert_true(fabs(vx - 6.0) < 1e-9 && fabs(vy - 6.0) < 1e-9);
    free(text);
    text = tk_slurp("build/test-xefg-growth/cracks.pvd", NULL);
    snprintf(path, sizeof path, "file=\"cracks_%05d.vtp\"", last);
    assert_non_null(strstr(text, path));
    free(text);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(mode_i_grows_straight),
        cmocka_unit_test(beam_grows_straight),
        cmocka_unit_test(edge_stops_growth),
        cmocka_unit_test(full_stops_the_run),
        cmocka_unit_test(tip_on_a_node),
        cmocka_unit_test(inclined_crack_turns),
        cmocka_unit_test(tip_at_end_zero),
        cmocka_unit_test(both_tips_grow),
        cmocka_unit_test(two_tips_meeting),
        cmocka_unit_test(speed_limit_waits),
        cmocka_unit_test(path_in_the_outputs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
