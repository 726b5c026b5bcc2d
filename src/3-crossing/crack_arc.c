/**
 * @file crack_arc.c
 * @brief A crack given as a circular arc: the scene names its centre,
 *        radius and the angles it runs between, and stage 3 turns it into
 *        the polyline that every crossing search works on.
 */
#include <math.h>

#include "scene_read.h"
#include "searches.h"

/** Degrees to radians. */
static const double DEGREE = 3.14159265358979323846 / 180.0;

/** Most segments an arc may have (a crack of more is a scene error). */
#define ARC_MAX_SEGMENTS 10000000

const char *const crack_arc_keys[] = {"center", "radius", "angles", "segments",
                                      NULL};

/// [crack_read_arc]
int crack_read_arc(Sim *sim, const config_setting_t *s, int index,
                   SceneReader *r)
{
    Crack *c = &cracks_of(sim)->crack[index];
    const Scene *sc = &sim->scene;
    double centre[2], radius, angles[2], segments;
    if (config_setting_type(s) != CONFIG_TYPE_GROUP)
        return scene_error(r, s, "arc", "expected a group { center = [x, y]; "
                           "radius = r; angles = [from, to]; }");
    if (c->n)
        return scene_error(r, s, "arc", "a crack has points or an arc, not both");
    if (scene_check_keys(r, s, crack_arc_keys) || scene_pair(r, s, "center", 1, centre) < 0 ||
        scene_number(r, s, "radius", 1, 0.0, &radius) < 0 ||
        scene_pair(r, s, "angles", 1, angles) < 0)
        return -1;
    if (!(radius > 0))
        return scene_error(r, config_setting_get_member(s, "radius"), "radius",
                           "%g must be positive", radius);
    double sweep = (angles[1] - angles[0]) * DEGREE;
    if (!(fabs(sweep) > 0 && fabs(sweep) < 360.0 * DEGREE))
        return scene_error(r, config_setting_get_member(s, "angles"), "angles",
                           "the arc from %g to %g degrees must turn by more "
                           "than 0 and less than 360 degrees", angles[0], angles[1]);
    /* by default a segment is about half the smaller cell side long */
    double h = 0.5 * fmin(sc->dx, sc->dy);
    int n = scene_number(r, s, "segments", 0, ceil(fabs(sweep) * radius / h),
                         &segments);
    if (n < 0)
        return -1;
    if (!(segments >= 1 && segments <= ARC_MAX_SEGMENTS &&
          segments == floor(segments)))
        return scene_error(r, n ? config_setting_get_member(s, "segments") : s,
                           "segments", "%g must be a whole number from 1 to %d",
                           segments, ARC_MAX_SEGMENTS);
    if (crack_alloc_points(c, (int)segments + 1))
        return scene_error(r, s, "arc", "out of memory");
    for (int k = 0; k < c->n; k++) {
        double a = angles[0] * DEGREE + sweep * k / segments;
        c->x[k] = centre[0] + radius * cos(a);
        c->y[k] = centre[1] + radius * sin(a);
    }
    return crack_check_points(r, s, "arc", sc, c);
}
/// [crack_read_arc]
