/**
 * @file checkpoint.c
 * @brief Writing and reading checkpoint.mpm (see checkpoint.h).
 */
#include "checkpoint.h"

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "outfile.h"

static const char MAGIC[16] = "MPM checkpoint\n";

/** The sizes and a known double, to refuse a file from another machine. */
typedef struct Layout {
    uint32_t version, size_long, size_int, size_double;
    double probe;
    int32_t stage;
} Layout;

/** The layout this program writes and reads: build of stage @p stage. */
static Layout this_layout(int stage)
{
    Layout l;
    memset(&l, 0, sizeof l);
    l.version = CHECKPOINT_VERSION;
    l.size_long = sizeof(long);
    l.size_int = sizeof(int);
    l.size_double = sizeof(double);
    l.probe = 1.0 / 3.0;
    l.stage = stage;
    return l;
}

int checkpoint_io(FILE *f, void *p, size_t bytes, int save)
{
    if (bytes == 0)
        return 0;
    if (save)
        return fwrite(p, 1, bytes, f) == bytes ? 0 : -1;
    return fread(p, 1, bytes, f) == bytes ? 0 : -1;
}

/** A string as its length and bytes; restored into a new allocation. */
static int io_string(FILE *f, char **s, int save)
{
    uint32_t n = save ? (uint32_t)strlen(*s) : 0;
    if (checkpoint_io(f, &n, sizeof n, save))
        return -1;
    if (!save) {
        if (n > (1u << 20) || !(*s = malloc((size_t)n + 1)))
            return -1;
        (*s)[n] = '\0';
    }
    return checkpoint_io(f, *s, n, save);
}

/** The header: magic, layout, the scene's fingerprint, path, overrides. */
static int io_header(FILE *f, Layout *l, uint64_t *hash, CheckpointScene *cs,
                     int stage, int save)
{
    char magic[16];
    memcpy(magic, MAGIC, sizeof magic);
    if (checkpoint_io(f, magic, sizeof magic, save) || memcmp(magic, MAGIC, sizeof magic))
        return -2;
    if (checkpoint_io(f, l, sizeof *l, save) || checkpoint_io(f, hash, sizeof *hash, save))
        return -1;
    Layout want = this_layout(stage);
    if (!save && memcmp(l, &want, sizeof want))
        return -3;
    int32_t n = cs->noverrides;
    if (io_string(f, &cs->path, save) || checkpoint_io(f, &n, sizeof n, save))
        return -1;
    if (!save) {
        if (n < 0 || n > 10000 || !(cs->overrides = calloc((size_t)n + 1, sizeof(char *))))
            return -1;
        cs->noverrides = n;
    }
    for (int k = 0; k < n; k++)
        if (io_string(f, &cs->overrides[k], save))
            return -1;
    return 0;
}

/** The points' arrays that change from step to step. */
static int io_points(FILE *f, Particles *P, int save)
{
    double *a[] = {P->x, P->y, P->vx, P->vy, P->sxx, P->syy, P->sxy,
                   P->exx, P->eyy, P->exy};
    for (size_t k = 0; k < sizeof a / sizeof a[0]; k++)
        if (checkpoint_io(f, a[k], (size_t)P->n * sizeof(double), save))
            return -1;
    return 0;
}

/** The clock, the points, the run loop and the stages' sections. */
static int io_body(FILE *f, Sim *sim, RunProgress *rp, int save)
{
    long nsteps = sim->nsteps;
    double dt = sim->dt;
    int n = sim->pts.n;
    if (checkpoint_io(f, &sim->step, sizeof sim->step, save) ||
        checkpoint_io(f, &sim->t, sizeof sim->t, save) ||
        checkpoint_io(f, &nsteps, sizeof nsteps, save) ||
        checkpoint_io(f, &dt, sizeof dt, save) ||
        checkpoint_io(f, &n, sizeof n, save))
        return -1;
    if (n != sim->pts.n || sim->step < 0 || sim->step > nsteps)
        return -4;
    if (io_points(f, &sim->pts, save) ||
        checkpoint_io(f, &rp->nsnap, sizeof rp->nsnap, save) ||
        checkpoint_io(f, &rp->asked, sizeof rp->asked, save) ||
        checkpoint_io(f, &rp->snap_at, sizeof rp->snap_at, save) ||
        checkpoint_io(f, &rp->history_bytes, sizeof rp->history_bytes, save))
        return -1;
    if (rp->nsnap < 0 || rp->nsnap > rp->cap)
        return -4;
    if (checkpoint_io(f, rp->times, (size_t)rp->nsnap * sizeof(double), save))
        return -1;
    const SeamList *l = &sim->hooks.seam[SEAM_CHECKPOINT];
    int count = l->n;
    if (checkpoint_io(f, &count, sizeof count, save))
        return -1;
    if (count != l->n)
        return -4;
    for (int k = 0; k < l->n; k++)
        if (l->at[k].fn.checkpoint(sim, l->at[k].state, f, save))
            return -1;
    char end[4] = "end";
    if (checkpoint_io(f, end, sizeof end, save) || memcmp(end, "end", 4))
        return -1;
    /* the step and its count are compared after the sections: a section
     * may rebuild what set them (an XEFG crack's growth, replayed, lowers
     * the step as the run did; chapter 6b) */
    if (nsteps != sim->nsteps || memcmp(&dt, &sim->dt, sizeof dt))
        return -4;
    return 0;
}

