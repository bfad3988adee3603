/*
 * fo_forces.c — hydrodynamic (pressure) force on named wall patches
 * (doc/theory.md A.9 [P]; force on the obstacle, Figs. 18 and 24 of Xie
 * et al. 2025):
 *
 *     F_k = sum over wall particles i of patch k of  p_i dp^(d-1) n_i
 *
 * with n_i the unit normal from the fluid into the solid, so that a
 * positive pressure pushes on the face; dp^(d-1) is the face area a wall
 * particle stands for (a length in 2-D, where F is per unit width, N/m).
 * Dummy particles carry copies of wall pressures and are not counted.
 * A solver that knows better publishes per wall particle its area A_i
 * (field wallArea) and the viscous stress t_i the fluid exerts on it
 * (field viscousTraction; mlpgFluid, doc/theory.md M0-24); then
 *
 *     F_k = sum over wall particles i of patch k of  A_i (p_i n_i + t_i)
 *
 * and the columns Fvx Fvy Fvz give the viscous part alone.
 *
 * On a still lattice of N fluid layers against a vertical wall (wall
 * particles level with the fluid ones, p = rho g (h - z) with the surface
 * h dp/2 above the top layer) the sum is exactly rho g (N dp)^2/2 per unit
 * width: the continuous rho g h^2/2 with h = N dp, short of the
 * h = (N + 1/2) dp of the particle surface by a relative 1/N.
 *
 * With soil (doc/theory.md K), `phase soil` or `phase water` splits the
 * load: each wall particle's term times the soil's share s_i of its
 * fluid neighbours (kernel-weighted, field soilFraction), or 1 - s_i; the
 * two add up to the whole.
 *
 * Keys:
 *   patches (obstacle ...);   // wall patch names (constant/particlePatches)
 *   phase   all;              // all (default) | water | soil
 * Columns: time, then Fx Fy Fz of each patch [N, or N/m in 2-D] (with
 * viscousTraction: Fx Fy Fz Fvx Fvy Fvz).
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"
#include "functionObjects/mps_functionObjects.h"

#define FIELDS (MPS_FO_TYPE | MPS_FO_PATCH | MPS_FO_PRESSURE | MPS_FO_NORMAL)

struct forces {
    int n;          /* patches asked for          */
    int *which;     /* n scene patch indices      */
    int npatches;   /* of the scene at create     */
    int *column;    /* npatches: index in which[] or -1 */
    double *F;      /* 6n work and result: F, Fv  */
    int phase;      /* enum mps_fo_phase          */
    int viscous;    /* the cloud has viscousTraction */
};

static void destroy(void *data)
{
    struct forces *fo = data;
    if (!fo)
        return;
    free(fo->which);
    free(fo->column);
    free(fo->F);
    free(fo);
}

static int unknown_patch(const struct dict_value *v, const char *name,
                         const struct fo_scene *s)
{
    char valid[1024] = "";
    size_t used = 0;
    for (int k = 0; k < s->npatches && used < sizeof valid - 64; k++)
        used += snprintf(valid + used, sizeof valid - used, " %s",
                         s->patch_names[k]);
    return dict_value_error(v, SIM_ERR_DICT, "unknown wall patch '%s'; "
                            "valid:%s", name, s->npatches ? valid : " (none)");
}

static int find_patch(const struct fo_scene *s, const char *name)
{
    for (int k = 0; k < s->npatches; k++)
        if (s->patch_names[k] && !strcmp(s->patch_names[k], name))
            return k;
    return -1;
}

static int read_patches(const struct dict *d, const struct fo_scene *s,
                        struct forces *fo)
{
    const struct dict_value *list;
    TRY(dict_get_list(d, "patches", &list));
    fo->n = dict_value_len(list);
    if (fo->n < 1)
        return dict_error(d, "patches", SIM_ERR_DICT,
                          "patches needs at least one wall patch name");
    fo->npatches = s->npatches;
    fo->which = sim_calloc((size_t)fo->n, sizeof *fo->which);
    fo->column = sim_calloc((size_t)s->npatches + 1, sizeof *fo->column);
    fo->F = sim_calloc(6 * (size_t)fo->n, sizeof *fo->F);
    if (!fo->which || !fo->column || !fo->F)
        return SIM_ERR_NOMEM;
    for (int k = 0; k < s->npatches; k++)
        fo->column[k] = -1;
    for (int j = 0; j < fo->n; j++) {
        const struct dict_value *v = dict_value_at(list, j);
        const char *name;
        TRY(dict_value_get_word(v, &name));
        int k = find_patch(s, name);
        if (k < 0)
            return unknown_patch(v, name, s);
        if (fo->column[k] >= 0)
            return dict_value_error(v, SIM_ERR_DICT, "patch '%s' is listed "
                                    "twice", name);
        fo->which[j] = k;
        fo->column[k] = j;
    }
    return SIM_OK;
}

