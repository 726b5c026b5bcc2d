/**
 * @file stages.c
 * @brief The stages of this build, chosen at compile time by MPM_STAGE:
 *        the one file compiled with it (the Makefile passes -DMPM_STAGE=N
 *        to this file alone, with -Wundef).
 *
 * Stage N's folder provides stageN.h with stageN_install(); a build with
 * MPM_STAGE = N compiles the folders of stages 1..N only, so the lines for
 * later stages below are never compiled in an earlier stage's build.
 */
#include "stages.h"

#include "stage1.h"

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
#if MPM_STAGE >= 6
#include "stage6.h"
#endif
#if MPM_STAGE >= 7
#include "stage7.h"
#endif
#if MPM_STAGE >= 8
#include "stage8.h"
#endif

/// [install_stages]
void mpm_install_stages(Hooks *h)
{
    h->build_stage = MPM_STAGE;
    hooks_begin_stage(h, 1);
    stage1_install(h);
    hooks_begin_stage(h, 2);
#if MPM_STAGE >= 2
    stage2_install(h);
#else
    hooks_add_refusal(h, "cracks", NULL, "stage 2 (multi-field nodes and cracks)");
    hooks_add_refusal(h, "run.crack_search", NULL, "stage 2 (multi-field nodes and cracks)");
#endif
    hooks_begin_stage(h, 3);
#if MPM_STAGE >= 3
    stage3_install(h);
#else
    hooks_add_refusal(h, "cracks.arc", NULL, "stage 3 (line crossing)");
    hooks_add_refusal(h, "run.crack_search", "screened", "stage 3 (line crossing)");
    hooks_add_refusal(h, "run.crack_search", "indexed", "stage 3 (line crossing)");
#endif
    hooks_begin_stage(h, 4);
#if MPM_STAGE >= 4
    stage4_install(h);
#else
    hooks_add_refusal(h, "cracks.contact", NULL, "stage 4 (crack contact)");
    hooks_add_refusal(h, "contact", NULL, "stage 4 (contact between bodies)");
    hooks_add_refusal(h, "bodies.contact_group", NULL, "stage 4 (contact between bodies)");
#endif
    hooks_begin_stage(h, 5);
#if MPM_STAGE >= 5
    stage5_install(h);
#else
    hooks_add_refusal(h, "run.update", "usavg", "stage 5 (USAVG)");
#endif
    hooks_begin_stage(h, 6);
#if MPM_STAGE >= 6
    stage6_install(h);
#else
    hooks_add_refusal(h, "run.method", "xefg", "stage 6 (the XEFG meshfree method)");
    hooks_add_refusal(h, "cracks.cohesive", NULL, "stage 6 (cohesive XEFG cracks)");
#endif
    hooks_begin_stage(h, 7);
#if MPM_STAGE >= 7
    stage7_install(h);
#else
    hooks_add_refusal(h, "cracks.j_integral", NULL, "stage 7 (fracture parameters)");
    hooks_add_refusal(h, "cracks.growth", NULL, "stage 7 (crack growth)");
#endif
    hooks_begin_stage(h, 8);
#if MPM_STAGE >= 8
    stage8_install(h);
#else
    hooks_add_refusal(h, "run.shape", "gimp", "stage 8 (GIMP and CPDI shape functions)");
    hooks_add_refusal(h, "run.shape", "cpdi", "stage 8 (GIMP and CPDI shape functions)");
    hooks_add_refusal(h, "run.transfer", NULL, "stage 8 (the APIC transfer)");
    hooks_add_refusal(h, "boundaries.mirror", NULL, "stage 8 (a mirror for GIMP and CPDI)");
#endif
    hooks_begin_stage(h, 99);    /* a test's plug-in comes after every stage */
}
/// [install_stages]

int mpm_stage(void)
{
    return MPM_STAGE;
}
