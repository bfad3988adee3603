/*
 * dict_parse.c — OpenFOAM dictionary grammar (see dict.h), #include, $var
 * substitution and `$sub;` merging, all resolved while reading, as OpenFOAM
 * does: a variable refers to an entry written before it, looked up in the
 * current dictionary and then in its parents ($a/b descends from the first
 * match, $../a starts one level up, $/a/b starts at the top of the file).
 *
 * Values are collected on one scratch stack and copied into the arena when
 * their list or entry closes, so that a list of a million numbers is built
 * without a million reallocations.
 *
 * A missing ';' is reported where it is missing, not at the next entry: an
 * entry's value may span lines, but a bare word that begins a new line after
 * the value has started is taken as the next keyword.
 */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/dict_impl.h"
#include "core/error.h"

#define MAX_INCLUDE_DEPTH 32
#define MAX_NESTING 200
/* $var copies may not grow the parsed data beyond this many bytes plus a
 * multiple of the text read: "b ($a $a); c ($b $b); ..." doubles per line */
#ifndef COPY_BUDGET_BASE /* test/fuzz/run builds with a smaller one */
#define COPY_BUDGET_BASE (128u << 20)
#endif
#define COPY_BUDGET_PER_BYTE 64
#define MAX_TEXT_BYTES (1 << 28)

struct inc_frame {
    const char *display; /* as written in messages (arena)    */
    char *canon;         /* realpath, or NULL                  */
};

struct parser {
    struct dict_root *root;
    struct dict *top;
    struct lexer *lx;
    struct inc_frame inc[MAX_INCLUDE_DEPTH + 1];
    int ninc;
    int nesting;
    size_t text_bytes;        /* read so far, includes too      */
    struct dict_value *stack; /* scratch values being collected */
    size_t sp, scap;
};

static int perr(const struct parser *p, int line, int col, const char *fmt,
                ...) __attribute__((format(printf, 4, 5)));

