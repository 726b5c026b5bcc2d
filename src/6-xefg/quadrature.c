/**
 * @file quadrature.c
 * @brief Gauss-Legendre rules (Golub-Welsch) and the quadrature points of a
 *        background cell, split along the cracks that cut it and fanned
 *        from the tips (xefg.md 2.6, pitfall 4).
 */
#include <float.h>
#include <lapacke.h>
#include <math.h>
#include <stdlib.h>

#include "quadrature.h"

/// [gauss_legendre]
int gauss_legendre(int n, double *xi, double *w)
{
    if (n < 1 || n > GAUSS_MAX)
        return -1;
    /* Golub-Welsch: the nodes are the eigenvalues of the Jacobi matrix of
     * the Legendre recurrence (zero diagonal, off-diagonal k/sqrt(4k^2-1));
     * the weights 2 z_0^2 from the first components of the eigenvectors */
    double d[GAUSS_MAX] = {0}, e[GAUSS_MAX] = {0}, z[GAUSS_MAX * GAUSS_MAX];
    double work[2 * GAUSS_MAX];           /* LAPACK's room: no allocation */
    for (int k = 1; k < n; k++)
        e[k - 1] = k / sqrt(4.0 * k * k - 1.0);
    if (LAPACKE_dstev_work(LAPACK_COL_MAJOR, 'V', n, d, e, z, n, work) != 0)
        return -1;
    /* the rule is symmetric: average each node with its mirror image */
    for (int i = 0; i < n; i++) {
        int j = n - 1 - i;
        xi[i] = 0.5 * (d[i] - d[j]);
        w[i] = z[i * n] * z[i * n] + z[j * n] * z[j * n];
    }
    return 0;
}
/// [gauss_legendre]

/** A cut: the line through (ax, ay) along the unit vector (dx, dy). */
typedef struct Cut {
    double ax, ay, dx, dy;
} Cut;

/** Convex pieces of the cell, each of at most vmax vertices. */
typedef struct Pieces {
    int count, cap, vmax;
    int *nv;             /**< vertices of each piece */
    double *x, *y;       /**< piece p's vertices from [p * vmax] */
    int nv_room;         /**< entries of nv allocated */
    size_t room;         /**< entries of x and of y allocated */
} Pieces;

/** Signed distance of (x, y) from the cut's line, + on its left. */
static double cut_dist(const Cut *c, double x, double y)
{
    return c->dx * (y - c->ay) - c->dy * (x - c->ax);
}

/** Twice the signed area of a polygon. */
static double area2(const double *x, const double *y, int n)
{
    double a = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        a += x[i] * y[j] - x[j] * y[i];
    }
    return a;
}

/**
 * Does the segment (ax, ay)-(bx, by) meet the rectangle grown by tol?
 * Separating axes: x, y and the segment's normal.
 */
static int segment_meets_rect(double ax, double ay, double bx, double by,
                              double x0, double y0, double x1, double y1,
                              double tol)
{
    if (fmax(ax, bx) < x0 - tol || fmin(ax, bx) > x1 + tol ||
        fmax(ay, by) < y0 - tol || fmin(ay, by) > y1 + tol)
        return 0;
    double len = hypot(bx - ax, by - ay);
    Cut c = {ax, ay, (bx - ax) / len, (by - ay) / len};
    double s[4] = {cut_dist(&c, x0, y0), cut_dist(&c, x1, y0),
                   cut_dist(&c, x1, y1), cut_dist(&c, x0, y1)};
    int pos = 0, neg = 0;
    for (int k = 0; k < 4; k++) {
        pos += s[k] > tol;
        neg += s[k] < -tol;
    }
    return pos < 4 && neg < 4;
}

/**
 * The cuts of the cell [0, lx] x [0, ly] in coordinates from its corner
 * (ox, oy): the line of every crack segment that meets it, and through every
 * tip on it the line perpendicular to its last segment. With @p cuts NULL,
 * only counts. Tips on the cell go to @p tips (2 per tip).
 */
