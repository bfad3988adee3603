/*
 * liggghtsDump.c — `format liggghtsDump;`: a LIGGGHTS (or LAMMPS) text dump,
 * `dump custom ... id type x y z radius` (any columns, in any order, among
 * them x y z (or xu yu zu) and radius (or diameter)). Of several snapshots
 * the last one is read:
 *
 *     ITEM: TIMESTEP
 *     1000
 *     ITEM: NUMBER OF ATOMS
 *     3
 *     ITEM: BOX BOUNDS ff ff ff
 *     0 0.1                                  (three lines, skipped)
 *     ...
 *     ITEM: ATOMS id type x y z radius
 *     1 1 0.01 0.02 0.005 0.002
 *     ...
 *
 * Other ITEM blocks (UNITS, TIME) are skipped. A last snapshot with fewer
 * rows than its NUMBER OF ATOMS (a run killed while writing) is refused.
 */
#include "grainFile.h"

#include <stdio.h>
#include <string.h>

#include "core/error.h"

#define MAX_COLUMNS 64
#define ITEM "ITEM:"

/* Start of the last line that begins with `prefix`, and its number. */
static int find_last(const struct grain_text *t, const char *prefix,
                     size_t *pos, long *line)
{
    size_t n = strlen(prefix), at = 0;
    long ln = 1;
    int found = 0;
    for (;;) {
        if (t->len - at >= n && memcmp(t->buf + at, prefix, n) == 0) {
            *pos = at;
            *line = ln;
            found = 1;
        }
        const char *nl = memchr(t->buf + at, '\n', t->len - at);
        if (!nl)
            return found;
        at = (size_t)(nl - t->buf) + 1;
        ln++;
    }
}

static int column(char **names, int n, const char *a, const char *b)
{
    for (int k = 0; k < n; k++)
        if (strcmp(names[k], a) == 0 || (b && strcmp(names[k], b) == 0))
            return k;
    return -1;
}

static int dump_read(struct grain_text *t, struct grain_rows *out)
{
    char *line, *tok[MAX_COLUMNS], *names[MAX_COLUMNS], hold[1024];
    const char *item = "";
    long natoms = -1, step = -1, first;
    size_t pos;
    int skip = 0;

    if (!find_last(t, ITEM " TIMESTEP", &pos, &first))
        return grain_text_error(t, 0, "no 'ITEM: TIMESTEP' line: not a text "
                                "dump (dump custom ... id type x y z "
                                "radius)");
    t->pos = pos;
    t->line = first - 1;
    grain_text_line(t);
    while ((line = grain_text_line(t))) {
        if (strncmp(line, ITEM, strlen(ITEM)) != 0) {
            if (step < 0) {
                TRY(grain_text_count(t, line, "timestep", &step));
                continue;
            }
            if (skip)
                continue;
            return grain_text_error(t, t->line, "'%.40s' where an ITEM line "
                                    "was expected", line);
        }
        item = line + strlen(ITEM) + (line[strlen(ITEM)] == ' ');
        skip = 0;
        if (strcmp(item, "NUMBER OF ATOMS") == 0) {
            if (!(line = grain_text_line(t)))
                break;
            TRY(grain_text_count(t, line, "number of atoms", &natoms));
        } else if (strncmp(item, "BOX BOUNDS", 10) == 0) {
            for (int k = 0; k < 3; k++)
                if (!grain_text_line(t))
                    break;
        } else if (strncmp(item, "ATOMS", 5) == 0) {
            break;
        } else {
            skip = 1; /* UNITS, TIME, ...: their lines are not read */
        }
    }
    if (!line || natoms < 0)
        return grain_text_error(t, first, "the last snapshot (from this "
                                "line) has no %s", natoms < 0
                                ? "'ITEM: NUMBER OF ATOMS'"
                                : "'ITEM: ATOMS ...' line");
    snprintf(hold, sizeof hold, "%s", item + strlen("ATOMS"));
    int ncol = grain_text_split(hold, 0, names, MAX_COLUMNS);
    if (ncol > MAX_COLUMNS)
        return grain_text_error(t, t->line, "%d columns; at most %d are read",
                                ncol, MAX_COLUMNS);
    if (column(names, ncol, "xs", "xsu") >= 0 &&
        column(names, ncol, "x", "xu") < 0)
        return grain_text_error(t, t->line, "scaled coordinates (xs ys zs) "
                                "are not read: dump x y z");
    int cx = column(names, ncol, "x", "xu"), cy = column(names, ncol, "y",
                                                         "yu");
    int cz = column(names, ncol, "z", "zu");
    int cr = column(names, ncol, "radius", NULL);
    int cd = column(names, ncol, "diameter", NULL);
    const char *missing = cx < 0 ? "x" : cy < 0 ? "y" : cz < 0 ? "z"
                          : cr < 0 && cd < 0 ? "radius (or diameter)" : NULL;
    if (missing)
        return grain_text_error(t, t->line, "no column %s in '%s'", missing,
                                line);
    long atoms_line = t->line;
    for (long k = 0; k < natoms; k++) {
        double x[3], s;
        line = grain_text_line(t);
        if (!line || strncmp(line, ITEM, strlen(ITEM)) == 0)
            return grain_text_error(t, atoms_line, "the last snapshot "
                                    "(timestep %ld) ends after %ld of its %ld "
                                    "atoms: a truncated dump?", step, k,
                                    natoms);
        int n = grain_text_split(line, 0, tok, MAX_COLUMNS);
        if (n != ncol)
            return grain_text_error(t, t->line, "%d values, 'ITEM: ATOMS' "
                                    "(line %ld) names %d columns", n,
                                    atoms_line, ncol);
        TRY(grain_text_number(t, tok[cx], names[cx], &x[0]));
        TRY(grain_text_number(t, tok[cy], names[cy], &x[1]));
        TRY(grain_text_number(t, tok[cz], names[cz], &x[2]));
        TRY(grain_text_number(t, tok[cr >= 0 ? cr : cd],
                              cr >= 0 ? "radius" : "diameter", &s));
        TRY(grain_rows_add(out, x, cr >= 0 ? s : 0.5 * s, t->line));
    }
    if ((line = grain_text_line(t)))
        return grain_text_error(t, t->line, "a row after the %ld atoms of "
                                "the last snapshot", natoms);
    return SIM_OK;
}

const struct grain_format_ops grain_format_liggghts_dump = {
    "liggghtsDump", "text dump custom with x y z and radius, last snapshot",
    dump_read
};
