/*
 * dict_lex.c — tokens of OpenFOAM dictionary text.
 *
 * Words follow OpenFOAM's rule: a word runs until blank, ';', '{', '}', '"',
 * '[', ']', a comment, or a ')' that closes nothing; a '(' inside a word
 * nests, so that "div(phi,U)" is one word while "(1 2 3)" is a list.
 * A token that starts like a number (digit, or sign/point then digit) must
 * be a whole decimal number, so "1e" or "2.5x" is reported, not taken as a
 * word. Strings may not span lines: a missing closing quote is then found
 * on the line where it was opened.
 */
#include <ctype.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "core/dict_impl.h"
#include "core/error.h"

void lex_init(struct lexer *lx, const char *text, size_t len, const char *file)
{
    memset(lx, 0, sizeof *lx);
    lx->text = text;
    lx->len = len;
    lx->line = 1;
    lx->col = 1;
    lx->file = file;
    /* a UTF-8 byte-order mark written by some editors is not a word */
    if (len >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0)
        lx->pos = 3;
}

void lex_release(struct lexer *lx)
{
    free(lx->sbuf);
    lx->sbuf = NULL;
    lx->scap = 0;
}

const char *lex_kind_text(enum tok_kind k)
{
    switch (k) {
    case T_EOF: return "end of file";
    case T_WORD: return "word";
    case T_NUMBER: return "number";
    case T_STRING: return "string";
    case T_VAR: return "variable";
    case T_DIRECTIVE: return "directive";
    case T_LBRACE: return "'{'";
    case T_RBRACE: return "'}'";
    case T_LPAREN: return "'('";
    case T_RPAREN: return "')'";
    case T_LBRACK: return "'['";
    case T_RBRACK: return "']'";
    case T_SEMI: return "';'";
    }
    return "token";
}

static int peekc(const struct lexer *lx, size_t ahead)
{
    size_t p = lx->pos + ahead;
    return p < lx->len ? (unsigned char)lx->text[p] : -1;
}

static void advance(struct lexer *lx)
{
    if (lx->text[lx->pos] == '\n') {
        lx->line++;
        lx->col = 1;
        lx->line_has_token = 0;
    } else {
        lx->col++;
    }
    lx->pos++;
}

static int lex_error(const struct lexer *lx, int line, int col,
                     const char *what, const char *detail)
{
    return sim_error(SIM_ERR_PARSE, "%s:%d:%d: %s%s", lx->file, line, col,
                     what, detail);
}

/* Skip blanks and comments. */
static int skip_space(struct lexer *lx)
{
    for (;;) {
        int c = peekc(lx, 0);
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'
            || c == '\v') {
            advance(lx);
        } else if (c == '/' && peekc(lx, 1) == '/') {
            while (lx->pos < lx->len && lx->text[lx->pos] != '\n')
                advance(lx);
        } else if (c == '/' && peekc(lx, 1) == '*') {
            int line = lx->line, col = lx->col;
            advance(lx);
            advance(lx);
            for (;;) {
                if (lx->pos >= lx->len) {
                    char at[64];
                    snprintf(at, sizeof at, " opened at %d:%d", line, col);
                    return lex_error(lx, lx->line, lx->col,
                                     "unterminated comment '/*'", at);
                }
                if (peekc(lx, 0) == '*' && peekc(lx, 1) == '/') {
                    advance(lx);
                    advance(lx);
                    break;
                }
                advance(lx);
            }
        } else {
            return SIM_OK;
        }
    }
}

/* Ends a word (or number, or variable name). */
static int is_stop(const struct lexer *lx, int c)
{
    if (c <= 0 || c == ' ' || c == '\t' || c == '\n' || c == '\r'
        || c == '\f' || c == '\v')
        return 1;
    if (c == ';' || c == '{' || c == '}' || c == '"' || c == '[' || c == ']')
        return 1;
    if (c == '/' && (peekc(lx, 1) == '/' || peekc(lx, 1) == '*'))
        return 1;
    return 0;
}

static void read_word(struct lexer *lx, int nest_parens)
{
    int depth = 0;
    for (;;) {
        int c = peekc(lx, 0);
        if (is_stop(lx, c))
            return;
        if (c == '(') {
            if (!nest_parens)
                return;
            depth++;
        } else if (c == ')') {
            if (depth == 0)
                return;
            depth--;
        }
        advance(lx);
    }
}

/* Decimal number: [+-] digits [. digits] [eE [+-] digits], at least one
 * digit in the mantissa. */
static int is_decimal(const char *s, size_t n)
{
    size_t i = 0, digits = 0;
    if (i < n && (s[i] == '+' || s[i] == '-'))
        i++;
    while (i < n && isdigit((unsigned char)s[i]))
        i++, digits++;
    if (i < n && s[i] == '.') {
        i++;
        while (i < n && isdigit((unsigned char)s[i]))
            i++, digits++;
    }
    if (digits == 0)
        return 0;
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        size_t e = 0;
        i++;
        if (i < n && (s[i] == '+' || s[i] == '-'))
            i++;
        while (i < n && isdigit((unsigned char)s[i]))
            i++, e++;
        if (e == 0)
            return 0;
    }
    return i == n;
}

static int starts_number(const struct lexer *lx)
{
    int c = peekc(lx, 0), c1 = peekc(lx, 1), c2 = peekc(lx, 2);
    if (isdigit(c))
        return 1;
    if (c == '.' && isdigit(c1))
        return 1;
    if (c == '+' || c == '-')
        return isdigit(c1) || (c1 == '.' && isdigit(c2));
    return 0;
}