static int perr(const struct parser *p, int line, int col, const char *fmt,
                ...)
{
    char msg[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return sim_error(SIM_ERR_PARSE, "%s:%d:%d: %s", p->lx->file, line, col,
                     msg);
}

static struct dict_value *push(struct parser *p, const struct token *t,
                               enum dict_kind kind)
{
    if (p->sp == p->scap) {
        size_t cap = p->scap ? 2 * p->scap : 256;
        struct dict_value *s = realloc(p->stack, cap * sizeof *s);
        if (!s) {
            sim_error(SIM_ERR_NOMEM, "out of memory reading %s", p->lx->file);
            return NULL;
        }
        p->stack = s;
        p->scap = cap;
    }
    struct dict_value *v = &p->stack[p->sp++];
    memset(v, 0, sizeof *v);
    v->kind = (unsigned char)kind;
    v->file = p->lx->file;
    v->line = t->line;
    v->col = t->col;
    return v;
}

/* Move stack[base..sp) into the arena as the items of v. */
static int collect(struct parser *p, size_t base, struct dict_value *v)
{
    size_t n = p->sp - base;
    if (n > INT_MAX)
        return sim_error(SIM_ERR_PARSE, "%s: list too long", p->lx->file);
    v->u.l.n = (int)n;
    v->u.l.items = NULL;
    if (n) {
        v->u.l.items = arena_alloc(&p->root->arena, n * sizeof *v->u.l.items);
        if (!v->u.l.items)
            return SIM_ERR_NOMEM;
        memcpy(v->u.l.items, p->stack + base, n * sizeof *v->u.l.items);
    }
    p->sp = base;
    return SIM_OK;
}

static const char *tok_text(struct parser *p, const struct token *t)
{
    if (t->kind == T_STRING)
        return arena_strndup(&p->root->arena, t->str, t->str_len);
    return arena_strndup(&p->root->arena, t->start, t->len);
}

static char *scoped(struct parser *p, const char *parent, const char *key)
{
    size_t np = strlen(parent), nk = strlen(key);
    char *s = arena_alloc(&p->root->arena, np + nk + 2);
    if (!s)
        return NULL;
    if (np) {
        memcpy(s, parent, np);
        s[np++] = '/';
    }
    memcpy(s + np, key, nk + 1);
    return s;
}

static int parse_body(struct parser *p, struct dict *d, const struct token *open,
                      int file_top, size_t *close_end);
static int parse_value(struct parser *p, struct dict *d, const struct token *t,
                       const char *name);

/* ---- variables ---------------------------------------------------------- */

/* Keys visible from d, for "did you mean". */
static int suggest_var(const struct dict *d, int upward, const char *word,
                       char *buf, size_t n)
{
    const char *cand[256];
    int nc = 0;
    for (const struct dict *s = d; s && nc < 256; s = upward ? s->parent : NULL)
        for (int i = 0; i < s->n && nc < 256; i++)
            cand[nc++] = s->e[i].key;
    const char *best = dict_suggest(word, cand, nc);
    if (best)
        snprintf(buf, n, " (did you mean '$%s'?)", best);
    else
        buf[0] = '\0';
    return best != NULL;
}

/* Entry named by the variable token t, as seen from d. */
static int resolve_var(struct parser *p, struct dict *d, const struct token *t,
                       struct dict_entry **out)
{
    char name[512];
    const char *s = t->start + 1;
    size_t n = t->len - 1;
    if (s[0] == '{') {
        s++;
        n -= 2;
    }
    if (n >= sizeof name)
        return perr(p, t->line, t->col, "variable name too long");
    memcpy(name, s, n);
    name[n] = '\0';

    const struct dict *cur = d;
    char *comp = name;
    int upward = 1;
    if (comp[0] == '/') {
        cur = p->top;
        upward = 0;
        while (*comp == '/')
            comp++;
    }
    while (strncmp(comp, "../", 3) == 0 || strcmp(comp, "..") == 0) {
        if (!cur->parent)
            return perr(p, t->line, t->col,
                        "variable '$%s' goes above the top level", name);
        cur = cur->parent;
        comp += comp[2] ? 3 : 2;
    }
    for (;;) {
        char *slash = strchr(comp, '/');
        if (slash)
            *slash = '\0';
        struct dict_entry *e = NULL;
        for (const struct dict *sc = cur; sc && !e;
             sc = upward ? sc->parent : NULL)
            e = dict_lookup(sc, comp);
        if (!e) {
            char hint[300];
            suggest_var(cur, upward, comp, hint, sizeof hint);
            if (slash)
                *slash = '/';
            return perr(p, t->line, t->col, "undefined variable '$%s'%s",
                        name, hint);
        }
        if (!slash) {
            e->referenced = 1;
            *out = e;
            return SIM_OK;
        }
        *slash = '/';
        if (e->val->kind != DICT_DICT)
            return perr(p, t->line, t->col,
                        "variable '$%s': '%.*s' is not a dictionary", name,
                        (int)(slash - name), name);
        e->referenced = 1;
        cur = e->val->u.d;
        upward = 0;
        comp = slash + 1;
    }
}

/* A substituted value is reported where the $var was written: that is the
 * entry a getter asked for (its parts keep their own locations). */
static void relocate(struct dict_value *v, const char *file,
                     const struct token *t)
{
    v->file = file;
    v->line = t->line;
    v->col = t->col;
}

static int copy_budget(const struct parser *p, const struct token *t)
{
    size_t budget = COPY_BUDGET_BASE + COPY_BUDGET_PER_BYTE * p->text_bytes;
    if (p->root->arena.bytes <= budget)
        return SIM_OK;
    return perr(p, t->line, t->col, "'%.*s': substitutions make the "
                "dictionary larger than %zu MB (a $var doubling itself?)",
                (int)(t->len > 60 ? 60 : t->len), t->start, budget >> 20);
}

/* `$var` in a value: push copies of the referenced entry's values. */
static int splice_var(struct parser *p, struct dict *d, const struct token *t,
                      const char *name)
{
    struct dict_entry *e;
    TRY(resolve_var(p, d, t, &e));
    TRY(copy_budget(p, t));
    const struct dict_value *src = e->val;
    if (src->kind == DICT_DICT) {
        struct dict_value *v = push(p, t, DICT_DICT);
        if (!v)
            return SIM_ERR_NOMEM;
        struct dict_value tmp;
        TRY(dict_value_copy(p->root, d, name, src, &tmp));
        relocate(&tmp, p->lx->file, t);
        p->stack[p->sp - 1] = tmp;
        return SIM_OK;
    }
    for (int i = 0; i < src->u.l.n; i++) {
        if (!push(p, t, DICT_WORD))
            return SIM_ERR_NOMEM;
        struct dict_value tmp;
        TRY(dict_value_copy(p->root, d, name, &src->u.l.items[i], &tmp));
        relocate(&tmp, p->lx->file, t);
        p->stack[p->sp - 1] = tmp;
    }
    return SIM_OK;
}

/* `$sub;` inside a dictionary: merge the entries of sub. */
static int parse_merge(struct parser *p, struct dict *d, const struct token *t)
{
    struct dict_entry *e;
    TRY(resolve_var(p, d, t, &e));
    struct token semi;
    TRY(lex_next(p->lx, &semi));
    if (semi.kind != T_SEMI)
        return perr(p, t->end_line, t->end_col, "expected ';' after '%.*s'",
                    (int)t->len, t->start);
    if (e->val->kind != DICT_DICT)
        return perr(p, t->line, t->col,
                    "cannot merge '%.*s' here: '%s' is not a dictionary",
                    (int)t->len, t->start, e->key);
    const struct dict *src = e->val->u.d;
    for (const struct dict *a = d; a; a = a->parent)
        if (a == src)
            return perr(p, t->line, t->col,
                        "cannot merge '%.*s' into itself", (int)t->len,
                        t->start);
    TRY(copy_budget(p, t));
    return dict_merge_into(d, src);
}

/* ---- values -------------------------------------------------------------- */

static int parse_dims(struct parser *p, const struct token *open)
{
    int dims[7] = { 0 }, n = 0;
    for (;;) {
        struct token t;
        TRY(lex_next(p->lx, &t));
        if (t.kind == T_RBRACK)
            break;
        if (t.kind == T_EOF || t.kind == T_SEMI || t.kind == T_RBRACE)
            return perr(p, t.line, t.col,
                        "unbalanced '[' opened at %d:%d: found %s before ']'",
                        open->line, open->col, lex_kind_text(t.kind));
        if (t.kind != T_NUMBER || t.num > 1000 || t.num < -1000
            || t.num != (double)(int)t.num)
            return perr(p, t.line, t.col,
                        "expected an integer exponent in the dimension set, "
                        "got '%.*s'", (int)(t.len > 60 ? 60 : t.len), t.start);
        if (n == 7)
            return perr(p, t.line, t.col,
                        "a dimension set has 7 exponents "
                        "[kg m s K mol A cd], found more");
        dims[n++] = (int)t.num;
    }
    if (n != 7 && n != 5)
        return perr(p, open->line, open->col,
                    "a dimension set has 7 exponents [kg m s K mol A cd] "
                    "(or the first 5), found %d", n);
    struct dict_value *v = push(p, open, DICT_DIMS);
    if (!v)
        return SIM_ERR_NOMEM;
    memcpy(v->u.dims, dims, sizeof dims);
    return SIM_OK;
}

static int parse_list(struct parser *p, struct dict *d, const struct token *open,
                      const char *name)
{
    if (++p->nesting > MAX_NESTING)
        return perr(p, open->line, open->col,
                    "lists and dictionaries nested deeper than %d levels",
                    MAX_NESTING);
    size_t base = p->sp;
    for (;;) {
        struct token t;
        TRY(lex_next(p->lx, &t));
        if (t.kind == T_RPAREN)
            break;
        if (t.kind == T_EOF || t.kind == T_SEMI || t.kind == T_RBRACE)
            return perr(p, t.line, t.col,
                        "unbalanced '(' opened at %d:%d: found %s before ')'",
                        open->line, open->col, lex_kind_text(t.kind));
        if (t.kind == T_LBRACE) {
            /* "name { ... }" pairs as in blockMeshDict's boundary list */
            char label[64];
            const char *sub = label;
            size_t nitems = p->sp - base;
            if (nitems && p->stack[p->sp - 1].kind == DICT_WORD)
                sub = p->stack[p->sp - 1].u.s.text;
            else
                snprintf(label, sizeof label, "%zu", nitems);
            char *dname = scoped(p, name, sub);
            struct dict *sd = dname ? dict_new(p->root, d, dname, p->lx->file,
                                               t.line, t.col) : NULL;
            if (!sd)
                return SIM_ERR_NOMEM;
            sd->in_list = 1;
            TRY(parse_body(p, sd, &t, 0, NULL));
            struct dict_value *v = push(p, &t, DICT_DICT);
            if (!v)
                return SIM_ERR_NOMEM;
            v->u.d = sd;
            continue;
        }
        TRY(parse_value(p, d, &t, name));
    }
    p->nesting--;
    struct dict_value lv = { .kind = DICT_LIST, .file = p->lx->file,
                             .line = open->line, .col = open->col };
    TRY(collect(p, base, &lv));
    struct dict_value *v = push(p, open, DICT_LIST);
    if (!v)
        return SIM_ERR_NOMEM;
    *v = lv;
    return SIM_OK;
}

static int parse_value(struct parser *p, struct dict *d, const struct token *t,
                       const char *name)
{
    struct dict_value *v;
    switch (t->kind) {
    case T_WORD:
    case T_NUMBER:
    case T_STRING:
        v = push(p, t, t->kind == T_WORD     ? DICT_WORD
                       : t->kind == T_NUMBER ? DICT_NUMBER
                                             : DICT_STRING);
        if (!v)
            return SIM_ERR_NOMEM;
        v->u.s.num = t->num;
        v->u.s.text = tok_text(p, t);
        return v->u.s.text ? SIM_OK : SIM_ERR_NOMEM;
    case T_LPAREN:
        return parse_list(p, d, t, name);
    case T_LBRACK:
        return parse_dims(p, t);
    case T_VAR:
        return splice_var(p, d, t, name);
    case T_DIRECTIVE:
        return perr(p, t->line, t->col, "directive '%.*s' is not allowed "
                    "inside a value", (int)t->len, t->start);
    default:
        return perr(p, t->line, t->col, "unexpected %s",
                    lex_kind_text(t->kind));
    }
}

/* ---- entries ------------------------------------------------------------- */

static int parse_subdict(struct parser *p, struct dict *d, const struct token *kt,
                         const char *key, const struct token *open,
                         int file_top)
{
    if (++p->nesting > MAX_NESTING)
        return perr(p, open->line, open->col,
                    "lists and dictionaries nested deeper than %d levels",
                    MAX_NESTING);
    char *name = scoped(p, d->name, key);
    struct dict *sd = name ? dict_new(p->root, d, name, p->lx->file,
                                      open->line, open->col) : NULL;
    struct dict_value *v = arena_alloc(&p->root->arena, sizeof *v);
    if (!sd || !v)
        return SIM_ERR_NOMEM;
    size_t end = open->end;
    TRY(parse_body(p, sd, open, 0, &end));
    p->nesting--;
    /* an included file's own header is not part of the includer */
    if (file_top && p->ninc > 1 && strcmp(key, "FoamFile") == 0)
        return SIM_OK;
    v->kind = DICT_DICT;
    v->file = p->lx->file;
    v->line = open->line;
    v->col = open->col;
    v->u.d = sd;
    struct dict_entry *e = dict_put(d, key);
    if (!e)
        return SIM_ERR_NOMEM;
    e->file = p->lx->file;
    e->line = kt->line;
    e->col = kt->col;
    e->val = v;
    e->vbeg = open->off;
    e->vend = end;
    return SIM_OK;
}

static int parse_entry(struct parser *p, struct dict *d, const struct token *kt,
                       int file_top)
{
    const char *key = tok_text(p, kt);
    if (!key)
        return SIM_ERR_NOMEM;
    struct token t;
    TRY(lex_next(p->lx, &t));
    if (t.kind == T_LBRACE)
        return parse_subdict(p, d, kt, key, &t, file_top);

    char *name = scoped(p, d->name, key);
    if (!name)
        return SIM_ERR_NOMEM;
    size_t base = p->sp, vbeg = t.off, vend = t.off;
    int last_line = kt->end_line, last_col = kt->end_col, nvals = 0;
    while (t.kind != T_SEMI) {
        int lost = t.kind == T_EOF || t.kind == T_RBRACE || t.kind == T_LBRACE
                   || (t.kind == T_WORD && t.first_on_line && nvals > 0);
        if (lost)
            return perr(p, last_line, last_col,
                        "expected ';' after the value of '%s'", key);
        TRY(parse_value(p, d, &t, name));
        nvals++;
        vend = t.end;
        last_line = t.end_line;
        last_col = t.end_col;
        /* a list's closing ')' is where the value ended */
        if (t.kind == T_LPAREN || t.kind == T_LBRACK) {
            vend = p->lx->pos;
            last_line = p->lx->line;
            last_col = p->lx->col;
        }
        TRY(lex_next(p->lx, &t));
    }
    if (nvals == 0)
        vbeg = vend = t.off;

    struct dict_value *v = arena_alloc(&p->root->arena, sizeof *v);
    if (!v)
        return SIM_ERR_NOMEM;
    v->kind = DICT_ENTRY;
    v->file = p->lx->file;
    v->line = p->sp > base ? p->stack[base].line : kt->line;
    v->col = p->sp > base ? p->stack[base].col : kt->col;
    TRY(collect(p, base, v));
    /* "key $sub;" copies a whole dictionary: the entry is a dictionary */
    if (v->u.l.n == 1 && v->u.l.items[0].kind == DICT_DICT)
        v = &v->u.l.items[0];
    for (int i = 0; v->kind == DICT_ENTRY && i < v->u.l.n; i++)
        if (v->u.l.items[i].kind == DICT_DICT) /* no syntax to write it */
            return perr(p, v->u.l.items[i].line, v->u.l.items[i].col,
                        "a dictionary cannot be one of several values of "
                        "'%s' (put it in a list, or merge it with '$name;')",
                        key);
    struct dict_entry *e = dict_put(d, key);
    if (!e)
        return SIM_ERR_NOMEM;
    e->file = p->lx->file;
    e->line = kt->line;
    e->col = kt->col;
    e->val = v;
    e->vbeg = vbeg;
    e->vend = vend;
    return SIM_OK;
}

/* ---- files and #include ------------------------------------------------- */

const char *dict_strerror(int err)
{
    return err == DICT_ENOTREG ? "not a regular file" : strerror(err);
}

int dict_slurp(const char *path, char **text, size_t *len)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK); /* a FIFO must not block */
    if (fd < 0)
        return errno;
    struct stat st;
    /* only regular files: "#include \"/dev/zero\"" must not hang */
    if (fstat(fd, &st) != 0) {
        int err = errno;
        close(fd);
        return err;
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return S_ISDIR(st.st_mode) ? EISDIR : DICT_ENOTREG;
    }
    size_t cap = st.st_size > 0 ? (size_t)st.st_size + 1 : 4096, n = 0;
    char *buf = malloc(cap);
    if (!buf) {
        close(fd);
        return ENOMEM;
    }
    for (;;) {
        if (n + 1 >= cap) {
            char *nb = realloc(buf, cap * 2);
            if (!nb) {
                free(buf);
                close(fd);
                return ENOMEM;
            }
            buf = nb;
            cap *= 2;
        }
        ssize_t r = read(fd, buf + n, cap - n - 1);
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0) {
            int err = errno;
            free(buf);
            close(fd);
            return err;
        }
        if (r == 0)
            break;
        n += (size_t)r;
    }
    close(fd);
    buf[n] = '\0';
    *text = buf;
    *len = n;
    return 0;
}