static int find_cuts(const CrackLine *cracks, int ncracks, double ox,
                     double oy, double lx, double ly, double tol, Cut *cuts,
                     double *tips, int *ntips)
{
    int nc = 0, nt = 0;
    for (int i = 0; i < ncracks; i++) {
        const CrackLine *c = &cracks[i];
        for (int k = 0; k + 1 < c->n; k++) {
            double ax = c->x[k] - ox, ay = c->y[k] - oy,
                   bx = c->x[k + 1] - ox, by = c->y[k + 1] - oy;
            double len = hypot(bx - ax, by - ay);
            if (!(len > 0) ||
                !segment_meets_rect(ax, ay, bx, by, 0, 0, lx, ly, tol))
                continue;
            if (cuts)
                cuts[nc] = (Cut){ax, ay, (bx - ax) / len, (by - ay) / len};
            nc++;
        }
        for (int e = 0; e < 2; e++) {
            if (!c->tip[e])
                continue;
            double tip[2], dir[2];
            crack_line_tip(c, e, tip, dir);
            tip[0] -= ox;
            tip[1] -= oy;
            if (tip[0] < -tol || tip[0] > lx + tol || tip[1] < -tol ||
                tip[1] > ly + tol || (dir[0] == 0 && dir[1] == 0))
                continue;
            if (cuts) {
                /* the tip becomes a vertex of every piece touching it */
                cuts[nc] = (Cut){tip[0], tip[1], -dir[1], dir[0]};
                tips[2 * nt] = tip[0];
                tips[2 * nt + 1] = tip[1];
            }
            nc++;
            nt++;
        }
    }
    *ntips = nt;
    return nc;
}

/** Append a polygon to the pieces, growing them; 0, or -1 out of memory. */
static int piece_add(Pieces *p, const double *x, const double *y, int n)
{
    if (p->count == p->cap) {
        int cap = 2 * p->cap;
        size_t nd = (size_t)cap * (size_t)p->vmax;
        int *nv = realloc(p->nv, (size_t)cap * sizeof(int));
        if (nv)
            p->nv = nv;
        double *px = realloc(p->x, nd * sizeof(double));
        if (px)
            p->x = px;
        double *py = realloc(p->y, nd * sizeof(double));
        if (py)
            p->y = py;
        if (!nv || !px || !py)
            return -1;
        p->cap = p->nv_room = cap;
        p->room = nd;
    }
    size_t o = (size_t)p->count * (size_t)p->vmax;
    for (int i = 0; i < n; i++) {
        p->x[o + i] = x[i];
        p->y[o + i] = y[i];
    }
    p->nv[p->count++] = n;
    return 0;
}

/** The side of a vertex: +1 / -1 farther than tol left / right of the line. */
static int cut_side(const Cut *c, double x, double y, double tol)
{
    double s = cut_dist(c, x, y);
    return s > tol ? 1 : s < -tol ? -1 : 0;
}

/**
 * Split a convex polygon by the cut's line into the part on its left (lx,
 * ly) and on its right (rx, ry), each of at most vmax vertices. Vertices
 * within tol of the line lie on it, so that a line along an edge or through
 * a corner makes no sliver. 1 when split (both parts hold a vertex farther
 * than tol from the line), else 0.
 */