static int create(const struct dict *d, const struct fo_scene *s, void **data)
{
    struct mps_fo_fields f;
    struct forces *fo = sim_calloc(1, sizeof *fo);
    if (!fo)
        return SIM_ERR_NOMEM;
    int rc = mps_fo_fields_get(d, s, FIELDS, &f);
    if (rc == SIM_OK)
        rc = read_patches(d, s, fo);
    fo->viscous = f.traction != NULL;
    if (rc == SIM_OK)
        rc = mps_fo_read_phase(d, s, &fo->phase);
    if (rc == SIM_OK && fo->phase != MPS_FO_ALL_PHASES && f.phase
        && !f.soil_frac)
        rc = dict_error(d, "phase", SIM_ERR_DICT, "phase %s: the cloud has "
                        "no field soilFraction to split the load by",
                        fo->phase == MPS_FO_SOIL ? "soil" : "water");
    if (rc != SIM_OK) {
        destroy(fo);
        return rc;
    }
    *data = fo;
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    struct forces *fo = data;
    fprintf(f, "# forces: %s on wall patches [%s]%s\n# time",
            fo->viscous ? "force sum A (p n + t), t the viscous traction "
                          "(Fv: its part)" : "pressure force sum p dp^(d-1) n",
            s->dim == 2 ? "N/m" : "N",
            fo->phase == MPS_FO_SOIL ? ", the soil's share"
            : fo->phase == MPS_FO_WATER ? ", the water's share" : "");
    for (int j = 0; j < fo->n; j++) {
        const char *p = s->patch_names[fo->which[j]];
        fprintf(f, " %s_Fx %s_Fy %s_Fz", p, p, p);
        if (fo->viscous)
            fprintf(f, " %s_Fvx %s_Fvy %s_Fvz", p, p, p);
    }
    fprintf(f, "\n");
    return SIM_OK;
}

static void sum_forces(const struct mps_fo_fields *f, struct forces *fo,
                       double area)
{
    double *F = fo->F;
    int m = 6 * fo->n, np = fo->npatches;
    long n = (long)f->n;
    memset(F, 0, (size_t)m * sizeof *F);
#pragma omp parallel for reduction(+ : F[:m]) schedule(static)
    for (long i = 0; i < n; i++) {
        int k = f->patch[i];
        if (f->type[i] != 1 || k < 0 || k >= np || fo->column[k] < 0)
            continue;
        double a = f->wall_area ? f->wall_area[i] : area;
        if (fo->phase != MPS_FO_ALL_PHASES && f->soil_frac)
            a *= fo->phase == MPS_FO_SOIL ? f->soil_frac[i]
                                          : 1.0 - f->soil_frac[i];
        double *Fk = F + 6 * fo->column[k];
        for (int c = 0; c < 3; c++) {
            double tv = f->traction ? a * f->traction[3 * i + c] : 0;
            Fk[c] += a * f->p[i] * f->normal[3 * i + c] + tv;
            Fk[3 + c] += tv;
        }
    }
}

static int execute(void *data, const struct fo_scene *s, FILE *out)
{
    struct forces *fo = data;
    struct mps_fo_fields f;
    TRY(mps_fo_fields_get(NULL, s, FIELDS, &f));
    if (s->npatches != fo->npatches)
        return sim_error(SIM_ERR_INTERNAL, "forces: the solver had %d wall "
                         "patches at start and now %d", fo->npatches,
                         s->npatches);
    sum_forces(&f, fo, s->dim == 2 ? s->spacing
                                   : s->spacing * s->spacing);
    fprintf(out, "%.15g", s->time);
    for (int j = 0; j < fo->n; j++)
        for (int c = 0; c < (fo->viscous ? 6 : 3); c++)
            fprintf(out, " %.15g", fo->F[6 * j + c]);
    fprintf(out, "\n");
    return SIM_OK;
}

const struct fo_ops fo_mps_forces = {
    .name = "forces",
    .reference = "doc/theory.md A.9",
    .file = "forces",
    .create = create,
    .header = header,
    .execute = execute,
    .destroy = destroy,
};
