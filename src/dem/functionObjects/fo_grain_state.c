/*
 * fo_grain_state.c — probe of selected grains (by id): position, velocity
 * and spin over time, for single-grain validation cases (restitution,
 * sliding to rolling).
 * Columns: time, then for each id: x y z [m] vx vy vz [m/s] wx wy wz
 * [rad/s] (nan when the grain no longer exists).
 * Keys: ids (0 1 ...);   required.
 * Reads the cloud's fields by name (position, velocity, omega, id), looked
 * up again at every execution: removal moves them.
 */
#include <math.h>
#include <stdlib.h>

#include "core/dict.h"
#include "core/error.h"
#include "dem/functionObjects/dem_fo.h"

#define MAX_IDS 64

struct grain_state {
    int n;
    long long id[MAX_IDS];
};

struct grain_fields {
    const double *x, *v, *w;
    const int64_t *id;
};

static int fields(const struct fo_scene *s, const char *who,
                  struct grain_fields *g)
{
    const void *p[4];
    TRY(store_require(s->store, who, "position", VTU_FLOAT64, 3, &p[0]));
    TRY(store_require(s->store, who, "velocity", VTU_FLOAT64, 3, &p[1]));
    TRY(store_require(s->store, who, "omega", VTU_FLOAT64, 3, &p[2]));
    TRY(store_require(s->store, who, "id", VTU_INT64, 1, &p[3]));
    *g = (struct grain_fields){ p[0], p[1], p[2], p[3] };
    return SIM_OK;
}

static int create(const struct dict *dd, const struct fo_scene *s,
                  void **data)
{
    struct grain_fields gf;
    TRY(fields(s, dict_name(dd), &gf));
    struct grain_state *g = sim_calloc(1, sizeof *g);
    if (!g)
        return SIM_ERR_NOMEM;
    *data = g;
    const struct dict_value *l;
    TRY(dict_get_list(dd, "ids", &l));
    if (dict_value_len(l) < 1 || dict_value_len(l) > MAX_IDS)
        return dict_error(dd, "ids", SIM_ERR_DICT, "give 1 to %d grain ids",
                          MAX_IDS);
    for (int i = 0; i < dict_value_len(l); i++) {
        double v;
        TRY(dict_value_get_scalar(dict_value_at(l, i), &v));
        if (v != floor(v) || v < 0)
            return dict_value_error(dict_value_at(l, i), SIM_ERR_DICT,
                                    "a grain id is a whole number >= 0");
        g->id[g->n++] = (long long)v;
    }
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    struct grain_state *g = data;
    (void)s;
    fprintf(f, "# grain states [m, m/s, rad/s]\n# time");
    for (int k = 0; k < g->n; k++)
        fprintf(f, " x%lld y%lld z%lld vx%lld vy%lld vz%lld wx%lld wy%lld "
                   "wz%lld", g->id[k], g->id[k], g->id[k], g->id[k],
                g->id[k], g->id[k], g->id[k], g->id[k], g->id[k]);
    fprintf(f, "\n");
    return SIM_OK;
}

static int execute(void *data, const struct fo_scene *s, FILE *f)
{
    struct grain_state *g = data;
    struct grain_fields d;
    TRY(fields(s, "grainState", &d));
    const size_t n = s->store->n;
    fprintf(f, "%.9g", s->time);
    for (int k = 0; k < g->n; k++) {
        size_t i = 0;
        while (i < n && d.id[i] != g->id[k])
            i++;
        if (i == n) {
            fprintf(f, " nan nan nan nan nan nan nan nan nan");
            continue;
        }
        for (int a = 0; a < 3; a++)
            fprintf(f, " %.12g", d.x[3 * i + a]);
        for (int a = 0; a < 3; a++)
            fprintf(f, " %.12g", d.v[3 * i + a]);
        for (int a = 0; a < 3; a++)
            fprintf(f, " %.12g", d.w[3 * i + a]);
    }
    fprintf(f, "\n");
    return SIM_OK;
}

static void destroy(void *data)
{
    free(data);
}

const struct fo_ops dem_fo_grain_state = {
    .name = "grainState",
    .reference = "",
    .file = "",
    .create = create,
    .header = header,
    .execute = execute,
    .destroy = destroy,
};