static int split_polygon(const double *x, const double *y, int n,
                         const Cut *c, double tol, int vmax, double *lx,
                         double *ly, int *nl, double *rx, double *ry, int *nr)
{
    int pos = 0, neg = 0;
    for (int i = 0; i < n; i++) {
        int si = cut_side(c, x[i], y[i], tol);
        pos += si > 0;
        neg += si < 0;
    }
    if (!pos || !neg)
        return 0;
    int a = 0, b = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        int si = cut_side(c, x[i], y[i], tol), sj = cut_side(c, x[j], y[j], tol);
        if (a + 2 > vmax || b + 2 > vmax)
            return 0;
        if (si >= 0) {
            lx[a] = x[i];
            ly[a++] = y[i];
        }
        if (si <= 0) {
            rx[b] = x[i];
            ry[b++] = y[i];
        }
        if (si * sj < 0) {              /* the edge crosses the line */
            double di = cut_dist(c, x[i], y[i]), dj = cut_dist(c, x[j], y[j]);
            double t = di / (di - dj);
            double px = x[i] + t * (x[j] - x[i]), py = y[i] + t * (y[j] - y[i]);
            lx[a] = rx[b] = px;
            ly[a++] = ry[b++] = py;
        }
    }
    *nl = a;
    *nr = b;
    return 1;
}

/**
 * Drop repeated vertices and vertices on the line of their neighbours
 * (within tol) in place, so that no fan triangle is flat; the new count.
 */
static int clean_polygon(double *x, double *y, int n, double tol)
{
    int changed = 1;
    while (changed && n > 3) {
        changed = 0;
        for (int i = 0; i < n && n > 3; i++) {
            int h = (i + n - 1) % n, j = (i + 1) % n;
            double ex = x[j] - x[h], ey = y[j] - y[h], len = hypot(ex, ey);
            double d = len > 0 ? fabs(ex * (y[i] - y[h]) - ey * (x[i] - x[h])) / len
                               : hypot(x[i] - x[h], y[i] - y[h]);
            if (d <= tol || hypot(x[i] - x[h], y[i] - y[h]) <= tol) {
                for (int k = i; k + 1 < n; k++) {
                    x[k] = x[k + 1];
                    y[k] = y[k + 1];
                }
                n--;
                changed = 1;
            }
        }
    }
    return n;
}

/** Store a point while there is room; count it anyway. */
static void emit(QuadPoint *out, int cap, int *count, double x, double y,
                 double w)
{
    if (*count < cap)
        out[*count] = (QuadPoint){x, y, w};
    (*count)++;
}

/**
 * n x n collapsed Gauss points on the triangle (p0, p1, p2): the square
 * (u, v) in [0, 1]^2 maps to p0 + u (p1 - p0) + u v (p2 - p1), the edge
 * u = 0 collapsing onto p0 (Duffy); Jacobian 2 A u. (ox, oy) is added to
 * the points.
 */
static void duffy_triangle(const double *g, const double *gw, int n,
                           double x0, double y0, double x1, double y1,
                           double x2, double y2, double ox, double oy,
                           QuadPoint *out, int cap, int *count)
{
    double a2 = fabs((x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0));
    for (int i = 0; i < n; i++) {
        double u = 0.5 * (1 + g[i]);
        for (int j = 0; j < n; j++) {
            double v = 0.5 * (1 + g[j]);
            double px = x0 + u * ((x1 - x0) + v * (x2 - x1));
            double py = y0 + u * ((y1 - y0) + v * (y2 - y1));
            emit(out, cap, count, ox + px, oy + py,
                 0.25 * gw[i] * gw[j] * a2 * u);
        }
    }
}

/** n x n tensor Gauss points on the rectangle. */
static int tensor_gauss(const double *g, const double *gw, int n, double x0,
                        double y0, double x1, double y1, QuadPoint *out,
                        int cap)
{
    int count = 0;
    double hx = 0.5 * (x1 - x0), hy = 0.5 * (y1 - y0);
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++)
            emit(out, cap, &count, x0 + hx * (1 + g[i]), y0 + hy * (1 + g[j]),
                 gw[i] * gw[j] * hx * hy);
    return count;
}

static void pieces_free(Pieces *p)
{
    free(p->nv);
    free(p->x);
    free(p->y);
}

