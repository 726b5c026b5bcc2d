/**
 * @file stage2.c
 * @brief Stage 2 adds the "cracks" section to the scene file.
 */
#include "stage2.h"

#include "cracks.h"

/// [stage2_install]
void stage2_install(Hooks *h)
{
    hooks_add_section(h, "cracks", cracks_read);
}
/// [stage2_install]
