/*
 * dict_get.c — lookups, typed getters and value accessors of dict.h.
 *
 * A getter finds the entry (scoped paths "a/b/c" walk sub-dictionaries),
 * checks the shape of its value, marks it used and records the effective
 * value for the usedParameters report; an absent key is remembered in the
 * innermost dictionary that exists, for "did you mean" in
 * dict_warn_unused(). Messages are located at the offending value, or at
 * the dictionary for a missing key, and name the key and what was expected.
 *
 * Accepted shapes (OpenFOAM's): a scalar is "1e-6", "[dims] 1e-6" or
 * "name [dims] 1e-6"; a vector is "(x y z)" with the same optional prefix.
 */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/dict_impl.h"
#include "core/error.h"

/* ---- finding entries ----------------------------------------------------- */

static void remember_asked(struct dict *d, const char *key)
{
    for (int i = 0; i < d->nasked; i++)
        if (strcmp(d->asked[i], key) == 0)
            return;
    if (d->nasked == d->capasked) {
        int cap = d->capasked ? 2 * d->capasked : 8;
        const char **a = realloc(d->asked, (size_t)cap * sizeof *a);
        if (!a)
            return; /* book-keeping only: losing a suggestion is harmless */
        d->asked = a;
        d->capasked = cap;
    }
    const char *k = arena_strndup(&d->root->arena, key, strlen(key));
    if (k)
        d->asked[d->nasked++] = k;
}

/* Entry at scoped `key` or NULL; *owner is the dictionary holding it (or
 * the innermost existing one). With `book`, intermediate dictionaries are
 * marked used and an absent key is remembered. */
static struct dict_entry *find(const struct dict *cd, const char *key,
                               struct dict **owner, int book)
{
    struct dict *d = (struct dict *)cd;
    if (book)
        d->touched = 1;
    *owner = d;
    struct dict_entry *e = dict_lookup(d, key);
    if (e || !strchr(key, '/')) {
        if (!e && book)
            remember_asked(d, key);
        return e;
    }
    char comp[256];
    const char *s = key;
    for (;;) {
        const char *slash = strchr(s, '/');
        size_t n = slash ? (size_t)(slash - s) : strlen(s);
        if (n >= sizeof comp)
            return NULL;
        memcpy(comp, s, n);
        comp[n] = '\0';
        e = dict_lookup(d, comp);
        if (!e || !slash) {
            if (!e && book)
                remember_asked(d, comp);
            *owner = d;
            return e;
        }
        if (e->val->kind != DICT_DICT)
            return NULL;
        if (book) {
            e->used = 1;
            e->val->u.d->touched = 1;
        }
        d = e->val->u.d;
        s = slash + 1;
    }
}

struct dict_entry *dict_find_entry(const struct dict *d, const char *key)
{
    struct dict *owner;
    return find(d, key, &owner, 0);
}

int dict_has(const struct dict *d, const char *key)
{
    struct dict *owner;
    return find(d, key, &owner, 0) != NULL;
}

int dict_is_dict(const struct dict *d, const char *key)
{
    struct dict *owner;
    struct dict_entry *e = find(d, key, &owner, 0);
    return e && e->val->kind == DICT_DICT;
}

const char *dict_file(const struct dict *d) { return d->file; }
const char *dict_name(const struct dict *d) { return d->name; }
int dict_size(const struct dict *d) { return d->n; }

const char *dict_key_at(const struct dict *d, int i)
{
    return i >= 0 && i < d->n ? d->e[i].key : NULL;
}

void dict_mark_used(const struct dict *d, const char *key)
{
    struct dict *owner;
    struct dict_entry *e = find(d, key, &owner, 0);
    if (e)
        e->used = 1;
}

/* ---- locations and messages ------------------------------------------------ */

const char *dict_value_where(const struct dict_value *v, char *buf, size_t n)
{
    snprintf(buf, n, "%s:%d:%d", v->file, v->line, v->col);
    return buf;
}

