/**
 * @file scene_text.h
 * @brief A scene's text before libconfig reads it: a growing buffer, and a
 *        line-by-line scan that knows strings and comments and finds an
 *        integer too large for the integer libconfig reads it into.
 */
#ifndef MPM_SCENE_TEXT_H
#define MPM_SCENE_TEXT_H

#include <stddef.h>

/** A growing NUL-terminated text. */
typedef struct SceneBuf {
    char *s;       /**< the text (NULL while empty) */
    size_t len;    /**< its length */
    size_t cap;    /**< bytes allocated */
} SceneBuf;

/** What the start of a line is inside of. */
typedef enum {
    TEXT_CODE,     /**< settings: where @@include is read */
    TEXT_STRING,   /**< a "string" that goes on from an earlier line */
    TEXT_COMMENT   /**< a block comment that goes on from an earlier line */
} TextState;

/** A scan of a scene's text, line by line. */
typedef struct TextScan {
    TextState state;   /**< what the next line starts in */
    char key[64];      /**< the last setting name seen (for messages) */
} TextScan;

/** @brief Append @p n bytes at @p p to @p b. @return 0, or -1 out of memory. */
int scene_buf_add(SceneBuf *b, const char *p, size_t n);

/**
 * @brief Scan the line [@p p, @p end), moving @p scan on to what the next
 *        line starts in, and look for an integer libconfig would misread.
 *
 * libconfig 1.5 wraps a decimal integer outside the int range (without L;
 * outside the int64 range with L) to another number without a word.
 * @return 0, or 1 with the first such literal at *@p bad, *@p len bytes
 *         (scan->key: the setting it is in).
 */
int scene_text_scan(const char *p, const char *end, TextScan *scan,
                    const char **bad, int *len);

/** @brief The message for the integer [@p bad, @p bad + @p len) out of
 *         range, after "key: ". */
void scene_text_range_message(const char *bad, int len, char *buf, size_t n);

#endif
