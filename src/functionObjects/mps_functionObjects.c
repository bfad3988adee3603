/*
 * mps_functionObjects.c — the list of MPS function objects (the only place
 * to register a new one) and the helpers they share: checked access to the
 * fields of the contract in mps_functionObjects.h, and point lists.
 */
#include "functionObjects/mps_functionObjects.h"

#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/select.h"

extern const struct fo_ops fo_mps_probes, fo_mps_wave_gauges, fo_mps_front,
    fo_mps_forces, fo_mps_volume;

const struct fo_ops *const mps_fo_table[] = {
    &fo_mps_probes, &fo_mps_wave_gauges, &fo_mps_front,
    &fo_mps_forces, &fo_mps_volume, NULL,
};

struct field_spec {
    unsigned bit;
    const char *name;
    enum vtu_type type;
    int ncomp;
    size_t offset; /* of the pointer in struct mps_fo_fields */
};

static const struct field_spec specs[] = {
    {MPS_FO_TYPE, "type", VTU_INT32, 1, offsetof(struct mps_fo_fields, type)},
    {MPS_FO_PATCH, "patch", VTU_INT32, 1,
     offsetof(struct mps_fo_fields, patch)},
    {MPS_FO_PRESSURE, "pressure", VTU_FLOAT64, 1,
     offsetof(struct mps_fo_fields, p)},
    {MPS_FO_VELOCITY, "velocity", VTU_FLOAT64, 3,
     offsetof(struct mps_fo_fields, u)},
    {MPS_FO_NORMAL, "normal", VTU_FLOAT64, 3,
     offsetof(struct mps_fo_fields, normal)},
    {MPS_FO_ND, "numberDensity", VTU_FLOAT64, 1,
     offsetof(struct mps_fo_fields, nd)},
    {MPS_FO_FS, "freeSurface", VTU_UINT8, 1,
     offsetof(struct mps_fo_fields, fs)},
    {MPS_FO_ID, "id", VTU_INT64, 1, offsetof(struct mps_fo_fields, id)},
};

/* Re-issue the current message prefixed with who's location. */
static int located(const struct dict *who, int code)
{
    char msg[1024], where[512];
    snprintf(msg, sizeof msg, "%s", sim_error_message());
    if (!who)
        return sim_error(code, "%s", msg);
    return sim_error(code, "%s: function object '%s': %s",
                     dict_where(who, "type", where, sizeof where),
                     dict_name(who), msg);
}

/* The data of an optional field of that type, or NULL. */
static void *optional(const struct store *st, const char *name,
                      enum vtu_type type, int ncomp)
{
    const struct store_field *sf = store_find(st, name);
    return sf && sf->type == type && sf->ncomp == ncomp ? *sf->ref : NULL;
}

int mps_fo_fields_get(const struct dict *who, const struct fo_scene *s,
                      unsigned mask, struct mps_fo_fields *f)
{
    memset(f, 0, sizeof *f);
    if (s->dim != 2 && s->dim != 3) {
        sim_error(SIM_ERR_INPUT, "the solver gave dim = %d (2 or 3)", s->dim);
        return located(who, SIM_ERR_INPUT);
    }
    if (!(s->spacing > 0)) {
        sim_error(SIM_ERR_INPUT, "the solver gave particle spacing %g",
                  s->spacing);
        return located(who, SIM_ERR_INPUT);
    }
    const char *cloud = s->cloud_name ? s->cloud_name : "cloud";
    const void *v;
    f->n = s->store->n;
    if (store_require(s->store, cloud, "position", VTU_FLOAT64, 3, &v))
        return located(who, SIM_ERR_INPUT);
    f->x = v;
    for (size_t k = 0; k < sizeof specs / sizeof specs[0]; k++) {
        if (!(mask & specs[k].bit))
            continue;
        if (store_require(s->store, cloud, specs[k].name, (int)specs[k].type,
                          specs[k].ncomp, &v) != SIM_OK)
            return located(who, SIM_ERR_INPUT);
        memcpy((char *)f + specs[k].offset, &v, sizeof(void *));
    }
    f->phase = optional(s->store, "phase", VTU_INT32, 1);
    f->soil_frac = optional(s->store, "soilFraction", VTU_FLOAT64, 1);
    f->wall_area = optional(s->store, "wallArea", VTU_FLOAT64, 1);
    f->traction = optional(s->store, "viscousTraction", VTU_FLOAT64, 3);
    return SIM_OK;
}

static const struct model_head phase_all = {
    "all", "every fluid particle, water and soil" };
static const struct model_head phase_water = {
    "water", "the fluid particles of phase 0" };
static const struct model_head phase_soil = {
    "soil", "the soil particles (phase 1, doc/theory.md K)" };
const struct model_head *const mps_fo_phase_table[] = {
    &phase_all, &phase_water, &phase_soil, NULL };

int mps_fo_read_phase(const struct dict *d, const struct fo_scene *s,
                      int *phase)
{
    TRY(model_select_index(d, "phase", "phase",
                           (const void *const *)mps_fo_phase_table, "all",
                           phase));
    if (*phase == MPS_FO_SOIL && !store_find(s->store, "phase"))
        return dict_error(d, "phase", SIM_ERR_DICT, "phase soil: the case "
                          "has no soil particles (no genParticles region "
                          "of type soil)");
    return SIM_OK;
}

int mps_fo_vertical(int dim) { return dim == 2 ? 1 : 2; }

static int read_point(const struct dict_value *v, const char *key, int k,
                      int nmin, int nmax, double *out)
{
    if (nmin == 1 && dict_value_kind(v) == DICT_NUMBER) {
        /* a bare coordinate, e.g. 2-D gauges "(0.5 1.2)" */
        out[0] = dict_value_number(v);
        out[1] = out[2] = 0;
        return SIM_OK;
    }
    int len = dict_value_kind(v) == DICT_LIST ? dict_value_len(v) : -1;
    if (len < nmin || len > nmax) {
        if (nmin == nmax)
            return dict_value_error(v, SIM_ERR_DICT, "%s: point %d must be "
                                    "a list of %d numbers", key, k, nmin);
        return dict_value_error(v, SIM_ERR_DICT, "%s: point %d must be a "
                                "list of %d to %d numbers", key, k, nmin,
                                nmax);
    }
    out[0] = out[1] = out[2] = 0;
    return dict_value_get_vector(v, len, out);
}

int mps_fo_read_points(const struct dict *d, const char *key, int nmin,
                       int nmax, double **pts, int *n)
{
    const struct dict_value *list;
    *pts = NULL;
    *n = 0;
    TRY(dict_get_list(d, key, &list));
    int m = dict_value_len(list);
    if (m < 1)
        return dict_error(d, key, SIM_ERR_DICT, "%s needs at least one point",
                          key);
    double *p = sim_calloc(3 * (size_t)m, sizeof *p);
    if (!p)
        return SIM_ERR_NOMEM;
    for (int k = 0; k < m; k++) {
        int rc = read_point(dict_value_at(list, k), key, k, nmin, nmax,
                            p + 3 * k);
        if (rc != SIM_OK) {
            free(p);
            return rc;
        }
    }
    *pts = p;
    *n = m;
    return SIM_OK;
}

const struct fo_value *mps_fo_value(const struct fo_scene *s,
                                    const char *name)
{
    for (int i = 0; i < s->nvalues; i++)
        if (s->values[i].name && !strcmp(s->values[i].name, name))
            return &s->values[i];
    return NULL;
}
