/*
 * fo_cloudInfo.c — particle counts and bounding box of a cloud over time.
 *
 * Columns: time, number of particles, count per value of the integer field
 * `type` when the cloud has one (fluid/wall/dummy for the MPS cloud), and
 * the bounding box (min x y z, max x y z) of the moving particles: those of
 * type 0 when there is a `type` field, all particles otherwise. A growing
 * box or a changing count is the first sign of particles escaping.
 *
 * Keys: none beyond the schedule.
 */
#include <float.h>
#include <stdint.h>
#include <stdlib.h>

#include "core/error.h"
#include "functionObjects/functionObject.h"

#define MAX_TYPES 8

struct cloud_info {
    int has_type;
};

static const int32_t *type_field(const struct fo_scene *s)
{
    const struct store_field *f = store_find(s->store, "type");
    if (!f || f->type != VTU_INT32 || f->ncomp != 1)
        return NULL;
    return *f->ref;
}

static int create(const struct dict *d, const struct fo_scene *s, void **data)
{
    (void)d;
    struct cloud_info *c = sim_calloc(1, sizeof *c);
    if (!c)
        return SIM_ERR_NOMEM;
    c->has_type = type_field(s) != NULL;
    *data = c;
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    struct cloud_info *c = data;
    fprintf(f, "# cloudInfo of cloud '%s'\n# time n", s->cloud_name);
    if (c->has_type)
        for (int k = 0; k < MAX_TYPES; k++)
            fprintf(f, " n_type%d", k);
    fprintf(f, " xmin ymin zmin xmax ymax zmax\n");
    return SIM_OK;
}

static int execute(void *data, const struct fo_scene *s, FILE *f)
{
    struct cloud_info *c = data;
    const void *x;
    TRY(store_require(s->store, s->cloud_name, "position", VTU_FLOAT64, 3,
                      &x));
    const double *points = x;
    const size_t n = s->store->n;
    const int32_t *type = c->has_type ? type_field(s) : NULL;
    long count[MAX_TYPES] = {0};
    double lo[3] = {DBL_MAX, DBL_MAX, DBL_MAX};
    double hi[3] = {-DBL_MAX, -DBL_MAX, -DBL_MAX};
    for (size_t i = 0; i < n; i++) {
        if (type && type[i] >= 0 && type[i] < MAX_TYPES)
            count[type[i]]++;
        if (type && type[i] != 0)
            continue;
        for (int k = 0; k < 3; k++) {
            double x = points[3 * i + k];
            lo[k] = x < lo[k] ? x : lo[k];
            hi[k] = x > hi[k] ? x : hi[k];
        }
    }
    fprintf(f, "%.9g %zu", s->time, n);
    if (c->has_type)
        for (int k = 0; k < MAX_TYPES; k++)
            fprintf(f, " %ld", count[k]);
    if (lo[0] > hi[0])  /* no moving particle */
        fprintf(f, " nan nan nan nan nan nan\n");
    else
        fprintf(f, " %.9g %.9g %.9g %.9g %.9g %.9g\n", lo[0], lo[1], lo[2],
                hi[0], hi[1], hi[2]);
    return SIM_OK;
}

static void destroy(void *data) { free(data); }

const struct fo_ops fo_cloud_info = {
    .name = "cloudInfo",
    .reference = "",
    .file = "cloudInfo",
    .create = create,
    .header = header,
    .execute = execute,
    .destroy = destroy,
};
