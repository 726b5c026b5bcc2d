/**
 * @file checkpoint.h
 * @brief Checkpoint and restart: the state a run needs to go on, written
 *        whole into OUTDIR/checkpoint.mpm, and read back so that a run of
 *        N steps restarted for N more writes the same bytes as one run of
 *        2N steps.
 *
 * The file is binary, for this machine and build only: a header (format
 * version, stage, sizes, the scene's fingerprint, its path and overrides),
 * the clock, the points' changing arrays, where the run loop stands, and
 * one section per SEAM_CHECKPOINT subscriber (the stages' state).
 */
#ifndef MPM_CHECKPOINT_H
#define MPM_CHECKPOINT_H

#include <libconfig.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "sim.h"

/** The checkpoint's file name in the output directory. */
#define CHECKPOINT_FILE "checkpoint.mpm"

/** The format's version; a file of another version is refused. */
#define CHECKPOINT_VERSION 1

/** What the run loop carries across a restart. */
typedef struct RunProgress {
    int nsnap;          /**< snapshots written */
    int asked;          /**< the next asked snapshot, k of k T / K */
    long snap_at;       /**< the step it is written at (-1: none left) */
    double *times;      /**< times of snapshots 0 .. nsnap - 1 */
    int cap;            /**< room in times */
    long history_bytes; /**< length of history.csv up to its last row */
} RunProgress;

/** The scene a checkpoint was written for. */
typedef struct CheckpointScene {
    char *path;         /**< the scene file, absolute */
    int noverrides;     /**< command-line overrides */
    char **overrides;   /**< "key.path=value" */
} CheckpointScene;

/** @brief A fingerprint of the scene's settings (overrides applied): a
 *         restart refuses a scene whose fingerprint changed. */
uint64_t checkpoint_fingerprint(const config_t *cfg);

/** @brief Save (@p save = 1) or restore @p bytes at @p p. @return 0, or -1
 *         when the write failed or the file ended. */
int checkpoint_io(FILE *f, void *p, size_t bytes, int save);

/** @brief Write @p dir/checkpoint.mpm, whole or not at all (an older one
 *         stays). @return 0, or -1 after a message naming the file. */
int checkpoint_write(Sim *sim, const RunProgress *rp, const char *dir);

/** @brief Read which scene @p dir's checkpoint belongs to (to load it
 *         before checkpoint_read()), refusing one that a build of another
 *         stage than @p stage wrote. @return 0, or -1 with a message. */
int checkpoint_scene(const char *dir, int stage, CheckpointScene *cs,
                     char *err, size_t errlen);

/** @brief Release what checkpoint_scene() allocated. */
void checkpoint_scene_free(CheckpointScene *cs);

/**
 * @brief Restore the state of @p dir's checkpoint into @p sim, loaded from
 *        the same scene; refused when the file is of another version or
 *        stage, another scene, or cut short.
 * @return 0, or -1 with a message naming the file in @p err.
 */
int checkpoint_read(Sim *sim, RunProgress *rp, const char *dir, char *err,
                    size_t errlen);

#endif
