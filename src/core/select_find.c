/*
 * select_find.c — finding a name in a model table and the answer to an
 * unknown one (the valid names, and the nearest by edit distance: "did you
 * mean"). Kept apart from select.c and the dictionary code so that a
 * library that names models without a dictionary (linsolve_create_named)
 * does not pull the parser into programs that never read one.
 */
#include <stdio.h>
#include <string.h>

#include "core/dict_impl.h"
#include "core/select.h"

int dict_edit_distance(const char *a, const char *b, int cap)
{
    size_t na = strlen(a), nb = strlen(b);
    if (na > 64 || nb > 64)
        return strcmp(a, b) == 0 ? 0 : cap + 1;
    int d[66][66];
    for (size_t i = 0; i <= na; i++)
        d[i][0] = (int)i;
    for (size_t j = 0; j <= nb; j++)
        d[0][j] = (int)j;
    for (size_t i = 1; i <= na; i++) {
        for (size_t j = 1; j <= nb; j++) {
            int sub = a[i - 1] == b[j - 1] ? 0 : 1;
            int best = d[i - 1][j - 1] + sub;
            if (d[i - 1][j] + 1 < best)
                best = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < best)
                best = d[i][j - 1] + 1;
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]
                && d[i - 2][j - 2] + 1 < best)
                best = d[i - 2][j - 2] + 1;
            d[i][j] = best;
        }
    }
    return d[na][nb] > cap ? cap + 1 : d[na][nb];
}

static int lower_equal(const char *a, const char *b)
{
    for (; *a && *b; a++, b++) {
        int ca = *a >= 'A' && *a <= 'Z' ? *a + 32 : *a;
        int cb = *b >= 'A' && *b <= 'Z' ? *b + 32 : *b;
        if (ca != cb)
            return 0;
    }
    return *a == *b;
}

const char *dict_suggest(const char *word, const char *const *cand, int n)
{
    /* small means: a case change, or at most one edit per four letters
     * (and at most 3), so "nu" never suggests "mu" but "writeIntervall"
     * suggests "writeInterval" */
    size_t len = strlen(word);
    int cap = (int)(len / 4);
    if (cap < 1)
        cap = 1;
    if (cap > 3)
        cap = 3;
    if (len <= 2)
        cap = 0;
    const char *best = NULL;
    int bestd = cap + 1;
    for (int i = 0; i < n; i++) {
        if (strcmp(cand[i], word) == 0)
            continue;
        int dd = lower_equal(cand[i], word)
                     ? 0 : dict_edit_distance(word, cand[i], cap);
        if (dd < bestd) {
            bestd = dd;
            best = cand[i];
        }
    }
    return bestd <= cap ? best : NULL;
}

const void *model_find(const void *const *table, const char *name)
{
    for (int i = 0; table[i]; i++) {
        const struct model_head *h = table[i];
        if (strcmp(h->name, name) == 0)
            return h;
    }
    return NULL;
}

const char *model_unknown(const void *const *table, const char *category,
                          const char *name, char *buf, size_t len)
{
    char valid[1024] = "";
    size_t used = 0;
    const char *cand[64];
    int nc = 0;
    for (int i = 0; table[i] && used < sizeof valid - 64; i++) {
        const struct model_head *m = table[i];
        used += (size_t)snprintf(valid + used, sizeof valid - used, " %s",
                                 m->name);
        if (nc < 64)
            cand[nc++] = m->name;
    }
    const char *best = dict_suggest(name, cand, nc);
    char hint[128] = "";
    if (best)
        snprintf(hint, sizeof hint, " (did you mean '%s'?)", best);
    snprintf(buf, len, "unknown %s '%s'; valid:%s%s", category, name, valid,
             hint);
    return buf;
}