static int pieces_alloc(Pieces *p, int cap, int vmax)
{
    size_t nd = (size_t)cap * (size_t)vmax;
    *p = (Pieces){0, cap, vmax, malloc((size_t)cap * sizeof(int)),
                  malloc(nd * sizeof(double)), malloc(nd * sizeof(double)),
                  cap, nd};
    return p->nv && p->x && p->y ? 0 : -1;
}

/** Empty pieces of at most @p vmax vertices, as many as their room holds. */
static void pieces_reset(Pieces *p, int vmax)
{
    size_t fit = p->room / (size_t)vmax;
    p->count = 0;
    p->vmax = vmax;
    p->cap = fit < (size_t)p->nv_room ? (int)fit : p->nv_room;
}

/** The room quad_cell_in() works in. */
struct QuadWork {
    int max_cuts;        /**< most cuts a cell may have */
    Cut *cuts;           /**< the cuts */
    double *tips;        /**< the tips on the cell */
    double *scratch;     /**< a split's two parts */
    Pieces cur, next;    /**< the pieces, before and after a cut */
};

QuadWork *quad_work_new(int max_cuts)
{
    QuadWork *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    int k = max_cuts > 0 ? max_cuts : 1;
    int cap_p = 1 + k + k * (k - 1) / 2, vmax = 6 + 2 * k;
    w->max_cuts = k;
    w->cuts = malloc((size_t)k * sizeof(Cut));
    w->tips = malloc((size_t)(2 * k + 1) * sizeof(double));
    w->scratch = malloc(4 * (size_t)vmax * sizeof(double));
    int ra = pieces_alloc(&w->cur, cap_p, vmax), rb = pieces_alloc(&w->next, cap_p, vmax);
    if (!w->cuts || !w->tips || !w->scratch || ra || rb) {
        quad_work_free(w);
        return NULL;
    }
    return w;
}

void quad_work_free(QuadWork *w)
{
    if (!w)
        return;
    free(w->cuts);
    free(w->tips);
    free(w->scratch);
    pieces_free(&w->cur);
    pieces_free(&w->next);
    free(w);
}

/**
 * Cut the cell [x0, x1] x [y0, y1], in coordinates from its corner (x0, y0),
 * by every cut in turn into convex pieces (in cur; next is a second buffer of
 * the same vmax), then fan the pieces into Duffy triangles. The number of
 * points, or -1 out of memory.
 */
static int cut_and_fan(const Cut *cuts, int ncuts, const double *tips,
                       int ntips, double x0, double y0, double x1, double y1,
                       double tol, const double *g, const double *gw, int n,
                       Pieces *cur, Pieces *next, double *scratch,
                       QuadPoint *out, int cap)
{
    int vmax = cur->vmax;
    double *lx = scratch, *ly = lx + vmax, *qx = ly + vmax, *qy = qx + vmax;
    double wx = x1 - x0, wy = y1 - y0, cell = wx * wy;
    const double rx[4] = {0, wx, wx, 0}, ry[4] = {0, 0, wy, wy};
    if (piece_add(cur, rx, ry, 4) != 0)
        return -1;
    for (int c = 0; c < ncuts; c++) {
        next->count = 0;
        for (int p = 0; p < cur->count; p++) {
            const double *px = cur->x + (size_t)p * (size_t)vmax,
                         *py = cur->y + (size_t)p * (size_t)vmax;
            int nl, nr, m = cur->nv[p], rc = 0;
            if (split_polygon(px, py, m, &cuts[c], tol, vmax, lx, ly, &nl, qx,
                              qy, &nr)) {
                /* drop a part of no area (below the rounding of the cell) */
                if (fabs(area2(lx, ly, nl)) > 2e-14 * cell)
                    rc |= piece_add(next, lx, ly, nl);
                if (fabs(area2(qx, qy, nr)) > 2e-14 * cell)
                    rc |= piece_add(next, qx, qy, nr);
            } else {
                rc = piece_add(next, px, py, m);
            }
            if (rc != 0)
                return -1;
        }
        Pieces t = *cur;
        *cur = *next;
        *next = t;
    }
    /* the cracks only touch the cell (along an edge, at a corner) */
    if (cur->count == 1 && ntips == 0)
        return tensor_gauss(g, gw, n, x0, y0, x1, y1, out, cap);

    /* fan every piece into triangles, from a tip where it has one */
    int count = 0;
    for (int p = 0; p < cur->count; p++) {
        double *px = cur->x + (size_t)p * (size_t)vmax,
               *py = cur->y + (size_t)p * (size_t)vmax;
        int m = clean_polygon(px, py, cur->nv[p], tol), f = 0;
        double dbest = INFINITY;
        for (int t = 0; t < ntips; t++)
            for (int i = 0; i < m; i++) {
                double d = hypot(px[i] - tips[2 * t], py[i] - tips[2 * t + 1]);
                if (d <= 4 * tol && d < dbest) {
                    dbest = d;
                    f = i;
                }
            }
        for (int i = 1; i + 1 < m; i++) {
            int a = (f + i) % m, b = (f + i + 1) % m;
            duffy_triangle(g, gw, n, px[f], py[f], px[a], py[a], px[b], py[b],
                           x0, y0, out, cap, &count);
        }
    }
    return count;
}

