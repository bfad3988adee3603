/*
 * fo_forces.c — pressure force on named wall patches, F = sum_i p_i
 * dp^(d-1) n_i over the patch's wall particles (METHODS.md A.9 [P]; per
 * unit depth [N/m] in 2-D), published by the solver as the scene value
 * "wallForce.<patch>".
 *
 * Keys: patches (name ...) — names from constant/particlePatches.
 * Columns: time, then Fx Fy Fz per patch, then the sum over the patches.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"
#include "mps/functionObjects/mps_functionObjects.h"

struct forces {
    int n;
    char (*name)[64];
};

static const struct fo_value *find(const struct fo_scene *s, const char *p)
{
    char key[96];
    snprintf(key, sizeof key, "wallForce.%s", p);
    for (int k = 0; k < s->nvalues; k++)
        if (strcmp(s->values[k].name, key) == 0)
            return &s->values[k];
    return NULL;
}

static int create(const struct dict *d, const struct fo_scene *s, void **data)
{
    const struct dict_value *list;
    TRY(dict_get_list(d, "patches", &list));
    struct forces *fc = sim_calloc(1, sizeof *fc);
    if (!fc)
        return SIM_ERR_NOMEM;
    fc->n = dict_value_len(list);
    fc->name = sim_calloc((size_t)fc->n + 1, sizeof *fc->name);
    int rc = fc->name ? SIM_OK : SIM_ERR_NOMEM;
    if (!rc && fc->n < 1)
        rc = dict_error(d, "patches", SIM_ERR_DICT, "patches is empty");
    for (int k = 0; k < fc->n && !rc; k++) {
        const char *w;
        rc = dict_value_get_word(dict_value_at(list, k), &w);
        if (rc)
            break;
        snprintf(fc->name[k], sizeof fc->name[k], "%s", w);
        if (!find(s, w)) {
            char valid[512] = "";
            for (int p = 0; p < s->npatches; p++) {
                strncat(valid, " ", sizeof valid - strlen(valid) - 1);
                strncat(valid, s->patch_names[p],
                        sizeof valid - strlen(valid) - 1);
            }
            rc = dict_value_error(dict_value_at(list, k), SIM_ERR_DICT,
                                  "unknown patch '%s'; patches:%s", w, valid);
        }
    }
    if (rc) {
        free(fc->name);
        free(fc);
        return rc;
    }
    *data = fc;
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    struct forces *fc = data;
    fprintf(f, "# pressure force on wall patches [%s]\n# time",
            s->dim == 2 ? "N/m" : "N");
    for (int k = 0; k < fc->n; k++)
        fprintf(f, " %s_x %s_y %s_z", fc->name[k], fc->name[k], fc->name[k]);
    fprintf(f, " total_x total_y total_z\n");
    return SIM_OK;
}

static int execute(void *data, const struct fo_scene *s, FILE *f)
{
    struct forces *fc = data;
    double tot[3] = { 0, 0, 0 };
    fprintf(f, "%.10g", s->time);
    for (int k = 0; k < fc->n; k++) {
        const struct fo_value *v = find(s, fc->name[k]);
        for (int q = 0; q < 3; q++) {
            double c = v ? v->v[q] : 0.0;
            tot[q] += c;
            fprintf(f, " %.8g", c);
        }
    }
    fprintf(f, " %.8g %.8g %.8g\n", tot[0], tot[1], tot[2]);
    return SIM_OK;
}

static void destroy(void *data)
{
    struct forces *fc = data;
    if (fc)
        free(fc->name);
    free(fc);
}

const struct fo_ops mps_fo_forces = {
    .name = "forces", .reference = "METHODS.md A.9", .file = "forces",
    .create = create, .header = header, .execute = execute,
    .destroy = destroy,
};