static int parse_text(struct parser *p, struct dict *d, const char *text,
                      size_t len, const char *display)
{
    struct lexer lx, *saved = p->lx;
    lex_init(&lx, text, len, display);
    p->lx = &lx;
    p->text_bytes += len;
    int rc = parse_body(p, d, NULL, 1, NULL);
    lex_release(&lx);
    p->lx = saved;
    return rc;
}

static char *include_path(struct parser *p, const char *rel)
{
    const char *cur = p->lx->file;
    const char *slash = strrchr(cur, '/');
    if (rel[0] == '/' || !slash)
        return arena_strndup(&p->root->arena, rel, strlen(rel));
    size_t nd = (size_t)(slash - cur) + 1, nr = strlen(rel);
    char *s = arena_alloc(&p->root->arena, nd + nr + 1);
    if (s) {
        memcpy(s, cur, nd);
        memcpy(s + nd, rel, nr + 1);
    }
    return s;
}

static int include_cycle(struct parser *p, const struct token *t,
                         const char *canon, const char *path)
{
    for (int i = 0; i < p->ninc; i++) {
        if (!p->inc[i].canon || strcmp(p->inc[i].canon, canon) != 0)
            continue;
        char chain[1024] = "";
        size_t used = 0;
        for (int j = i; j < p->ninc && used < sizeof chain; j++)
            used += (size_t)snprintf(chain + used, sizeof chain - used,
                                     "%s -> ", p->inc[j].display);
        return perr(p, t->line, t->col, "#include cycle: %s%s", chain, path);
    }
    return SIM_OK;
}

