/* sizeDistribution.c — the table of diameter distributions and the
 * reading of `diameterDistribution <name> (...)...;` (sizeDistribution.h). */
#include "sizeDistribution.h"

#include <math.h>
#include <stdio.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "core/select.h"

const struct size_dist_ops *const size_dist_table[] = {
    &size_dist_uniform, &size_dist_normal, NULL
};

int size_dist_numbers(const struct dict_value *entry, int i, int n,
                      const char *model, const char *what, double *out)
{
    const struct dict_value *l = dict_value_at(entry, i);
    if (!l || dict_value_kind(l) != DICT_LIST || dict_value_len(l) != n)
        return dict_value_error(l ? l : entry, SIM_ERR_DICT, "%s needs %s "
                                "after its name: %d number%s in ( )", model,
                                what, n, n == 1 ? "" : "s");
    for (int k = 0; k < n; k++) {
        const struct dict_value *x = dict_value_at(l, k);
        TRY(dict_value_get_scalar(x, &out[k]));
        if (!(out[k] > 0) || !isfinite(out[k]))
            return dict_value_error(x, SIM_ERR_DICT, "%s %s: every value "
                                    "must be a positive length [m], not %g",
                                    model, what, out[k]);
    }
    return SIM_OK;
}

int size_dist_read(const struct dict *d, const char *key, double fixed,
                   struct size_dist *s)
{
    const struct dict_value *v, *w;
    const char *name;

    s->ops = NULL;
    s->min = s->max = s->mean = fixed;
    s->sd = 0;
    if (!dict_has(d, key))
        return SIM_OK;
    TRY(dict_get_value(d, key, &v));
    w = dict_value_kind(v) == DICT_ENTRY ? dict_value_at(v, 0) : v;
    if (!w || dict_value_kind(w) != DICT_WORD)
        return dict_error(d, key, SIM_ERR_DICT, "%s starts with the name of "
                          "a distribution: uniform (min max) or normal "
                          "(mean standardDeviation) (min max)", key);
    name = dict_value_text(w);
    s->ops = model_find((const void *const *)size_dist_table, name);
    if (!s->ops) {
        char valid[256] = "";
        size_t used = 0;
        for (int i = 0; size_dist_table[i]; i++)
            used += (size_t)snprintf(valid + used, sizeof valid - used, " %s",
                                     size_dist_table[i]->name);
        return dict_value_error(w, SIM_ERR_DICT, "unknown grain diameter "
                                "distribution '%s'; valid:%s", name, valid);
    }
    log_info("Selecting grain diameter distribution %s (%s)", s->ops->name,
             s->ops->reference);
    return s->ops->read(v, s);
}

double size_dist_draw(const struct size_dist *s, struct gen_rng *g)
{
    return s->ops ? s->ops->draw(s, g) : s->min;
}
