/*
 * dict.h — OpenFOAM-syntax dictionaries: parse, query with typed getters,
 * report what was used, expand, and edit in place.
 *
 * Grammar (doc/design.md §3, OpenFOAM's):
 *   file    := [FoamFile { ... }] entry*
 *   entry   := key value+ ';' | key '{' entry* '}' | '#include' "file" | '$var' ';'
 *   value   := word | number | "string" | '(' value* ')' | '{' entry* '}'
 *            | '[' n n n n n n n ']'          (dimension set, SI exponents:
 *                                              kg m s K mol A cd)
 *   comments: // to end of line, and C block comments
 *   $var, $sub/var, $../var, $/abs/var  substitute an entry's value; a bare
 *   `$var;` inside a dictionary merges the named sub-dictionary there.
 *   #include "file" is relative to the including file, with a cycle check.
 *   A key may be repeated: the last one wins (OpenFOAM behaviour).
 *
 * A value that is a single dimensioned scalar may be written
 *   nu [0 2 -1 0 0 0 0] 1e-6;     or     nu nu [0 2 -1 0 0 0 0] 1e-6;
 * and dict_get_scalar_dim() checks the set against what the code expects.
 *
 * Keys given to getters may be scoped paths "a/b/c" (sub-dictionaries).
 *
 * Every error sets a message (error.h) that starts with the location of the
 * offending text, "system/controlDict:12:5: ", and says what was expected;
 * the code returned is SIM_ERR_PARSE (syntax), SIM_ERR_IO (missing file) or
 * SIM_ERR_DICT (missing key, wrong type, bad value).
 *
 * Book-keeping: every getter marks the entry it read as used and records the
 * effective value (defaults included) for the usedParameters report; a key
 * asked for but absent is remembered too, so that dict_warn_unused() can
 * suggest it for a misspelt entry ("did you mean 'writeInterval'?").
 *
 * Ownership: a struct dict returned by dict_read()/dict_read_string() owns
 * every sub-dictionary and value reachable from it; free it with dict_free().
 * Pointers obtained from getters stay valid until then. Getters on one
 * dictionary are not thread-safe (they update the book-keeping).
 */
#ifndef MPSDEM_CORE_DICT_H
#define MPSDEM_CORE_DICT_H

#include <stddef.h>
#include <stdio.h>

struct dict;       /* a dictionary: a file, or a { } sub-dictionary        */
struct dict_value; /* one value: word, number, string, list, dict or dims  */

enum dict_kind {
    DICT_WORD,   /* bare word: yes, hertz, uniform                         */
    DICT_NUMBER, /* 1, -2.5e-3 (integers keep their exact text, see below) */
    DICT_STRING, /* "quoted text" (quotes removed)                         */
    DICT_LIST,   /* ( ... ): any values, including dicts                   */
    DICT_DICT,   /* { ... } inside a list                                  */
    DICT_DIMS,   /* [ ... ] dimension set                                  */
    DICT_ENTRY   /* the whole value of an entry: a sequence of values      */
};

/* ---- reading -------------------------------------------------------------- */

/* Parse a file. */
int dict_read(const char *path, struct dict **out);

/* Parse text held in memory; `name` is used in messages and to resolve
 * #include (relative to the directory part of name). */
int dict_read_string(const char *text, size_t len, const char *name,
                     struct dict **out);

void dict_free(struct dict *d);

/* File the dictionary was read from, and its scoped name within the file
 * ("" for the top level, "functions/probes1" for a sub-dictionary). */
const char *dict_file(const struct dict *d);
const char *dict_name(const struct dict *d);

/* Entries in file order (after substitution and merging). */
int dict_size(const struct dict *d);
const char *dict_key_at(const struct dict *d, int i);
/* Non-zero when the entry exists (scoped path allowed); nothing is marked. */
int dict_has(const struct dict *d, const char *key);
/* Non-zero when the entry exists and is a sub-dictionary. */
int dict_is_dict(const struct dict *d, const char *key);

/* ---- typed getters (mark used, record the effective value) ---------------- */

int dict_get_scalar(const struct dict *d, const char *key, double *out);
int dict_get_scalar_or(const struct dict *d, const char *key, double def,
                       double *out);
/* As dict_get_scalar; if the entry carries a dimension set it must equal
 * `dims` (7 SI exponents), else SIM_ERR_DICT naming both sets. */
int dict_get_scalar_dim(const struct dict *d, const char *key,
                        const int dims[7], double *out);
int dict_get_scalar_dim_or(const struct dict *d, const char *key,
                           const int dims[7], double def, double *out);

/* Integer; 2.0 is accepted, 2.5 is an error. */
int dict_get_label(const struct dict *d, const char *key, long *out);
int dict_get_label_or(const struct dict *d, const char *key, long def,
                      long *out);

/* yes/no, on/off, true/false, 1/0. */
int dict_get_bool(const struct dict *d, const char *key, int *out);
int dict_get_bool_or(const struct dict *d, const char *key, int def, int *out);

/* A word from `allowed` (NULL-terminated); *index is its position. An
 * unknown word is an error listing the valid ones. */
int dict_get_word(const struct dict *d, const char *key,
                  const char *const allowed[], int *index);
int dict_get_word_or(const struct dict *d, const char *key,
                     const char *const allowed[], int def_index, int *index);