static int read_number(struct lexer *lx, struct token *t)
{
    read_word(lx, 0);
    t->len = lx->pos - t->off;
    /* "3(1 2 3)" is OpenFOAM's counted list: the count ends at '(' */
    if (!is_decimal(t->start, t->len)) {
        char detail[96];
        snprintf(detail, sizeof detail, "'%.*s'",
                 (int)(t->len > 64 ? 64 : t->len), t->start);
        return lex_error(lx, t->line, t->col, "bad number ", detail);
    }
    char buf[128];
    char *tmp = t->len < sizeof buf ? buf : malloc(t->len + 1);
    if (!tmp)
        return sim_error(SIM_ERR_NOMEM, "out of memory reading a number");
    memcpy(tmp, t->start, t->len);
    tmp[t->len] = '\0';
    errno = 0;
    t->num = strtod(tmp, NULL);
    int range = errno == ERANGE && (t->num > 1.0 || t->num < -1.0);
    if (tmp != buf)
        free(tmp);
    if (range) {
        char detail[96];
        snprintf(detail, sizeof detail, "'%.*s' (out of range)",
                 (int)(t->len > 64 ? 64 : t->len), t->start);
        return lex_error(lx, t->line, t->col, "bad number ", detail);
    }
    t->kind = T_NUMBER;
    return SIM_OK;
}

static int push_char(struct lexer *lx, size_t *n, char c)
{
    if (*n + 1 >= lx->scap) {
        size_t cap = lx->scap ? 2 * lx->scap : 64;
        char *p = realloc(lx->sbuf, cap);
        if (!p)
            return sim_error(SIM_ERR_NOMEM, "out of memory reading a string");
        lx->sbuf = p;
        lx->scap = cap;
    }
    lx->sbuf[(*n)++] = c;
    lx->sbuf[*n] = '\0';
    return SIM_OK;
}

static int read_string(struct lexer *lx, struct token *t)
{
    size_t n = 0;
    TRY(push_char(lx, &n, '\0')); /* so that "" has a buffer */
    n = 0;
    advance(lx); /* opening quote */
    for (;;) {
        int c = peekc(lx, 0);
        if (c < 0 || c == '\n') {
            char at[64];
            snprintf(at, sizeof at, " of the string opened at %d:%d",
                     t->line, t->col);
            return lex_error(lx, lx->line, lx->col, "missing closing '\"'",
                             at);
        }
        if (c == '"') {
            advance(lx);
            break;
        }
        if (c == '\\') {
            int e = peekc(lx, 1);
            char out = 0;
            if (e == '"' || e == '\\')
                out = (char)e;
            else if (e == 'n')
                out = '\n';
            else if (e == 't')
                out = '\t';
            if (out) {
                advance(lx);
                advance(lx);
                TRY(push_char(lx, &n, out));
                continue;
            }
        }
        if (c == '\0')
            return lex_error(lx, lx->line, lx->col, "NUL byte in a string",
                             "");
        TRY(push_char(lx, &n, (char)c));
        advance(lx);
    }
    t->kind = T_STRING;
    t->str = lx->sbuf;
    t->str_len = n;
    return SIM_OK;
}

static int read_var(struct lexer *lx, struct token *t)
{
    advance(lx); /* '$' */
    if (peekc(lx, 0) == '{') {
        while (lx->pos < lx->len && lx->text[lx->pos] != '}'
               && lx->text[lx->pos] != '\n')
            advance(lx);
        if (peekc(lx, 0) != '}')
            return lex_error(lx, t->line, t->col,
                             "missing '}' closing '${'", "");
        advance(lx);
    } else {
        read_word(lx, 0);
    }
    t->len = lx->pos - t->off;
    if (t->len <= 1 || (t->start[1] == '{' && t->len <= 3))
        return lex_error(lx, t->line, t->col,
                         "expected a variable name after '$'", "");
    t->kind = T_VAR;
    return SIM_OK;
}

static int read_punct(struct lexer *lx, struct token *t, int c)
{
    switch (c) {
    case '{': t->kind = T_LBRACE; break;
    case '}': t->kind = T_RBRACE; break;
    case '(': t->kind = T_LPAREN; break;
    case ')': t->kind = T_RPAREN; break;
    case '[': t->kind = T_LBRACK; break;
    case ']': t->kind = T_RBRACK; break;
    case ';': t->kind = T_SEMI; break;
    default: return 0;
    }
    advance(lx);
    t->len = 1;
    return 1;
}

int lex_next(struct lexer *lx, struct token *t)
{
    TRY(skip_space(lx));
    memset(t, 0, sizeof *t);
    t->off = lx->pos;
    t->start = lx->text + lx->pos;
    t->line = lx->line;
    t->col = lx->col;
    t->first_on_line = !lx->line_has_token;
    int c = peekc(lx, 0);
    int rc = SIM_OK;
    if (c < 0) {
        t->kind = T_EOF;
    } else if (c == '\0') {
        return lex_error(lx, lx->line, lx->col, "unexpected NUL byte", "");
    } else if (read_punct(lx, t, c)) {
        /* done */
    } else if (c == '"') {
        rc = read_string(lx, t);
    } else if (c == '$') {
        rc = read_var(lx, t);
    } else if (starts_number(lx)) {
        rc = read_number(lx, t);
    } else {
        t->kind = (c == '#' && isalpha(peekc(lx, 1))) ? T_DIRECTIVE : T_WORD;
        read_word(lx, t->kind == T_WORD);
        t->len = lx->pos - t->off;
        if (t->len == 0) { /* a lone ')' handled above; cannot happen */
            advance(lx);
            t->len = 1;
        }
    }
    if (rc != SIM_OK)
        return rc;
    t->end = lx->pos;
    t->end_line = lx->line;
    t->end_col = lx->col;
    lx->line_has_token = 1;
    return SIM_OK;
}
