/*
 * dict_impl.h — private layout of the dictionary library (dict_*.c only).
 *
 * Everything a parsed file owns (values, strings, sub-dictionaries) lives in
 * one arena per top-level dictionary, so dict_free() is a handful of free()
 * calls whatever the size of the file. Only the growable entry arrays and
 * their hash indices are malloc'd per dictionary; the root keeps a chain of
 * all its dictionaries to release them.
 *
 * Values of lists and entries are stored inline and contiguously
 * (struct dict_value items[n]) so that a list of a million numbers costs one
 * allocation, and dict_value_at() is an index.
 */
#ifndef MPSDEM_CORE_DICT_IMPL_H
#define MPSDEM_CORE_DICT_IMPL_H

#include <stddef.h>

#include "core/dict.h"

/* ---- arena ---------------------------------------------------------------- */

struct arena_block;
struct arena {
    struct arena_block *head;
    size_t bytes;           /* handed out so far                           */
};
void *arena_alloc(struct arena *a, size_t n);   /* zeroed, 16-aligned */
char *arena_strndup(struct arena *a, const char *s, size_t n);
void arena_free(struct arena *a);

/* ---- values, entries, dictionaries ----------------------------------------- */

struct dict_value {
    unsigned char kind;     /* enum dict_kind                              */
    int line, col;          /* where the value was written                 */
    const char *file;       /* interned in the root's arena                */
    union {
        struct { const char *text; double num; } s; /* word/string/number  */
        struct { struct dict_value *items; int n; } l; /* list/entry       */
        struct dict *d;                                /* DICT_DICT         */
        int dims[7];                                   /* DICT_DIMS         */
    } u;
};

struct dict_entry {
    const char *key;
    const char *file;       /* where the key was written                   */
    int line, col;
    struct dict_value *val; /* DICT_ENTRY, or DICT_DICT for a sub-dict     */
    /* byte range of the value text in `file` (for dict_set_in_file): for a
     * sub-dictionary, from '{' to just past '}'; vbeg == vend for "key;".  */
    size_t vbeg, vend;
    unsigned char used;       /* read by a getter or marked               */
    unsigned char referenced; /* used as $var / merged: not "unused"      */
};

struct dict_root;

struct dict {
    struct dict *parent;
    struct dict_root *root;
    struct dict *next_in_root;  /* chain for dict_free                     */
    const char *name;           /* scoped: "", "functions/probes1"         */
    const char *file;
    int line, col;              /* the '{' (1:1 for a file)                */
    struct dict_entry *e;
    int n, cap;
    int *hash;                  /* open addressing, entry index + 1        */
    int hcap;
    const char **asked;         /* keys asked for but absent               */
    int nasked, capasked;
    unsigned char touched;      /* a getter looked at this dictionary      */
    unsigned char in_list;      /* a { } value inside a list               */
};

struct dict_root {
    struct arena arena;
    struct dict *dicts;         /* chain of every dictionary               */
};

/* ---- lexer (dict_lex.c) ------------------------------------------------------ */

enum tok_kind {
    T_EOF, T_WORD, T_NUMBER, T_STRING, T_VAR, T_DIRECTIVE,
    T_LBRACE, T_RBRACE, T_LPAREN, T_RPAREN, T_LBRACK, T_RBRACK, T_SEMI
};

struct token {
    enum tok_kind kind;
    const char *start;      /* raw text in the buffer                      */
    size_t len;
    size_t off, end;        /* byte range in the buffer                    */
    int line, col;          /* of the first byte                           */
    int end_line, end_col;  /* just past the last byte                     */
    int first_on_line;      /* nothing but blanks/comments before it       */
    double num;             /* T_NUMBER                                    */
    char *str;              /* T_STRING unescaped (lexer's buffer)         */
    size_t str_len;
};

struct lexer {
    const char *text;
    size_t len, pos;
    int line, col;
    const char *file;
    int line_has_token;
    char *sbuf;             /* unescaped string of the last T_STRING        */
    size_t scap;
};

void lex_init(struct lexer *lx, const char *text, size_t len,
              const char *file);
void lex_release(struct lexer *lx);
/* Next token; SIM_ERR_PARSE with a located message on bad input. */
int lex_next(struct lexer *lx, struct token *t);
/* Text of a token kind for messages ("'{'", "end of file"). */
const char *lex_kind_text(enum tok_kind k);

/* ---- shared helpers ---------------------------------------------------------- */

/* New empty dictionary owned by root. */
struct dict *dict_new(struct dict_root *root, struct dict *parent,
                      const char *name, const char *file, int line, int col);
/* Entry called key in d (exact, no scoping), or NULL. */
struct dict_entry *dict_lookup(const struct dict *d, const char *key);
/* Entry at a scoped path "a/b/c", or NULL; no book-keeping. */
struct dict_entry *dict_find_entry(const struct dict *d, const char *key);
/* Add or replace (last wins, keeping the first position). Returns the slot,
 * NULL on allocation failure (message set). */
struct dict_entry *dict_put(struct dict *d, const char *key);
/* Deep copy of v into root's arena; sub-dictionaries get parent `parent`
 * and scoped names under `name`. */
int dict_value_copy(struct dict_root *root, struct dict *parent,
                    const char *name, const struct dict_value *src,
                    struct dict_value *dst);
int dict_merge_into(struct dict *dst, const struct dict *src);

/* Damerau–Levenshtein distance, capped (returns cap+1 when larger). */
int dict_edit_distance(const char *a, const char *b, int cap);
/* Best candidate for `word` among `cand`, or NULL when none is close. */
const char *dict_suggest(const char *word, const char *const *cand, int n);

/* "word 'abc'", "list of 3 items", ... for messages. */
void dict_describe(const struct dict_value *v, char *buf, size_t n);
/* Value as dict_write_value prints it, malloc'd (NULL on failure). */
char *dict_value_to_text(const struct dict_value *v);

/* Write d's entries at the given indent (dict_write.c). */
int dict_write_body(const struct dict *d, FILE *f, int indent);

/* Whole regular file into a malloc'd NUL-terminated buffer; 0, an errno,
 * or DICT_ENOTREG (devices and FIFOs could block or never end). */
#define DICT_ENOTREG (-1)
int dict_slurp(const char *path, char **text, size_t *len);
const char *dict_strerror(int err);
/* Write text to path via a temporary file and rename(); with mkparent the
 * parent directories are created. Keeps an existing file's mode. */
int dict_write_atomic(const char *path, const char *text, size_t len,
                      int mkparent);

/* Remember a parameter (dict_params.c); value text is copied. */
void params_record_entry(const struct dict *d, const char *key,
                         const char *value, int is_default);

#endif