static int parse_include(struct parser *p, struct dict *d, const struct token *t)
{
    int optional = t->len == 17 && strncmp(t->start, "#includeIfPresent", 17) == 0;
    if (!optional && !(t->len == 8 && strncmp(t->start, "#include", 8) == 0))
        return perr(p, t->line, t->col, "unsupported directive '%.*s' "
                    "(supported: #include, #includeIfPresent)",
                    (int)(t->len > 40 ? 40 : t->len), t->start);
    struct token f;
    TRY(lex_next(p->lx, &f));
    if (f.kind != T_STRING)
        return perr(p, f.line, f.col, "expected a quoted file name after "
                    "'%.*s', got %s", (int)t->len, t->start,
                    lex_kind_text(f.kind));
    char *path = include_path(p, f.str);
    if (!path)
        return SIM_ERR_NOMEM;
    if (p->ninc >= MAX_INCLUDE_DEPTH)
        return perr(p, t->line, t->col, "#include nested deeper than %d "
                    "files", MAX_INCLUDE_DEPTH);
    if (p->text_bytes > MAX_TEXT_BYTES) /* repeated includes, nested */
        return perr(p, t->line, t->col, "#include: more than %d MB of text "
                    "read in all", MAX_TEXT_BYTES >> 20);
    char *text;
    size_t len;
    int err = dict_slurp(path, &text, &len);
    if (err) {
        if (optional && err == ENOENT)
            return SIM_OK;
        char where[64];
        snprintf(where, sizeof where, "%d:%d", f.line, f.col);
        return sim_error(SIM_ERR_IO, "%s:%s: cannot open included file "
                         "'%s': %s", p->lx->file, where, path,
                         dict_strerror(err));
    }
    char *canon = realpath(path, NULL);
    int rc = canon ? include_cycle(p, t, canon, path) : SIM_OK;
    if (rc == SIM_OK) {
        p->inc[p->ninc].display = path;
        p->inc[p->ninc].canon = canon;
        p->ninc++;
        rc = parse_text(p, d, text, len, path);
        p->ninc--;
    }
    free(canon);
    free(text);
    return rc;
}

