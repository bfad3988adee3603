/*
 * liggghtsData.c — `format liggghtsData;`: a LIGGGHTS (or LAMMPS) data
 * file as write_data makes it, atom style sphere (LIGGGHTS: granular), in
 * the layout of LAMMPS' read_data documentation:
 *
 *     LIGGGHTS data file via write_data, ...   (line 1: a title, skipped)
 *
 *     3 atoms                                  (header: 'N atoms' needed,
 *     1 atom types                              the other lines ignored)
 *     0 0.1 xlo xhi
 *     ...
 *     Atoms # sphere                           (a section keyword)
 *
 *     1 1 0.004 2500 0.01 0.02 0.005           (id type diameter density
 *     ...                                       x y z [ix iy iz])
 *
 *     Velocities                               (other sections ignored)
 *
 * Densities are not read (demSolid takes rho from constant/demProperties);
 * positions are taken as written (image flags are not applied).
 */
#include "grainFile.h"

#include <ctype.h>
#include <string.h>

#include "core/error.h"

static int keyword_line(const char *s)
{
    return isalpha((unsigned char)s[0]);
}

static int data_read(struct grain_text *t, struct grain_rows *out)
{
    char *line, *tok[16];
    long natoms = -1, header_line = 0;

    if (!grain_text_raw(t))
        return grain_text_error(t, 0, "empty file");
    while ((line = grain_text_line(t)) && !keyword_line(line)) {
        int n = grain_text_split(line, 0, tok, 16);
        if (n == 2 && strcmp(tok[1], "atoms") == 0) {
            TRY(grain_text_count(t, tok[0], "number of atoms", &natoms));
            header_line = t->line;
        }
    }
    if (natoms < 0)
        return grain_text_error(t, line ? t->line : 0, "no 'N atoms' line in "
                                "the header (before the first section)");
    for (; line; line = grain_text_line(t)) {
        if (strcmp(line, "Atoms") != 0)
            continue; /* another section's keyword or data */
        const char *style = t->comment;
        if (*style && strcmp(style, "sphere") != 0 &&
            strcmp(style, "granular") != 0)
            return grain_text_error(t, t->line, "Atoms section of atom style "
                                    "'%s': only sphere (granular) is read, "
                                    "id type diameter density x y z", style);
        long start = t->line;
        for (long k = 0; k < natoms; k++) {
            double x[3], d;
            long id;
            line = grain_text_line(t);
            if (!line || keyword_line(line))
                return grain_text_error(t, line ? t->line : start, "the Atoms "
                                        "section ends after %ld of the %ld "
                                        "atoms of the header (line %ld)", k,
                                        natoms, header_line);
            int n = grain_text_split(line, 0, tok, 16);
            if (n != 7 && n != 10)
                return grain_text_error(t, t->line, "%d values: atom style "
                                        "sphere has 7, id type diameter "
                                        "density x y z (10 with image flags)",
                                        n);
            TRY(grain_text_count(t, tok[0], "atom id", &id));
            TRY(grain_text_number(t, tok[2], "diameter", &d));
            TRY(grain_text_number(t, tok[4], "x", &x[0]));
            TRY(grain_text_number(t, tok[5], "y", &x[1]));
            TRY(grain_text_number(t, tok[6], "z", &x[2]));
            TRY(grain_rows_add(out, x, 0.5 * d, t->line));
        }
        line = grain_text_line(t);
        if (line && !keyword_line(line))
            return grain_text_error(t, t->line, "a row after the %ld atoms "
                                    "of the header (line %ld)", natoms,
                                    header_line);
        return SIM_OK;
    }
    return grain_text_error(t, 0, "no Atoms section");
}

const struct grain_format_ops grain_format_liggghts_data = {
    "liggghtsData", "write_data file, Atoms section of atom style sphere",
    data_read
};
