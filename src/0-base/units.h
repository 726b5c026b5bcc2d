/**
 * @file units.h
 * @brief The unit systems a scene may be written in. The method has no
 *        units of its own; a system only names the units in messages and
 *        sets the defaults that carry one (a body's thickness).
 */
#ifndef MPM_UNITS_H
#define MPM_UNITS_H

/** A consistent system of units (force = mass x length / time^2). */
typedef struct Units {
    const char *name;    /**< value of run.units */
    const char *length;  /**< "mm", "m" */
    const char *time;    /**< "ms", "s" */
    const char *stress;  /**< "MPa", "Pa" */
    const char *energy;  /**< "mJ", "J" */
    double mm;           /**< one millimetre in this length unit */
} Units;

/** @brief The system named @p name ("mm-g-ms" or "SI"), or NULL. */
const Units *units_find(const char *name);

/** @brief The default system, mm-g-ms (force N, stress MPa, energy mJ). */
const Units *units_default(void);

#endif
