/* select.c — see select.h. */
#include "core/select.h"

#include <stdio.h>
#include <string.h>

#include "core/dict.h"
#include "core/dict_impl.h"
#include "core/error.h"
#include "core/log.h"

const void *model_find(const void *const *table, const char *name)
{
    for (int i = 0; table[i]; i++) {
        const struct model_head *h = table[i];
        if (strcmp(h->name, name) == 0)
            return h;
    }
    return NULL;
}

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
        char valid[1024] = "";
        size_t used = 0;
        for (int i = 0; table[i] && used < sizeof valid - 64; i++) {
            const struct model_head *m = table[i];
            used += snprintf(valid + used, sizeof valid - used, " %s", m->name);
        }
        const char *cand[64];
        int nc = 0;
        while (nc < 64 && table[nc]) {
            cand[nc] = ((const struct model_head *)table[nc])->name;
            nc++;
        }
        const char *best = dict_suggest(name, cand, nc);
        char hint[128] = "";
        if (best)
            snprintf(hint, sizeof hint, " (did you mean '%s'?)", best);
        return dict_error(d, key, SIM_ERR_DICT,
                          "unknown %s '%s'; valid:%s%s", category, name,
                          valid, hint);
    }
    if (h->reference && h->reference[0])
        log_info("Selecting %s %s (%s)", category, h->name, h->reference);
    else
        log_info("Selecting %s %s", category, h->name);
    *out = h;
    return SIM_OK;
}
