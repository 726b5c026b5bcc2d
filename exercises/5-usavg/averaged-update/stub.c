/* Exercise 5.1: write USAVG from MUSL and USF (exercises/5-usavg/averaged-update/README.md). */
#include "usavg_scheme.h"

UpdateScheme usavg_scheme(void)
{
    /* TODO: the share of dt at Task 2, the share at Task 6, and whether
       Task 6 re-extrapolates the new velocities first (stage1.c registers
       USL, MUSL and USF the same way) */
    return (UpdateScheme){"usavg", 0.0, 0.0, 0};
}
