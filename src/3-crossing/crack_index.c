/**
 * @file crack_index.c
 * @brief The segment index: for every grid cell a crack reaches, the list
 *        of the segments that reach it, rebuilt after the cracks move.
 *
 * A point's lines to its four nodes lie in its cell, so only the segments
 * of that cell can cross them, and a point in a cell no segment reaches
 * skips Task 1. With a wider stencil (Cracks::reach, chapter 8) a cell
 * lists the segments that reach it or the cells around it. The index costs in proportion to the segments and the
 * cells they reach, not to the points.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "searches.h"

/** One segment in one cell's list. */
typedef struct IndexEntry {
    int crack;      /* which crack */
    int seg;        /* which of its segments */
    int next;       /* next entry of the same cell, or -1 */
} IndexEntry;

/** The index: per cell the first entry, and the entries. Cells are
 *  numbered by their lower-left node, as Task 0 numbers a point's cell, so
 *  head[] serves as Cracks::near_cell too. */
typedef struct SegmentIndex {
    SearchGrid sg;      /* the grid and the margin */
    int *head;          /* per cell: first entry, or -1 */
    int *touched;       /* cells with entries */
    int ntouched;       /* how many */
    IndexEntry *e;      /* entries */
    int n;              /* in use */
    int cap;            /* allocated */
} SegmentIndex;

/** Add segment @p seg of crack @p crack to cell @p cell. */
static int index_add(SegmentIndex *ix, int cell, int crack, int seg)
{
    if (ix->n == ix->cap) {
        int cap = ix->cap ? 2 * ix->cap : 256;
        IndexEntry *e = realloc(ix->e, (size_t)cap * sizeof *e);
        if (!e)
            return -1;
        ix->e = e;
        ix->cap = cap;
    }
    if (ix->head[cell] < 0)
        ix->touched[ix->ntouched++] = cell;
    ix->e[ix->n] = (IndexEntry){crack, seg, ix->head[cell]};
    ix->head[cell] = ix->n++;
    return 0;
}

/** Clamp a cell coordinate to the grid. */
static int clamp_cell(double g, int n)
{
    int i = (int)floor(g);
    return i < 0 ? 0 : i > n - 1 ? n - 1 : i;
}

/// [index_update]
/** Rebuild the index: each segment goes into every cell whose box (with
 *  the Cracks::reach cells around it), grown by eps, its grown box meets
 *  and whose corners do not all lie strictly on one side of its line. */
static int index_update(Cracks *C, const Grid *g)
{
    SegmentIndex *ix = C->search_state;
    if (!ix) {
        ix = calloc(1, sizeof *ix);
        if (!ix)
            return -1;
        C->search_state = ix;
        int cells = g->nnodes;
        ix->head = malloc(sizeof(int) * (size_t)cells);
        ix->touched = malloc(sizeof(int) * (size_t)cells);
        if (!ix->head || !ix->touched)
            return -1;
        for (int c = 0; c < cells; c++)
            ix->head[c] = -1;
    }
    search_grid_of(&ix->sg, g);
    const SearchGrid *sg = &ix->sg;
    for (int k = 0; k < ix->ntouched; k++)
        ix->head[ix->touched[k]] = -1;
    ix->ntouched = ix->n = 0;
    double eps = sg->eps;
    int R = C->reach, wide = 2 * R + 1;    /* the block of cells a point's
                                              lines may cross */
    for (int k = 0; k < C->ncracks; k++) {
        const Crack *c = &C->crack[k];
        for (int j = 0; j + 1 < c->n; j++) {
            double ax = c->x[j], ay = c->y[j], bx = c->x[j + 1], by = c->y[j + 1];
            double len = hypot(bx - ax, by - ay);
            int i0 = clamp_cell((fmin(ax, bx) - 2 * eps - sg->ox) / sg->dx - R, sg->ncx);
            int i1 = clamp_cell((fmax(ax, bx) + 2 * eps - sg->ox) / sg->dx + R, sg->ncx);
            int j0 = clamp_cell((fmin(ay, by) - 2 * eps - sg->oy) / sg->dy - R, sg->ncy);
            int j1 = clamp_cell((fmax(ay, by) + 2 * eps - sg->oy) / sg->dy + R, sg->ncy);
            for (int cj = j0; cj <= j1; cj++)
                for (int ci = i0; ci <= i1; ci++) {
                    double x0 = sg->ox + (ci - R) * sg->dx - eps;
                    double x1 = x0 + wide * sg->dx + 2 * eps;
                    double y0 = sg->oy + (cj - R) * sg->dy - eps;
                    double y1 = y0 + wide * sg->dy + 2 * eps;
                    int above = 0, below = 0;   /* corners off the line */
                    double cx[4] = {x0, x1, x0, x1}, cy[4] = {y0, y0, y1, y1};
                    for (int q = 0; q < 4; q++) {
                        double d = (bx - ax) * (cy[q] - ay) - (by - ay) * (cx[q] - ax);
                        above += d > eps * len;
                        below += d < -eps * len;
                    }
                    if (above == 4 || below == 4)
                        continue;
                    if (index_add(ix, cj * sg->nnx + ci, k, j))
                        return -1;
                }
        }
    }
    C->near_cell = ix->head;
    return 0;
}
/// [index_update]

static void index_release(Cracks *C)
{
    SegmentIndex *ix = C->search_state;
    if (ix) {
        free(ix->head);
        free(ix->touched);
        free(ix->e);
        free(ix);
    }
    C->search_state = NULL;
    C->near_cell = NULL;
}

/// [index_visit]
static void index_visit(const Cracks *C, int cell, double px, double py,
                        double nx, double ny, Crossings *x)
{
    const SegmentIndex *ix = C->search_state;
    for (int e = ix->head[cell]; e >= 0; e = ix->e[e].next)
        crossings_test(C, ix->e[e].crack, ix->e[e].seg, px, py, nx, ny, x);
}

/** index_visit() of a point's @p n lines at once, entry after entry. */
static void index_visit_lines(const Cracks *C, int cell, double px, double py,
                              int n, const double *nx, const double *ny,
                              Crossings *x)
{
    const SegmentIndex *ix = C->search_state;
    for (int e = ix->head[cell]; e >= 0; e = ix->e[e].next)
        for (int a = 0; a < n; a++)
            crossings_test(C, ix->e[e].crack, ix->e[e].seg, px, py, nx[a], ny[a], &x[a]);
}

const CrossingSearch crossing_indexed = {
    "indexed", index_visit, index_update, index_release, index_visit_lines,
};
/// [index_visit]
