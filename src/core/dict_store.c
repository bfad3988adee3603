/*
 * dict_store.c — storage of parsed dictionaries: the arena, the entry table
 * with its hash index, deep copies for $var substitution and $sub merging,
 * and the edit distance behind "did you mean" suggestions.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/dict_impl.h"
#include "core/error.h"

/* ---- arena ------------------------------------------------------------------ */

struct arena_block {
    struct arena_block *next;
    size_t used, cap;
    _Alignas(16) unsigned char data[];
};

#define ARENA_BLOCK (64 * 1024)

void *arena_alloc(struct arena *a, size_t n)
{
    n = (n + 15) & ~(size_t)15;
    struct arena_block *b = a->head;
    if (!b || b->cap - b->used < n) {
        size_t cap = n > ARENA_BLOCK / 4 ? n : ARENA_BLOCK;
        struct arena_block *nb = malloc(sizeof *nb + cap);
        if (!nb) {
            sim_error(SIM_ERR_NOMEM, "cannot allocate %zu bytes", cap);
            return NULL;
        }
        nb->used = 0;
        nb->cap = cap;
        if (b && cap != ARENA_BLOCK) {
            /* a big one-off block goes behind the current one, which keeps
             * serving small requests */
            nb->next = b->next;
            b->next = nb;
        } else {
            nb->next = b;
            a->head = nb;
        }
        b = nb;
    }
    void *p = b->data + b->used;
    b->used += n;
    a->bytes += n;
    memset(p, 0, n);
    return p;
}

char *arena_strndup(struct arena *a, const char *s, size_t n)
{
    char *d = arena_alloc(a, n + 1);
    if (d) {
        memcpy(d, s, n);
        d[n] = '\0';
    }
    return d;
}

void arena_free(struct arena *a)
{
    struct arena_block *b = a->head;
    while (b) {
        struct arena_block *next = b->next;
        free(b);
        b = next;
    }
    a->head = NULL;
}

/* ---- dictionaries -------------------------------------------------------------- */

struct dict *dict_new(struct dict_root *root, struct dict *parent,
                      const char *name, const char *file, int line, int col)
{
    struct dict *d = arena_alloc(&root->arena, sizeof *d);
    if (!d)
        return NULL;
    d->parent = parent;
    d->root = root;
    d->name = arena_strndup(&root->arena, name, strlen(name));
    if (!d->name)
        return NULL;
    d->file = file;
    d->line = line;
    d->col = col;
    d->next_in_root = root->dicts;
    root->dicts = d;
    return d;
}

static uint32_t hash_str(const char *s)
{
    uint32_t h = 2166136261u; /* FNV-1a */
    for (; *s; s++)
        h = (h ^ (unsigned char)*s) * 16777619u;
    return h;
}

#define HASH_MIN 16 /* below this many entries a linear scan is faster */

static int rehash(struct dict *d)
{
    int cap = 64;
    while (cap < 2 * d->n)
        cap *= 2;
    int *h = calloc((size_t)cap, sizeof *h);
    if (!h)
        return sim_error(SIM_ERR_NOMEM, "out of memory indexing a dictionary");
    for (int i = 0; i < d->n; i++) {
        uint32_t k = hash_str(d->e[i].key) & (uint32_t)(cap - 1);
        while (h[k])
            k = (k + 1) & (uint32_t)(cap - 1);
        h[k] = i + 1;
    }
    free(d->hash);
    d->hash = h;
    d->hcap = cap;
    return SIM_OK;
}

struct dict_entry *dict_lookup(const struct dict *d, const char *key)
{
    if (!d->hash) {
        for (int i = 0; i < d->n; i++)
            if (strcmp(d->e[i].key, key) == 0)
                return &d->e[i];
        return NULL;
    }
    uint32_t mask = (uint32_t)(d->hcap - 1);
    for (uint32_t k = hash_str(key) & mask; d->hash[k]; k = (k + 1) & mask) {
        struct dict_entry *e = &d->e[d->hash[k] - 1];
        if (strcmp(e->key, key) == 0)
            return e;
    }
    return NULL;
}

