/**
 * @file footprint.c
 * @brief The memory a scene will take, estimated before it is set up, so
 *        that a scene too large is refused at once rather than after
 *        allocating until memory runs out.
 */
#include "footprint.h"

#include "scene_include.h"

#include <math.h>
#include <stdio.h>
#include <unistd.h>

/** Points fill_body() visits in body @p B's bounding box: k x k per cell. */
static double box_points(const Scene *sc, const Body *B)
{
    double nx = ceil((B->shape.xmax - sc->ox) / sc->dx) -
                floor((B->shape.xmin - sc->ox) / sc->dx);
    double ny = ceil((B->shape.ymax - sc->oy) / sc->dy) -
                floor((B->shape.ymin - sc->oy) / sc->dy);
    return fmax(nx, 0.0) * fmax(ny, 0.0) * B->ppc * B->ppc;
}

/** An area at least that of @p s (a polygon's fan of triangles covers
 *  whatever its crossings enclose) and the length of its edges. */
static void shape_measure(const Shape *s, double *area, double *edge)
{
    const double pi = 3.14159265358979323846;
    double w = s->xmax - s->xmin, h = s->ymax - s->ymin;
    *area = w * h;
    *edge = 2.0 * (w + h);
    if (s->kind == SHAPE_DISK) {
        *area = pi * (s->r * s->r - s->rin * s->rin);
        *edge = 2.0 * pi * (s->r + s->rin);
    } else if (s->kind == SHAPE_POLYGON) {
        const double *v = s->v;
        *area = *edge = 0.0;
        for (int i = 0; i < s->nv; i++) {
            int j = (i + 1) % s->nv;
            *edge += hypot(v[2 * j] - v[2 * i], v[2 * j + 1] - v[2 * i + 1]);
            if (i > 0 && j > 0)
                *area += 0.5 * fabs((v[2 * i] - v[0]) * (v[2 * j + 1] - v[1]) -
                                    (v[2 * j] - v[0]) * (v[2 * i + 1] - v[1]));
        }
    }
}

/** Points of body @p B: one per point area inside, plus one for each
 *  point cell its edge crosses, at most the bounding box's count. */
static double body_points(const Scene *sc, const Body *B)
{
    double hx = sc->dx / B->ppc, hy = sc->dy / B->ppc, area, edge;
    shape_measure(&B->shape, &area, &edge);
    double n = area / (hx * hy) + edge * (1.0 / hx + 1.0 / hy) +
               2.0 * B->shape.nv + 16.0;
    return fmin(n, box_points(sc, B));
}

Footprint footprint_estimate(const Scene *sc)
{
    Footprint f = {0.0, 0.0, 0.0, -1};
    double most = -1.0;
    for (int b = 0; b < sc->nbodies; b++) {
        double n = body_points(sc, &sc->bodies[b]);
        f.points += n;
        if (n > most) {
            most = n;
            f.body = b;
        }
    }
    f.nodes = (sc->ncx + 1.0) * (sc->ncy + 1.0);
    f.bytes = f.points * FOOTPRINT_POINT_BYTES + f.nodes * FOOTPRINT_NODE_BYTES;
    return f;
}

double footprint_available(void)
{
    FILE *f = fopen("/proc/meminfo", "r");
    char line[256];
    double kb = -1.0;
    while (f && fgets(line, sizeof line, f))
        if (sscanf(line, "MemAvailable: %lf kB", &kb) == 1)
            break;
    if (f)
        fclose(f);
    if (kb >= 0.0)
        return 1024.0 * kb;
    long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
    return pages > 0 && size > 0 ? (double)pages * (double)size : INFINITY;
}

/** @p bytes as "61 GB", "3.2 TB", "640 kB" into @p buf. */
static const char *human_bytes(double bytes, char *buf, size_t len)
{
    static const char *const unit[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
    int u = 0;
    while (bytes >= 1000.0 && u < 6) {
        bytes /= 1000.0;
        u++;
    }
    snprintf(buf, len, bytes < 10.0 && u > 0 ? "%.1f %s" : "%.0f %s", bytes, unit[u]);
    return buf;
}

int footprint_check(const Scene *sc, size_t limit, int grid_line, char *err,
                    size_t errlen)
{
    Footprint f = footprint_estimate(sc);
    double cap = limit ? (double)limit : footprint_available();
    if (f.bytes <= cap)
        return 0;
    int by_points = f.points * FOOTPRINT_POINT_BYTES >= f.nodes * FOOTPRINT_NODE_BYTES;
    int line = by_points && f.body >= 0 ? sc->bodies[f.body].line : grid_line;
    char where[SCENE_AT_LEN], need[32], have[32];
    if (line > 0)
        scene_lines_at(sc->lines, sc->file, line, where, sizeof where);
    else
        snprintf(where, sizeof where, "%s", sc->file);
    snprintf(err, errlen, "%s: needs about %s (%.1e points, %.1e nodes), more "
             "than the %s %s (--max-memory to change)", where,
             human_bytes(f.bytes, need, sizeof need), f.points, f.nodes,
             human_bytes(cap, have, sizeof have), limit ? "allowed" : "available");
    return -1;
}
