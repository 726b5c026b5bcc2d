/**
 * @file scene_include.c
 * @brief A scene's @@include lines expanded into one text, each file read
 *        relative to the file that names it, with a map of where every
 *        line came from.
 *
 * An @@include line is read as libconfig reads it: at the start of a line
 * (after blanks) outside a string or a block comment, @@include, blanks,
 * then the file in quotes (\" and \\ escape).  Whatever follows the closing
 * quote on that line is read after the included text.
 */
#include "scene_include.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "scene_text.h"

/** An expansion under way: the text, its map, and the files being read. */
typedef struct Expand {
    SceneBuf text;                          /* the expanded text */
    SceneLines *m;                          /* its map */
    dev_t dev[SCENE_INCLUDE_DEPTH + 1];     /* the files being read, */
    ino_t ino[SCENE_INCLUDE_DEPTH + 1];     /* the scene first */
    int known[SCENE_INCLUDE_DEPTH + 1];     /* 0: a scene given as text */
    int depth;                              /* how many */
    char *err;
    size_t errlen;
} Expand;

/** Add a part; @return its index, or -1 out of memory. */
static int add_part(SceneLines *m, const char *file, int from, int at)
{
    ScenePart *p = realloc(m->part, sizeof *p * ((size_t)m->nparts + 1));
    if (!p)
        return -1;
    m->part = p;
    p[m->nparts] = (ScenePart){strdup(file), from, at};
    return p[m->nparts].file ? m->nparts++ : -1;
}

/** The next line of the text is line @p line of @p part. */
static int map_line(SceneLines *m, int part, int line)
{
    const SceneSpan *s = m->nspans ? &m->span[m->nspans - 1] : NULL;
    int next = ++m->nlines;
    if (s && s->part == part && s->line + (next - s->first) == line)
        return 0;                       /* goes on from the span before */
    SceneSpan *t = realloc(m->span, sizeof *t * ((size_t)m->nspans + 1));
    if (!t)
        return -1;
    m->span = t;
    t[m->nspans++] = (SceneSpan){next, part, line};
    return 0;
}

static int out_of_memory(Expand *x)
{
    snprintf(x->err, x->errlen, "%s: out of memory", x->m->part[0].file);
    return -1;
}

/** Copy [p, end) as line @p line of @p part, ending it with a newline;
 *  refuse an integer that libconfig would wrap. */
static int emit(Expand *x, int part, int line, const char *p, const char *end,
                TextScan *scan)
{
    const char *bad;
    int len;
    if (scene_text_scan(p, end, scan, &bad, &len)) {
        char why[256], chain[512];
        scene_text_range_message(bad, len, why, sizeof why);
        scene_lines_chain(x->m, part, chain, sizeof chain);
        snprintf(x->err, x->errlen, "%s:%d: %s: %s%s", x->m->part[part].file, line,
                 scan->key[0] ? scan->key : "number", why, chain);
        return -1;
    }
    if (map_line(x->m, part, line) || scene_buf_add(&x->text, p, (size_t)(end - p)) ||
        ((end == p || end[-1] != '\n') && scene_buf_add(&x->text, "\n", 1)))
        return out_of_memory(x);
    return 0;
}

/**
 * Is [p, end) an @@include line? 1 with the file's name in @p name (escapes
 * undone) and *rest after the closing quote; 0 when not (a line that
 * starts @@include but does not close its quote is left to libconfig);
 * -1 when the name does not fit @p len.
 */
static int include_line(const char *p, const char *end, char *name, size_t len,
                        const char **rest)
{
    while (p < end && (*p == ' ' || *p == '\t'))
        p++;
    if ((size_t)(end - p) < 9 || strncmp(p, "@include", 8) != 0 ||
        (p[8] != ' ' && p[8] != '\t'))
        return 0;
    for (p += 8; p < end && (*p == ' ' || *p == '\t'); p++)
        ;
    if (p == end || *p++ != '"')
        return 0;
    size_t n = 0;
    for (; p < end && *p != '"' && *p != '\n'; p++) {
        if (*p == '\\' && p + 1 < end && (p[1] == '"' || p[1] == '\\'))
            p++;
        if (n + 1 >= len)
            return -1;
        name[n++] = *p;
    }
    name[n] = '\0';
    if (p == end || *p != '"')
        return 0;
    *rest = p + 1;
    return 1;
}

