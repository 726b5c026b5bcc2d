/**
 * @file stage1.h
 * @brief Installer of stage 1: conventional MPM.
 */
#ifndef MPM_STAGE1_H
#define MPM_STAGE1_H

#include "hooks.h"

/** @brief Register the MPM method, Hooke's law, USL, MUSL and USF;
 *         subscribe to no seam. */
void stage1_install(Hooks *h);

#endif
