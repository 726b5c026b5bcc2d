/**
 * @file outfile.h
 * @brief An output file that is whole on disk or absent: written under a
 *        temporary name ("NAME.part") and renamed when every write
 *        succeeded; a failure names the file and the system's reason.
 */
#ifndef MPM_OUTFILE_H
#define MPM_OUTFILE_H

#include <stdio.h>

/** One output file being written. */
typedef struct OutFile {
    FILE *f;      /**< write here (the temporary file) */
    char *path;   /**< the name it gets when whole */
    char *part;   /**< the temporary name: path + ".part" */
} OutFile;

/**
 * @brief "DIR/NAME" in a new string (NAME formatted like printf), sized to
 *        fit: no path is ever cut. @return it (free() it), or NULL.
 */
char *outfile_path(const char *dir, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/**
 * @brief Open DIR/NAME.part for writing (NAME formatted like printf).
 * @return 0, or -1 after printing "mpm: cannot write PATH: REASON".
 */
int outfile_open(OutFile *o, const char *dir, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/**
 * @brief Flush and close the file, check that no write failed, and rename
 *        it to its name; on failure remove the temporary file (an older
 *        file of that name stays as it was).
 * @return 0, or -1 after printing "mpm: cannot write PATH: REASON".
 */
int outfile_commit(OutFile *o);

/** @brief Close and remove the temporary file without a message (another
 *         error has been reported). */
void outfile_abandon(OutFile *o);

/** @brief Print "mpm: cannot write PATH: REASON" for errno value @p err. */
void outfile_report(const char *path, int err);

#endif
