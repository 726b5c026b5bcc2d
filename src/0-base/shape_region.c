/**
 * @file shape_region.c
 * @brief Point-in-region tests for the shapes of a scene.
 */
#include <stdlib.h>

#include "scene.h"

int shape_contains(const Shape *s, double x, double y)
{
    if (x < s->xmin || x > s->xmax || y < s->ymin || y > s->ymax)
        return 0;
    if (s->kind == SHAPE_RECTANGLE)
        return 1;
    if (s->kind == SHAPE_DISK) {
        double r2 = (x - s->cx) * (x - s->cx) + (y - s->cy) * (y - s->cy);
        return r2 <= s->r * s->r && r2 >= s->rin * s->rin;
    }
    /* polygon: count crossings of the ray from (x, y) towards +x */
    int inside = 0;
    for (int i = 0, j = s->nv - 1; i < s->nv; j = i++) {
        double xi = s->v[2 * i], yi = s->v[2 * i + 1];
        double xj = s->v[2 * j], yj = s->v[2 * j + 1];
        if ((yi > y) != (yj > y) && x < xj + (y - yj) * (xi - xj) / (yi - yj))
            inside = !inside;
    }
    return inside;
}

void scene_free(Scene *sc)
{
    for (int k = 0; k < sc->nbodies; k++)
        free(sc->bodies[k].shape.v);
    for (int k = 0; k < sc->nbc; k++) {
        free(sc->bc[k].region.v);
        free(sc->bc[k].hold.table);
    }
    for (int k = 0; k < sc->nloads; k++) {
        free(sc->loads[k].region.v);
        free(sc->loads[k].points);
    }
    for (int k = 0; k < sc->nheld; k++) {
        free(sc->held[k].region.v);
        free(sc->held[k].points);
        free(sc->held[k].hold.table);
    }
    free(sc->held);
    sc->held = NULL;
    sc->nheld = 0;
    free(sc->mat);
    free(sc->bodies);
    free(sc->bc);
    free(sc->loads);
    sc->mat = NULL;
    sc->bodies = NULL;
    sc->bc = NULL;
    sc->loads = NULL;
    sc->nmat = sc->nbodies = sc->nbc = sc->nloads = 0;
    scene_lines_free(sc->lines);
    sc->lines = NULL;
}
