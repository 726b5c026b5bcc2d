/**
 * @file output.h
 * @brief Files a run writes: history.csv, ParaView snapshots (.vtu with a
 *        .pvd series), grid stresses as CSV, and the final points as CSV.
 */
#ifndef MPM_OUTPUT_H
#define MPM_OUTPUT_H

#include <stdio.h>

#include "sim.h"

/** @brief Significant digits of a number written to an output file: the
 *         writer's @p usual count, or 17 (every bit of a double) when the
 *         scene asks for run.precision = "full". */
static inline int output_digits(const Sim *sim, int usual)
{
    return sim->scene.run.full_precision ? 17 : usual;
}

/** @brief The first line of every CSV snapshot: "# t = T UNIT, step N"
 *         (a comment to gnuplot; the column names follow). */
void output_csv_time(const Sim *sim, FILE *f);

/** @brief Create @p dir and its parents if missing. @return 0, or -1
 *         after printing which directory and why. */
int output_make_dir(const char *dir);

/** @brief Write the header row of history.csv. */
void output_history_header(const Sim *sim, FILE *f);

/** @brief Append one row of history.csv for the current state.
 *  @return the totals it wrote (the run loop checks that they are finite). */
Totals output_history_row(Sim *sim, FILE *f);

/**
 * @brief Write snapshot @p index: particles_NNNNN.vtu, grid_NNNNN.csv, the
 *        stages' extras, and rewrite particles.pvd to list snapshots 0..index.
 * @param sim   the simulation
 * @param dir   output directory
 * @param index snapshot number, 0 for the initial state
 * @param times times of snapshots 0..index
 * Each file is written whole or not at all (outfile.h).
 * @return 0, or -1 when a file cannot be written (the message, naming the
 *         file and the reason, is printed).
 */
int output_snapshot(Sim *sim, const char *dir, int index, const double *times);

/**
 * @brief Write the ParaView series @p dir/@p name (a .pvd file) that lists
 *        the files STEM_00000.EXT .. STEM_NNNNN.EXT (NNNNN = @p index) of
 *        snapshots 0 .. index at their @p times; ParaView opens it as one
 *        data set in time. A writer of snapshot files rewrites it with
 *        each snapshot, so that it is complete after every one.
 * @return 0, or -1 after a message naming the file.
 */
int output_series(const Sim *sim, const char *dir, const char *name,
                  const char *stem, const char *ext, int index,
                  const double *times);

/** @brief Write all points as CSV to @p dir/@p name. @return 0, or -1
 *         after a message naming the file. */
int output_points_csv(const Sim *sim, const char *dir, const char *name);

/** @brief The points at the end of a run (or a stop): particles_final.csv,
 *         or particles_final.vtu with run.output = "binary". @return 0, or
 *         -1 after a message naming the file. */
int output_points_final(const Sim *sim, const char *dir);

/** @brief Extrapolate point stresses to the grid nodes (mass-weighted, as
 *         momenta are) and write x, y, mass, sigma to @p dir/@p name (CSV;
 *         with run.output = "binary" a .vtu of the nodes that carry mass).
 *         @return 0, or -1 after a message naming the file. */
int output_grid_csv(Sim *sim, const char *dir, const char *name);

#endif
