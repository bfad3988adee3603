/*
 * dict_write.c — print dictionaries and values in OpenFOAM layout
 * (foamDictionary -expand): 4-space indent, keys padded to 16 columns,
 * short lists on one line, long or nested ones as a block
 *
 *     vertices
 *     (
 *         (0 0 0) (1 0 0)
 *     );
 *
 * The output must parse back to the same content, so keys that are not
 * plain words are quoted, strings are re-escaped, numbers keep their text,
 * and a line inside an entry never starts with a bare word (the parser
 * would take it for a keyword after a missing ';').
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/dict_impl.h"
#include "core/error.h"

#define KEY_WIDTH 16
#define LINE_WIDTH 72

static void put_indent(FILE *f, int n)
{
    for (int i = 0; i < n; i++)
        fputc(' ', f);
}

static void put_quoted(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        switch (*s) {
        case '"': fputs("\\\"", f); break;
        case '\\': fputs("\\\\", f); break;
        case '\n': fputs("\\n", f); break;
        case '\t': fputs("\\t", f); break;
        default: fputc(*s, f);
        }
    }
    fputc('"', f);
}

/* A key the lexer reads back as one word or number with the same text. */
static int plain_key(const char *k)
{
    struct lexer lx;
    struct token t;
    size_t n = strlen(k);
    lex_init(&lx, k, n, "");
    int ok = lex_next(&lx, &t) == SIM_OK && (t.kind == T_WORD
                                             || t.kind == T_NUMBER)
             && t.len == n;
    lex_release(&lx);
    if (!ok)
        sim_error_clear();
    return ok;
}

static long quoted_len(const char *s)
{
    long n = 2;
    for (; *s; s++)
        n += strchr("\"\\\n\t", *s) ? 2 : 1;
    return n;
}

static int put_key(FILE *f, const char *k)
{
    if (plain_key(k)) {
        fputs(k, f);
        return (int)strlen(k);
    }
    put_quoted(f, k);
    return (int)quoted_len(k);
}

/* A word such as "f((x)" whose '(' the lexer left open: a ')' right after
 * it would be read as part of the word. */
static int open_word(const struct dict_value *v)
{
    if (v->kind != DICT_WORD)
        return 0;
    int depth = 0;
    for (const char *s = v->u.s.text; *s; s++)
        depth += *s == '(' ? 1 : *s == ')' && depth > 0 ? -1 : 0;
    return depth > 0;
}

/* Length of v written on one line, or -1 when it needs a block. */
static long inline_len(const struct dict_value *v)
{
    switch ((enum dict_kind)v->kind) {
    case DICT_WORD:
    case DICT_NUMBER:
        return (long)strlen(v->u.s.text) + open_word(v);
    case DICT_STRING:
        return quoted_len(v->u.s.text);
    case DICT_DIMS:
        return 20;
    case DICT_DICT:
        return -1;
    case DICT_LIST:
    case DICT_ENTRY: {
        long n = v->kind == DICT_LIST ? 2 : 0;
        for (int i = 0; i < v->u.l.n; i++) {
            long m = inline_len(&v->u.l.items[i]);
            if (m < 0)
                return -1;
            n += m + (i > 0);
            if (n > LINE_WIDTH && v->kind == DICT_LIST)
                return -1;
        }
        return n;
    }
    }
    return -1;
}

static void put_body(const struct dict *d, FILE *f, int indent);
static void put_block(const struct dict_value *l, FILE *f, int indent);

static void put_inline(const struct dict_value *v, FILE *f)
{
    switch ((enum dict_kind)v->kind) {
    case DICT_WORD:
    case DICT_NUMBER:
        fputs(v->u.s.text, f);
        break;
    case DICT_STRING:
        put_quoted(f, v->u.s.text);
        break;
    case DICT_DIMS:
        fprintf(f, "[%d %d %d %d %d %d %d]", v->u.dims[0], v->u.dims[1],
                v->u.dims[2], v->u.dims[3], v->u.dims[4], v->u.dims[5],
                v->u.dims[6]);
        break;
    case DICT_LIST:
    case DICT_ENTRY:
        if (v->kind == DICT_LIST)
            fputc('(', f);
        for (int i = 0; i < v->u.l.n; i++) {
            if (i)
                fputc(' ', f);
            put_inline(&v->u.l.items[i], f);
        }
        if (v->kind == DICT_LIST) {
            if (v->u.l.n && open_word(&v->u.l.items[v->u.l.n - 1]))
                fputc(' ', f);
            fputc(')', f);
        }
        break;
    case DICT_DICT:
        break; /* never inline */
    }
}