/* Any single word or quoted string. */
int dict_get_string(const struct dict *d, const char *key, const char **out);
int dict_get_string_or(const struct dict *d, const char *key, const char *def,
                       const char **out);

/* A list of exactly n numbers, "(x y z)". */
int dict_get_vector(const struct dict *d, const char *key, int n, double *out);
int dict_get_vector_or(const struct dict *d, const char *key, int n,
                       const double *def, double *out);

/* A sub-dictionary. dict_find_dict gives *out = NULL (and SIM_OK) when the
 * key is absent, an error when it exists but is not a dictionary. */
int dict_get_dict(const struct dict *d, const char *key,
                  const struct dict **out);
int dict_find_dict(const struct dict *d, const char *key,
                   const struct dict **out);

/* An entry whose value is one list "( ... )". */
int dict_get_list(const struct dict *d, const char *key,
                  const struct dict_value **out);

/* An entry "( word ... )" of at most max words: out[k] point into d. */
int dict_get_words(const struct dict *d, const char *key, int max,
                   const char **out, int *n);

/* The raw value of an entry (kind DICT_ENTRY, or DICT_DICT for a
 * sub-dictionary entry), for entries with free-form content. Marks used. */
int dict_get_value(const struct dict *d, const char *key,
                   const struct dict_value **out);

/* ---- values --------------------------------------------------------------- */

enum dict_kind dict_value_kind(const struct dict_value *v);
/* Items of a DICT_LIST or DICT_ENTRY (0 for other kinds). */
int dict_value_len(const struct dict_value *v);
const struct dict_value *dict_value_at(const struct dict_value *v, int i);
/* Accessors: undefined for the wrong kind (check the kind, or use the
 * checked forms below). */
double dict_value_number(const struct dict_value *v);
const char *dict_value_text(const struct dict_value *v); /* word/string/number text */
const struct dict *dict_value_dict(const struct dict_value *v);
const int *dict_value_dims(const struct dict_value *v);  /* 7 exponents */

/* Checked forms: set a located error message on the wrong kind/length. */
int dict_value_get_scalar(const struct dict_value *v, double *out);
int dict_value_get_vector(const struct dict_value *v, int n, double *out);
int dict_value_get_word(const struct dict_value *v, const char **out);

/* "file:line:col" of a value or of an entry's key; the buffer is the
 * caller's. Returns buf. A missing key gives the dictionary's own location. */
const char *dict_value_where(const struct dict_value *v, char *buf, size_t n);
const char *dict_where(const struct dict *d, const char *key, char *buf,
                       size_t n);

/* Set an error message located at `key` of `d` (or at `d` itself when key is
 * NULL or absent): "file:line:col: <formatted text>". Returns code. */
int dict_error(const struct dict *d, const char *key, int code,
               const char *fmt, ...) __attribute__((format(printf, 4, 5)));
/* SIM_OK when v of entry `key` lies in (lo, hi] (lo_open) or [lo, hi],
 * else the dict_error "key = v is out of range (lo, hi]" at the entry. */
int dict_range(const struct dict *d, const char *key, double v, double lo,
               double hi, int lo_open);
int dict_value_error(const struct dict_value *v, int code, const char *fmt,
                     ...) __attribute__((format(printf, 3, 4)));

/* ---- book-keeping --------------------------------------------------------- */

/* Mark an entry (and, for a sub-dictionary, nothing below it) as used
 * without reading it through a getter. */
void dict_mark_used(const struct dict *d, const char *key);

/* Warn (log_warn) about every entry of d and its sub-dictionaries that no
 * getter read, with a "did you mean" suggestion among the keys asked for in
 * the same dictionary. Returns the number of warnings. The FoamFile header
 * is never reported. */
int dict_warn_unused(const struct dict *d);

/* Record a parameter that did not come from a getter (derived values,
 * command-line options) so that it appears in the report. */
void params_record(const char *file, const char *key, const char *value,
                   int is_default);
/* Write every recorded parameter, grouped by file, in dictionary syntax,
 * defaults marked "// default", to `path` (atomically: tmp + rename), and
 * the same text to the log when `echo` is set. */
int params_write(const char *path, int echo);
/* Forget all records (tests; a program reading a second case). */
void params_clear(void);

/* ---- expansion and editing (dictTool) ------------------------------------- */

/* Print d with includes and substitutions resolved, comments dropped, in
 * OpenFOAM layout (4-space indent, keys padded to a column). The output is
 * itself a valid dictionary that parses to the same content. */
int dict_write_expanded(const struct dict *d, FILE *f);

/* Print one value as it would appear after the key in dict_write_expanded. */
int dict_write_value(const struct dict_value *v, FILE *f);

/* Replace the value of scoped key `keypath` in the file `path` by the text
 * `value`, keeping every other byte (comments, layout) unchanged; a missing
 * key is appended to the innermost existing sub-dictionary (creating the
 * missing sub-dictionaries). Written atomically. */
int dict_set_in_file(const char *path, const char *keypath, const char *value);

/* n edits of one file, applied in turn and written once: every keypaths[k]
 * must then hold values[k], else nothing is written. Without allow_new a
 * key path that is not in the file (nor in what it includes) is refused,
 * naming the file and line of the innermost dictionary that exists and
 * suggesting a near key ("did you mean"). */
int dict_set_entries_in_file(const char *path, int n,
                             const char *const *keypaths,
                             const char *const *values, int allow_new);

#endif
