/*
 * dict_edit.c — dict_set_in_file (foamDictionary -set) and atomic writes.
 *
 * The file is parsed once to find the byte range of the value (the parser
 * records it per entry); only that range changes, so comments and layout
 * survive. A key that is absent, or whose text lives elsewhere (an
 * #include, a $sub merge), gets a new entry at the end of the innermost
 * dictionary of this file on its path, which overrides (last one wins).
 * The edited text is parsed again and must give the requested value before
 * the file is replaced; otherwise nothing is written. Several edits of one
 * file are applied in turn to the text and written once.
 */
#include <errno.h>
#include <libgen.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/dict_impl.h"
#include "core/error.h"
#include "core/files.h"

/* ---- atomic write ------------------------------------------------------------ */

int dict_write_atomic(const char *path, const char *text, size_t len,
                      int mkparent)
{
    char *copy = strdup(path);
    if (!copy)
        return sim_error(SIM_ERR_NOMEM, "out of memory");
    int rc = mkparent ? files_mkdir_p(dirname(copy)) : SIM_OK;
    free(copy);
    if (rc != SIM_OK)
        return rc;
    size_t n = strlen(path);
    char *tmp = malloc(n + 16);
    if (!tmp)
        return sim_error(SIM_ERR_NOMEM, "out of memory");
    snprintf(tmp, n + 16, "%s.tmpXXXXXX", path);
    int fd = mkstemp(tmp);
    if (fd < 0) {
        rc = sim_error(SIM_ERR_IO, "cannot write '%s': %s", path,
                       strerror(errno));
        free(tmp);
        return rc;
    }
    struct stat st;
    mode_t mode = 0644;
    if (stat(path, &st) == 0) {
        mode = st.st_mode & 07777;
    } else {
        mode_t mask = umask(0);
        umask(mask);
        mode &= ~mask;
    }
    size_t done = 0;
    while (done < len) {
        ssize_t w = write(fd, text + done, len - done);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            break;
        done += (size_t)w;
    }
    int err = done < len ? errno : 0;
    if (!err && (fchmod(fd, mode) != 0 || fsync(fd) != 0))
        err = errno;
    if (close(fd) != 0 && !err)
        err = errno;
    if (!err && rename(tmp, path) != 0)
        err = errno;
    if (err) {
        unlink(tmp);
        rc = sim_error(SIM_ERR_IO, "cannot write '%s': %s", path,
                       strerror(err ? err : EIO));
    }
    free(tmp);
    return rc;
}

/* ---- set in file ------------------------------------------------------------ */

struct edit {
    size_t at, cut;   /* replace text[at, at+cut) ...  */
    char *with;       /* ... by this (malloc'd)        */
};

