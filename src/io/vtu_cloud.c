/* vtu_cloud.c — owning and querying a struct vtu_cloud (vtu.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "io/vtu.h"

static const char *const type_names[] = { "Float64", "Int64", "Int32",
                                          "UInt8" };
static const size_t type_sizes[] = { 8, 8, 4, 1 };

const char *vtu_type_name(enum vtu_type t)
{
    return type_names[t];
}

size_t vtu_type_size(enum vtu_type t)
{
    return type_sizes[t];
}

void vtu_cloud_free(struct vtu_cloud *c)
{
    if (!c)
        return;
    for (int i = 0; i < c->nfields; i++)
        free(c->fields[i].data);
    free(c->fields);
    free(c->points);
    memset(c, 0, sizeof *c);
}

const struct vtu_field *vtu_find(const struct vtu_cloud *c, const char *name)
{
    for (int i = 0; i < c->nfields; i++)
        if (strcmp(c->fields[i].name, name) == 0)
            return &c->fields[i];
    return NULL;
}

int vtu_require(const struct vtu_cloud *c, const char *file, const char *name,
                int type, int ncomp, const struct vtu_field **out)
{
    const struct vtu_field *f = vtu_find(c, name);

    *out = NULL;
    if (!f)
        return sim_error(SIM_ERR_IO, "%s: no point field '%s'", file, name);
    if (type >= 0 && type <= VTU_UINT8 && f->type != (enum vtu_type)type)
        return sim_error(SIM_ERR_IO, "%s: point field '%s' is %s, expected %s",
                         file, name, type_names[f->type], type_names[type]);
    if (ncomp > 0 && f->ncomp != ncomp)
        return sim_error(SIM_ERR_IO, "%s: point field '%s' has %d components, "
                         "expected %d", file, name, f->ncomp, ncomp);
    *out = f;
    return SIM_OK;
}

/* The first non-finite value of n*ncomp doubles, or -1. */
static long first_non_finite(const double *v, size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (!isfinite(v[k]))
            return (long)k;
    return -1;
}

static int non_finite(const struct vtu_cloud *c, const char *file,
                      const char *what, const double *v, int ncomp, long k)
{
    const struct vtu_field *id = vtu_find(c, "id");
    size_t i = (size_t)k / (size_t)ncomp;
    char who[64] = "";
    if (id && id->type == VTU_INT64 && id->ncomp == 1)
        snprintf(who, sizeof who, " (id %lld)",
                 (long long)((const int64_t *)id->data)[i]);
    return sim_error(SIM_ERR_INPUT, "%s: %s holds %g at point %zu%s, "
                     "component %d: a state to start from must be finite",
                     file, what, v[k], i, who, (int)((size_t)k % ncomp));
}

int vtu_check_finite(const struct vtu_cloud *c, const char *file)
{
    char what[96];
    long k;
    if (!isfinite(c->time))
        return sim_error(SIM_ERR_INPUT, "%s: TimeValue is %g: a state to "
                         "start from must be finite", file, c->time);
    if ((k = first_non_finite(c->points, 3 * c->n)) >= 0)
        return non_finite(c, file, "Points", c->points, 3, k);
    for (int f = 0; f < c->nfields; f++) {
        const struct vtu_field *x = &c->fields[f];
        if (x->type != VTU_FLOAT64)
            continue;
        k = first_non_finite(x->data, c->n * (size_t)x->ncomp);
        if (k < 0)
            continue;
        snprintf(what, sizeof what, "point field '%s'", x->name);
        return non_finite(c, file, what, x->data, x->ncomp, k);
    }
    return SIM_OK;
}

int vtu_cloud_add_field(struct vtu_cloud *c, const char *name,
                        enum vtu_type type, int ncomp, void **data)
{
    struct vtu_field *f;
    void *mem;

    *data = NULL;
    if (!name[0] || strlen(name) >= sizeof f->name)
        return sim_error(SIM_ERR_INTERNAL, "field name '%s' is empty or "
                         "longer than %zu characters", name,
                         sizeof f->name - 1);
    if ((unsigned)type > VTU_UINT8 || ncomp < 1 || ncomp > 9)
        return sim_error(SIM_ERR_INTERNAL, "field '%s': bad type %d or "
                         "component count %d", name, (int)type, ncomp);
    if (vtu_find(c, name))
        return sim_error(SIM_ERR_INTERNAL, "field '%s' exists already", name);
    mem = sim_calloc(c->n * (size_t)ncomp, type_sizes[type]);
    if (!mem)
        return SIM_ERR_NOMEM;
    f = sim_realloc(c->fields, (size_t)(c->nfields + 1) * sizeof *f);
    if (!f) {
        free(mem);
        return SIM_ERR_NOMEM;
    }
    c->fields = f;
    f = &c->fields[c->nfields++];
    memset(f, 0, sizeof *f);
    strcpy(f->name, name);
    f->type = type;
    f->ncomp = ncomp;
    f->data = mem;
    *data = mem;
    return SIM_OK;
}
