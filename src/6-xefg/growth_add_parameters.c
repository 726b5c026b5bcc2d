/**
 * @file growth_add_parameters.c
 * @brief The enrichment of the nodes a new segment reaches (eq. 1-2 with
 *        the longer crack): a node whose support the crack now cuts
 *        through gains a step parameter of the whole line, one whose
 *        support holds the new tip gains branch parameters about it.
 *        Parameters are only added, never changed or removed: each keeps
 *        the part of the line it was made with (Xefg::dof_line) and a
 *        branch parameter its tip (Xefg::dof_frame), so that with the new
 *        parameters at zero the displacement field is the same as before
 *        the event, whatever the angle of the new segment.
 *        The parameters of a node stay together (its standard one first),
 *        so the later ones are renumbered in place.
 */
#include <math.h>
#include <string.h>

#include "cohesive.h"
#include "growth.h"

/** Distance from (px, py) to the segment from @p a to @p b. */
double growth_segment_distance(const double a[2], const double b[2], double px,
                               double py)
{
    double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
    double s = l2 > 0.0 ? ((px - a[0]) * dx + (py - a[1]) * dy) / l2 : 0.0;
    s = s < 0.0 ? 0.0 : s > 1.0 ? 1.0 : s;
    return hypot(px - a[0] - s * dx, py - a[1] - s * dy);
}

/** What node @p I lacks on crack @p c with its line now: how many
 *  parameters, and whether they are branch ones (*@p tip_end >= 0, the
 *  tip's end) or a step one. */
static int lacks(const Xefg *x, int c, int I, int *tip_end)
{
    const CrackLine *l = &x->crack[c];
    int nb = x->set.tip == BRANCH_LEFM ? 4 : 1, e = -1;
    *tip_end = -1;
    SupportCut cut = crack_line_cut(l, x->X[I], x->Y[I], x->d[I], &e);
    if (cut == SUPPORT_UNCUT)
        return 0;
    double tip[2], dir[2];
    if (cut == SUPPORT_TIP)
        crack_line_tip(l, e, tip, dir);
    for (int q = x->node_dof[I]; q < x->node_dof[I + 1]; q++) {
        if (x->dof_crack[q] != c)
            continue;
        const double *f = x->dof_frame + 4 * q;
        if (cut == SUPPORT_CUT && x->dof_kind[q] == DOF_STEP &&
            x->dof_line[2 * q] == 0 && x->dof_line[2 * q + 1] == l->n)
            return 0;                    /* has a step of the whole line */
        if (cut == SUPPORT_TIP && x->dof_kind[q] >= DOF_BRANCH &&
            f[0] == tip[0] && f[1] == tip[1] && f[2] == dir[0] && f[3] == dir[1])
            return 0;                                /* has this tip's */
    }
    *tip_end = cut == SUPPORT_TIP ? e : -1;
    return cut == SUPPORT_TIP ? nb : 1;
}

/** Renumber the parameters of rows @p R: q -> q + shift of its node. */
static void remap(ShapeRows *R, const Xefg *x, const int *shift)
{
    for (int e = 0; e < R->len; e++)
        R->dof[e] += shift[x->dof_node[R->dof[e]]];
}

/** Move parameter @p q to @p d (d > q; d's old content is moved already). */
static void move(Xefg *x, int q, int d)
{
    x->dof_node[d] = x->dof_node[q];
    x->dof_kind[d] = x->dof_kind[q];
    x->dof_crack[d] = x->dof_crack[q];
    x->dof_end[d] = x->dof_end[q];
    memcpy(x->dof_frame + 4 * d, x->dof_frame + 4 * q, 4 * sizeof(double));
    x->dof_line[2 * d] = x->dof_line[2 * q];
    x->dof_line[2 * d + 1] = x->dof_line[2 * q + 1];
    x->mass[d] = x->mass[q];
    x->load[d] = x->load[q];
    for (int k = 0; k < 2; k++) {
        x->u[2 * d + k] = x->u[2 * q + k];
        x->v[2 * d + k] = x->v[2 * q + k];
        x->a[2 * d + k] = x->a[2 * q + k];
        x->f[2 * d + k] = x->f[2 * q + k];
    }
}

/// [growth_add_parameters]
int growth_add_parameters(Xefg *x, Growth *g, int c, const double a[2],
                      const double b[2], char *err, size_t errlen)
{
    int total = 0, e = -1;
    for (int I = 0; I < x->nnode; I++) {
        g->add[I] = 0;
        if (growth_segment_distance(a, b, x->X[I], x->Y[I]) < x->d[I])
            g->add[I] = lacks(x, c, I, &e);     /* its support meets it */
        g->len[I] = e;                          /* the tip's end, or -1 */
        total += g->add[I];
    }
    if (total == 0)
        return 0;
    if (x->ndof + total > g->dof_cap) {
        snprintf(err, errlen, "growth of crack %d stopped: its new segment "
                 "needs %d parameters more than the %d reserved at set-up",
                 c, x->ndof + total - g->dof_cap, g->dof_cap);
        return -1;
    }
    g->shift[0] = 0;
    for (int I = 0; I < x->nnode; I++)
        g->shift[I + 1] = g->shift[I] + g->add[I];
    /* every row that names a parameter, then the parameters themselves,
     * from the last down, so that nothing is overwritten before it moves */
    remap(&x->gauss, x, g->shift);
    remap(&x->at_node, x, g->shift);
    for (int k = 0; k < 2; k++)
        remap(&x->fix[k].rows, x, g->shift);
    remap(&x->coh->jump, x, g->shift);
    for (int q = x->ndof - 1; q >= 0; q--)
        if (g->shift[x->dof_node[q]] > 0)
            move(x, q, q + g->shift[x->dof_node[q]]);
    for (int I = 0; I <= x->nnode; I++)
        x->node_dof[I] += g->shift[I];
    x->ndof += total;
    for (int I = 0; I < x->nnode; I++) {     /* the new ones, at zero */
        if (!g->add[I])
            continue;
        e = g->len[I];
        int q0 = x->node_dof[I + 1] - g->add[I];
        for (int j = 0; j < g->add[I]; j++) {
            int q = q0 + j;
            double *f = x->dof_frame + 4 * q;
            x->dof_node[q] = I;
            x->dof_kind[q] = e >= 0 ? DOF_BRANCH + j : DOF_STEP;
            x->dof_crack[q] = c;
            x->dof_end[q] = e >= 0 ? e : 0;
            f[0] = f[1] = f[2] = f[3] = 0.0;
            if (e >= 0)                              /* the tip it enriches */
                crack_line_tip(&x->crack[c], e, f, f + 2);
            x->dof_line[2 * q] = 0;                  /* the line it knows */
            x->dof_line[2 * q + 1] = x->crack[c].n;
            x->mass[q] = x->load[q] = 0.0;           /* lumped later */
            for (int k = 0; k < 2; k++)
                x->u[2 * q + k] = x->v[2 * q + k] = x->a[2 * q + k] =
                    x->f[2 * q + k] = 0.0;
            if (e >= 0)
                x->nbranch++;
            else
                x->nstep++;
        }
    }
    return total;
}
/// [growth_add_parameters]
