/**
 * @file scene_include.h
 * @brief A scene with its @@include files expanded into one text, and the
 *        map from a line of that text back to its file, its line and the
 *        @@include lines that led to it.
 *
 * libconfig 1.5 reads an @@include against one folder for every file; the
 * scene's own expansion reads each relative to the file that names it.
 */
#ifndef MPM_SCENE_INCLUDE_H
#define MPM_SCENE_INCLUDE_H

#include <stddef.h>

/** Deepest chain of @@include files (the scene itself not counted). */
#define SCENE_INCLUDE_DEPTH 10

/** Room for "file:line" of a scene line. */
#define SCENE_AT_LEN 320

/** One reading of a file: the scene, or a file an @@include line names. */
typedef struct ScenePart {
    char *file;   /**< its path, as read */
    int from;     /**< the part whose @@include read it; -1 for the scene */
    int at;       /**< the line of that @@include in part @p from */
} ScenePart;

/** Lines [first, next span's first) of the text are lines line, line + 1,
 *  ... of one part. */
typedef struct SceneSpan {
    int first;    /**< first line in the expanded text (from 1) */
    int part;     /**< index into SceneLines::part */
    int line;     /**< its line in that part's file */
} SceneSpan;

/** Where each line of an expanded scene came from. */
typedef struct SceneLines {
    ScenePart *part;  /**< the files read, the scene first */
    int nparts;       /**< how many */
    SceneSpan *span;  /**< runs of lines, by first line */
    int nspans;       /**< how many */
    int nlines;       /**< lines in the text */
} SceneLines;

/**
 * @brief Read scene file @p path with the files its @@include lines name
 *        (relative to the naming file's folder unless absolute) into one
 *        text.
 *
 * A missing, unreadable or non-regular file (a directory), a cycle, or
 * more than #SCENE_INCLUDE_DEPTH nested files is refused naming the
 * @@include line and the file it names. An @@include is read, as by
 * libconfig, at the start of a line outside strings and comments.
 * @param path   the scene file
 * @param text   the text (the caller frees it)
 * @param lines  its map (scene_lines_free())
 * @param err    the message, when refused
 * @param errlen its room
 * @return 0, or -1 with a message in @p err (nothing to free).
 */
int scene_expand_file(const char *path, char **text, SceneLines **lines,
                      char *err, size_t errlen);

/** @brief As scene_expand_file() for a scene held in @p src named @p name
 *         (its @@include files are read relative to @p name's folder). */
int scene_expand_string(const char *src, const char *name, char **text,
                        SceneLines **lines, char *err, size_t errlen);

/**
 * @brief The file and its line that line @p line of the expanded text came
 *        from.
 * @return the part (index into SceneLines::part), or -1 (with *file and
 *         *fline untouched) when @p m is NULL or @p line is not in it.
 */
int scene_lines_find(const SceneLines *m, int line, const char **file,
                     int *fline);

/** @brief " (included from b.cfg:2, from scene.cfg:3)" for @p part into
 *         @p buf; "" for the scene itself. */
void scene_lines_chain(const SceneLines *m, int part, char *buf, size_t len);

/** @brief "file:line" of line @p line of the expanded text into @p buf
 *         (@p file and @p line as they are when the map has no such line).
 *  @return @p buf */
const char *scene_lines_at(const SceneLines *m, const char *file, int line,
                           char *buf, size_t len);

/** @brief Release a map (NULL is fine). */
void scene_lines_free(SceneLines *m);

#endif
