/*
 * motion_table.c — a displacement table: rows "t x y z" (seconds, metres)
 * separated by blanks or commas, '#' comments, an optional header line;
 * times strictly increasing; linear between rows, constant beyond the
 * first and the last (motion.h).
 */
#include "particles/motion/motion.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"

/* Split a line into at most 8 numbers; returns the count, or -1 if a
 * field is not a number. */
static int split(char *line, double *v)
{
    int n = 0;
    for (char *tok = strtok(line, " \t\r\n,;"); tok;
         tok = strtok(NULL, " \t\r\n,;")) {
        char *end;
        errno = 0;
        double x = strtod(tok, &end);
        if (*end || errno == ERANGE)
            return -1;
        if (n < 8)
            v[n] = x;
        n++;
    }
    return n;
}

static int grow(struct wall_motion *w, size_t *cap)
{
    if (w->nrows < *cap)
        return SIM_OK;
    size_t c = *cap ? 2 * *cap : 64;
    double *t = sim_realloc(w->t, c * sizeof *t);
    if (!t)
        return SIM_ERR_NOMEM;
    w->t = t;
    double *d = sim_realloc(w->d, 3 * c * sizeof *d);
    if (!d)
        return SIM_ERR_NOMEM;
    w->d = d;
    *cap = c;
    return SIM_OK;
}

static int read_rows(const struct dict *m, FILE *f, const char *path,
                     int dim, struct wall_motion *w)
{
    char line[4096];
    long ln = 0;
    size_t cap = 0;
    int seen = 0;
    while (fgets(line, sizeof line, f)) {
        ln++;
        char *hash = strchr(line, '#');
        if (hash)
            *hash = 0;
        double v[8];
        int n = split(line, v);
        if (n == 0)
            continue;
        if (n < 0 && !seen++)
            continue;   /* a header line ("t,x,y,z") */
        seen = 1;
        if (n != 4)
            return dict_error(m, "file", SIM_ERR_DICT, "%s:%ld: expected 4 "
                              "numbers per row (t x y z), found %s", path,
                              ln, n < 0 ? "text" : n < 4 ? "fewer" : "more");
        for (int k = 0; k < 4; k++)
            if (!isfinite(v[k]))
                return dict_error(m, "file", SIM_ERR_DICT, "%s:%ld: "
                                  "non-finite value", path, ln);
        if (w->nrows && !(v[0] > w->t[w->nrows - 1]))
            return dict_error(m, "file", SIM_ERR_DICT, "%s:%ld: time %g s "
                              "does not follow %g s of the row before "
                              "(times must increase strictly)", path, ln,
                              v[0], w->t[w->nrows - 1]);
        TRY(grow(w, &cap));
        w->t[w->nrows] = v[0];
        for (int a = 0; a < 3; a++)
            w->d[3 * w->nrows + a] = a == 2 && dim == 2 ? 0.0 : v[1 + a];
        w->nrows++;
    }
    if (w->nrows < 2)
        return dict_error(m, "file", SIM_ERR_DICT, "%s: needs at least two "
                          "rows \"t x y z\", found %zu", path, w->nrows);
    return SIM_OK;
}

static int read_table(const struct dict *m, int dim, const char *case_dir,
                      struct wall_motion *w)
{
    const char *name;
    char path[4400];
    TRY(dict_get_string(m, "file", &name));
    if (name[0] == '/' || !case_dir)
        snprintf(path, sizeof path, "%s", name);
    else
        snprintf(path, sizeof path, "%s/%s", case_dir, name);
    FILE *f = fopen(path, "r");
    if (!f)
        return dict_error(m, "file", SIM_ERR_DICT, "cannot open the motion "
                          "table '%s' (%s; relative to the case directory)",
                          name, strerror(errno));
    int rc = read_rows(m, f, name, dim, w);
    fclose(f);
    return rc;
}

/* Row k with t[k] <= t < t[k+1], for t inside the table. */
static size_t segment(const struct wall_motion *w, double t)
{
    size_t lo = 0, hi = w->nrows - 1;
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (w->t[mid] <= t)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

static void displacement(const struct wall_motion *w, double t, double d[3])
{
    size_t n = w->nrows;
    if (t <= w->t[0] || t >= w->t[n - 1]) {
        size_t k = t <= w->t[0] ? 0 : n - 1;
        for (int a = 0; a < 3; a++)
            d[a] = w->d[3 * k + a];
        return;
    }
    size_t k = segment(w, t);
    double s = (t - w->t[k]) / (w->t[k + 1] - w->t[k]);
    for (int a = 0; a < 3; a++)
        d[a] = (1 - s) * w->d[3 * k + a] + s * w->d[3 * (k + 1) + a];
}

static void velocity(const struct wall_motion *w, double t, double v[3])
{
    size_t n = w->nrows;
    if (t < w->t[0] || t >= w->t[n - 1]) {
        v[0] = v[1] = v[2] = 0;
        return;
    }
    size_t k = segment(w, t);
    double h = w->t[k + 1] - w->t[k];
    for (int a = 0; a < 3; a++)
        v[a] = (w->d[3 * (k + 1) + a] - w->d[3 * k + a]) / h;
}

const struct wall_motion_ops wall_motion_table = {
    .name = "table",
    .reference = "displacement table t x y z, linear interpolation",
    .read = read_table,
    .displacement = displacement,
    .velocity = velocity,
};
