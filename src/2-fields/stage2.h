/**
 * @file stage2.h
 * @brief Installer of stage 2: multi-field nodes and explicit cracks.
 */
#ifndef MPM_STAGE2_H
#define MPM_STAGE2_H

#include "hooks.h"

/** @brief Register the "cracks" section, run.crack_search, the crack
 *         side's part of the field key and the plain search; the section's
 *         parser subscribes to the seams when a scene has cracks. */
void stage2_install(Hooks *h);

#endif