const char *dict_where(const struct dict *d, const char *key, char *buf,
                       size_t n)
{
    struct dict *owner;
    struct dict_entry *e = key ? find(d, key, &owner, 0) : NULL;
    if (e)
        snprintf(buf, n, "%s:%d:%d", e->file, e->line, e->col);
    else
        snprintf(buf, n, "%s:%d:%d", d->file, d->line, d->col);
    return buf;
}

int dict_error(const struct dict *d, const char *key, int code,
               const char *fmt, ...)
{
    char where[512], msg[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return sim_error(code, "%s: %s", dict_where(d, key, where, sizeof where),
                     msg);
}

int dict_value_error(const struct dict_value *v, int code, const char *fmt,
                     ...)
{
    char where[512], msg[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return sim_error(code, "%s: %s", dict_value_where(v, where, sizeof where),
                     msg);
}

/* "missing keyword 'x' in system/controlDict" (+ did you mean). */
static int missing(const struct dict *d, const struct dict *owner,
                   const char *key)
{
    const char *cand[256];
    int nc = 0;
    for (int i = 0; i < owner->n && nc < 256; i++)
        cand[nc++] = owner->e[i].key;
    const char *leaf = strrchr(key, '/') ? strrchr(key, '/') + 1 : key;
    const char *best = dict_suggest(leaf, cand, nc);
    char hint[300] = "";
    if (best)
        snprintf(hint, sizeof hint, " (did you mean '%s'?)", best);
    if (d->name[0])
        return dict_error(d, NULL, SIM_ERR_DICT, "missing keyword '%s' in "
                          "dictionary '%s'%s", key, d->name, hint);
    return dict_error(d, NULL, SIM_ERR_DICT, "missing keyword '%s' in %s%s",
                      key, d->file, hint);
}

static int wrong(const struct dict_value *v, const char *what, const char *key)
{
    char got[128];
    dict_describe(v, got, sizeof got);
    return dict_value_error(v, SIM_ERR_DICT, "expected %s for '%s', got %s",
                            what, key, got);
}

/* Entry for a getter: *e NULL when absent and not required. */
static int get_entry(const struct dict *d, const char *key, int required,
                     struct dict_entry **e)
{
    struct dict *owner;
    *e = find(d, key, &owner, 1);
    if (!*e && required)
        return missing(d, owner, key);
    if (*e)
        (*e)->used = 1;
    return SIM_OK;
}

static void record(const struct dict *d, const char *key,
                   const struct dict_value *v)
{
    char *text = dict_value_to_text(v);
    if (text)
        params_record_entry(d, key, text, 0);
    free(text);
}

static void fmt_double(double x, char *buf, size_t n)
{
    snprintf(buf, n, "%.15g", x);
    if (strtod(buf, NULL) != x)
        snprintf(buf, n, "%.17g", x);
}

/* ---- shapes ----------------------------------------------------------------- */

/* The single number of an entry "x", "[dims] x" or "name [dims] x".
 * *dims is NULL when no set was written. */
static const struct dict_value *scalar_item(const struct dict_value *v,
                                            const int **dims,
                                            enum dict_kind want)
{
    *dims = NULL;
    if (v->kind != DICT_ENTRY)
        return v->kind == want ? v : NULL;
    const struct dict_value *it = v->u.l.items;
    int n = v->u.l.n;
    if (n == 3 && it[0].kind == DICT_WORD && it[1].kind == DICT_DIMS) {
        it++;
        n--;
    }
    if (n == 2 && it[0].kind == DICT_DIMS) {
        *dims = it[0].u.dims;
        it++;
        n--;
    }
    return n == 1 && it[0].kind == want ? &it[0] : NULL;
}

static const struct dict_value *single(const struct dict_value *v)
{
    if (v->kind != DICT_ENTRY)
        return v;
    return v->u.l.n == 1 ? &v->u.l.items[0] : NULL;
}

/* Whether items[0..k) alone is a value of the shape asked for: `want`
 * DICT_NUMBER a scalar, DICT_LIST a list (of `len` numbers when len > 0),
 * DICT_WORD a word or string. */
static int prefix_fits(const struct dict_value *items, int k,
                       enum dict_kind want, int len)
{
    struct dict_value e = { .kind = DICT_ENTRY };
    const int *dims;
    e.u.l.items = (struct dict_value *)items;
    e.u.l.n = k;
    if (want == DICT_WORD)
        return k == 1 && (items[0].kind == DICT_WORD ||
                          items[0].kind == DICT_STRING);
    const struct dict_value *x = scalar_item(&e, &dims, want);
    if (!x || want != DICT_LIST || len <= 0)
        return x != NULL;
    if (x->u.l.n != len)
        return 0;
    for (int i = 0; i < len; i++)
        if (x->u.l.items[i].kind != DICT_NUMBER)
            return 0;
    return 1;
}

/* `min (0 0 0) max (1 1 1);` is one entry 'min' of four values, and "got 4
 * values" would contradict "expected a vector of 3 numbers": a value of
 * the right shape followed by a word is a forgotten ';', reported at that
 * word. Anything else gets the plain "expected ..., got ..." message. */
static int wrong_shape(const struct dict_value *v, const char *what,
                       const char *key, enum dict_kind want, int len)
{
    if (v->kind == DICT_ENTRY)
        for (int k = 1; k < v->u.l.n; k++) {
            const struct dict_value *w = &v->u.l.items[k];
            if (w->kind != DICT_WORD || !prefix_fits(v->u.l.items, k, want,
                                                     len))
                continue;
            return dict_value_error(w, SIM_ERR_DICT, "'%s' holds %s "
                                    "followed by '%s': missing ';' "
                                    "before '%s'?", key, what, w->u.s.text,
                                    w->u.s.text);
        }
    return wrong(v, what, key);
}

/* ---- getters ---------------------------------------------------------------- */

static int scalar_impl(const struct dict *d, const char *key,
                       const int want[7], const double *def, double *out)
{
    struct dict_entry *e;
    TRY(get_entry(d, key, def == NULL, &e));
    if (!e) {
        char buf[64];
        fmt_double(*def, buf, sizeof buf);
        params_record_entry(d, key, buf, 1);
        *out = *def;
        return SIM_OK;
    }
    const int *dims;
    const struct dict_value *x = scalar_item(e->val, &dims, DICT_NUMBER);
    if (!x)
        return wrong_shape(e->val, "a scalar", key, DICT_NUMBER, 0);
    if (want && dims && memcmp(dims, want, 7 * sizeof *dims) != 0) {
        const int *g = dims;
        const int *w = want;
        return dict_value_error(e->val, SIM_ERR_DICT, "dimensions of '%s' "
            "are [%d %d %d %d %d %d %d], expected [%d %d %d %d %d %d %d]", key,
            g[0], g[1], g[2], g[3], g[4], g[5], g[6],
            w[0], w[1], w[2], w[3], w[4], w[5], w[6]);
    }
    *out = x->u.s.num;
    record(d, key, e->val);
    return SIM_OK;
}

int dict_get_scalar(const struct dict *d, const char *key, double *out)
{
    return scalar_impl(d, key, NULL, NULL, out);
}

int dict_get_scalar_or(const struct dict *d, const char *key, double def,
                       double *out)
{
    return scalar_impl(d, key, NULL, &def, out);
}

int dict_get_scalar_dim(const struct dict *d, const char *key,
                        const int dims[7], double *out)
{
    return scalar_impl(d, key, dims, NULL, out);
}

int dict_get_scalar_dim_or(const struct dict *d, const char *key,
                           const int dims[7], double def, double *out)
{
    return scalar_impl(d, key, dims, &def, out);
}

#define EXACT_INT 9007199254740992.0 /* 2^53 */

static int label_of(const struct dict_value *x, const char *key, long *out)
{
    const char *t = x->u.s.text;
    const char *p = t + (*t == '-' || *t == '+');
    if (*p && strspn(p, "0123456789") == strlen(p)) {
        errno = 0;
        long long v = strtoll(t, NULL, 10);
        if (errno == ERANGE || v > (long long)EXACT_INT
            || v < -(long long)EXACT_INT)
            return dict_value_error(x, SIM_ERR_DICT, "integer %s for '%s' is "
                                    "beyond the exact range of a double "
                                    "(2^53)", t, key);
        *out = (long)v;
        return SIM_OK;
    }
    double v = x->u.s.num;
    if (v != floor(v))
        return dict_value_error(x, SIM_ERR_DICT, "expected an integer for "
                                "'%s', got %s", key, t);
    if (fabs(v) > EXACT_INT)
        return dict_value_error(x, SIM_ERR_DICT, "integer %s for '%s' is "
                                "beyond the exact range of a double (2^53)",
                                t, key);
    *out = (long)v;
    return SIM_OK;
}

static int label_impl(const struct dict *d, const char *key, const long *def,
                      long *out)
{
    struct dict_entry *e;
    TRY(get_entry(d, key, def == NULL, &e));
    if (!e) {
        char buf[32];
        snprintf(buf, sizeof buf, "%ld", *def);
        params_record_entry(d, key, buf, 1);
        *out = *def;
        return SIM_OK;
    }
    const int *dims;
    const struct dict_value *x = scalar_item(e->val, &dims, DICT_NUMBER);
    if (!x)
        return wrong_shape(e->val, "an integer", key, DICT_NUMBER, 0);
    TRY(label_of(x, key, out));
    record(d, key, e->val);
    return SIM_OK;
}

int dict_get_label(const struct dict *d, const char *key, long *out)
{
    return label_impl(d, key, NULL, out);
}

int dict_get_label_or(const struct dict *d, const char *key, long def,
                      long *out)
{
    return label_impl(d, key, &def, out);
}

static int bool_impl(const struct dict *d, const char *key, const int *def,
                     int *out)
{
    static const char *const yes[] = { "yes", "on", "true", "y", "1", NULL };
    static const char *const no[] = { "no", "off", "false", "n", "0", NULL };
    struct dict_entry *e;
    TRY(get_entry(d, key, def == NULL, &e));
    if (!e) {
        params_record_entry(d, key, *def ? "true" : "false", 1);
        *out = *def != 0;
        return SIM_OK;
    }
    const struct dict_value *x = single(e->val);
    if (x && (x->kind == DICT_WORD || x->kind == DICT_NUMBER)) {
        for (int i = 0; yes[i]; i++) {
            if (strcmp(x->u.s.text, yes[i]) == 0 || strcmp(x->u.s.text,
                                                           no[i]) == 0) {
                *out = strcmp(x->u.s.text, yes[i]) == 0;
                record(d, key, e->val);
                return SIM_OK;
            }
        }
    }
    return wrong_shape(e->val, "yes/no, on/off, true/false or 1/0", key,
                       DICT_WORD, 0);
}

int dict_get_bool(const struct dict *d, const char *key, int *out)
{
    return bool_impl(d, key, NULL, out);
}

int dict_get_bool_or(const struct dict *d, const char *key, int def, int *out)
{
    return bool_impl(d, key, &def, out);
}

static int word_impl(const struct dict *d, const char *key,
                     const char *const allowed[], const int *def, int *index)
{
    struct dict_entry *e;
    TRY(get_entry(d, key, def == NULL, &e));
    if (!e) {
        params_record_entry(d, key, allowed[*def], 1);
        *index = *def;
        return SIM_OK;
    }
    const struct dict_value *x = single(e->val);
    if (!x || (x->kind != DICT_WORD && x->kind != DICT_STRING))
        return wrong_shape(e->val, "a word", key, DICT_WORD, 0);
    int n = 0;
    for (; allowed[n]; n++) {
        if (strcmp(allowed[n], x->u.s.text) == 0) {
            *index = n;
            record(d, key, e->val);
            return SIM_OK;
        }
    }
    char valid[1024] = "", hint[300] = "";
    size_t used = 0;
    for (int i = 0; i < n && used < sizeof valid - 1; i++)
        used += (size_t)snprintf(valid + used, sizeof valid - used, " %s",
                                 allowed[i]);
    const char *best = dict_suggest(x->u.s.text, (const char *const *)allowed,
                                    n);
    if (best)
        snprintf(hint, sizeof hint, " (did you mean '%s'?)", best);
    return dict_value_error(x, SIM_ERR_DICT, "unknown value '%s' for '%s'%s; "
                            "valid:%s", x->u.s.text, key, hint, valid);
}

int dict_get_word(const struct dict *d, const char *key,
                  const char *const allowed[], int *index)
{
    return word_impl(d, key, allowed, NULL, index);
}

int dict_get_word_or(const struct dict *d, const char *key,
                     const char *const allowed[], int def_index, int *index)
{
    return word_impl(d, key, allowed, &def_index, index);
}

static int string_impl(const struct dict *d, const char *key, const char *def,
                       int has_def, const char **out)
{
    struct dict_entry *e;
    TRY(get_entry(d, key, !has_def, &e));
    if (!e) {
        params_record_entry(d, key, def ? def : "", 1);
        *out = def;
        return SIM_OK;
    }
    const struct dict_value *x = single(e->val);
    if (!x || (x->kind != DICT_WORD && x->kind != DICT_STRING))
        return wrong_shape(e->val, "a word or a quoted string", key,
                           DICT_WORD, 0);
    *out = x->u.s.text;
    record(d, key, e->val);
    return SIM_OK;
}

int dict_get_string(const struct dict *d, const char *key, const char **out)
{
    return string_impl(d, key, NULL, 0, out);
}

int dict_get_string_or(const struct dict *d, const char *key, const char *def,
                       const char **out)
{
    return string_impl(d, key, def, 1, out);
}

static int vector_of(const struct dict_value *v, const char *key, int n,
                     double *out)
{
    const int *dims;
    const struct dict_value *l = scalar_item(v, &dims, DICT_LIST);
    char what[64];
    snprintf(what, sizeof what, "a vector of %d numbers", n);
    if (!l || l->u.l.n != n)
        return l ? wrong(l, what, key)
                 : wrong_shape(v, what, key, DICT_LIST, n);
    for (int i = 0; i < n; i++)
        if (l->u.l.items[i].kind != DICT_NUMBER)
            return wrong(&l->u.l.items[i], "a number", key);
    for (int i = 0; i < n; i++)
        out[i] = l->u.l.items[i].u.s.num;
    return SIM_OK;
}

static int vector_impl(const struct dict *d, const char *key, int n,
                       const double *def, double *out)
{
    struct dict_entry *e;
    TRY(get_entry(d, key, def == NULL, &e));
    if (!e) {
        char buf[1024] = "(";
        size_t used = 1;
        for (int i = 0; i < n && used < sizeof buf - 40; i++) {
            fmt_double(def[i], buf + used, sizeof buf - used);
            used = strlen(buf);
            buf[used++] = i + 1 < n ? ' ' : ')';
            buf[used] = '\0';
        }
        params_record_entry(d, key, buf, 1);
        for (int i = 0; i < n; i++)
            out[i] = def[i];
        return SIM_OK;
    }
    TRY(vector_of(e->val, key, n, out));
    record(d, key, e->val);
    return SIM_OK;
}

int dict_get_vector(const struct dict *d, const char *key, int n, double *out)
{
    return vector_impl(d, key, n, NULL, out);
}

int dict_get_vector_or(const struct dict *d, const char *key, int n,
                       const double *def, double *out)
{
    return vector_impl(d, key, n, def, out);
}

int dict_find_dict(const struct dict *d, const char *key,
                   const struct dict **out)
{
    struct dict_entry *e;
    *out = NULL;
    TRY(get_entry(d, key, 0, &e));
    if (!e)
        return SIM_OK;
    if (e->val->kind != DICT_DICT)
        return wrong(e->val, "a dictionary { ... }", key);
    e->val->u.d->touched = 1;
    *out = e->val->u.d;
    return SIM_OK;
}

int dict_get_dict(const struct dict *d, const char *key,
                  const struct dict **out)
{
    struct dict_entry *e;
    TRY(get_entry(d, key, 1, &e));
    return dict_find_dict(d, key, out);
}

int dict_get_list(const struct dict *d, const char *key,
                  const struct dict_value **out)
{
    struct dict_entry *e;
    TRY(get_entry(d, key, 1, &e));
    const struct dict_value *x = single(e->val);
    if (!x || x->kind != DICT_LIST)
        return wrong_shape(e->val, "a list ( ... )", key, DICT_LIST, 0);
    *out = x;
    record(d, key, e->val);
    return SIM_OK;
}

int dict_get_words(const struct dict *d, const char *key, int max,
                   const char **out, int *n)
{
    const struct dict_value *list;
    TRY(dict_get_list(d, key, &list));
    *n = dict_value_len(list);
    if (*n > max)
        return dict_error(d, key, SIM_ERR_DICT, "%s: more than %d entries",
                          key, max);
    for (int k = 0; k < *n; k++)
        TRY(dict_value_get_word(dict_value_at(list, k), &out[k]));
    return SIM_OK;
}

int dict_get_value(const struct dict *d, const char *key,
                   const struct dict_value **out)
{
    struct dict_entry *e;
    TRY(get_entry(d, key, 1, &e));
    *out = e->val;
    if (e->val->kind == DICT_DICT)
        e->val->u.d->touched = 1;
    else
        record(d, key, e->val);
    return SIM_OK;
}

/* ---- values ------------------------------------------------------------------ */

enum dict_kind dict_value_kind(const struct dict_value *v)
{
    return (enum dict_kind)v->kind;
}

int dict_value_len(const struct dict_value *v)
{
    return v->kind == DICT_LIST || v->kind == DICT_ENTRY ? v->u.l.n : 0;
}

const struct dict_value *dict_value_at(const struct dict_value *v, int i)
{
    if (v->kind != DICT_LIST && v->kind != DICT_ENTRY)
        return NULL;
    return i >= 0 && i < v->u.l.n ? &v->u.l.items[i] : NULL;
}

double dict_value_number(const struct dict_value *v) { return v->u.s.num; }
const char *dict_value_text(const struct dict_value *v) { return v->u.s.text; }

const struct dict *dict_value_dict(const struct dict_value *v)
{
    if (v->kind == DICT_DICT)
        v->u.d->touched = 1;
    return v->u.d;
}

const int *dict_value_dims(const struct dict_value *v) { return v->u.dims; }

int dict_value_get_scalar(const struct dict_value *v, double *out)
{
    const int *dims;
    const struct dict_value *x = scalar_item(v, &dims, DICT_NUMBER);
    if (!x) {
        char got[128];
        dict_describe(v, got, sizeof got);
        return dict_value_error(v, SIM_ERR_DICT, "expected a scalar, got %s",
                                got);
    }
    *out = x->u.s.num;
    return SIM_OK;
}

int dict_value_get_vector(const struct dict_value *v, int n, double *out)
{
    const int *dims;
    const struct dict_value *l = scalar_item(v, &dims, DICT_LIST);
    if (!l || l->u.l.n != n) {
        char got[128];
        dict_describe(l ? l : v, got, sizeof got);
        return dict_value_error(v, SIM_ERR_DICT, "expected a vector of %d "
                                "numbers, got %s", n, got);
    }
    for (int i = 0; i < n; i++) {
        if (l->u.l.items[i].kind != DICT_NUMBER) {
            char got[128];
            dict_describe(&l->u.l.items[i], got, sizeof got);
            return dict_value_error(&l->u.l.items[i], SIM_ERR_DICT,
                                    "expected a number, got %s", got);
        }
        out[i] = l->u.l.items[i].u.s.num;
    }
    return SIM_OK;
}

int dict_value_get_word(const struct dict_value *v, const char **out)
{
    const struct dict_value *x = single(v);
    if (!x || (x->kind != DICT_WORD && x->kind != DICT_STRING)) {
        char got[128];
        dict_describe(v, got, sizeof got);
        return dict_value_error(v, SIM_ERR_DICT, "expected a word, got %s",
                                got);
    }
    *out = x->u.s.text;
    return SIM_OK;
}

int dict_range(const struct dict *d, const char *key, double v, double lo,
               double hi, int lo_open)
{
    if (lo_open ? (v > lo && v <= hi) : (v >= lo && v <= hi))
        return SIM_OK;
    return dict_error(d, key, SIM_ERR_DICT, "%s = %g is out of range %c%g, "
                      "%g]", key, v, lo_open ? '(' : '[', lo, hi);
}
