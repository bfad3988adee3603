/* store.c — see store.h. */
#include "particles/store.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "core/select.h"

/* Room past the last particle (store.h). */
#define PAD 64

static size_t type_size(enum vtu_type t)
{
    switch (t) {
    case VTU_FLOAT64: case VTU_INT64: return 8;
    case VTU_INT32: return 4;
    case VTU_UINT8: return 1;
    }
    return 0;
}

static const char *type_name(int t)
{
    static const char *const names[] = { "Float64", "Int64", "Int32",
                                         "UInt8" };
    return t >= 0 && t < 4 ? names[t] : "?";
}

static int owned(const struct store_field *f)
{
    return !(f->flags & STORE_VIEW);
}

void store_init(struct store *s, const char *category)
{
    memset(s, 0, sizeof *s);
    s->category = category ? category : "particle field";
}

void store_free(struct store *s)
{
    for (int k = 0; k < s->nfields; k++) {
        struct store_field *f = &s->f[k];
        if (owned(f)) {
            free(*f->ref);
            *f->ref = NULL;
        }
    }
    free(s->scratch);
    free(s->inv);
    store_init(s, s->category);
}

/* Grow one owned array from `from` to `to` particles, zeroing the new
 * part. */
static int grow(struct store_field *f, size_t from, size_t to)
{
    char *a = sim_realloc(*f->ref, to * f->elem + PAD);
    if (!a)
        return SIM_ERR_NOMEM;
    memset(a + from * f->elem, 0, (to - from) * f->elem + PAD);
    *f->ref = a;
    return SIM_OK;
}

int store_add(struct store *s, const char *name, const char *doc,
              enum vtu_type type, int ncomp, unsigned flags, void *ref)
{
    if (store_find(s, name))
        return sim_error(SIM_ERR_INTERNAL, "%s '%s' registered twice",
                         s->category, name);
    if (s->nfields == STORE_MAX_FIELDS)
        return sim_error(SIM_ERR_INTERNAL, "more than %d fields (%s '%s')",
                         STORE_MAX_FIELDS, s->category, name);
    if ((flags & STORE_INDEX) && (type != VTU_INT32 || ncomp != 1))
        return sim_error(SIM_ERR_INTERNAL, "%s '%s': indices are Int32 x1",
                         s->category, name);
    struct store_field *f = &s->f[s->nfields];
    *f = (struct store_field){ .name = name, .doc = doc ? doc : "",
                               .type = type, .ncomp = ncomp, .flags = flags,
                               .elem = type_size(type) * (size_t)ncomp,
                               .ref = ref };
    if (owned(f)) {
        *f->ref = NULL;
        TRY(grow(f, 0, s->cap));
    }
    s->nfields++;
    return SIM_OK;
}

int store_reserve(struct store *s, size_t cap)
{
    if (cap <= s->cap)
        return SIM_OK;
    for (int k = 0; k < s->nfields; k++)
        if (owned(&s->f[k]))
            TRY(grow(&s->f[k], s->n, cap));
    s->cap = cap;
    return SIM_OK;
}

int store_resize(struct store *s, size_t n)
{
    TRY(store_reserve(s, n));
    for (int k = 0; n > s->n && k < s->nfields; k++) {
        struct store_field *f = &s->f[k];
        if (owned(f))
            memset((char *)*f->ref + s->n * f->elem, 0, (n - s->n) * f->elem);
    }
    s->n = n;
    return SIM_OK;
}

/* inv[old] = new index or -1, for the STORE_INDEX fields; 0 when there is
 * none (nothing to do). */
static int index_map(struct store *s, const int32_t *list, size_t m,
                     int *any)
{
    *any = 0;
    for (int k = 0; k < s->nfields; k++)
        *any |= (s->f[k].flags & STORE_INDEX) != 0;
    if (!*any)
        return SIM_OK;
    if (s->n > s->inv_cap) {
        SIM_GROW(s->inv, s->n);
        s->inv_cap = s->n;
    }
    for (size_t i = 0; i < s->n; i++)
        s->inv[i] = -1;
    for (size_t i = 0; i < m; i++)
        s->inv[list[i]] = (int32_t)i;
    return SIM_OK;
}

static void remap(struct store *s, size_t m)
{
    for (int k = 0; k < s->nfields; k++) {
        if (!(s->f[k].flags & STORE_INDEX) || !owned(&s->f[k]))
            continue;
        int32_t *a = *s->f[k].ref;
        for (size_t i = 0; i < m; i++)
            if (a[i] >= 0)
                a[i] = s->inv[a[i]];
    }
}

/* dst[i] = src[perm[i]], elem bytes each; the common sizes as words so
 * that the loop is a plain gather. */
