/**
 * @file stage8.h
 * @brief Stage 8: other shape functions than the paper's bilinear ones,
 *        chosen by run.shape, and the affine transfer run.transfer
 *        (chapter 8).
 */
#ifndef MPM_STAGE8_H
#define MPM_STAGE8_H

#include "hooks.h"

/** @brief Register run.shape = "gimp" and "cpdi" and their set-up, and
 *         run.transfer = "flip" | "apic". */
void stage8_install(Hooks *h);

#endif
