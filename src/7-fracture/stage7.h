/**
 * @file stage7.h
 * @brief Installer of stage 7: fracture parameters of CRAMP cracks (the
 *        J-integral, K_I and K_II at their tips) and their growth.
 */
#ifndef MPM_STAGE7_H
#define MPM_STAGE7_H

#include "hooks.h"

/** @brief Register a crack's keys `j_integral` and `growth`; a scene that
 *         gives them subscribes the evaluation (and growth), their history
 *         columns and their report. */
void stage7_install(Hooks *h);

#endif