uint64_t checkpoint_fingerprint(const config_t *cfg)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    if (!f)
        return 0;
    config_write(cfg, f);
    fclose(f);
    uint64_t h = 14695981039346656037ull;          /* FNV-1a, 64 bits */
    for (size_t k = 0; k < len; k++)
        h = (h ^ (unsigned char)text[k]) * 1099511628211ull;
    free(text);
    return h;
}

/** @p path as an absolute path in a new string (NULL: no memory, or no
 *  current directory). */
static char *absolute_path(const char *path)
{
    if (path[0] == '/')
        return NULL;                    /* already absolute: used as it is */
    for (size_t size = 256; size < (1u << 20); size *= 2) {
        char *cwd = malloc(size);
        if (!cwd)
            return NULL;
        if (getcwd(cwd, size)) {
            char *abs = outfile_path(cwd, "%s", path);
            free(cwd);
            return abs;
        }
        free(cwd);
        if (errno != ERANGE)
            return NULL;
    }
    return NULL;
}

int checkpoint_write(Sim *sim, const RunProgress *rp, const char *dir)
{
    OutFile o;
    if (outfile_open(&o, dir, "%s", CHECKPOINT_FILE))
        return -1;
    Layout l = this_layout(sim->hooks.build_stage);
    uint64_t hash = sim->scene_hash;
    char *abs = absolute_path(sim->source);       /* restart from anywhere */
    CheckpointScene cs = {abs ? abs : (char *)sim->source, sim->noverrides,
                          (char **)sim->overrides};
    RunProgress copy = *rp;
    errno = 0;
    int bad = io_header(o.f, &l, &hash, &cs, l.stage, 1) || io_body(o.f, sim, &copy, 1);
    free(abs);
    if (bad) {
        outfile_report(o.path, errno ? errno : EIO);
        outfile_abandon(&o);
        return -1;
    }
    return outfile_commit(&o);
}

void checkpoint_scene_free(CheckpointScene *cs)
{
    free(cs->path);
    for (int k = 0; cs->overrides && k < cs->noverrides; k++)
        free(cs->overrides[k]);
    free(cs->overrides);
    memset(cs, 0, sizeof *cs);
}

/** The message for io_header()'s or io_body()'s return @p rc. */
static void explain(int rc, const char *path, const Layout *l, int stage, char *err,
                    size_t errlen)
{
    if (rc == -2)
        snprintf(err, errlen, "%s: not a checkpoint of mpm", path);
    else if (rc == -3 && l->stage != stage)
        snprintf(err, errlen, "%s: written by stage %d, this is stage %d: "
                 "restart it with build/stage%d/mpm", path, (int)l->stage,
                 stage, (int)l->stage);
    else if (rc == -3)
        snprintf(err, errlen, "%s: checkpoint format %u or another machine's "
                 "sizes, this build reads format %d: run the scene again",
                 path, (unsigned)l->version, CHECKPOINT_VERSION);
    else if (rc == -4)
        snprintf(err, errlen, "%s: does not match the scene as loaded now "
                 "(points, steps, time step or stages differ)", path);
    else if (rc == -5)
        snprintf(err, errlen, "%s: the scene or its overrides changed since "
                 "the checkpoint was written", path);
    else
        snprintf(err, errlen, "%s: cut short or unreadable", path);
}

static FILE *open_checkpoint(const char *dir, char **path, char *err,
                             size_t errlen)
{
    *path = outfile_path(dir, "%s", CHECKPOINT_FILE);
    FILE *f = *path ? fopen(*path, "rb") : NULL;
    if (!f)
        snprintf(err, errlen, "%s: %s", *path ? *path : dir,
                 *path ? strerror(errno) : "out of memory");
    return f;
}

/** Read @p dir's checkpoint: its header into @p cs and, when @p sim is
 *  not NULL, its state into @p sim and @p rp. @return 0, or -1 with a
 *  message. */
static int read_checkpoint(const char *dir, int stage, CheckpointScene *cs, Sim *sim,
                           RunProgress *rp, char *err, size_t errlen)
{
    memset(cs, 0, sizeof *cs);
    char *path;
    FILE *f = open_checkpoint(dir, &path, err, errlen);
    if (!f) {
        free(path);
        return -1;
    }
    Layout l;
    uint64_t hash;
    int rc = io_header(f, &l, &hash, cs, stage, 0);
    if (rc == 0 && sim && hash != sim->scene_hash)
        rc = -5;
    if (rc == 0 && sim)
        rc = io_body(f, sim, rp, 0);
    if (rc) {
        explain(rc, path, &l, stage, err, errlen);
        checkpoint_scene_free(cs);
    }
    fclose(f);
    free(path);
    return rc ? -1 : 0;
}

int checkpoint_scene(const char *dir, int stage, CheckpointScene *cs,
                     char *err, size_t errlen)
{
    return read_checkpoint(dir, stage, cs, NULL, NULL, err, errlen);
}

int checkpoint_read(Sim *sim, RunProgress *rp, const char *dir, char *err,
                    size_t errlen)
{
    CheckpointScene cs;
    int rc = read_checkpoint(dir, sim->hooks.build_stage, &cs, sim, rp, err, errlen);
    checkpoint_scene_free(&cs);
    return rc;
}