static void put_dict_block(const struct dict *d, FILE *f, int indent)
{
    put_indent(f, indent);
    fputs("{\n", f);
    put_body(d, f, indent + 4);
    put_indent(f, indent);
    fputc('}', f);
}

/* "(" and ")" on lines of their own at `indent`, items packed in between. */
static void put_block(const struct dict_value *l, FILE *f, int indent)
{
    put_indent(f, indent);
    fputs("(\n", f);
    long col = 0;
    for (int i = 0; i < l->u.l.n; i++) {
        const struct dict_value *it = &l->u.l.items[i];
        long m = inline_len(it);
        int before_dict = i + 1 < l->u.l.n
                          && l->u.l.items[i + 1].kind == DICT_DICT;
        if (m < 0 || before_dict || (col > 0 && col + 1 + m > LINE_WIDTH)) {
            if (col > 0)
                fputc('\n', f);
            col = 0;
        }
        if (m < 0) {
            if (it->kind == DICT_DICT)
                put_dict_block(it->u.d, f, indent + 4);
            else
                put_block(it, f, indent + 4);
            fputc('\n', f);
            continue;
        }
        if (col == 0) {
            put_indent(f, indent + 4);
            col = indent + 4;
        } else {
            fputc(' ', f);
            col++;
        }
        put_inline(it, f);
        col += m;
        if (before_dict) {
            fputc('\n', f);
            col = 0;
        }
    }
    if (col > 0)
        fputc('\n', f);
    put_indent(f, indent);
    fputc(')', f);
}

/* The items of an entry after its key: inline ones on the key's line,
 * blocks on their own lines. */
static void put_items(const struct dict_value *v, FILE *f, int indent,
                      int key_len)
{
    if (v->kind == DICT_DICT) {
        fputc('\n', f);
        put_dict_block(v->u.d, f, indent);
        return;
    }
    long m = inline_len(v);
    if (m >= 0 && m + indent + KEY_WIDTH <= 200) {
        if (v->u.l.n) {
            put_indent(f, key_len < KEY_WIDTH ? KEY_WIDTH - key_len : 1);
            put_inline(v, f);
        }
        fputc(';', f);
        return;
    }
    /* a block's ')' is followed by the next items on its line */
    for (int i = 0; i < v->u.l.n; i++) {
        const struct dict_value *it = &v->u.l.items[i];
        if (inline_len(it) < 0) {
            fputc('\n', f);
            put_block(it, f, indent);
        } else {
            fputc(' ', f);
            put_inline(it, f);
        }
    }
    fputc(';', f);
}

static void put_body(const struct dict *d, FILE *f, int indent)
{
    for (int i = 0; i < d->n; i++) {
        const struct dict_entry *e = &d->e[i];
        put_indent(f, indent);
        int kl = put_key(f, e->key);
        put_items(e->val, f, indent, kl);
        fputc('\n', f);
        if (indent == 0 && e->val->kind == DICT_DICT && i + 1 < d->n)
            fputc('\n', f);
    }
}

int dict_write_body(const struct dict *d, FILE *f, int indent)
{
    put_body(d, f, indent);
    return ferror(f) ? sim_error(SIM_ERR_IO, "write error") : SIM_OK;
}

int dict_write_expanded(const struct dict *d, FILE *f)
{
    put_body(d, f, 0);
    fflush(f);
    return ferror(f) ? sim_error(SIM_ERR_IO, "write error while printing %s",
                                 d->file)
                     : SIM_OK;
}

int dict_write_value(const struct dict_value *v, FILE *f)
{
    if (v->kind == DICT_DICT) {
        put_dict_block(v->u.d, f, 0);
    } else if (v->kind == DICT_LIST || v->kind == DICT_ENTRY) {
        long m = inline_len(v);
        if (m >= 0)
            put_inline(v, f);
        else if (v->kind == DICT_LIST)
            put_block(v, f, 0);
        else
            for (int i = 0; i < v->u.l.n; i++) {
                const struct dict_value *it = &v->u.l.items[i];
                if (inline_len(it) < 0) {
                    if (i)
                        fputc('\n', f);
                    if (it->kind == DICT_DICT)
                        put_dict_block(it->u.d, f, 0);
                    else
                        put_block(it, f, 0);
                } else {
                    if (i)
                        fputc(' ', f);
                    put_inline(it, f);
                }
            }
    } else {
        put_inline(v, f);
    }
    return ferror(f) ? sim_error(SIM_ERR_IO, "write error") : SIM_OK;
}

char *dict_value_to_text(const struct dict_value *v)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    if (!f) {
        sim_error(SIM_ERR_NOMEM, "cannot open a memory stream");
        return NULL;
    }
    dict_write_value(v, f);
    fclose(f);
    return buf;
}
