/**
 * @file crack_watch.c
 * @brief Crossings and opening of a crack, from its geometry (test helper).
 */
#include "crack_watch.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int watch_side(const double *cx, const double *cy, int n, double x, double y,
               int *within, double *dist)
{
    double best = INFINITY;
    int side = 0;
    *within = 0;
    for (int k = 0; k + 1 < n; k++) {
        double dx = cx[k + 1] - cx[k], dy = cy[k + 1] - cy[k];
        double wx = x - cx[k], wy = y - cy[k];
        double len2 = dx * dx + dy * dy, t = (wx * dx + wy * dy) / len2;
        if (!(t >= 0 && t <= 1))
            continue;
        double cross = dx * wy - dy * wx, d = fabs(cross) / sqrt(len2);
        if (d < best) {
            best = d;
            side = (cross > 0) - (cross < 0);
            *within = 1;
        }
    }
    *dist = best;
    return side;
}

/** Arc length of the polyline up to the foot of (x, y) on its nearest
 *  segment, as a fraction of the whole length. */
static double foot_fraction(const double *cx, const double *cy, int n, double x,
                            double y)
{
    double total = 0, at = -1, best = INFINITY;
    for (int k = 0; k + 1 < n; k++) {
        double dx = cx[k + 1] - cx[k], dy = cy[k + 1] - cy[k];
        double len = sqrt(dx * dx + dy * dy);
        double t = ((x - cx[k]) * dx + (y - cy[k]) * dy) / (len * len);
        if (t >= 0 && t <= 1) {
            double d = fabs(dx * (y - cy[k]) - dy * (x - cx[k])) / len;
            if (d < best) {
                best = d;
                at = total + t * len;
            }
        }
        total += len;
    }
    return at < 0 ? -1 : at / total;
}

void watch_start(CrackWatch *w, const Sim *sim, int body, const double *cx,
                 const double *cy, int n, double band, double middle)
{
    const Particles *P = &sim->pts;
    memset(w, 0, sizeof *w);
    w->body = body;
    w->first_p = -1;
    w->last = calloc((size_t)P->n, 1);
    w->face = malloc(sizeof(int) * (size_t)P->n);
    w->face_side = malloc((size_t)P->n);
    double above = 0, below = 0;
    int na = 0, nb = 0;
    for (int p = 0; p < P->n; p++) {
        if (body >= 0 && P->body[p] != body)
            continue;
        int within;
        double d;
        int side = watch_side(cx, cy, n, P->x[p], P->y[p], &within, &d);
        w->last[p] = (signed char)side;
        double f = foot_fraction(cx, cy, n, P->x[p], P->y[p]);
        if (side && d < band && f >= 0.5 - 0.5 * middle && f <= 0.5 + 0.5 * middle) {
            w->face[w->nface] = p;
            w->face_side[w->nface++] = (signed char)side;
            if (side > 0) {
                above += d;
                na++;
            } else {
                below -= d;
                nb++;
            }
        }
    }
    w->open0 = (na ? above / na : 0) - (nb ? below / nb : 0);
}

int watch_check(CrackWatch *w, const Sim *sim, const double *cx,
                const double *cy, int n)
{
    const Particles *P = &sim->pts;
    int found = 0;
    for (int p = 0; p < P->n; p++) {
        if (w->body >= 0 && P->body[p] != w->body)
            continue;
        int within;
        double d;
        int side = watch_side(cx, cy, n, P->x[p], P->y[p], &within, &d);
        if (!within || side == 0)
            continue;
        if (w->last[p] && side != w->last[p]) {
            found++;
            if (w->first_p < 0) {
                w->first_p = p;
                w->first_step = sim->step;
            }
        }
        w->last[p] = (signed char)side;
    }
    w->crossings += found;
    return found;
}

double watch_opening(const CrackWatch *w, const Sim *sim, const double *cx,
                     const double *cy, int n)
{
    const Particles *P = &sim->pts;
    double above = 0, below = 0;
    int na = 0, nb = 0;
    for (int k = 0; k < w->nface; k++) {
        int p = w->face[k], within;
        double d;
        int side = watch_side(cx, cy, n, P->x[p], P->y[p], &within, &d);
        if (!within)
            continue;
        double s = side ? side * d : 0;      /* signed distance */
        if (w->face_side[k] > 0) {
            above += s;
            na++;
        } else {
            below += s;
            nb++;
        }
    }
    return (na ? above / na : 0) - (nb ? below / nb : 0) - w->open0;
}

void watch_free(CrackWatch *w)
{
    free(w->last);
    free(w->face);
    free(w->face_side);
    memset(w, 0, sizeof *w);
}
