/**
 * @file units.c
 * @brief The two unit systems: mm-g-ms (the default, the paper's) and SI.
 */
#include <string.h>

#include "units.h"

/// [unit_systems]
static const Units systems[] = {
    {"mm-g-ms", "mm", "ms", "MPa", "mJ", 1.0},   /* force N, velocity m/s */
    {"SI", "m", "s", "Pa", "J", 1.0e-3},
};
/// [unit_systems]

const Units *units_find(const char *name)
{
    for (size_t k = 0; k < sizeof systems / sizeof systems[0]; k++)
        if (strcmp(systems[k].name, name) == 0)
            return &systems[k];
    return NULL;
}

const Units *units_default(void)
{
    return &systems[0];
}
