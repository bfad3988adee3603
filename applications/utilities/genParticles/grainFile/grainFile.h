/*
 * grainFile.h — grains read from a file (`shape file;` in a grains region
 * of system/particleDict): positions and radii from a table or from
 * LIGGGHTS output, one format per file, selected by name with
 * `format <name>;`:
 *
 *   csv            x,y,z,radius or x,y,z,diameter with a header line naming
 *                  the columns (any order, other columns ignored), '#'
 *                  comments
 *   liggghtsData   a write_data file, atom style sphere (granular): the
 *                  Atoms section, id type diameter density x y z [ix iy iz]
 *   liggghtsDump   a text `dump custom` holding x y z and radius (or
 *                  diameter): the last snapshot
 *
 * A reader only parses: every row is checked for its shape and numbers,
 * and errors name the file and the line. The region's checks (positive
 * radii, the domain, overlaps) are in grainFile.c.
 */
#ifndef MPSDEM_GENPARTICLES_GRAINFILE_H
#define MPSDEM_GENPARTICLES_GRAINFILE_H

#include <stddef.h>

/* A file read into memory, handed out line by line. */
struct grain_text {
    const char *path;
    char *buf;
    size_t len, pos;
    long line;            /* number of the line last returned (1-based) */
    const char *comment;  /* what followed '#' on that line, trimmed    */
};

/* The next line, NUL-terminated in place, without its end of line;
 * NULL at the end of the file. */
char *grain_text_raw(struct grain_text *t);
/* The next line that is not empty once a '#' comment and surrounding
 * blanks are removed (the comment goes to t->comment); NULL at the end. */
char *grain_text_line(struct grain_text *t);
/* Split `line` in place at `sep` (0: runs of blanks) into at most `max`
 * trimmed tokens; returns the number of fields (which may exceed max). */
int grain_text_split(char *line, char sep, char **tok, int max);
/* "path:line: message" (line 0: "path: message"). */
int grain_text_error(const struct grain_text *t, long line, const char *fmt,
                     ...) __attribute__((format(printf, 3, 4)));
/* A finite number from token `tok` of column `col`, else an error at the
 * current line. */
int grain_text_number(const struct grain_text *t, const char *tok,
                      const char *col, double *out);
/* A whole number, likewise. */
int grain_text_count(const struct grain_text *t, const char *tok,
                     const char *what, long *out);

/* The rows read: positions (x y z interleaved), radii, and the line of
 * each in the file. */
struct grain_rows {
    size_t n, cap;
    double *x, *r;
    long *line;
};
int grain_rows_add(struct grain_rows *g, const double x[3], double r,
                   long line);
void grain_rows_free(struct grain_rows *g);

struct grain_format_ops {
    const char *name;      /* the word of `format`                      */
    const char *reference; /* the documentation of the format           */
    int (*read)(struct grain_text *t, struct grain_rows *out);
};

extern const struct grain_format_ops grain_format_csv;
extern const struct grain_format_ops grain_format_liggghts_data;
extern const struct grain_format_ops grain_format_liggghts_dump;
extern const struct grain_format_ops *const grain_format_table[];

#endif
