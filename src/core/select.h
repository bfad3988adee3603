/*
 * select.h — run-time selection of a model by name (doc/design.md C3).
 *
 * A model category is a NULL-terminated `const` array of pointers to ops
 * structs, each of which begins with the two members of struct model_head:
 *
 *     struct drag_ops { const char *name; const char *reference; ... };
 *     static const struct drag_ops *const drag_models[] = {
 *         &drag_ergun_wen_yu, &drag_di_felice, NULL };
 *
 * model_select() reads the word at `key`, logs
 *     Selecting <category> <name> (<reference>)
 * and returns the matching entry; an unknown name is an error located at the
 * entry, listing the valid names and the nearest one ("did you mean").
 *
 * One way for every model choice. A choice between methods of the
 * literature (kernel, gradient form, wall pressure, PPE solver, drag law,
 * contact sub-model, integrator, ...) is such a table, whether or not its
 * entries carry functions: a choice without ops is a table of bare
 * struct model_head, read with model_select_index(), which gives the
 * entry's position (the value of the matching enum):
 *
 *     static const struct model_head grad_sym = { "symmetric", "eq. 8" };
 *     const struct model_head *const mps_gradient_table[] = {
 *         &grad_sym, &grad_min, &grad_corr, NULL };
 *
 * dict_get_word() (the same did-you-mean machinery, dict_suggest()) stays
 * for settings that are not methods (writeControl, writeFormat, shapes).
 * Each library lists its choices in a `struct model_choice` array
 * (dictionary, key, table) that the programs print with -listModels and
 * test/cases/choices.sh checks against the comments of the reference and
 * tutorial dictionaries. Lookups outside a dictionary (a solver named by a
 * program) use model_unknown() for the same message.
 */
#ifndef MPSDEM_CORE_SELECT_H
#define MPSDEM_CORE_SELECT_H

#include <stddef.h>

struct dict;

struct model_head {
    const char *name;      /* the word used in dictionaries          */
    const char *reference; /* source, printed at selection; may be "" */
};

/* def: name used when the key is absent, or NULL when the key is required. */
int model_select(const struct dict *d, const char *key, const char *category,
                 const void *const *table, const char *def, const void **out);

/* The same for a table of bare heads; *index is the entry's position. */
int model_select_index(const struct dict *d, const char *key,
                       const char *category, const void *const *table,
                       const char *def, int *index);

/* Entry called `name`, or NULL (select_find.c: no dictionary code). */
const void *model_find(const void *const *table, const char *name);

/* "unknown <category> '<name>'; valid: a b c (did you mean 'b'?)" into
 * buf (select_find.c). */
const char *model_unknown(const void *const *table, const char *category,
                          const char *name, char *buf, size_t len);

/* A program's choice: dictionary file (relative to the case), key path in
 * it, table. An array of them ends with a NULL key. */
struct model_choice {
    const char *file;
    const char *key;
    const void *const *table;
};

/* One line "FILE KEY NAME" per registered name (-listModels); prefix is
 * put before every key ("PPE/" for a sub-dictionary), file replaces the
 * entries' file when not NULL. */
void model_choices_print(const struct model_choice *list, const char *file,
                         const char *prefix);

#endif
