/**
 * @file stage6.c
 * @brief Stage 6 registers the XEFG method (run.method = "xefg").
 */
#include "stage6.h"

/// [stage6_install]
void stage6_install(Hooks *h)
{
    (void)h;
}
/// [stage6_install]
