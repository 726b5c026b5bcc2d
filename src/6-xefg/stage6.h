/**
 * @file stage6.h
 * @brief Stage 6: the meshfree method of the second paper (Rabczuk and Zi,
 *        XEFG), a row of the method table beside MPM.
 */
#ifndef MPM_STAGE6_H
#define MPM_STAGE6_H

#include "hooks.h"

/** @brief Register the method "xefg", its scene section and its set-up. */
void stage6_install(Hooks *h);

#endif
