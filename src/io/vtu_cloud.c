/* vtu_cloud.c — owning and querying a struct vtu_cloud (vtu.h). */
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "io/vtu.h"

static const char *const type_names[] = { "Float64", "Int64", "Int32",
                                          "UInt8" };
static const size_t type_sizes[] = { 8, 8, 4, 1 };

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
