/*
 * dict_params.c — what the case files meant to the program: warnings for
 * entries nothing read (with "did you mean"), and the usedParameters report
 * of every effective value, defaults included (SWIFT's used_parameters.yml,
 * PETSc's -options_left; doc/design.md C7).
 *
 * The records are process-wide: a program reads several files and writes
 * one report. Getters are not thread-safe (dict.h), and neither is this.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/dict_impl.h"
#include "core/error.h"
#include "core/log.h"

extern const char *const mpsdem_git_revision;

/* ---- unused entries -------------------------------------------------------- */

static int warn_dict(const struct dict *d);

static const char *suggestion(const struct dict *d, const char *key,
                              char *buf, size_t n)
{
    const char *best = dict_suggest(key, d->asked, d->nasked);
    if (best)
        snprintf(buf, n, " (did you mean '%s'?)", best);
    else
        buf[0] = '\0';
    return buf;
}

/* Dictionaries inside lists are checked when a getter looked at them. */
static int warn_in_value(const struct dict_value *v)
{
    int n = 0;
    if (v->kind == DICT_DICT)
        return v->u.d->touched ? warn_dict(v->u.d) : 0;
    if (v->kind == DICT_LIST || v->kind == DICT_ENTRY)
        for (int i = 0; i < v->u.l.n; i++)
            n += warn_in_value(&v->u.l.items[i]);
    return n;
}

static int warn_dict(const struct dict *d)
{
    int n = 0;
    for (int i = 0; i < d->n; i++) {
        const struct dict_entry *e = &d->e[i];
        if (!d->parent && strcmp(e->key, "FoamFile") == 0)
            continue;
        if (e->used) {
            n += e->val->kind == DICT_DICT ? warn_dict(e->val->u.d)
                                           : warn_in_value(e->val);
            continue;
        }
        if (e->referenced)
            continue; /* served as $var or was merged: it did its job */
        char hint[300];
        suggestion(d, e->key, hint, sizeof hint);
        if (d->name[0])
            log_warn("%s:%d:%d: keyword '%s' in '%s' is not used%s", e->file,
                     e->line, e->col, e->key, d->name, hint);
        else
            log_warn("%s:%d:%d: keyword '%s' is not used%s", e->file, e->line,
                     e->col, e->key, hint);
        n++;
    }
    return n;
}

int dict_warn_unused(const struct dict *d)
{
    return warn_dict(d);
}

/* ---- parameter records --------------------------------------------------- */

struct param {
    char *file, *key, *value;
    int is_default;
};

static struct param *params;
static int nparams, capparams;

void params_clear(void)
{
    for (int i = 0; i < nparams; i++) {
        free(params[i].file);
        free(params[i].key);
        free(params[i].value);
    }
    free(params);
    params = NULL;
    nparams = capparams = 0;
}

void params_record(const char *file, const char *key, const char *value,
                   int is_default)
{
    struct param *p = NULL;
    for (int i = 0; i < nparams && !p; i++)
        if (strcmp(params[i].file, file) == 0 && strcmp(params[i].key, key) == 0)
            p = &params[i];
    char *v = strdup(value ? value : "");
    if (!v)
        return; /* the report loses a line; nothing else depends on it */
    if (p) {
        free(p->value);
        p->value = v;
        p->is_default = is_default;
        return;
    }
    if (nparams == capparams) {
        int cap = capparams ? 2 * capparams : 64;
        struct param *np = realloc(params, (size_t)cap * sizeof *np);
        if (!np) {
            free(v);
            return;
        }
        params = np;
        capparams = cap;
    }
    p = &params[nparams];
    p->file = strdup(file);
    p->key = strdup(key);
    p->value = v;
    p->is_default = is_default;
    if (!p->file || !p->key) {
        free(p->file);
        free(p->key);
        free(v);
        return;
    }
    nparams++;
}

void params_record_entry(const struct dict *d, const char *key,
                         const char *value, int is_default)
{
    /* the report is grouped by the file the program opened */
    const struct dict *top = d;
    while (top->parent)
        top = top->parent;
    size_t nn = strlen(d->name), nk = strlen(key);
    char *full = malloc(nn + nk + 2);
    if (!full)
        return;
    if (nn)
        snprintf(full, nn + nk + 2, "%s/%s", d->name, key);
    else
        memcpy(full, key, nk + 1);
    params_record(top->file, full, value, is_default);
    free(full);
}

/* ---- the report ---------------------------------------------------------- */

/* Records of one file whose key starts with prefix, nested by '/'. */
static void write_group(FILE *f, const int *idx, int n, const char *prefix,
                        int indent)
{
    size_t np = strlen(prefix);
    for (int i = 0; i < n; i++) {
        const struct param *p = &params[idx[i]];
        if (strncmp(p->key, prefix, np) != 0)
            continue;
        const char *rest = p->key + np;
        const char *slash = strchr(rest, '/');
        if (!slash) {
            int pad = 16 - (int)strlen(rest);
            fprintf(f, "%*s%s%*s%s;%s\n", indent, "", rest, pad > 1 ? pad : 1,
                    "", p->value, p->is_default ? "  // default" : "");
            continue;
        }
        size_t nc = (size_t)(slash - rest);
        int seen = 0;
        for (int j = 0; j < i && !seen; j++) {
            const char *k = params[idx[j]].key;
            seen = strncmp(k, p->key, np + nc + 1) == 0;
        }
        if (seen)
            continue;
        char *sub = strndup(p->key, np + nc + 1);
        if (!sub)
            continue;
        fprintf(f, "%*s%.*s\n%*s{\n", indent, "", (int)nc, rest, indent, "");
        write_group(f, idx, n, sub, indent + 4);
        fprintf(f, "%*s}\n", indent, "");
        free(sub);
    }
}

static char *report_text(void)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    int *idx = malloc((size_t)(nparams ? nparams : 1) * sizeof *idx);
    if (!f || !idx) {
        if (f)
            fclose(f);
        free(buf);
        free(idx);
        sim_error(SIM_ERR_NOMEM, "out of memory writing usedParameters");
        return NULL;
    }
    fprintf(f, "// usedParameters: effective parameters of this run, grouped "
               "by file;\n// \"// default\" marks values the case did not "
               "set. mpsdem revision %s\n", mpsdem_git_revision);
    for (int i = 0; i < nparams; i++) {
        int first = 1;
        for (int j = 0; j < i && first; j++)
            first = strcmp(params[j].file, params[i].file) != 0;
        if (!first)
            continue;
        int n = 0;
        for (int j = i; j < nparams; j++)
            if (strcmp(params[j].file, params[i].file) == 0)
                idx[n++] = j;
        fputc('\n', f);
        fputc('"', f);
        for (const char *s = params[i].file; *s; s++) {
            if (*s == '"' || *s == '\\')
                fputc('\\', f);
            fputc(*s, f);
        }
        fputs("\"\n{\n", f);
        write_group(f, idx, n, "", 4);
        fputs("}\n", f);
    }
    fclose(f);
    free(idx);
    return buf;
}

int params_write(const char *path, int echo)
{
    char *text = report_text();
    if (!text)
        return SIM_ERR_NOMEM;
    int rc = dict_write_atomic(path, text, strlen(text), 1);
    if (rc == SIM_OK && echo) {
        size_t n = strlen(text);
        while (n && text[n - 1] == '\n')
            text[--n] = '\0';
        log_info("%s", text);
    }
    free(text);
    return rc;
}
