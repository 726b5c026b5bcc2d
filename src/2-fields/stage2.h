/**
 * @file stage2.h
 * @brief Installer of stage 2: multi-field nodes and explicit cracks.
 */
#ifndef MPM_STAGE2_H
#define MPM_STAGE2_H

#include "hooks.h"

/** @brief Register the "cracks" scene section; its parser installs the
 *         field and crack hooks when a scene has cracks. */
void stage2_install(Hooks *h);

#endif
