/**
 * @file usavg_scheme.c
 * @brief The USAVG row of the update-scheme table (section 2.3): an
 *        exercise (exercises/5-usavg/averaged-update).
 */
#include "usavg_scheme.h"

/// [usavg_scheme]
UpdateScheme usavg_scheme(void)
{
    /* half of dt at Task 2 from the start-of-step momenta (USF's), half at
       Task 6 from the re-extrapolated new velocities (MUSL's), eq. 31 */
    return (UpdateScheme){"usavg", 0.5, 0.5, 1};
}
/// [usavg_scheme]
