/*
 * fo_waveGauges.c — free-surface elevation at fixed horizontal positions
 * (doc/theory.md A.12.3 [P], wave gauge H1 of A0-18; also the column height
 * H(tau) of Martin and Moyce 1952 with a gauge at the wall).
 *
 * For a gauge at horizontal position (x_g, y_g) (2-D: x_g only), the
 * column C = { |x - x_g| <= b, |y - y_g| <= b } with b = halfWidth*dp, and
 * z the vertical coordinate (y in 2-D):
 *
 *     eta = max { z_i : i fluid in C, n_i/n0 >= minNumberDensity } + dp/2
 *
 * The number-density threshold ignores isolated splash (spray above the
 * surface has few neighbours); dp/2 turns the centre of the top particle
 * into the surface of the layer it represents, so that a still lattice of
 * N layers above a floor reads exactly its depth N dp.
 *
 * A dry column reads the elevation of its floor: the highest wall
 * particle in C whose normal points downwards (n_z < -0.5: a floor or the
 * top of an obstacle, not a side wall that the column may graze) + dp/2,
 * i.e. a water depth of zero. A column with neither fluid nor floor (a
 * gauge outside the tank) writes nan and warns once.
 *
 * The result is an elevation (the vertical coordinate of the surface);
 * the depth is eta minus the floor's elevation, which is eta itself when
 * the case puts the floor's surface at z = 0.
 *
 * Keys:
 *   gaugeLocations   ((x y) ...);   // [m]; 2-D: (x) or (x 0), or (x0 x1 ...)
 *   halfWidth        1;             // b in units of dp
 *   minNumberDensity 0.5;           // n/n0 threshold for fluid particles
 *   phase            all;           // all | water | soil (cases with soil:
 *                                   // soil reads the top of the bed)
 * Columns: time, eta of each gauge [m].
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/select.h"
#include "core/log.h"
#include "functionObjects/mps_functionObjects.h"

#define FIELDS (MPS_FO_TYPE | MPS_FO_ND | MPS_FO_NORMAL)

struct gauges {
    char *name;
    int n;
    double half;    /* b [m]                   */
    double nd_min;
    double *pt;     /* 3n: horizontal x, y, 0  */
    char *warned;
    int phase;      /* enum mps_fo_phase       */
};

static void destroy(void *data)
{
    struct gauges *g = data;
    if (!g)
        return;
    free(g->name);
    free(g->pt);
    free(g->warned);
    free(g);
}

/* In 2-D a second number is the unused horizontal coordinate: it must be
 * 0, or the user meant a 3-D point. */
static int check_2d(const struct dict *d, struct gauges *g)
{
    for (int k = 0; k < g->n; k++)
        if (g->pt[3 * k + 1] != 0)
            return dict_error(d, "gaugeLocations", SIM_ERR_DICT,
                              "gauge %d: a 2-D gauge is (x) or (x 0); got "
                              "(%g %g)", k, g->pt[3 * k], g->pt[3 * k + 1]);
    return SIM_OK;
}

static int read_keys(const struct dict *d, const struct fo_scene *s,
                     struct gauges *g)
{
    double b;
    TRY(mps_fo_read_points(d, "gaugeLocations", s->dim == 2 ? 1 : 2, 2,
                           &g->pt, &g->n));
    if (s->dim == 2)
        TRY(check_2d(d, g));
    TRY(dict_get_scalar_or(d, "halfWidth", 1.0, &b));
    if (!(b > 0) || !isfinite(b))
        return dict_error(d, "halfWidth", SIM_ERR_DICT, "halfWidth (in "
                          "units of dp) must be positive, got %g", b);
    g->half = b * s->spacing;
    TRY(dict_get_scalar_or(d, "minNumberDensity", 0.5, &g->nd_min));
    if (!(g->nd_min >= 0) || !isfinite(g->nd_min))
        return dict_error(d, "minNumberDensity", SIM_ERR_DICT,
                          "minNumberDensity (n/n0) must be >= 0, got %g",
                          g->nd_min);
    return SIM_OK;
}