struct dict_entry *dict_put(struct dict *d, const char *key)
{
    struct dict_entry *e = dict_lookup(d, key);
    if (e) {
        const char *k = e->key;
        memset(e, 0, sizeof *e);
        e->key = k;
        return e;
    }
    if (d->n == d->cap) {
        int cap = d->cap ? 2 * d->cap : 8;
        struct dict_entry *ne = realloc(d->e, (size_t)cap * sizeof *ne);
        if (!ne) {
            sim_error(SIM_ERR_NOMEM, "out of memory adding '%s'", key);
            return NULL;
        }
        d->e = ne;
        d->cap = cap;
    }
    e = &d->e[d->n++];
    memset(e, 0, sizeof *e);
    e->key = arena_strndup(&d->root->arena, key, strlen(key));
    if (!e->key) {
        d->n--;
        return NULL;
    }
    if (d->n >= HASH_MIN && (!d->hash || 2 * d->n > d->hcap)) {
        if (rehash(d) != SIM_OK) {
            d->n--;
            return NULL;
        }
    } else if (d->hash) {
        uint32_t mask = (uint32_t)(d->hcap - 1);
        uint32_t k = hash_str(e->key) & mask;
        while (d->hash[k])
            k = (k + 1) & mask;
        d->hash[k] = d->n;
    }
    return e;
}

/* ---- deep copies ------------------------------------------------------------ */

static int copy_dict(struct dict_root *root, struct dict *parent,
                     const char *name, const struct dict *src,
                     struct dict **out)
{
    struct dict *d = dict_new(root, parent, name, src->file, src->line,
                              src->col);
    if (!d)
        return SIM_ERR_NOMEM;
    d->in_list = src->in_list;
    TRY(dict_merge_into(d, src));
    *out = d;
    return SIM_OK;
}

int dict_value_copy(struct dict_root *root, struct dict *parent,
                    const char *name, const struct dict_value *src,
                    struct dict_value *dst)
{
    *dst = *src;
    switch (src->kind) {
    case DICT_LIST:
    case DICT_ENTRY: {
        int n = src->u.l.n;
        dst->u.l.items = NULL;
        if (n == 0)
            return SIM_OK;
        dst->u.l.items = arena_alloc(&root->arena,
                                     (size_t)n * sizeof *dst->u.l.items);
        if (!dst->u.l.items)
            return SIM_ERR_NOMEM;
        for (int i = 0; i < n; i++)
            TRY(dict_value_copy(root, parent, name, &src->u.l.items[i],
                                &dst->u.l.items[i]));
        return SIM_OK;
    }
    case DICT_DICT:
        return copy_dict(root, parent, name, src->u.d, &dst->u.d);
    default:
        return SIM_OK; /* strings stay shared: same arena or the source's */
    }
}

static char *join_name(struct dict_root *root, const char *a, const char *b)
{
    size_t na = strlen(a), nb = strlen(b);
    char *s = arena_alloc(&root->arena, na + nb + 2);
    if (!s)
        return NULL;
    if (na) {
        memcpy(s, a, na);
        s[na++] = '/';
    }
    memcpy(s + na, b, nb + 1);
    return s;
}

/* Entries of src are added to dst (replacing equal keys), deep-copied. */
int dict_merge_into(struct dict *dst, const struct dict *src)
{
    struct dict_root *root = dst->root;
    for (int i = 0; i < src->n; i++) {
        const struct dict_entry *se = &src->e[i];
        const char *name = join_name(root, dst->name, se->key);
        struct dict_value *v = arena_alloc(&root->arena, sizeof *v);
        if (!name || !v)
            return SIM_ERR_NOMEM;
        TRY(dict_value_copy(root, dst, name, se->val, v));
        struct dict_entry *de = dict_put(dst, se->key);
        if (!de)
            return SIM_ERR_NOMEM;
        const char *key = de->key;
        *de = *se;
        de->key = key;
        de->val = v;
        de->used = 0;
        de->referenced = 0;
        /* the copy's text lives elsewhere: dict_set_in_file must not edit
         * there, but add an overriding entry */
        de->vbeg = de->vend = (size_t)-1;
    }
    return SIM_OK;
}

/* ---- descriptions --------------------------------------------------------- */

void dict_describe(const struct dict_value *v, char *buf, size_t n)
{
    switch ((enum dict_kind)v->kind) {
    case DICT_WORD:
        snprintf(buf, n, "word '%.60s'", v->u.s.text);
        break;
    case DICT_NUMBER:
        snprintf(buf, n, "number %.60s", v->u.s.text);
        break;
    case DICT_STRING:
        snprintf(buf, n, "string \"%.60s\"", v->u.s.text);
        break;
    case DICT_LIST:
        snprintf(buf, n, "a list of %d item%s", v->u.l.n,
                 v->u.l.n == 1 ? "" : "s");
        break;
    case DICT_DICT:
        snprintf(buf, n, "a dictionary");
        break;
    case DICT_DIMS:
        snprintf(buf, n, "a dimension set");
        break;
    case DICT_ENTRY:
        if (v->u.l.n == 1)
            dict_describe(&v->u.l.items[0], buf, n);
        else if (v->u.l.n == 0)
            snprintf(buf, n, "no value");
        else
            snprintf(buf, n, "%d values", v->u.l.n);
        break;
    }
}
