/**
 * @file mirror.h
 * @brief A mirror (reflective symmetry) on a grid line for uGIMP and CPDI,
 *        boundaries.[k].mirror = true: the nodes one cell beyond the plane
 *        are ghosts of the nodes one cell inside (chapter 8, "The mirror").
 */
#ifndef MPM_MIRROR_H
#define MPM_MIRROR_H

#include <libconfig.h>

#include "hooks.h"

struct Sim;
struct SceneReader;

/** The name under which the mirror is attached to a simulation. */
#define MIRROR_STATE "mirror"

/** One mirror plane and the nodes it pairs. */
typedef struct Mirror {
    int bc;          /**< the boundary (Scene::bc) that carries it */
    int line;        /**< line of its `mirror` key, for messages */
    int axis;        /**< the normal: 0 x (a plane x = c), 1 y */
    int side;        /**< +1: the body on the side of larger coordinates */
    double at;       /**< the plane's coordinate */
    double lo;       /**< the segment of the plane it holds, along it */
    double hi;       /**< ... (the boundary's extent) */
    int n;           /**< node pairs */
    int *ghost;      /**< pair k: the node beyond the plane, or a node on it */
    int *node;       /**< its mirror inside (the node itself on the plane) */
    int *pair_of;    /**< per node: the pair whose ghost it is, or -1 */
    unsigned char *use; /**< per pair, this step: 1 when a point reaches
                             its ghost through the segment (folded) */
    unsigned key;    /**< the field key of a pair beyond the plane that
                          crosses it outside the segment */
    int folded;      /**< masses and momenta folded this step (Task 2) */
} Mirror;

/** @brief Read boundaries.[@p index].mirror (true or false); true
 *         subscribes the mirror's set-up. */
int mirror_read(struct Sim *sim, const config_setting_t *s, int index,
                struct SceneReader *r);

#endif
