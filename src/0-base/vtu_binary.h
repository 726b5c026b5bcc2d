/**
 * @file vtu_binary.h
 * @brief VTK XML unstructured grids (.vtu) of vertices with their data in
 *        binary: the "appended" raw encoding that ParaView and VTK read
 *        (VTK's file formats, XML, format="appended", encoding="raw",
 *        header_type="UInt64": each array a 64-bit byte count followed by
 *        its bytes, at the offset its DataArray names). Every double is
 *        written whole, so the file holds the run's numbers to the last bit.
 */
#ifndef MPM_VTU_BINARY_H
#define MPM_VTU_BINARY_H

#include <stdio.h>

/** One array of point data: doubles (one or three components: (x, y, 0))
 *  or ints. */
typedef struct VtuArray {
    const char *name;    /**< its Name in the file */
    int ncomp;           /**< 1, or 3 for a vector (x, y, 0) */
    const double *x;     /**< the values, or the vector's x (NULL: ints) */
    const double *y;     /**< the vector's y (ncomp 3) */
    const int *i;        /**< the values as Int32, when x is NULL */
} VtuArray;

/**
 * @brief Write @p n vertices at (@p px, @p py, 0) with the arrays @p arr
 *        as point data, time @p t and @p step as field data, into @p f.
 * @param f        the open file (binary: no text translation)
 * @param t        the time, field data TimeValue
 * @param step     the step, field data step
 * @param n        vertices
 * @param px       their x
 * @param py       their y
 * @param arr      the point data
 * @param narr     arrays in @p arr
 * @param scalars  the PointData's active scalars (a name in arr), or NULL
 * @param vectors  its active vectors, or NULL
 * @return 0, or -1 when a write failed (the caller's OutFile then
 *         abandons the file).
 */
int vtu_binary_write(FILE *f, double t, long step, int n, const double *px,
                     const double *py, const VtuArray *arr, int narr,
                     const char *scalars, const char *vectors);

#endif
