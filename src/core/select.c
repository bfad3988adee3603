/* select.c — see select.h. */
#include "core/select.h"

#include <stdio.h>
#include <string.h>

#include "core/dict.h"
#include "core/dict_impl.h"
#include "core/error.h"
#include "core/log.h"

int model_select(const struct dict *d, const char *key, const char *category,
                 const void *const *table, const char *def, const void **out)
{
    const char *name;
    if (def)
        TRY(dict_get_string_or(d, key, def, &name));
    else
        TRY(dict_get_string(d, key, &name));

    const struct model_head *h = model_find(table, name);
    if (!h) {
        char msg[1400];
        return dict_error(d, key, SIM_ERR_DICT, "%s",
                          model_unknown(table, category, name, msg,
                                        sizeof msg));
    }
    if (h->reference && h->reference[0])
        log_info("Selecting %s %s (%s)", category, h->name, h->reference);
    else
        log_info("Selecting %s %s", category, h->name);
    *out = h;
    return SIM_OK;
}

int model_select_index(const struct dict *d, const char *key,
                       const char *category, const void *const *table,
                       const char *def, int *index)
{
    const void *m;
    TRY(model_select(d, key, category, table, def, &m));
    for (int i = 0; table[i]; i++)
        if (table[i] == m)
            *index = i;
    return SIM_OK;
}

void model_choices_print(const struct model_choice *list, const char *file,
                         const char *prefix)
{
    for (; list->key; list++)
        for (int i = 0; list->table[i]; i++) {
            const struct model_head *h = list->table[i];
            printf("%s %s%s %s\n", file ? file : list->file,
                   prefix ? prefix : "", list->key, h->name);
        }
}
