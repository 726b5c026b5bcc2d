/**
 * @file outfile.c
 * @brief Output files written whole or not at all.
 */
#include "outfile.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char *vjoin(const char *dir, const char *fmt, va_list ap)
{
    va_list again;
    va_copy(again, ap);
    int n = vsnprintf(NULL, 0, fmt, ap);
    size_t ld = strlen(dir);
    char *s = n < 0 ? NULL : malloc(ld + (size_t)n + 2);
    if (s) {
        memcpy(s, dir, ld);
        s[ld] = '/';
        vsnprintf(s + ld + 1, (size_t)n + 1, fmt, again);
    }
    va_end(again);
    return s;
}

char *outfile_path(const char *dir, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *s = vjoin(dir, fmt, ap);
    va_end(ap);
    return s;
}

void outfile_report(const char *path, int err)
{
    fprintf(stderr, "mpm: cannot write %s: %s\n", path, strerror(err));
}

void outfile_abandon(OutFile *o)
{
    if (o->f)
        fclose(o->f);
    if (o->part)
        unlink(o->part);
    free(o->path);
    free(o->part);
    o->f = NULL;
    o->path = o->part = NULL;
}

static int fail(OutFile *o, int err)
{
    outfile_report(o->path ? o->path : "an output file", err ? err : EIO);
    outfile_abandon(o);
    return -1;
}

int outfile_open(OutFile *o, const char *dir, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    o->f = NULL;
    o->part = NULL;
    o->path = vjoin(dir, fmt, ap);
    va_end(ap);
    if (!o->path)
        return fail(o, ENOMEM);
    size_t n = strlen(o->path);
    o->part = malloc(n + 6);
    if (!o->part)
        return fail(o, ENOMEM);
    memcpy(o->part, o->path, n);
    memcpy(o->part + n, ".part", 6);
    o->f = fopen(o->part, "w");
    return o->f ? 0 : fail(o, errno);
}

int outfile_commit(OutFile *o)
{
    errno = 0;
    if (fflush(o->f) != 0 || ferror(o->f))
        return fail(o, errno);
    FILE *f = o->f;
    o->f = NULL;
    if (fclose(f) != 0)
        return fail(o, errno);
    if (rename(o->part, o->path) != 0)
        return fail(o, errno);
    free(o->path);
    free(o->part);
    o->path = o->part = NULL;
    return 0;
}
