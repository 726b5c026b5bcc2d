/**
 * @file scene_text.c
 * @brief A scene's text before libconfig reads it: strings and comments
 *        passed over, setting names noted, and integers that libconfig
 *        would wrap found.
 */
#include "scene_text.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int scene_buf_add(SceneBuf *b, const char *p, size_t n)
{
    if (b->len + n + 1 > b->cap) {
        size_t cap = b->cap ? b->cap : 4096;
        while (cap < b->len + n + 1)
            cap *= 2;
        char *s = realloc(b->s, cap);
        if (!s)
            return -1;
        b->s = s;
        b->cap = cap;
    }
    memcpy(b->s + b->len, p, n);
    b->len += n;
    b->s[b->len] = '\0';
    return 0;
}

/** Characters of a setting name after its first (libconfig 1.5). */
static int name_char(int c)
{
    return isalnum(c) || c == '-' || c == '_' || c == '*';
}

/** Does a number start at @p p (a digit, ".5", "-3", "+.5")? */
static int number_starts(const char *p, const char *end)
{
    if (p < end && (*p == '+' || *p == '-'))
        p++;
    if (p < end && *p == '.')
        p++;
    return p < end && isdigit((unsigned char)*p);
}

/**
 * The end of the number at @p p; *wraps when it is a decimal integer beyond
 * its type's range (int, or int64 with an L suffix).
 */
static const char *number_end(const char *p, const char *end, int *wraps)
{
    const char *q = p;
    int neg = 0, real = 0, huge = 0;
    unsigned long long mag = 0;
    *wraps = 0;
    if (*q == '+' || *q == '-')
        neg = *q++ == '-';
    if (q + 1 < end && q[0] == '0' && (q[1] == 'x' || q[1] == 'X')) {
        for (q += 2; q < end && (isxdigit((unsigned char)*q) || *q == 'L'); q++)
            ;
        return q;                     /* hexadecimal: refused where it is read */
    }
    for (; q < end && isdigit((unsigned char)*q); q++) {
        unsigned d = (unsigned)(*q - '0');
        if (mag > (~0ull - d) / 10)
            huge = 1;
        else
            mag = mag * 10 + d;
    }
    if (q < end && *q == '.')
        for (real = 1, q++; q < end && isdigit((unsigned char)*q); q++)
            ;
    if (q < end && (*q == 'e' || *q == 'E')) {
        const char *e = q + 1;
        if (e < end && (*e == '+' || *e == '-'))
            e++;
        if (e < end && isdigit((unsigned char)*e))
            for (real = 1, q = e; q < end && isdigit((unsigned char)*q); q++)
                ;
    }
    int suffix = 0;
    while (!real && q < end && *q == 'L' && suffix < 2) {
        q++;
        suffix++;
    }
    /* the largest magnitude its type holds, one more when negative */
    unsigned long long top = suffix ? 9223372036854775807ull : 2147483647ull;
    *wraps = !real && (huge || mag > top + (unsigned long long)neg);
    return q;
}

/** Where a string's closing quote, or the line, ends (after escapes). */
static const char *string_end(const char *p, const char *end, TextState *state)
{
    for (; p < end; p++) {
        if (*p == '\\' && p + 1 < end)
            p++;
        else if (*p == '"') {
            *state = TEXT_CODE;
            return p + 1;
        }
    }
    return end;
}

/** Where a block comment's closing, or the line, ends. */
static const char *comment_end(const char *p, const char *end, TextState *state)
{
    for (; p + 1 < end; p++)
        if (p[0] == '*' && p[1] == '/') {
            *state = TEXT_CODE;
            return p + 2;
        }
    return end;
}

int scene_text_scan(const char *p, const char *end, TextScan *scan,
                    const char **bad, int *len)
{
    while (p < end) {
        const char *q = p + 1;
        int wraps = 0;
        if (scan->state == TEXT_STRING)
            q = string_end(p, end, &scan->state);
        else if (scan->state == TEXT_COMMENT)
            q = comment_end(p, end, &scan->state);
        else if (*p == '"') {
            scan->state = TEXT_STRING;
            q = string_end(p + 1, end, &scan->state);
        } else if (*p == '#' || (*p == '/' && q < end && *q == '/')) {
            q = end;                                 /* to the end of the line */
        } else if (*p == '/' && q < end && *q == '*') {
            scan->state = TEXT_COMMENT;
            q = comment_end(p + 2, end, &scan->state);
        } else if (isalpha((unsigned char)*p) || *p == '*') {
            while (q < end && name_char((unsigned char)*q))
                q++;                                 /* a name: x1, a-2 */
            snprintf(scan->key, sizeof scan->key, "%.*s", (int)(q - p), p);
        } else if (number_starts(p, end)) {
            q = number_end(p, end, &wraps);
        }
        if (wraps) {
            *bad = p;
            *len = (int)(q - p);
            return 1;
        }
        p = q;
    }
    return 0;
}

void scene_text_range_message(const char *bad, int len, char *buf, size_t n)
{
    int wide = bad[len - 1] == 'L';
    snprintf(buf, n, "%.*s does not fit an integer (%s); a real is written "
             "with a point: %.*s.0", len, bad,
             wide ? "with L: -2^63 to 2^63 - 1" : "-2147483648 to 2147483647",
             len - (wide ? 1 + (len > 1 && bad[len - 2] == 'L') : 0), bad);
}
