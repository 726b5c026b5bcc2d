/**
 * @file stage7.h
 * @brief Installer of stage 7: fracture parameters of CRAMP cracks (the
 *        J-integral, K_I and K_II at their tips).
 */
#ifndef MPM_STAGE7_H
#define MPM_STAGE7_H

#include "hooks.h"

/** @brief Register a crack's key `j_integral`; a scene that gives it
 *         subscribes the evaluation, its history columns and its report. */
void stage7_install(Hooks *h);

#endif
