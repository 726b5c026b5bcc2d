/**
 * @file stage2.c
 * @brief Stage 2 adds the "cracks" section, the crack side as a part of
 *        the field key, and the plain crossing search.
 */
#include "stage2.h"

#include "cracks.h"

/// [stage2_install]
void stage2_install(Hooks *h)
{
    hooks_add_key(h, "", "cracks", cracks_read, crack_keys);
    hooks_add_key(h, "run", "crack_search", cracks_read_search, NULL);
    hooks_add_field_key(h, "crack side", 2);      /* fields 1 and 2 */
    hooks_add_choice(h, "run.crack_search", "plain", &crossing_plain);
    hooks_add_outputs(h, "a scene with cracks adds cracks_NNNNN.vtp with cracks.pvd (the crack\n"
                         "lines in ParaView) and cracks_NNNNN.csv (their points)");
}
/// [stage2_install]
