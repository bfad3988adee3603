/*
 * fo_front.c — leading edge of the fluid (doc/theory.md A.12.2 [P], fronts
 * of Figs. 11, 13 and 21 of Xie et al. 2025):
 *
 *     X(t) = max { (x_i - o) . e : i fluid, n_i/n0 >= minNumberDensity,
 *                                  minHeight <= z_i - z_o <= maxHeight }
 *
 * with e = direction/|direction|, o = origin and z the vertical coordinate
 * (y in 2-D). The number-density threshold ignores isolated splash ahead
 * of the front; maxHeight (none by default) keeps only the fluid near the
 * floor, the surge that Martin and Moyce tracked, not a jet thrown forward
 * above it; minHeight (none by default) skips a thin layer of water lying
 * ahead of the surge, so that the bore on a wet bed is what is tracked
 * (the Yeh & Petroff column case: a 0.01 m bed, the bore 0.08 m deep).
 * X is the centre of
 * the leading particle: the edge of the volume it represents lies dp/2
 * further (a column of width a filled with particles reads X = a - dp/2).
 *
 * Dimensionless forms of Martin and Moyce (1952), for a column of width a
 * (referenceLength) released at t = 0:
 *
 *     Z = X/a,       T = t sqrt(2 g/a)   (g: the key `gravity`)
 *
 * Z is written when referenceLength is given, T when gravity is given as
 * well. The column height H(tau) of Martin and Moyce is a waveGauges
 * entry at the wall (divide by a yourself).
 *
 * No fluid particle above the threshold: nan, with one warning.
 *
 * Keys:
 *   direction        (1 0 0);   // e, normalised here
 *   origin           (0 0 0);   // o [m]
 *   minNumberDensity 0.5;       // n/n0 threshold
 *   maxHeight        0.02;      // [m] above o, optional (default: none)
 *   minHeight        0.03;      // [m] above o, optional (default: none)
 *   phase            all;       // all | water | soil (cases with soil)
 *   referenceLength  0.057;     // a [m], optional: adds the column Z
 *   gravity          9.81;      // |g| [m/s^2], optional (with
 *                               // referenceLength): adds the column T
 * Columns: time, X [m], then Z, T when asked for.
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

#define FIELDS (MPS_FO_TYPE | MPS_FO_ND)

struct front {
    char *name;
    double e[3], o[3];
    double nd_min;
    double zmin, zmax; /* minHeight, maxHeight, or -/+INFINITY */
    double a, g;    /* 0 when not given */
    int warned;
    int phase;      /* enum mps_fo_phase */
};

static void destroy(void *data)
{
    struct front *fr = data;
    if (fr)
        free(fr->name);
    free(fr);
}

static int read_direction(const struct dict *d, const struct fo_scene *s,
                          struct front *fr)
{
    static const double ex[3] = {1, 0, 0}, zero[3] = {0, 0, 0};
    TRY(dict_get_vector_or(d, "direction", 3, ex, fr->e));
    TRY(dict_get_vector_or(d, "origin", 3, zero, fr->o));
    if (s->dim == 2 && fr->e[2] != 0)
        return dict_error(d, "direction", SIM_ERR_DICT, "a 2-D case lies "
                          "in the x-y plane: the z component of direction "
                          "must be 0, got %g", fr->e[2]);
    double len = sqrt(fr->e[0] * fr->e[0] + fr->e[1] * fr->e[1]
                      + fr->e[2] * fr->e[2]);
    if (!(len > 0) || !isfinite(len))
        return dict_error(d, "direction", SIM_ERR_DICT, "direction must be "
                          "a non-zero vector");
    for (int k = 0; k < 3; k++)
        fr->e[k] /= len;
    return SIM_OK;
}

static int read_scales(const struct dict *d, struct front *fr)
{
    TRY(dict_get_scalar_or(d, "minNumberDensity", 0.5, &fr->nd_min));
    if (!(fr->nd_min >= 0) || !isfinite(fr->nd_min))
        return dict_error(d, "minNumberDensity", SIM_ERR_DICT,
                          "minNumberDensity (n/n0) must be >= 0, got %g",
                          fr->nd_min);
    TRY(dict_get_scalar_or(d, "maxHeight", INFINITY, &fr->zmax));
    if (!(fr->zmax > 0))
        return dict_error(d, "maxHeight", SIM_ERR_DICT, "maxHeight (above "
                          "the origin) must be positive, got %g", fr->zmax);
    TRY(dict_get_scalar_or(d, "minHeight", -INFINITY, &fr->zmin));
    if (!(fr->zmin < fr->zmax) || isnan(fr->zmin))
        return dict_error(d, "minHeight", SIM_ERR_DICT, "minHeight (above "
                          "the origin) must be below maxHeight (%g), got %g",
                          fr->zmax, fr->zmin);
    if (dict_has(d, "referenceLength")) {
        TRY(dict_get_scalar(d, "referenceLength", &fr->a));
        if (!(fr->a > 0) || !isfinite(fr->a))
            return dict_error(d, "referenceLength", SIM_ERR_DICT,
                              "referenceLength must be positive, got %g",
                              fr->a);
    }
    if (!dict_has(d, "gravity"))
        return SIM_OK;
    TRY(dict_get_scalar(d, "gravity", &fr->g));
    if (!(fr->g > 0) || !isfinite(fr->g))
        return dict_error(d, "gravity", SIM_ERR_DICT, "gravity is the "
                          "magnitude |g| > 0 [m/s^2], got %g", fr->g);
    if (fr->a == 0)
        return dict_error(d, "gravity", SIM_ERR_DICT, "gravity is used for "
                          "T = t sqrt(2 g/a): give referenceLength a too");
    return SIM_OK;
}

