/**
 * @file stages.c
 * @brief The stages of this build, chosen at compile time by MPM_STAGE.
 */
#include "stages.h"

#include "stage1.h"

#ifndef MPM_STAGE
#define MPM_STAGE 1
#endif

/// [install_stages]
void mpm_install_stages(Hooks *h)
{
    stage1_install(h);
#if MPM_STAGE < 2
    hooks_add_refusal(h, "cracks", NULL, "stage 2 (multi-field nodes and cracks)");
#endif
#if MPM_STAGE < 4
    hooks_add_refusal(h, "contact", NULL, "stage 4 (crack contact)");
#endif
#if MPM_STAGE < 5
    hooks_add_refusal(h, "run.update", "usavg", "stage 5 (USAVG)");
#endif
}
/// [install_stages]

int mpm_stage(void)
{
    return MPM_STAGE;
}
