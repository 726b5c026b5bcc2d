/**
 * @file stage3.h
 * @brief Installer of stage 3: fast line crossing (extent screening and
 *        the segment index).
 */
#ifndef MPM_STAGE3_H
#define MPM_STAGE3_H

#include "hooks.h"

/** @brief Register the "screened" and "indexed" crossing searches; the
 *         latter, registered last, is what a scene gets by default. */
void stage3_install(Hooks *h);

#endif
