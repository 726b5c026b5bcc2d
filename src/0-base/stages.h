/**
 * @file stages.h
 * @brief Which stages this build has: the only code that knows stage
 *        numbers (compiled with -DMPM_STAGE=N).
 */
#ifndef MPM_STAGES_H
#define MPM_STAGES_H

#include "hooks.h"

/** @brief Install the hooks of stages 1..N of this build and record the
 *         features of later stages as refused. */
void mpm_install_stages(Hooks *h);

/** @brief N, the last stage this build has. */
int mpm_stage(void);

#endif