/* Entries up to the closing '}' (open != NULL) or the end of the text. */
static int parse_body(struct parser *p, struct dict *d, const struct token *open,
                      int file_top, size_t *close_end)
{
    for (;;) {
        struct token t;
        TRY(lex_next(p->lx, &t));
        switch (t.kind) {
        case T_EOF:
            if (open)
                return perr(p, t.line, t.col, "unbalanced '{' opened at "
                            "%d:%d: end of file before '}'", open->line,
                            open->col);
            return SIM_OK;
        case T_RBRACE:
            if (!open)
                return perr(p, t.line, t.col, "unexpected '}': no '{' is "
                            "open");
            if (close_end)
                *close_end = t.end;
            return SIM_OK;
        case T_SEMI:
            break; /* stray ';' as after "};" is harmless */
        case T_DIRECTIVE:
            TRY(parse_include(p, d, &t));
            break;
        case T_VAR:
            TRY(parse_merge(p, d, &t));
            break;
        case T_WORD:
        case T_NUMBER:
        case T_STRING:
            TRY(parse_entry(p, d, &t, file_top));
            break;
        default:
            return perr(p, t.line, t.col, "expected a keyword, got %s",
                        lex_kind_text(t.kind));
        }
    }
}

/* ---- public ----------------------------------------------------------------- */

