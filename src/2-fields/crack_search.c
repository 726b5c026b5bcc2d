/**
 * @file crack_search.c
 * @brief The crossing seam: a search visits the segments a particle-node
 *        line may cross, in any order; the field follows from all the
 *        crossings by a rule that does not depend on that order.
 */
#include "cracks.h"
#include "step.h"

/// [crossings_result]
int crossings_result(const Crossings *x, CrackHit *hit)
{
    int best = -1, sum = 0;
    for (int i = 0; i < x->n; i++) {        /* lowest crack crossed oddly */
        int c = x->hit[i].crack, count = 0, s = 0;
        if (best >= 0 && c >= best)
            continue;
        for (int j = 0; j < x->n; j++)
            if (x->hit[j].crack == c) {
                count++;
                s += x->hit[j].side;
            }
        if (count % 2) {
            best = c;
            sum = s;
        }
    }
    if (best < 0)
        return 0;
    int side = sum > 0 ? 1 : -1;
    hit->crack = best;
    hit->side = side;
    hit->segment = -1;
    for (int i = 0; i < x->n; i++)          /* lowest segment of that side */
        if (x->hit[i].crack == best && x->hit[i].side == side &&
            (hit->segment < 0 || x->hit[i].segment < hit->segment))
            hit->segment = x->hit[i].segment;
    return side > 0 ? 1 : 2;
}
/// [crossings_result]

/// [crossing_plain]
/** Every segment of every crack, in order. */
static void plain_visit(const Cracks *C, int cell, double px, double py,
                        double nx, double ny, Crossings *x)
{
    const Crack *crack = C->crack;
    int ncracks = C->ncracks;
    (void)cell;
    for (int c = 0; c < ncracks; c++)
        for (int k = 0, segments = crack[c].n - 1; k < segments; k++) {
            int side = crack_segment_side(&crack[c], k, px, py, nx, ny);
            if (side)
                crossings_add(x, c, k, side);
        }
}

/** plain_visit() of a point's @p n lines at once, segment after segment. */
static void plain_visit_lines(const Cracks *C, int cell, double px, double py,
                              int n, const double *nx, const double *ny,
                              Crossings *x)
{
    const Crack *crack = C->crack;
    int ncracks = C->ncracks;
    (void)cell;
    for (int c = 0; c < ncracks; c++)
        for (int k = 0, segments = crack[c].n - 1; k < segments; k++)
            for (int a = 0; a < n; a++) {
                int side = crack_segment_side(&crack[c], k, px, py, nx[a], ny[a]);
                if (side)
                    crossings_add(&x[a], c, k, side);
            }
}

const CrossingSearch crossing_plain = {"plain", plain_visit, NULL, NULL,
                                       plain_visit_lines};
/// [crossing_plain]

int cracks_task7(Sim *sim, void *state, Seam seam)
{
    Cracks *C = state;
    (void)seam;
    if (cracks_move(sim))
        return -1;
    if (C->search->update && C->search->update(C, &sim->grid))
        return step_fail(sim, -1, "memory for the crossing search", 0);
    return 0;
}
