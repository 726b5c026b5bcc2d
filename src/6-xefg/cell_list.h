/**
 * @file cell_list.h
 * @brief Neighbour search by a cell list: the nodes whose support holds a
 *        point, in about constant time per query, not all pairs.
 */
#ifndef MPM_CELL_LIST_H
#define MPM_CELL_LIST_H

/** Nodes binned on square cells of side Cell::size. */
typedef struct CellList {
    double ox;      /**< lower-left corner x of cell (0, 0) */
    double oy;      /**< lower-left corner y */
    double size;    /**< cell side: at least the largest support radius */
    int nx;         /**< cells along x */
    int ny;         /**< cells along y */
    int *start;     /**< nodes of cell c: item[start[c] .. start[c + 1]) */
    int *item;      /**< node indices, grouped by cell, increasing in each */
} CellList;

/**
 * @brief Bin @p n nodes (X, Y) on cells of side @p size (the largest
 *        support radius). @return 0, or -1 when memory is exhausted or
 *        the nodes span more cells than an int counts.
 */
int cell_list_build(CellList *c, int n, const double *X, const double *Y,
                    double size);

/**
 * @brief The nodes k whose support holds (x, y): |(x, y) - (X_k, Y_k)| < d_k
 *        (d_k at most the cell size), in increasing order, into @p out.
 * @return how many; when more than @p cap, their number (only @p cap
 *         written), so that a caller can grow @p out and ask again.
 */
int cell_list_find(const CellList *c, const double *X, const double *Y,
                   const double *d, double x, double y, int *out, int cap);

/** @brief Release the cell list. */
void cell_list_free(CellList *c);

#endif
