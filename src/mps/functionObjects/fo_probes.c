/*
 * fo_probes.c — pressure at fixed points: the Shepard average of the
 * pressure of fluid and wall particles within `radius` of each point,
 *
 *     p(x) = sum_j w_j p_j / sum_j w_j,   w_j = 1 - |x_j - x|/radius,
 *
 * (METHODS.md A.9 [P]: "a Shepard average of fluid pressure within r_e";
 * wall particles are included so that a sensor on a wall face reads the
 * wall pressure). A dry point (no particle in reach) reads 0 (gauge
 * pressure of air).
 *
 * Keys: probeLocations ((x y z) ...) [m]; radius [m] (default 2.1 dp).
 * Columns: time, p_0 ... p_{n-1} [Pa].
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "core/dict.h"
#include "core/error.h"
#include "mps/functionObjects/mps_functionObjects.h"

struct probes {
    int n;
    double radius;
    double *pt;
};

static int create(const struct dict *d, const struct fo_scene *s, void **data)
{
    const struct dict_value *list;
    TRY(dict_get_list(d, "probeLocations", &list));
    int n = dict_value_len(list);
    if (n < 1)
        return dict_error(d, "probeLocations", SIM_ERR_DICT,
                          "probeLocations needs at least one point");
    struct probes *p = sim_calloc(1, sizeof *p);
    if (!p)
        return SIM_ERR_NOMEM;
    p->n = n;
    p->pt = sim_calloc(3 * (size_t)n, sizeof *p->pt);
    int rc = p->pt ? SIM_OK : SIM_ERR_NOMEM;
    for (int k = 0; k < n && !rc; k++)
        rc = dict_value_get_vector(dict_value_at(list, k), 3, p->pt + 3 * k);
    if (!rc)
        rc = dict_get_scalar_or(d, "radius", 2.1 * s->spacing, &p->radius);
    if (!rc && !(p->radius > 0))
        rc = dict_error(d, "radius", SIM_ERR_DICT, "radius must be > 0");
    if (!rc && (!mps_fo_field(s, "pressure", VTU_FLOAT64)
                || !mps_fo_field(s, "type", VTU_INT32)))
        rc = sim_error(SIM_ERR_INPUT, "probes: cloud '%s' has no pressure "
                       "or type field", s->cloud_name);
    if (rc) {
        free(p->pt);
        free(p);
        return rc;
    }
    *data = p;
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    struct probes *p = data;
    (void)s;
    fprintf(f, "# probes: Shepard-averaged pressure [Pa] within %g m\n",
            p->radius);
    for (int k = 0; k < p->n; k++)
        fprintf(f, "# probe %d (%g %g %g)\n", k, p->pt[3 * k],
                p->pt[3 * k + 1], p->pt[3 * k + 2]);
    fprintf(f, "# time");
    for (int k = 0; k < p->n; k++)
        fprintf(f, " p_%d", k);
    fprintf(f, "\n");
    return SIM_OK;
}

static int execute(void *data, const struct fo_scene *s, FILE *f)
{
    struct probes *p = data;
    const double *pr = mps_fo_field(s, "pressure", VTU_FLOAT64);
    const int32_t *ty = mps_fo_field(s, "type", VTU_INT32);
    const double *x = s->cloud->points;
    fprintf(f, "%.10g", s->time);
    for (int k = 0; k < p->n; k++) {
        double sw = 0, swp = 0;
        const double *c = p->pt + 3 * k;
        for (size_t i = 0; i < s->cloud->n; i++) {
            if (ty[i] != 0 && ty[i] != 1)
                continue;
            double r = sqrt(pow(x[3*i] - c[0], 2) + pow(x[3*i+1] - c[1], 2)
                            + pow(x[3*i+2] - c[2], 2));
            if (r >= p->radius)
                continue;
            double w = 1 - r / p->radius;
            sw += w;
            swp += w * pr[i];
        }
        fprintf(f, " %.8g", sw > 0 ? swp / sw : 0.0);
    }
    fprintf(f, "\n");
    return SIM_OK;
}

static void destroy(void *data)
{
    struct probes *p = data;
    if (p)
        free(p->pt);
    free(p);
}

const struct fo_ops mps_fo_probes = {
    .name = "probes", .reference = "METHODS.md A.9", .file = "p",
    .create = create, .header = header, .execute = execute,
    .destroy = destroy,
};