int dict_read_string(const char *text, size_t len, const char *name,
                     struct dict **out)
{
    *out = NULL;
    struct dict_root *root = calloc(1, sizeof *root);
    if (!root)
        return sim_error(SIM_ERR_NOMEM, "out of memory reading %s", name);
    struct parser p = { .root = root };
    char *file = arena_strndup(&root->arena, name, strlen(name));
    struct dict *top = file ? dict_new(root, NULL, "", file, 1, 1) : NULL;
    if (!top) {
        free(root);
        return SIM_ERR_NOMEM;
    }
    p.top = top;
    p.inc[0].display = file;
    p.inc[0].canon = realpath(name, NULL);
    p.ninc = 1;
    int rc = parse_text(&p, top, text, len, file);
    free(p.inc[0].canon);
    free(p.stack);
    if (rc != SIM_OK) {
        dict_free(top);
        return rc;
    }
    *out = top;
    return SIM_OK;
}

int dict_read(const char *path, struct dict **out)
{
    char *text;
    size_t len;
    *out = NULL;
    int err = dict_slurp(path, &text, &len);
    if (err)
        return sim_error(SIM_ERR_IO, "cannot open '%s': %s", path,
                         dict_strerror(err));
    int rc = dict_read_string(text, len, path, out);
    free(text);
    return rc;
}

void dict_free(struct dict *d)
{
    if (!d || d->parent)
        return; /* sub-dictionaries belong to their file */
    struct dict_root *root = d->root;
    for (struct dict *s = root->dicts; s; s = s->next_in_root) {
        free(s->e);
        free(s->hash);
        free(s->asked);
    }
    arena_free(&root->arena);
    free(root);
}
