/**
 * @file stage8.c
 * @brief Stage 8 adds two rows to the table of shape functions: uGIMP
 *        (Bardenhagen & Kober 2004) and CPDI (Sadeghirad, Brannon &
 *        Burghardt 2011); and the affine transfer APIC (Jiang et al. 2015),
 *        run.transfer; and a mirror for their stencils, which reach
 *        beyond a symmetry plane (boundaries.[k].mirror).
 */
#include "stage8.h"

#include "apic.h"
#include "cpdi.h"
#include "gimp.h"
#include "mirror.h"
#include "shapes_check.h"

/// [stage8_install]
void stage8_install(Hooks *h)
{
    hooks_add_choice(h, "run.shape", "gimp", &shape_gimp);  /* Bardenhagen 2004 */
    hooks_add_choice(h, "run.shape", "cpdi", &shape_cpdi);  /* Sadeghirad 2011 */
    hooks_on_prepare(h, shapes_prepare, NULL);   /* their scenes only */
    apic_install(h);                             /* run.transfer, Jiang 2015 */
    hooks_add_key(h, "boundaries", "mirror", mirror_read, NULL);
    hooks_add_field_key(h, "mirror side", 1);    /* pairs past its segment */
}
/// [stage8_install]
