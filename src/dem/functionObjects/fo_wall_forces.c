/*
 * fo_wall_forces.c — contact force that the grains exert on each wall
 * patch, F_p = -sum over contacts with walls of patch p of F^C (the "load
 * of solids on the structure", doc/theory.md A.9 and A.12.3-4). The value is
 * the instantaneous force at the accepted state ending the step.
 * Columns: time, then Fx Fy Fz [N] per patch that has walls.
 * Keys: patches (names ...);  optional, default every wall patch.
 */
#include <stdlib.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"
#include "dem/dem.h"
#include "dem/functionObjects/dem_fo.h"

struct wall_forces {
    int n;
    int patch[DEM_MAX_PATCHES];
};

static int has_walls(const struct dem *d, int p)
{
    for (int w = 0; w < d->nwalls; w++)
        if (d->walls[w].patch == p)
            return 1;
    return 0;
}

static int create(const struct dict *dd, const struct fo_scene *s,
                  void **data)
{
    const struct dem *d = s->solver;
    struct wall_forces *wf = sim_calloc(1, sizeof *wf);
    if (!wf)
        return SIM_ERR_NOMEM;
    *data = wf;
    if (!dict_has(dd, "patches")) {
        for (int p = 0; p < d->npatches; p++)
            if (has_walls(d, p))
                wf->patch[wf->n++] = p;
        return SIM_OK;
    }
    const struct dict_value *l;
    TRY(dict_get_list(dd, "patches", &l));
    for (int i = 0; i < dict_value_len(l) && wf->n < DEM_MAX_PATCHES; i++) {
        const char *name;
        TRY(dict_value_get_word(dict_value_at(l, i), &name));
        int p = 0;
        while (p < d->npatches && strcmp(d->patch_names[p], name))
            p++;
        if (p == d->npatches || !has_walls(d, p)) {
            char valid[1024] = "";
            size_t u = 0;
            for (int q = 0; q < d->npatches && u < sizeof valid - 70; q++)
                if (has_walls(d, q))
                    u += (size_t)snprintf(valid + u, sizeof valid - u, " %s",
                                          d->patch_names[q]);
            return dict_value_error(dict_value_at(l, i), SIM_ERR_DICT,
                                    "no wall patch '%s'; valid:%s", name,
                                    valid);
        }
        wf->patch[wf->n++] = p;
    }
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    struct wall_forces *wf = data;
    const struct dem *d = s->solver;
    fprintf(f, "# force of the grains on wall patches [N]\n# time");
    for (int k = 0; k < wf->n; k++) {
        const char *nm = d->patch_names[wf->patch[k]];
        fprintf(f, " %s_x %s_y %s_z", nm, nm, nm);
    }
    fprintf(f, "\n");
    return SIM_OK;
}

static int execute(void *data, const struct fo_scene *s, FILE *f)
{
    struct wall_forces *wf = data;
    const struct dem *d = s->solver;
    fprintf(f, "%.9g", s->time);
    for (int k = 0; k < wf->n; k++) {
        const double *F = &d->patch_force[3 * wf->patch[k]];
        fprintf(f, " %.9g %.9g %.9g", F[0], F[1], F[2]);
    }
    fprintf(f, "\n");
    return SIM_OK;
}

static void destroy(void *data)
{
    free(data);
}

const struct fo_ops dem_fo_wall_forces = {
    .name = "wallForces",
    .reference = "doc/theory.md A.9 (load of solids on a structure)",
    .file = "",
    .create = create,
    .header = header,
    .execute = execute,
    .destroy = destroy,
};
