/**
 * @file transfer.h
 * @brief The seam of the transfer between points and grid: what a point
 *        gives its nodes beyond m_p S_ip v_p (Tasks 1 and 6) and what it
 *        takes back at Task 5 beyond eq. 30. Chapter 1 has none; chapter
 *        8 adds APIC (run.transfer).
 */
#ifndef MPM_TRANSFER_H
#define MPM_TRANSFER_H

struct Sim;
struct Stencil;
struct Grid;
struct Owned;

/// [transfer]
/** A row of the table of run.transfer. Its functions run in the loops
 *  through a stencil function (RunSettings::stencil), after the paper's
 *  work for the same point and stencil. */
typedef struct Transfer {
    const char *name;   /**< the value of run.transfer */
    /** Tasks 1 and 6: add point @p p's further momentum to the nodes of
     *  its stencil @p st (masses and eq. 26's share are in already), to
     *  those of @p own only (a thread's strip; NULL: all, strip_scatter.h). */
    void (*scatter)(const struct Sim *sim, int p, const struct Stencil *st,
                    struct Grid *g, const struct Owned *own);
    /** Task 5, after eq. 30 moved point @p p: set what the point keeps. */
    void (*gather)(struct Sim *sim, int p, const struct Stencil *st);
} Transfer;
/// [transfer]

#endif
