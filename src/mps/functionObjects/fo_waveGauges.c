/*
 * fo_waveGauges.c — free-surface elevation at fixed horizontal positions
 * (METHODS.md A.12.3 [P]): the vertical coordinate of the highest fluid
 * particle with number density n/n0 >= minDensity inside a vertical column
 * of half-width `halfWidth` around the gauge, plus dp/2 (a particle stands
 * for a cell of side dp, so the water surface is half a spacing above the
 * top particle centre). A dry gauge reads the floor value `floor`.
 *
 * Keys: gauges ((x y) ...) in 3-D, (x ...) in 2-D [m]; halfWidth [m]
 * (default dp); minDensity [-] (default 0.5: isolated droplets do not
 * count); floor [m] (default 0).
 * Columns: time, h_0 ... h_{n-1} [m].
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "core/dict.h"
#include "core/error.h"
#include "mps/functionObjects/mps_functionObjects.h"

struct gauges {
    int n, nc;
    double *pt, half, min_nd, floor_;
};

static int create(const struct dict *d, const struct fo_scene *s, void **data)
{
    const struct dict_value *list;
    TRY(dict_get_list(d, "gauges", &list));
    struct gauges *g = sim_calloc(1, sizeof *g);
    if (!g)
        return SIM_ERR_NOMEM;
    g->n = dict_value_len(list);
    g->nc = s->dim - 1;
    g->pt = sim_calloc(2 * (size_t)g->n + 1, sizeof *g->pt);
    int rc = g->pt ? SIM_OK : SIM_ERR_NOMEM;
    if (!rc && g->n < 1)
        rc = dict_error(d, "gauges", SIM_ERR_DICT, "gauges needs at least "
                        "one position");
    for (int k = 0; k < g->n && !rc; k++) {
        const struct dict_value *v = dict_value_at(list, k);
        if (g->nc == 1 && dict_value_kind(v) == DICT_NUMBER)
            rc = dict_value_get_scalar(v, g->pt + 2 * k);
        else
            rc = dict_value_get_vector(v, g->nc, g->pt + 2 * k);
    }
    if (!rc)
        rc = dict_get_scalar_or(d, "halfWidth", s->spacing, &g->half);
    if (!rc)
        rc = dict_get_scalar_or(d, "minDensity", 0.5, &g->min_nd);
    if (!rc)
        rc = dict_get_scalar_or(d, "floor", 0.0, &g->floor_);
    if (!rc && !mps_fo_field(s, "numberDensity", VTU_FLOAT64))
        rc = sim_error(SIM_ERR_INPUT, "waveGauges: no numberDensity field");
    if (rc) {
        free(g->pt);
        free(g);
        return rc;
    }
    *data = g;
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    struct gauges *g = data;
    (void)s;
    fprintf(f, "# waveGauges: surface elevation [m] (top particle + dp/2)\n");
    for (int k = 0; k < g->n; k++)
        fprintf(f, "# gauge %d at (%g%s%g)\n", k, g->pt[2 * k],
                g->nc == 2 ? " " : "", g->nc == 2 ? g->pt[2 * k + 1] : 0.0);
    fprintf(f, "# time");
    for (int k = 0; k < g->n; k++)
        fprintf(f, " h_%d", k);
    fprintf(f, "\n");
    return SIM_OK;
}

static int execute(void *data, const struct fo_scene *s, FILE *f)
{
    struct gauges *g = data;
    const double *nd = mps_fo_field(s, "numberDensity", VTU_FLOAT64);
    const int32_t *ty = mps_fo_field(s, "type", VTU_INT32);
    const double *x = s->cloud->points;
    int v = mps_fo_vertical(s);
    fprintf(f, "%.10g", s->time);
    for (int k = 0; k < g->n; k++) {
        double top = -INFINITY;
        for (size_t i = 0; i < s->cloud->n; i++) {
            if ((ty && ty[i] != 0) || nd[i] < g->min_nd)
                continue;
            int in = 1;
            for (int c = 0; c < g->nc; c++)
                in &= fabs(x[3 * i + c] - g->pt[2 * k + c]) <= g->half;
            if (in)
                top = fmax(top, x[3 * i + v]);
        }
        fprintf(f, " %.8g", isfinite(top) ? top + 0.5 * s->spacing : g->floor_);
    }
    fprintf(f, "\n");
    return SIM_OK;
}

static void destroy(void *data)
{
    struct gauges *g = data;
    if (g)
        free(g->pt);
    free(g);
}

const struct fo_ops mps_fo_wave_gauges = {
    .name = "waveGauges", .reference = "METHODS.md A.12.3", .file = "height",
    .create = create, .header = header, .execute = execute,
    .destroy = destroy,
};
