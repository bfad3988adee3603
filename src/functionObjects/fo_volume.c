/*
 * fo_volume.c — fluid volume as a conservation check (doc/theory.md E1-17):
 *
 *     N_f = number of fluid particles,   V = N_f dp^d
 *     (V = sum of volumeFraction dp^d when the cloud has that field,
 *     genParticles grainVolume scale),
 *     dV  = (V - V_0)/V_0,  V_0 the volume at this run's first execution
 *
 * MPS particles carry fixed volumes, so V changes only when the solver
 * removes particles that left the domain; the solver's count of those, the
 * value "escaped" of the scene when it publishes one, is the last column
 * (nan when it does not). A restarted run measures dV from its own start.
 *
 * Keys: phase all | water | soil (cases with soil; default all).
 * Columns: time, N_f, V [m^3, or m^2 in 2-D], dV [-], escaped.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "core/error.h"
#include "core/select.h"
#include "functionObjects/mps_functionObjects.h"

struct volume {
    int started;
    double v0;
    int phase;      /* enum mps_fo_phase */
};

static int create(const struct dict *d, const struct fo_scene *s, void **data)
{
    struct mps_fo_fields f;
    TRY(mps_fo_fields_get(d, s, MPS_FO_TYPE, &f));
    struct volume *v = sim_calloc(1, sizeof *v);
    if (!v)
        return SIM_ERR_NOMEM;
    int rc = mps_fo_read_phase(d, s, &v->phase);
    if (rc != SIM_OK) {
        free(v);
        return rc;
    }
    *data = v;
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    const struct volume *v = data;
    if (v->phase != MPS_FO_ALL_PHASES)
        fprintf(f, "# only the %s particles\n",
                mps_fo_phase_table[v->phase]->name);
    fprintf(f, "# volume: fluid particles N, volume N dp^%d [%s], relative "
            "change from the first row, particles escaped (nan: not "
            "published by the solver)\n# time N V dV escaped\n", s->dim,
            s->dim == 2 ? "m^2" : "m^3");
    return SIM_OK;
}

static int execute(void *data, const struct fo_scene *s, FILE *out)
{
    struct volume *v = data;
    struct mps_fo_fields f;
    TRY(mps_fo_fields_get(NULL, s, MPS_FO_TYPE, &f));
    long count = 0, n = (long)f.n;
    double sum = 0; /* fluid volume in dp^d: the volume fractions if any */
    const struct store_field *vf = store_find(s->store, "volumeFraction");
    const double *phi = vf && vf->type == VTU_FLOAT64 && vf->ncomp == 1
                      ? *vf->ref : NULL;
#pragma omp parallel for reduction(+ : count, sum) schedule(static)
    for (long i = 0; i < n; i++)
        if (mps_fo_in_phase(&f, i, v->phase)) {
            count++;
            sum += phi ? phi[i] : 1.0;
        }
    double vol = sum * pow(s->spacing, s->dim);
    if (!v->started) {
        v->started = 1;
        v->v0 = vol;
    }
    const struct fo_value *esc = mps_fo_value(s, "escaped");
    fprintf(out, "%.15g %ld %.15g %.15g %.15g\n", s->time, count, vol,
            v->v0 > 0 ? (vol - v->v0) / v->v0 : NAN,
            esc && esc->ncomp >= 1 ? esc->v[0] : NAN);
    return SIM_OK;
}

static void destroy(void *data) { free(data); }

const struct fo_ops fo_mps_volume = {
    .name = "volume",
    .reference = "doc/theory.md E1-17",
    .file = "volume",
    .create = create,
    .header = header,
    .execute = execute,
    .destroy = destroy,
};
