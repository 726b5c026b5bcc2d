/**
 * @file stage1.h
 * @brief Installer of stage 1: conventional MPM.
 */
#ifndef MPM_STAGE1_H
#define MPM_STAGE1_H

#include "hooks.h"

/** @brief Register USL, MUSL and USF; leave every other hook empty. */
void stage1_install(Hooks *h);

#endif
