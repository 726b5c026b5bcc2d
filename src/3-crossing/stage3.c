/**
 * @file stage3.c
 * @brief Stage 3 adds two rows to the crossing-search table and cracks
 *        given as arcs.
 */
#include "stage3.h"

#include "searches.h"

/// [stage3_install]
void stage3_install(Hooks *h)
{
    hooks_add_choice(h, "run.crack_search", "screened", &crossing_screened);
    hooks_add_choice(h, "run.crack_search", "indexed", &crossing_indexed);
    hooks_add_key(h, "cracks", "arc", crack_read_arc, crack_arc_keys);
}
/// [stage3_install]
