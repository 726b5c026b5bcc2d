/**
 * @file vtu_binary.c
 * @brief Vertices and their data as a .vtu with raw appended arrays.
 */
#include "vtu_binary.h"

#include <stdint.h>
#include <string.h>

/** Values per chunk written at once: no allocation, whatever n. */
#define CHUNK 1024

/** Whether this machine stores the low byte first. */
static int little_endian(void)
{
    const uint16_t one = 1;
    unsigned char c;
    memcpy(&c, &one, 1);
    return c == 1;
}

/** An array's bytes in the appended block, its count excluded. */
static uint64_t bytes_of(const VtuArray *a, int n)
{
    return (uint64_t)n * (uint64_t)a->ncomp *
           (a->x ? sizeof(double) : sizeof(int32_t));
}

/** The count that heads each block. @return 0 or -1. */
static int put_count(FILE *f, uint64_t bytes)
{
    return fwrite(&bytes, sizeof bytes, 1, f) == 1 ? 0 : -1;
}

/** Doubles (x, y, 0) per point, or x alone, in chunks. */
static int put_doubles(FILE *f, const double *x, const double *y, int ncomp,
                       int n)
{
    double buf[3 * CHUNK];
    for (int p0 = 0; p0 < n; p0 += CHUNK) {
        int m = n - p0 < CHUNK ? n - p0 : CHUNK;
        for (int k = 0; k < m; k++) {
            if (ncomp == 3) {
                buf[3 * k] = x[p0 + k];
                buf[3 * k + 1] = y[p0 + k];
                buf[3 * k + 2] = 0.0;
            } else {
                buf[k] = x[p0 + k];
            }
        }
        size_t cnt = (size_t)m * (size_t)ncomp;
        if (fwrite(buf, sizeof(double), cnt, f) != cnt)
            return -1;
    }
    return 0;
}

/** Int32 values: @p v, or (v == NULL) first, first + step, ... */
static int put_ints(FILE *f, const int *v, int32_t first, int32_t step, int n)
{
    int32_t buf[CHUNK];
    for (int p0 = 0; p0 < n; p0 += CHUNK) {
        int m = n - p0 < CHUNK ? n - p0 : CHUNK;
        for (int k = 0; k < m; k++)
            buf[k] = v ? (int32_t)v[p0 + k] : first + step * (int32_t)(p0 + k);
        if (fwrite(buf, sizeof(int32_t), (size_t)m, f) != (size_t)m)
            return -1;
    }
    return 0;
}

/// [vtu_binary_write]
int vtu_binary_write(FILE *f, double t, long step, int n, const double *px,
                     const double *py, const VtuArray *arr, int narr,
                     const char *scalars, const char *vectors)
{
    const uint64_t head = sizeof(uint64_t);
    uint64_t off = 0, nn = (uint64_t)n;
    /* the points, then connectivity, offsets and types of n vertices */
    uint64_t o_pts = off;
    off += head + 3 * nn * sizeof(double);
    uint64_t o_conn = off;
    off += head + nn * sizeof(int32_t);
    uint64_t o_offs = off;
    off += head + nn * sizeof(int32_t);
    uint64_t o_types = off;
    off += head + nn;
    fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
               "version=\"1.0\" byte_order=\"%s\" header_type=\"UInt64\">\n"
               "<UnstructuredGrid>\n<FieldData>\n<DataArray type=\"Float64\" "
               "Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">%.17g"
               "</DataArray>\n<DataArray type=\"Int64\" Name=\"step\" "
               "NumberOfTuples=\"1\" format=\"ascii\">%ld</DataArray>\n"
               "</FieldData>\n<Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">\n"
               "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" "
               "format=\"appended\" offset=\"%llu\"/>\n</Points>\n<Cells>\n"
               "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"appended\" "
               "offset=\"%llu\"/>\n<DataArray type=\"Int32\" Name=\"offsets\" "
               "format=\"appended\" offset=\"%llu\"/>\n<DataArray type=\"UInt8\" "
               "Name=\"types\" format=\"appended\" offset=\"%llu\"/>\n</Cells>\n"
               "<PointData",
            little_endian() ? "LittleEndian" : "BigEndian", t, step, n, n,
            (unsigned long long)o_pts, (unsigned long long)o_conn,
            (unsigned long long)o_offs, (unsigned long long)o_types);
    if (scalars)
        fprintf(f, " Scalars=\"%s\"", scalars);
    if (vectors)
        fprintf(f, " Vectors=\"%s\"", vectors);
    fprintf(f, ">\n");
    for (int k = 0; k < narr; k++) {
        fprintf(f, "<DataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%d\" "
                   "format=\"appended\" offset=\"%llu\"/>\n",
                arr[k].x ? "Float64" : "Int32", arr[k].name, arr[k].ncomp,
                (unsigned long long)off);
        off += head + bytes_of(&arr[k], n);
    }
    fprintf(f, "</PointData>\n</Piece>\n</UnstructuredGrid>\n"
               "<AppendedData encoding=\"raw\">\n_");
    int bad = put_count(f, 3 * nn * sizeof(double)) ||
              put_doubles(f, px, py, 3, n) ||
              put_count(f, nn * sizeof(int32_t)) || put_ints(f, NULL, 0, 1, n) ||
              put_count(f, nn * sizeof(int32_t)) || put_ints(f, NULL, 1, 1, n) ||
              put_count(f, nn);
    unsigned char vertex[CHUNK];                  /* VTK_VERTEX = 1 */
    memset(vertex, 1, sizeof vertex);
    for (int p0 = 0; !bad && p0 < n; p0 += CHUNK) {
        size_t m = (size_t)(n - p0 < CHUNK ? n - p0 : CHUNK);
        bad = fwrite(vertex, 1, m, f) != m;
    }
    for (int k = 0; k < narr && !bad; k++)
        bad = put_count(f, bytes_of(&arr[k], n)) ||
              (arr[k].x ? put_doubles(f, arr[k].x, arr[k].y, arr[k].ncomp, n)
                        : put_ints(f, arr[k].i, 0, 0, n));
    if (!bad)
        bad = fprintf(f, "\n</AppendedData>\n</VTKFile>\n") < 0;
    return bad ? -1 : 0;
}
/// [vtu_binary_write]
