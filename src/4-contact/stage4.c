/**
 * @file stage4.c
 * @brief Stage 4 adds contact to cracks: a crack's "contact" settings.
 */
#include "stage4.h"

#include "crack_contact.h"

/// [stage4_install]
void stage4_install(Hooks *h)
{
    hooks_add_key(h, "cracks", "contact", crack_contact_read);
}
/// [stage4_install]