/** Refuse the @@include of @p name at @p line of @p part. */
static int refuse(Expand *x, int part, int line, const char *name,
                  const char *path, const char *why)
{
    char chain[512];
    scene_lines_chain(x->m, part, chain, sizeof chain);
    int same = strcmp(name, path) == 0;
    snprintf(x->err, x->errlen, "%s:%d: @include \"%s\"%s%s%s: %s%s",
             x->m->part[part].file, line, name, same ? "" : " (", same ? "" : path,
             same ? "" : ")", why, chain);
    return -1;
}

/** The whole of regular file @p path, NUL-ended; NULL with @p why. */
static char *read_file(const char *path, size_t *n, struct stat *st,
                       const char **why)
{
    *why = NULL;
    if (stat(path, st) != 0) {
        *why = strerror(errno);
        return NULL;
    }
    if (S_ISDIR(st->st_mode)) {
        *why = "is a directory";
        return NULL;
    }
    if (!S_ISREG(st->st_mode)) {
        *why = "is not a regular file";
        return NULL;
    }
    FILE *f = fopen(path, "rb");
    if (!f) {
        *why = strerror(errno);
        return NULL;
    }
    SceneBuf b = {NULL, 0, 0};
    char chunk[65536];
    size_t got;
    while ((got = fread(chunk, 1, sizeof chunk, f)) > 0)
        if (scene_buf_add(&b, chunk, got)) {
            *why = "out of memory";
            break;
        }
    if (!*why && ferror(f))
        *why = strerror(errno);
    fclose(f);
    if (!*why && !b.s && scene_buf_add(&b, "", 0))
        *why = "out of memory";
    if (*why) {
        free(b.s);
        return NULL;
    }
    *n = b.len;
    return b.s;
}

static int expand_part(Expand *x, int part, const char *data, size_t n);

/** Read the file @p name (as written at @p line of @p part) in its place. */
static int include(Expand *x, int part, int line, const char *name)
{
    const char *file = x->m->part[part].file, *slash = strrchr(file, '/');
    size_t dir = name[0] == '/' || !slash ? 0 : (size_t)(slash - file) + 1;
    char path[4096];
    if (dir + strlen(name) >= sizeof path)
        return refuse(x, part, line, name, name, "the path is too long");
    memcpy(path, file, dir);
    strcpy(path + dir, name);
    if (x->depth > SCENE_INCLUDE_DEPTH) {
        char why[64];
        snprintf(why, sizeof why, "more than %d nested @include files",
                 SCENE_INCLUDE_DEPTH);
        return refuse(x, part, line, name, path, why);
    }
    struct stat st;
    const char *why;
    size_t n = 0;
    char *data = read_file(path, &n, &st, &why);
    for (int k = 0; data && k < x->depth; k++)
        if (x->known[k] && x->dev[k] == st.st_dev && x->ino[k] == st.st_ino)
            why = "a cycle: that file is being read already";
    if (why) {
        free(data);
        return refuse(x, part, line, name, path, why);
    }
    int p = add_part(x->m, path, part, line), rc = -1;
    if (p >= 0) {
        x->dev[x->depth] = st.st_dev;
        x->ino[x->depth] = st.st_ino;
        x->known[x->depth++] = 1;
        rc = expand_part(x, p, data, n);
        x->depth--;
    } else {
        out_of_memory(x);
    }
    free(data);
    return rc;
}

/** Copy part @p part, the text @p data of @p n bytes, expanding its
 *  @@include lines. */