static char *append(char *s, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

static char *append(char *s, const char *fmt, ...)
{
    if (!s)
        return NULL;
    va_list ap;
    va_start(ap, fmt);
    char *add = NULL;
    int n = vasprintf(&add, fmt, ap);
    va_end(ap);
    if (n < 0) {
        free(s);
        return NULL;
    }
    size_t ns = strlen(s);
    char *r = realloc(s, ns + (size_t)n + 1);
    if (!r) {
        free(s);
        free(add);
        return NULL;
    }
    memcpy(r + ns, add, (size_t)n + 1);
    free(add);
    return r;
}

/* "key value;" nested under the dictionaries comps[0..n-2]. `shadow` is
 * the dictionary of this level that exists but whose text is elsewhere (an
 * #include): its entries are merged in first with "$name;", so that the new
 * dictionary replaces it without losing them. */
static char *nested(char *s, char **comps, int n, const char *value,
                    int indent, const struct dict *shadow)
{
    if (n == 1) {
        int pad = 16 - (int)strlen(comps[0]);
        return append(s, "%*s%s%*s%s;\n", indent, "", comps[0],
                      pad > 1 ? pad : 1, "", value);
    }
    const struct dict_entry *e = shadow ? dict_lookup(shadow, comps[0]) : NULL;
    const struct dict *sub = e && e->val->kind == DICT_DICT ? e->val->u.d
                                                            : NULL;
    s = append(s, "%*s%s\n%*s{\n", indent, "", comps[0], indent, "");
    if (sub)
        s = append(s, "%*s$%s;\n", indent + 4, "", comps[0]);
    s = nested(s, comps + 1, n - 1, value, indent + 4, sub);
    return append(s, "%*s}\n", indent, "");
}

/* Insert the missing part of the path into the dictionary whose text is
 * [beg, end) ("{ ... }"), or at the end of the file when beg == end == -1. */
static int plan_insert(const char *text, size_t len, size_t beg, size_t end,
                       char **comps, int n, const char *value, int depth,
                       const struct dict *shadow, struct edit *ed)
{
    int indent = 4 * depth;
    char *s = strdup("");
    if (beg == (size_t)-1) {
        ed->at = len;
        ed->cut = 0;
        if (len && text[len - 1] != '\n')
            s = append(s, "\n");
        s = append(s, "\n");
        s = nested(s, comps, n, value, 0, shadow);
    } else {
        size_t close = end - 1; /* the '}' */
        size_t ls = close;
        while (ls > beg && (text[ls - 1] == ' ' || text[ls - 1] == '\t'))
            ls--;
        if (ls > beg && text[ls - 1] == '\n') {
            ed->at = ls;
            ed->cut = 0;
            s = nested(s, comps, n, value, indent, shadow);
        } else {
            ed->at = close;
            ed->cut = 0;
            s = append(s, "\n");
            s = nested(s, comps, n, value, indent, shadow);
            s = append(s, "%*s", indent > 4 ? indent - 4 : 0, "");
        }
    }
    if (!s)
        return sim_error(SIM_ERR_NOMEM, "out of memory");
    ed->with = s;
    return SIM_OK;
}

/* A dictionary entry written as "$sub": its text becomes
 * "{ $sub; <new entries> }" so that the new entries override the copy. */
static int plan_open_copy(const char *text, const struct dict_entry *e,
                          char **comps, int n, const char *value, int depth,
                          struct edit *ed)
{
    int indent = 4 * depth;
    char *s = strdup("");
    s = append(s, "\n%*s{\n%*s%.*s;\n", indent - 4, "", indent, "",
               (int)(e->vend - e->vbeg), text + e->vbeg);
    s = nested(s, comps, n, value, indent, e->val->u.d);
    s = append(s, "%*s}", indent - 4, "");
    if (!s)
        return sim_error(SIM_ERR_NOMEM, "out of memory");
    ed->at = e->vbeg;
    while (ed->at > 0 && (text[ed->at - 1] == ' ' || text[ed->at - 1] == '\t'))
        ed->at--; /* no trailing blanks after the key */
    ed->cut = e->vend - ed->at;
    ed->with = s;
    return SIM_OK;
}

static int editable(const struct dict *top, const struct dict_entry *e)
{
    return e->file == top->file && e->vbeg != (size_t)-1;
}

static int plan_edit(const struct dict *top, const char *text, size_t len,
                     char **comps, int n, const char *value,
                     const struct dict_value *newv, struct edit *ed)
{
    const struct dict *cur = top;
    size_t beg = (size_t)-1, end = (size_t)-1;
    for (int i = 0; i < n; i++) {
        struct dict_entry *e = dict_lookup(cur, comps[i]);
        if (!e || !editable(top, e))
            return plan_insert(text, len, beg, end, comps + i, n - i, value,
                               i, cur, ed);
        if (i == n - 1) {
            ed->at = e->vbeg;
            ed->cut = e->vend - e->vbeg;
            const char *fmt = e->vbeg == e->vend ? " %s" : "%s";
            if (e->val->kind == DICT_DICT && newv->kind != DICT_DICT)
                fmt = "%s;";
            if (asprintf(&ed->with, fmt, value) < 0)
                return sim_error(SIM_ERR_NOMEM, "out of memory");
            return SIM_OK;
        }
        if (e->val->kind != DICT_DICT)
            return sim_error(SIM_ERR_DICT, "%s:%d:%d: cannot set '%s' below "
                             "'%s': '%s' is not a dictionary", e->file,
                             e->line, e->col, comps[n - 1], comps[i],
                             comps[i]);
        if (text[e->vbeg] != '{')
            return plan_open_copy(text, e, comps + i + 1, n - i - 1, value,
                                  i + 1, ed);
        beg = e->vbeg;
        end = e->vend;
        cur = e->val->u.d;
    }
    return sim_error(SIM_ERR_INTERNAL, "empty key path");
}

/* The new value, parsed on its own, must be one value and nothing else. */
static int check_value(const char *keypath, const char *value,
                       struct dict **vd)
{
    char *probe = NULL;
    if (asprintf(&probe, "x %s\n;", value) < 0)
        return sim_error(SIM_ERR_NOMEM, "out of memory");
    char name[300];
    snprintf(name, sizeof name, "value given for '%.200s'", keypath);
    int rc = dict_read_string(probe, strlen(probe), name, vd);
    free(probe);
    if (rc != SIM_OK)
        return rc;
    /* "1; y 2" would parse as two entries, "1; x 2" as a later x */
    if (dict_size(*vd) != 1 || strcmp(dict_key_at(*vd, 0), "x") != 0
        || (*vd)->e[0].vbeg != 2) {
        dict_free(*vd);
        *vd = NULL;
        return sim_error(SIM_ERR_DICT, "the value given for '%s' is not one "
                         "value: '%s'", keypath, value);
    }
    return SIM_OK;
}

static int split_path(char *kp, char **comps, int max)
{
    int n = 0;
    for (char *s = strtok(kp, "/"); s; s = strtok(NULL, "/")) {
        if (n == max)
            return -1;
        comps[n++] = s;
    }
    return n;
}

/* Parse the edited text and compare the value at keypath. */
static int verify(const char *path, const char *text, size_t len,
                  const char *keypath, const struct dict_value *want)
{
    struct dict *d;
    TRY(dict_read_string(text, len, path, &d));
    const struct dict_entry *e = dict_find_entry(d, keypath);
    int rc = e ? SIM_OK : sim_error(SIM_ERR_INTERNAL, "%s: '%s' not found "
                                    "after setting it", path, keypath);
    char *a = e ? dict_value_to_text(e->val) : NULL;
    char *b = dict_value_to_text(want);
    if (rc == SIM_OK && (!a || !b || strcmp(a, b) != 0))
        rc = sim_error(SIM_ERR_DICT, "%s: cannot set '%s': a later entry or "
                       "#include overrides it", path, keypath);
    free(a);
    free(b);
    dict_free(d);
    return rc;
}

/* Without allow_new, a key path must exist: a misspelt key would silently
 * become a new entry that nothing reads. The message names the innermost
 * dictionary that exists and suggests one of its keys. */
static int check_exists(const struct dict *top, char **comps, int n)
{
    const struct dict *cur = top;
    int i = 0;
    for (; i < n; i++) {
        struct dict_entry *e = dict_lookup(cur, comps[i]);
        if (!e)
            break;
        if (i == n - 1 || e->val->kind != DICT_DICT)
            return SIM_OK; /* a non-dictionary parent: plan_edit says so */
        cur = e->val->u.d;
    }
    const char *cand[256];
    int nc = 0;
    for (int k = 0; k < cur->n && nc < 256; k++)
        cand[nc++] = cur->e[k].key;
    const char *best = dict_suggest(comps[i], cand, nc);
    char want[1024] = "", near[1024] = "", hint[1100] = "", where[512];
    for (int k = 0; k < n; k++) {
        size_t used = strlen(want), un = strlen(near);
        snprintf(want + used, sizeof want - used, k ? "/%s" : "%s", comps[k]);
        snprintf(near + un, sizeof near - un, k ? "/%s" : "%s",
                 k == i && best ? best : comps[k]);
    }
    if (best)
        snprintf(hint, sizeof hint, " (did you mean '%s'?)", near);
    dict_where(cur, NULL, where, sizeof where);
    return sim_error(SIM_ERR_DICT, "%s: no key '%s' to set%s; a new key "
                     "needs -new", where, want, hint);
}

/* One edit of the text [text, text + len) of `path` into *out. */
static int set_in_text(const char *path, const char *text, size_t len,
                       const char *keypath, const char *value,
                       char **out, size_t *nout)
{
    struct dict *vd = NULL, *d = NULL;
    char *kp = strdup(keypath);
    char *comps[64];
    struct edit ed = { 0 };
    int rc, n;
    *out = NULL;
    if (!kp)
        return sim_error(SIM_ERR_NOMEM, "out of memory");
    n = split_path(kp, comps, 64);
    if (n <= 0) {
        rc = sim_error(SIM_ERR_INPUT, "bad key path '%s'", keypath);
        goto out;
    }
    TRY_GOTO(rc, check_value(keypath, value, &vd), out);
    TRY_GOTO(rc, dict_read_string(text, len, path, &d), out);
    const struct dict_value *newv = vd->e[0].val;
    TRY_GOTO(rc, plan_edit(d, text, len, comps, n, value, newv, &ed), out);
    size_t nw = strlen(ed.with);
    *nout = len - ed.cut + nw;
    *out = malloc(*nout + 1);
    if (!*out) {
        rc = sim_error(SIM_ERR_NOMEM, "out of memory");
        goto out;
    }
    memcpy(*out, text, ed.at);
    memcpy(*out + ed.at, ed.with, nw);
    memcpy(*out + ed.at + nw, text + ed.at + ed.cut, len - ed.at - ed.cut);
    (*out)[*nout] = '\0';
out:
    free(ed.with);
    free(kp);
    dict_free(d);
    dict_free(vd);
    return rc;
}

int dict_set_entries_in_file(const char *path, int n,
                             const char *const *keypaths,
                             const char *const *values, int allow_new)
{
    char *text = NULL, *next = NULL;
    size_t len, nnext = 0;
    struct dict *d = NULL;
    int rc = SIM_OK;
    /* the edits are checked together at the end, where an undone one
     * could only be reported as "overridden": say which */
    for (int k = 0; k < n; k++)
        for (int l = k + 1; l < n; l++) {
            size_t m = strlen(keypaths[l]);
            if (strncmp(keypaths[k], keypaths[l], m) == 0 &&
                (keypaths[k][m] == '\0' || keypaths[k][m] == '/'))
                return sim_error(SIM_ERR_INPUT, "%s: the edit of '%s' would "
                                 "be undone by the later one of '%s'", path,
                                 keypaths[k], keypaths[l]);
        }
    int err = dict_slurp(path, &text, &len);
    if (err)
        return sim_error(SIM_ERR_IO, "cannot open '%s': %s", path,
                         dict_strerror(err));
    /* every key is checked against the file as it is, so that the lines
     * named are the file's */
    if (!allow_new) {
        TRY_GOTO(rc, dict_read_string(text, len, path, &d), out);
        for (int k = 0; k < n && rc == SIM_OK; k++) {
            char *kp = strdup(keypaths[k]), *comps[64];
            if (!kp) {
                rc = sim_error(SIM_ERR_NOMEM, "out of memory");
                break;
            }
            int nc = split_path(kp, comps, 64);
            rc = nc <= 0 ? sim_error(SIM_ERR_INPUT, "bad key path '%s'",
                                     keypaths[k])
                         : check_exists(d, comps, nc);
            free(kp);
        }
        if (rc != SIM_OK)
            goto out;
    }
    for (int k = 0; k < n; k++) {
        TRY_GOTO(rc, set_in_text(path, text, len, keypaths[k], values[k],
                                 &next, &nnext), out);
        free(text);
        text = next;
        len = nnext;
        next = NULL;
    }
    /* a later edit of the same key (or of a dictionary above it) would
     * undo an earlier one: all must hold, or nothing is written */
    for (int k = 0; k < n; k++) {
        struct dict *vd;
        TRY_GOTO(rc, check_value(keypaths[k], values[k], &vd), out);
        rc = verify(path, text, len, keypaths[k], vd->e[0].val);
        dict_free(vd);
        if (rc != SIM_OK)
            goto out;
    }
    rc = dict_write_atomic(path, text, len, 0);
out:
    dict_free(d);
    free(text);
    return rc;
}

int dict_set_in_file(const char *path, const char *keypath, const char *value)
{
    return dict_set_entries_in_file(path, 1, &keypath, &value, 1);
}