static int create(const struct dict *d, const struct fo_scene *s, void **data)
{
    struct mps_fo_fields f;
    struct front *fr = sim_calloc(1, sizeof *fr);
    if (!fr)
        return SIM_ERR_NOMEM;
    int rc = mps_fo_fields_get(d, s, FIELDS, &f);
    if (rc == SIM_OK)
        rc = read_direction(d, s, fr);
    if (rc == SIM_OK)
        rc = read_scales(d, fr);
    if (rc == SIM_OK)
        rc = mps_fo_read_phase(d, s, &fr->phase);
    if (rc == SIM_OK) {
        fr->name = sim_strdup(dict_name(d));
        rc = fr->name ? SIM_OK : SIM_ERR_NOMEM;
    }
    if (rc != SIM_OK) {
        destroy(fr);
        return rc;
    }
    *data = fr;
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    struct front *fr = data;
    (void)s;
    fprintf(f, "# front: max over fluid particles with n/n0 >= %g of "
            "(x - (%.9g %.9g %.9g)) . (%.9g %.9g %.9g) [m]\n", fr->nd_min,
            fr->o[0], fr->o[1], fr->o[2], fr->e[0], fr->e[1], fr->e[2]);
    if (fr->phase != MPS_FO_ALL_PHASES)
        fprintf(f, "# only the %s particles\n",
                mps_fo_phase_table[fr->phase]->name);
    if (isfinite(fr->zmax))
        fprintf(f, "# only particles at most %.9g m above the origin\n",
                fr->zmax);
    if (isfinite(fr->zmin))
        fprintf(f, "# only particles at least %.9g m above the origin\n",
                fr->zmin);
    if (fr->a > 0)
        fprintf(f, "# Z = X/a with a = %.9g m\n", fr->a);
    if (fr->g > 0)
        fprintf(f, "# T = t sqrt(2 g/a) with g = %.9g m/s^2\n", fr->g);
    fprintf(f, "# time X%s%s\n", fr->a > 0 ? " Z" : "",
            fr->g > 0 ? " T" : "");
    return SIM_OK;
}

static double leading_edge(const struct mps_fo_fields *f, int dim,
                           const struct front *fr)
{
    int z = mps_fo_vertical(dim);
    double m = -DBL_MAX;
    long n = (long)f->n;
#pragma omp parallel for reduction(max : m) schedule(static)
    for (long i = 0; i < n; i++) {
        if (!mps_fo_in_phase(f, i, fr->phase) || !(f->nd[i] >= fr->nd_min))
            continue;
        const double *x = f->x + 3 * i;
        if (x[z] - fr->o[z] > fr->zmax || x[z] - fr->o[z] < fr->zmin)
            continue;
        double v = (x[0] - fr->o[0]) * fr->e[0] + (x[1] - fr->o[1]) * fr->e[1]
                   + (x[2] - fr->o[2]) * fr->e[2];
        m = v > m ? v : m;
    }
    return m > -DBL_MAX ? m : NAN;
}

static int execute(void *data, const struct fo_scene *s, FILE *out)
{
    struct front *fr = data;
    struct mps_fo_fields f;
    TRY(mps_fo_fields_get(NULL, s, FIELDS, &f));
    double X = leading_edge(&f, s->dim, fr);
    if (isnan(X) && !fr->warned) {
        fr->warned = 1;
        log_warn("%s: no fluid particle with n/n0 >= %g at time %g; the "
                 "front writes nan (warned once)", fr->name, fr->nd_min,
                 s->time);
    }
    fprintf(out, "%.15g %.15g", s->time, X);
    if (fr->a > 0)
        fprintf(out, " %.15g", X / fr->a);
    if (fr->g > 0)
        fprintf(out, " %.15g", s->time * sqrt(2 * fr->g / fr->a));
    fprintf(out, "\n");
    return SIM_OK;
}

const struct fo_ops fo_mps_front = {
    .name = "front",
    .reference = "doc/theory.md A.12.2; Martin and Moyce 1952",
    .file = "front",
    .create = create,
    .header = header,
    .execute = execute,
    .destroy = destroy,
};