static void gather(void *dst, const void *src, size_t elem,
                   const int32_t *perm, long m)
{
    if (elem == 8) {
        uint64_t *d = dst;
        const uint64_t *a = src;
#pragma omp parallel for schedule(static)
        for (long i = 0; i < m; i++)
            d[i] = a[perm[i]];
    } else if (elem == 24) {
        uint64_t *d = dst;
        const uint64_t *a = src;
#pragma omp parallel for schedule(static)
        for (long i = 0; i < m; i++)
            for (int c = 0; c < 3; c++)
                d[3 * i + c] = a[3 * (size_t)perm[i] + c];
    } else {
        char *d = dst;
        const char *a = src;
#pragma omp parallel for schedule(static)
        for (long i = 0; i < m; i++)
            memcpy(d + (size_t)i * elem, a + (size_t)perm[i] * elem, elem);
    }
}

int store_permute(struct store *s, const int32_t *perm, size_t m)
{
    int any;
    TRY(index_map(s, perm, m, &any));
    size_t need = 0;
    for (int k = 0; k < s->nfields; k++)
        if (owned(&s->f[k]) && s->f[k].elem * m > need)
            need = s->f[k].elem * m;
    if (need > s->scratch_bytes) {
        void *q = sim_realloc(s->scratch, need);
        if (!q)
            return SIM_ERR_NOMEM;
        s->scratch = q;
        s->scratch_bytes = need;
    }
    for (int k = 0; k < s->nfields; k++) {
        struct store_field *f = &s->f[k];
        if (!owned(f))
            continue;
        gather(s->scratch, *f->ref, f->elem, perm, (long)m);
        memcpy(*f->ref, s->scratch, m * f->elem);
    }
    if (any)
        remap(s, m);
    s->n = m;
    return SIM_OK;
}

int store_compact_unmapped(struct store *s, const int32_t *kept, size_t m)
{
    for (int k = 0; k < s->nfields; k++) {
        struct store_field *f = &s->f[k];
        if (!owned(f))
            continue;
        char *a = *f->ref;
        /* kept[i] >= i: moving forward never overwrites a later source */
        for (size_t i = 0; i < m; i++)
            if ((size_t)kept[i] != i)
                memcpy(a + i * f->elem, a + (size_t)kept[i] * f->elem,
                       f->elem);
    }
    s->n = m;
    return SIM_OK;
}

int store_compact(struct store *s, const int32_t *kept, size_t m)
{
    int any;
    TRY(index_map(s, kept, m, &any));
    TRY(store_compact_unmapped(s, kept, m));
    if (any)
        remap(s, m);
    return SIM_OK;
}

void store_moved(struct store *s, const void *old, void *now, size_t size)
{
    const char *o = old;
    for (int k = 0; k < s->nfields; k++) {
        char *r = (char *)s->f[k].ref;
        if (r >= o && r < o + size)
            s->f[k].ref = (void **)((char *)now + (r - o));
    }
}

const struct store_field *store_find(const struct store *s, const char *name)
{
    for (int k = 0; k < s->nfields; k++)
        if (strcmp(s->f[k].name, name) == 0)
            return &s->f[k];
    return NULL;
}

int store_require(const struct store *s, const char *who, const char *name,
                  int type, int ncomp, const void **data)
{
    const struct store_field *f = store_find(s, name);
    if (!f) {
        const void *table[STORE_MAX_FIELDS + 1];
        for (int k = 0; k < s->nfields; k++)
            table[k] = &s->f[k];
        table[s->nfields] = NULL;
        char msg[1400];
        return sim_error(SIM_ERR_INPUT, "%s: %s", who,
                         model_unknown(table, s->category, name, msg,
                                       sizeof msg));
    }
    if ((type >= 0 && (int)f->type != type)
        || (ncomp > 0 && f->ncomp != ncomp))
        return sim_error(SIM_ERR_INPUT, "%s: %s '%s' is %s x%d, not %s x%d",
                         who, s->category, name, type_name((int)f->type),
                         f->ncomp, type_name(type >= 0 ? type : (int)f->type),
                         ncomp > 0 ? ncomp : f->ncomp);
    *data = *f->ref;
    return SIM_OK;
}

void store_cloud(const struct store *s, double time, struct vtu_field *out,
                 struct vtu_cloud *c)
{
    *c = (struct vtu_cloud){ .n = s->n, .fields = out, .time = time };
    for (int k = 0; k < s->nfields; k++) {
        const struct store_field *f = &s->f[k];
        if (f->flags & STORE_POINTS)
            c->points = *f->ref;
        if (!(f->flags & STORE_WRITE))
            continue;
        struct vtu_field *o = &out[c->nfields++];
        snprintf(o->name, sizeof o->name, "%s", f->name);
        o->type = f->type;
        o->ncomp = f->ncomp;
        o->data = *f->ref;
    }
}

int store_view_cloud(struct store *s, struct vtu_cloud *c)
{
    TRY(store_add(s, "position", "[m]", VTU_FLOAT64, 3,
                  STORE_VIEW | STORE_POINTS, &c->points));
    for (int k = 0; k < c->nfields; k++)
        TRY(store_add(s, c->fields[k].name, "", c->fields[k].type,
                      c->fields[k].ncomp, STORE_VIEW | STORE_WRITE,
                      &c->fields[k].data));
    s->n = c->n;
    return SIM_OK;
}
