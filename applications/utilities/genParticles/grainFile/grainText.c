/* grainText.c — line reading, splitting and number parsing shared by the
 * grain file formats, and their table (grainFile.h). */
#include "grainFile.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"

const struct grain_format_ops *const grain_format_table[] = {
    &grain_format_csv, &grain_format_liggghts_data,
    &grain_format_liggghts_dump, NULL
};

static int blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

static char *trim(char *s)
{
    size_t n;
    while (blank(*s))
        s++;
    n = strlen(s);
    while (n && blank(s[n - 1]))
        s[--n] = '\0';
    return s;
}

char *grain_text_raw(struct grain_text *t)
{
    char *s, *nl;
    if (t->pos >= t->len)
        return NULL;
    s = t->buf + t->pos;
    nl = memchr(s, '\n', t->len - t->pos);
    if (nl) {
        *nl = '\0';
        t->pos = (size_t)(nl - t->buf) + 1;
    } else {
        t->pos = t->len; /* the buffer has a NUL after its last byte */
    }
    t->line++;
    t->comment = "";
    return s;
}

char *grain_text_line(struct grain_text *t)
{
    char *s;
    while ((s = grain_text_raw(t))) {
        char *hash = strchr(s, '#');
        if (hash) {
            *hash = '\0';
            t->comment = trim(hash + 1);
        }
        s = trim(s);
        if (*s)
            return s;
    }
    return NULL;
}

int grain_text_split(char *line, char sep, char **tok, int max)
{
    int n = 0;
    char *s = line;
    if (!sep) {
        for (;;) {
            while (blank(*s))
                s++;
            if (!*s)
                return n;
            if (n < max)
                tok[n] = s;
            n++;
            while (*s && !blank(*s))
                s++;
            if (*s)
                *s++ = '\0';
        }
    }
    for (;;) {
        char *end = strchr(s, sep);
        if (end)
            *end = '\0';
        if (n < max)
            tok[n] = trim(s);
        n++;
        if (!end)
            return n;
        s = end + 1;
    }
}

int grain_text_error(const struct grain_text *t, long line, const char *fmt,
                     ...)
{
    char msg[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (line > 0)
        return sim_error(SIM_ERR_INPUT, "%s:%ld: %s", t->path, line, msg);
    return sim_error(SIM_ERR_INPUT, "%s: %s", t->path, msg);
}

int grain_text_number(const struct grain_text *t, const char *tok,
                      const char *col, double *out)
{
    char *end;
    if (!*tok)
        return grain_text_error(t, t->line, "column '%s' is empty", col);
    errno = 0;
    *out = strtod(tok, &end);
    if (*end || end == tok)
        return grain_text_error(t, t->line, "column '%s': '%.40s' is not a "
                                "number", col, tok);
    if (!isfinite(*out) || errno == ERANGE)
        return grain_text_error(t, t->line, "column '%s': '%.40s' is not a "
                                "finite number", col, tok);
    return SIM_OK;
}

int grain_text_count(const struct grain_text *t, const char *tok,
                     const char *what, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(tok, &end, 10);
    if (*end || end == tok || errno == ERANGE || v < 0)
        return grain_text_error(t, t->line, "%s: '%.40s' is not a whole "
                                "number", what, tok);
    *out = v;
    return SIM_OK;
}

int grain_rows_add(struct grain_rows *g, const double x[3], double r,
                   long line)
{
    if (g->n == g->cap) {
        size_t cap = g->cap ? 2 * g->cap : 256;
        double *nx = sim_realloc(g->x, 3 * cap * sizeof *nx);
        if (!nx)
            return SIM_ERR_NOMEM;
        g->x = nx;
        double *nr = sim_realloc(g->r, cap * sizeof *nr);
        if (!nr)
            return SIM_ERR_NOMEM;
        g->r = nr;
        long *nl = sim_realloc(g->line, cap * sizeof *nl);
        if (!nl)
            return SIM_ERR_NOMEM;
        g->line = nl;
        g->cap = cap;
    }
    memcpy(g->x + 3 * g->n, x, 3 * sizeof *x);
    g->r[g->n] = r;
    g->line[g->n] = line;
    g->n++;
    return SIM_OK;
}

void grain_rows_free(struct grain_rows *g)
{
    free(g->x);
    free(g->r);
    free(g->line);
    memset(g, 0, sizeof *g);
}
