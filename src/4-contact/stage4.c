/**
 * @file stage4.c
 * @brief Stage 4 adds contact: a crack's "contact" settings, and contact
 *        between bodies (the "contact" section, a body's contact group,
 *        and the group as a part of the field key).
 */
#include "stage4.h"

#include "crack_contact.h"
#include "material_contact.h"

/// [stage4_install]
void stage4_install(Hooks *h)
{
    hooks_add_key(h, "cracks", "contact", crack_contact_read, crack_contact_keys);
    hooks_add_key(h, "bodies", "contact_group", material_group_read, NULL);
    hooks_add_key(h, "", "contact", material_contact_read, material_contact_keys);
    hooks_add_field_key(h, "contact group", 5);   /* groups 0 .. 31 */
}
/// [stage4_install]