static int create(const struct dict *d, const struct fo_scene *s, void **data)
{
    struct mps_fo_fields f;
    struct gauges *g = sim_calloc(1, sizeof *g);
    if (!g)
        return SIM_ERR_NOMEM;
    int rc = mps_fo_fields_get(d, s, FIELDS, &f);
    if (rc == SIM_OK)
        rc = read_keys(d, s, g);
    if (rc == SIM_OK)
        rc = mps_fo_read_phase(d, s, &g->phase);
    if (rc == SIM_OK) {
        g->name = sim_strdup(dict_name(d));
        g->warned = sim_calloc((size_t)g->n, 1);
        rc = g->name && g->warned ? SIM_OK : SIM_ERR_NOMEM;
    }
    if (rc != SIM_OK) {
        destroy(g);
        return rc;
    }
    *data = g;
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    struct gauges *g = data;
    fprintf(f, "# waveGauges: free-surface elevation [m] (top fluid particle "
            "with n/n0 >= %g + dp/2) in columns of half-width %g m\n",
            g->nd_min, g->half);
    if (g->phase != MPS_FO_ALL_PHASES)
        fprintf(f, "# only the %s particles\n",
                mps_fo_phase_table[g->phase]->name);
    for (int k = 0; k < g->n; k++) {
        if (s->dim == 2)
            fprintf(f, "# gauge %d x = %.9g\n", k, g->pt[3 * k]);
        else
            fprintf(f, "# gauge %d (x y) = (%.9g %.9g)\n", k, g->pt[3 * k],
                    g->pt[3 * k + 1]);
    }
    fprintf(f, "# time");
    for (int k = 0; k < g->n; k++)
        fprintf(f, " eta%d", k);
    fprintf(f, "\n");
    return SIM_OK;
}

/* Highest fluid particle (*top) and highest floor particle (*floor) in the
 * column of gauge c; -DBL_MAX when there is none. */
static void scan_column(const struct mps_fo_fields *f, int dim,
                        const struct gauges *g, const double *c, double *top,
                        double *floor_)
{
    int v = mps_fo_vertical(dim);
    double t = -DBL_MAX, fl = -DBL_MAX;
    long n = (long)f->n;
#pragma omp parallel for reduction(max : t, fl) schedule(static)
    for (long i = 0; i < n; i++) {
        const double *x = f->x + 3 * i;
        if (fabs(x[0] - c[0]) > g->half
            || (dim == 3 && fabs(x[1] - c[1]) > g->half))
            continue;
        if (mps_fo_in_phase(f, i, g->phase) && f->nd[i] >= g->nd_min)
            t = x[v] > t ? x[v] : t;
        else if (f->type[i] == 1 && f->normal[3 * i + v] < -0.5)
            fl = x[v] > fl ? x[v] : fl;
    }
    *top = t;
    *floor_ = fl;
}

static int execute(void *data, const struct fo_scene *s, FILE *out)
{
    struct gauges *g = data;
    struct mps_fo_fields f;
    TRY(mps_fo_fields_get(NULL, s, FIELDS, &f));
    fprintf(out, "%.15g", s->time);
    for (int k = 0; k < g->n; k++) {
        double top, floor_, eta = NAN;
        scan_column(&f, s->dim, g, g->pt + 3 * k, &top, &floor_);
        if (top > -DBL_MAX)
            eta = top + 0.5 * s->spacing;
        else if (floor_ > -DBL_MAX)
            eta = floor_ + 0.5 * s->spacing;
        else if (!g->warned[k]) {
            g->warned[k] = 1;
            log_warn("%s: gauge %d has neither fluid nor a floor in its "
                     "column at time %g; it writes nan (warned once)",
                     g->name, k, s->time);
        }
        fprintf(out, " %.15g", eta);
    }
    fprintf(out, "\n");
    return SIM_OK;
}

const struct fo_ops fo_mps_wave_gauges = {
    .name = "waveGauges",
    .reference = "doc/theory.md A.12.3",
    .file = "waveGauges",
    .create = create,
    .header = header,
    .execute = execute,
    .destroy = destroy,
};
