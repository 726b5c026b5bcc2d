/**
 * @file stage5.h
 * @brief Installer of stage 5: the USAVG stress update and the energy
 *        bookkeeping.
 */
#ifndef MPM_STAGE5_H
#define MPM_STAGE5_H

#include "hooks.h"

/** @brief Register the update scheme "usavg" (section 2.3) beside USL,
 *         MUSL and USF, and the energy balance of a run. */
void stage5_install(Hooks *h);

#endif
