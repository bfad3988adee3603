/*
 * couple_fo.c — function object couplingForces of a coupled demSolid run
 * (doc/theory.md A.12.1 outputs, Fig. 5): per written row the total drag
 * sum_k F_bar^d_k of eq. (25) averaged over the last coupling interval, the
 * total pressure-gradient force (Model A: sum -V_k gradP_k, eq. 34; Model
 * B: the buoyancy sum -V_k rho_f g, eq. 35), the largest grain-fluid slip
 * |u_k - v_k| and the smallest porosity eps_k at the grains.
 *
 * It reads the scene values couple_dem_values() publishes; in a run
 * without coupling there are none and the entry is refused at creation.
 */
#include <stdio.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"
#include "couplingDem/couple_dem.h"
#include "functionObjects/functionObject.h"

static const char *const names[COUPLE_DEM_NVALUES] = {
    "couplingDrag", "couplingPressureForce", "couplingSlipMax",
    "couplingPorosityMin", "couplingWetGrains" };

static const struct fo_value *find(const struct fo_scene *s, const char *n)
{
    for (int i = 0; i < s->nvalues; i++)
        if (!strcmp(s->values[i].name, n))
            return &s->values[i];
    return NULL;
}

static int create(const struct dict *d, const struct fo_scene *s,
                  void **data)
{
    *data = NULL;
    for (int i = 0; i < COUPLE_DEM_NVALUES; i++)
        if (!find(s, names[i]))
            return dict_error(d, "type", SIM_ERR_DICT, "couplingForces "
                              "needs a coupled demSolid run (system/"
                              "couplingDict, coupled yes; add 'cloud dem;')");
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    (void)data, (void)s;
    fprintf(f, "# coupling forces on all grains [N], averaged over the last "
               "coupling interval\n# time dragX dragY dragZ pressureX "
               "pressureY pressureZ slipMax[m/s] porosityMin wetGrains\n");
    return SIM_OK;
}

static int execute(void *data, const struct fo_scene *s, FILE *f)
{
    (void)data;
    const struct fo_value *dr = find(s, names[0]), *pr = find(s, names[1]);
    fprintf(f, "%.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.0f\n",
            s->time, dr->v[0], dr->v[1], dr->v[2], pr->v[0], pr->v[1],
            pr->v[2], find(s, names[2])->v[0], find(s, names[3])->v[0],
            find(s, names[4])->v[0]);
    return SIM_OK;
}

static void destroy(void *data)
{
    (void)data;
}

static const struct fo_ops couple_fo_forces = {
    .name = "couplingForces",
    .reference = "Xie et al. 2025 Fig. 5 (doc/theory.md A.12.1)",
    .file = "couplingForces",
    .create = create,
    .header = header,
    .execute = execute,
    .destroy = destroy,
};

const struct fo_ops *const couple_fo_table[] = { &couple_fo_forces, NULL };

void couple_dem_values(const struct couple_dem *cd, const struct dem *d,
                       struct fo_value *v)
{
    for (int i = 0; i < COUPLE_DEM_NVALUES; i++) {
        memset(&v[i], 0, sizeof v[i]);
        v[i].name = names[i];
        v[i].ncomp = i < 2 ? 3 : 1;
    }
    couple_dem_totals(cd, d, v[0].v, v[1].v, &v[2].v[0], &v[3].v[0],
                      &v[4].v[0]);
}
