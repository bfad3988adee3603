/*
 * fo_front.c — leading edge of the fluid: the largest (x_i - origin).dir
 * over fluid particles with number density n/n0 >= minDensity (isolated
 * splash has a low number density and is ignored) and, optionally, height
 * above the origin below maxHeight (Martin & Moyce track the surge on the
 * floor). The front is reported at the particle centre + dp/2 (edge of its
 * cell). Also written: the highest such particle within `columnWidth` of
 * the origin along dir (+ dp/2), the residual column height of the dam
 * break (Martin & Moyce's H).
 *
 * Keys: origin (x y z) [m] (default 0); direction (dx dy dz) (default
 * (1 0 0), normalised); minDensity [-] (default 0.5); maxHeight [m]
 * (default none); columnWidth [m] (default dp).
 * Columns: time, front [m], column height [m].
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "core/dict.h"
#include "core/error.h"
#include "mps/functionObjects/mps_functionObjects.h"

struct front {
    double o[3], dir[3], min_nd, max_h, col_w;
};

static int create(const struct dict *d, const struct fo_scene *s, void **data)
{
    struct front *fr = sim_calloc(1, sizeof *fr);
    if (!fr)
        return SIM_ERR_NOMEM;
    static const double zero[3] = { 0, 0, 0 }, ex[3] = { 1, 0, 0 };
    int rc = dict_get_vector_or(d, "origin", 3, zero, fr->o);
    if (!rc)
        rc = dict_get_vector_or(d, "direction", 3, ex, fr->dir);
    double l = sqrt(fr->dir[0] * fr->dir[0] + fr->dir[1] * fr->dir[1]
                    + fr->dir[2] * fr->dir[2]);
    if (!rc && !(l > 0))
        rc = dict_error(d, "direction", SIM_ERR_DICT, "direction is zero");
    for (int q = 0; q < 3 && !rc; q++)
        fr->dir[q] /= l;
    if (!rc)
        rc = dict_get_scalar_or(d, "minDensity", 0.5, &fr->min_nd);
    if (!rc)
        rc = dict_get_scalar_or(d, "maxHeight", INFINITY, &fr->max_h);
    if (!rc)
        rc = dict_get_scalar_or(d, "columnWidth", s->spacing, &fr->col_w);
    if (!rc && !mps_fo_field(s, "numberDensity", VTU_FLOAT64))
        rc = sim_error(SIM_ERR_INPUT, "front: no numberDensity field");
    if (rc) {
        free(fr);
        return rc;
    }
    *data = fr;
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    struct front *fr = data;
    (void)s;
    fprintf(f, "# front along (%g %g %g) from (%g %g %g) [m]; column: "
            "height of the fluid at the origin [m]\n# time front column\n",
            fr->dir[0], fr->dir[1], fr->dir[2], fr->o[0], fr->o[1], fr->o[2]);
    return SIM_OK;
}

static int execute(void *data, const struct fo_scene *s, FILE *f)
{
    struct front *fr = data;
    const double *nd = mps_fo_field(s, "numberDensity", VTU_FLOAT64);
    const int32_t *ty = mps_fo_field(s, "type", VTU_INT32);
    const double *x = s->cloud->points;
    int v = mps_fo_vertical(s);
    double best = -INFINITY, col = -INFINITY;
    for (size_t i = 0; i < s->cloud->n; i++) {
        if ((ty && ty[i] != 0) || nd[i] < fr->min_nd)
            continue;
        double a = 0;
        for (int q = 0; q < 3; q++)
            a += (x[3 * i + q] - fr->o[q]) * fr->dir[q];
        double h = x[3 * i + v] - fr->o[v];
        if (h <= fr->max_h)
            best = fmax(best, a);
        if (fabs(a) <= fr->col_w)
            col = fmax(col, h);
    }
    fprintf(f, "%.10g %.8g %.8g\n", s->time,
            isfinite(best) ? best + 0.5 * s->spacing : 0.0,
            isfinite(col) ? col + 0.5 * s->spacing : 0.0);
    return SIM_OK;
}

static void destroy(void *data)
{
    free(data);
}

const struct fo_ops mps_fo_front = {
    .name = "front", .reference = "Martin & Moyce 1952", .file = "front",
    .create = create, .header = header, .execute = execute,
    .destroy = destroy,
};
