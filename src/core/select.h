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
 * entry, listing the valid names.
 */
#ifndef MPSDEM_CORE_SELECT_H
#define MPSDEM_CORE_SELECT_H

struct dict;

struct model_head {
    const char *name;      /* the word used in dictionaries          */
    const char *reference; /* source, printed at selection; may be "" */
};

/* def: name used when the key is absent, or NULL when the key is required. */
int model_select(const struct dict *d, const char *key, const char *category,
                 const void *const *table, const char *def, const void **out);

/* Entry called `name`, or NULL. */
const void *model_find(const void *const *table, const char *name);

#endif
