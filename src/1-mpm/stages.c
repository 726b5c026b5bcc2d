/**
 * @file stages.c
 * @brief The stages of this build, chosen at compile time by MPM_STAGE.
 *
 * Stage N's folder provides stageN.h with stageN_install(); a build with
 * MPM_STAGE = N compiles the folders of stages 1..N only, so the lines for
 * later stages below are never compiled in an earlier stage's build.
 */
#include "stages.h"

#include "stage1.h"

#ifndef MPM_STAGE
/** Last stage of this build; the Makefile passes -DMPM_STAGE=N. */
#define MPM_STAGE 1
#endif
#if MPM_STAGE >= 2
#include "stage2.h"
#endif
#if MPM_STAGE >= 3
#include "stage3.h"
#endif
#if MPM_STAGE >= 4
#include "stage4.h"
#endif
#if MPM_STAGE >= 5
#include "stage5.h"
#endif

/// [install_stages]
void mpm_install_stages(Hooks *h)
{
    stage1_install(h);
#if MPM_STAGE >= 2
    stage2_install(h);
#else
    hooks_add_refusal(h, "cracks", NULL, "stage 2 (multi-field nodes and cracks)");
#endif
#if MPM_STAGE >= 3
    stage3_install(h);
#endif
#if MPM_STAGE >= 4
    stage4_install(h);
#else
    hooks_add_refusal(h, "contact", NULL, "stage 4 (crack contact)");
#endif
#if MPM_STAGE >= 5
    stage5_install(h);
#else
    hooks_add_refusal(h, "run.update", "usavg", "stage 5 (USAVG)");
#endif
}
/// [install_stages]

int mpm_stage(void)
{
    return MPM_STAGE;
}
