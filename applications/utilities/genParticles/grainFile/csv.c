/*
 * csv.c — `format csv;`: a table of grains, comma separated, whose first
 * line names the columns:
 *
 *     # bed of 0.1 m glass beads        ('#' starts a comment anywhere)
 *     x,y,z,radius
 *     0.01,0.02,0.005,0.0025
 *
 * x, y, z and one of radius or diameter are required, in any order and
 * any letter case; other columns (an id, a type) are ignored. Every row
 * has as many values as the header has names.
 */
#include "grainFile.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "core/error.h"

#define MAX_COLUMNS 64

enum { CX, CY, CZ, CRADIUS, CDIAMETER, NWANT };

static int numeric(const char *s)
{
    char *end;
    strtod(s, &end);
    return end != s && !*end;
}

static int csv_read(struct grain_text *t, struct grain_rows *out)
{
    static const char *const want[NWANT] = { "x", "y", "z", "radius",
                                             "diameter" };
    char *tok[MAX_COLUMNS], *line, names[512];
    int col[NWANT], ncol;
    long header;

    line = grain_text_line(t);
    if (!line)
        return grain_text_error(t, 0, "no header line: the first line names "
                                "the columns, x,y,z,radius or "
                                "x,y,z,diameter");
    header = t->line;
    snprintf(names, sizeof names, "%s", line);
    ncol = grain_text_split(line, ',', tok, MAX_COLUMNS);
    if (ncol > MAX_COLUMNS)
        return grain_text_error(t, header, "%d columns; at most %d are read",
                                ncol, MAX_COLUMNS);
    for (int w = 0; w < NWANT; w++) {
        col[w] = -1;
        for (int k = 0; k < ncol; k++) {
            if (strcasecmp(tok[k], want[w]) != 0)
                continue;
            if (col[w] >= 0)
                return grain_text_error(t, header, "column '%s' is named "
                                        "twice in the header '%s'", want[w],
                                        names);
            col[w] = k;
        }
    }
    for (int w = CX; w <= CZ; w++)
        if (col[w] < 0)
            return grain_text_error(t, header, "no column '%s' in the header "
                                    "'%s' (needed: x, y, z and radius or "
                                    "diameter)%s", want[w], names,
                                    numeric(tok[0]) ? "; is the header line "
                                    "missing?" : "");
    if ((col[CRADIUS] < 0) == (col[CDIAMETER] < 0))
        return grain_text_error(t, header, "the header '%s' needs one column "
                                "radius or diameter, %s", names,
                                col[CRADIUS] < 0 ? "it has neither"
                                                 : "not both");
    int size_col = col[CRADIUS] >= 0 ? CRADIUS : CDIAMETER;
    while ((line = grain_text_line(t))) {
        double x[3], s;
        int n = grain_text_split(line, ',', tok, MAX_COLUMNS);
        if (n != ncol)
            return grain_text_error(t, t->line, "%d values, the header (line "
                                    "%ld) names %d columns", n, header,
                                    ncol);
        for (int w = CX; w <= CZ; w++)
            TRY(grain_text_number(t, tok[col[w]], want[w], &x[w]));
        TRY(grain_text_number(t, tok[col[size_col]], want[size_col], &s));
        TRY(grain_rows_add(out, x, size_col == CDIAMETER ? 0.5 * s : s,
                           t->line));
    }
    return SIM_OK;
}

const struct grain_format_ops grain_format_csv = {
    "csv", "x,y,z,radius|diameter table with a header line", csv_read
};