static int expand_part(Expand *x, int part, const char *data, size_t n)
{
    const char *p = data, *end = data + n;
    TextScan scan = {TEXT_CODE, ""};
    int line = 1;
    for (; p < end; line++) {
        const char *nl = memchr(p, '\n', (size_t)(end - p));
        const char *q = nl ? nl + 1 : end, *rest = q;
        char name[1024];
        int inc = scan.state == TEXT_CODE ?
                  include_line(p, q, name, sizeof name, &rest) : 0;
        if (inc < 0) {
            snprintf(x->err, x->errlen, "%s:%d: @include: the file name is "
                     "longer than %zu characters", x->m->part[part].file, line,
                     sizeof name - 1);
            return -1;
        }
        if (inc > 0 && include(x, part, line, name))
            return -1;
        if (emit(x, part, line, inc ? rest : p, q, &scan))
            return -1;
        p = q;
    }
    if (scan.state != TEXT_CODE && part > 0) {   /* keep it from running on */
        char chain[512];
        scene_lines_chain(x->m, part, chain, sizeof chain);
        snprintf(x->err, x->errlen, "%s:%d: the file ends inside a %s%s",
                 x->m->part[part].file, line - 1, scan.state == TEXT_STRING ?
                 "string (a \" is not closed)" : "comment (a /* is not closed)",
                 chain);
        return -1;
    }
    return 0;
}

/** Expand the scene @p data named @p name (@p st: its file, or NULL). */
static int expand(const char *data, size_t n, const char *name,
                  const struct stat *st, char **text, SceneLines **lines,
                  char *err, size_t errlen)
{
    Expand x = {{NULL, 0, 0}, calloc(1, sizeof(SceneLines)), {0}, {0}, {0}, 1,
                err, errlen};
    int rc = -1;
    if (!x.m || add_part(x.m, name, -1, 0) < 0)
        snprintf(err, errlen, "%s: out of memory", name);
    else {
        if (st) {
            x.dev[0] = st->st_dev;
            x.ino[0] = st->st_ino;
            x.known[0] = 1;
        }
        rc = expand_part(&x, 0, data, n);
        if (rc == 0 && !x.text.s && scene_buf_add(&x.text, "", 0))
            rc = out_of_memory(&x);
    }
    if (rc) {
        free(x.text.s);
        scene_lines_free(x.m);
        return -1;
    }
    *text = x.text.s;
    *lines = x.m;
    return 0;
}

int scene_expand_file(const char *path, char **text, SceneLines **lines,
                      char *err, size_t errlen)
{
    struct stat st;
    const char *why;
    size_t n;
    char *data = read_file(path, &n, &st, &why);
    if (!data) {
        snprintf(err, errlen, "%s: cannot read the file (%s)", path, why);
        return -1;
    }
    int rc = expand(data, n, path, &st, text, lines, err, errlen);
    free(data);
    return rc;
}

int scene_expand_string(const char *src, const char *name, char **text,
                        SceneLines **lines, char *err, size_t errlen)
{
    return expand(src, strlen(src), name, NULL, text, lines, err, errlen);
}

int scene_lines_find(const SceneLines *m, int line, const char **file,
                     int *fline)
{
    if (!m || line < 1 || line > m->nlines || m->nspans == 0)
        return -1;
    int lo = 0, hi = m->nspans - 1;          /* the last span at or before */
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (m->span[mid].first <= line)
            lo = mid;
        else
            hi = mid - 1;
    }
    const SceneSpan *s = &m->span[lo];
    *file = m->part[s->part].file;
    *fline = s->line + (line - s->first);
    return s->part;
}

void scene_lines_chain(const SceneLines *m, int part, char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int p = part; m && p > 0 && used < len; p = m->part[p].from) {
        int w = snprintf(buf + used, len - used, "%s %s:%d", p == part ?
                         " (included from" : ", from", m->part[m->part[p].from].file,
                         m->part[p].at);
        used += w > 0 ? (size_t)w : 0;
    }
    if (used > 0 && used + 1 < len)
        strcat(buf, ")");
}

const char *scene_lines_at(const SceneLines *m, const char *file, int line,
                           char *buf, size_t len)
{
    int fline = line;
    scene_lines_find(m, line, &file, &fline);
    snprintf(buf, len, "%s:%d", file, fline);
    return buf;
}

void scene_lines_free(SceneLines *m)
{
    if (!m)
        return;
    for (int k = 0; k < m->nparts; k++)
        free(m->part[k].file);
    free(m->part);
    free(m->span);
    free(m);
}