/// [quad_cell]
int quad_cell_in(QuadWork *w, const CrackLine *cracks, int ncracks, double x0,
                 double y0, double x1, double y1, int n, QuadPoint *out,
                 int cap)
{
    double g[GAUSS_MAX], gw[GAUSS_MAX];
    if (gauss_legendre(n, g, gw) != 0)
        return -1;
    if (cap < 0)
        cap = 0;
    /* the cell is cut in coordinates from its corner, so that the areas of
     * the pieces keep their digits far from the origin. "On a line": within
     * a trillionth of the cell, or of the rounding of its coordinates */
    double tol = 1e-12 * ((x1 - x0) + (y1 - y0)) +
                 16 * DBL_EPSILON * (fabs(x0) + fabs(x1) + fabs(y0) + fabs(y1));
    int ntips;
    int ncuts = find_cuts(cracks, ncracks, x0, y0, x1 - x0, y1 - y0, tol, NULL,
                          NULL, &ntips);
    if (ncuts == 0)
        return tensor_gauss(g, gw, n, x0, y0, x1, y1, out, cap);
    if (!w || ncuts > w->max_cuts)
        return -2;
    /* k lines cut a convex region into at most 1 + k + k(k-1)/2 pieces of
     * at most 4 + k vertices (room for more, for rounding) */
    int vmax = 6 + 2 * ncuts;
    pieces_reset(&w->cur, vmax);
    pieces_reset(&w->next, vmax);
    find_cuts(cracks, ncracks, x0, y0, x1 - x0, y1 - y0, tol, w->cuts, w->tips,
              &ntips);
    return cut_and_fan(w->cuts, ncuts, w->tips, ntips, x0, y0, x1, y1, tol, g,
                       gw, n, &w->cur, &w->next, w->scratch, out, cap);
}

int quad_cell(const CrackLine *cracks, int ncracks, double x0, double y0,
              double x1, double y1, int n, QuadPoint *out, int cap)
{
    double tol = 1e-12 * ((x1 - x0) + (y1 - y0)) +
                 16 * DBL_EPSILON * (fabs(x0) + fabs(x1) + fabs(y0) + fabs(y1));
    int ntips;
    int ncuts = find_cuts(cracks, ncracks, x0, y0, x1 - x0, y1 - y0, tol, NULL,
                          NULL, &ntips);
    QuadWork *w = ncuts > 0 ? quad_work_new(ncuts) : NULL;
    if (ncuts > 0 && !w)
        return -1;
    int count = quad_cell_in(w, cracks, ncracks, x0, y0, x1, y1, n, out, cap);
    quad_work_free(w);
    return count < -1 ? -1 : count;
}
/// [quad_cell]
