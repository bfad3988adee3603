/*
 * fo_probes.c — pressure at fixed points (doc/theory.md A.9 [P], probe P1 of
 * A.12.3 / A0-18).
 *
 * interpolation shepard (default): Shepard average of the pressure of the
 * fluid and wall particles j within R = radius*dp of the point x,
 *
 *     p(x) = sum_j w(|x_j - x|) p_j / sum_j w(|x_j - x|),
 *     w(r) = R/(0.85 r + 0.15 R) - 1   (r < R),   0 otherwise,
 *
 * with the Zhang kernel of doc/theory.md A.3 eq. (6) (Zhang, Wan and Hino
 * 2014), the kernel the solver itself uses: finite at r = 0, so a probe on
 * a particle is not a singular case, and zero at r = R, so the value does
 * not jump when a particle crosses the edge of the reach. Wall particles
 * take part so that a sensor on a wall face reads the wall pressure;
 * dummies do not (their pressure is a copy of a wall particle's). The
 * average is exact for a constant field, and for a linear one when the
 * particles in reach are placed symmetrically about x; otherwise its
 * error is at most |grad p| R.
 *
 * interpolation nearestWall: the pressure of the wall particle nearest to
 * x within R, the reading of the paper's pressure sensor P1 (A.9). Equal
 * distances are resolved by the smaller particle `id`, so the choice does
 * not depend on the solver's particle order.
 *
 * field U: the velocity, Shepard average over the fluid particles only
 * (walls move with their patch and would drag the average towards it
 * beside a wall; the velocity probe of the Yeh & Petroff column case sits
 * 2.6 cm above the floor). nearestWall is a pressure sensor and is refused
 * with U.
 *
 * A probe with no particle in reach (a dry point, a point outside the
 * tank) writes nan and warns once.
 *
 * Keys:
 *   probeLocations ((x y z) ...);   // [m]; 2-D: (x y) or (x y 0)
 *   field          p;               // p | U
 *   interpolation  shepard;         // shepard | nearestWall (p only)
 *   radius         2.1;             // reach R in units of dp
 * Columns: time, then p of each probe [Pa], or Ux Uy Uz of each [m/s].
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "functionObjects/mps_functionObjects.h"

enum { SHEPARD, NEAREST_WALL };
static const char *const interp_words[] = {"shepard", "nearestWall", NULL};
enum { FIELD_P, FIELD_U };
static const char *const field_words[] = {"p", "U", NULL};

struct probes {
    char *name;
    int n, interp, field;
    double radius;  /* [m] */
    double *pt;     /* 3n  */
    char *warned;   /* n   */
};

static void destroy(void *data)
{
    struct probes *p = data;
    if (!p)
        return;
    free(p->name);
    free(p->pt);
    free(p->warned);
    free(p);
}

static int read_keys(const struct dict *d, const struct fo_scene *s,
                     struct probes *p)
{
    double r;
    TRY(mps_fo_read_points(d, "probeLocations", s->dim == 2 ? 2 : 3, 3,
                           &p->pt, &p->n));
    for (int k = 0; k < p->n && s->dim == 2; k++)
        if (p->pt[3 * k + 2] != 0)
            return dict_error(d, "probeLocations", SIM_ERR_DICT, "probe %d: "
                              "a 2-D case lies in the plane z = 0; got z = "
                              "%g", k, p->pt[3 * k + 2]);
    TRY(dict_get_word_or(d, "field", field_words, FIELD_P, &p->field));
    TRY(dict_get_word_or(d, "interpolation", interp_words, SHEPARD,
                         &p->interp));
    if (p->field == FIELD_U && p->interp == NEAREST_WALL)
        return dict_error(d, "interpolation", SIM_ERR_DICT, "interpolation "
                          "nearestWall is a wall pressure sensor; field U "
                          "takes shepard");
    TRY(dict_get_scalar_or(d, "radius", 2.1, &r));
    if (!(r > 0) || !isfinite(r))
        return dict_error(d, "radius", SIM_ERR_DICT, "radius (in units of "
                          "dp) must be positive, got %g", r);
    p->radius = r * s->spacing;
    return SIM_OK;
}

static unsigned fields_of(const struct probes *p)
{
    return MPS_FO_TYPE | MPS_FO_ID
         | (p->field == FIELD_U ? MPS_FO_VELOCITY : MPS_FO_PRESSURE);
}

static int create(const struct dict *d, const struct fo_scene *s, void **data)
{
    struct mps_fo_fields f;
    struct probes *p = sim_calloc(1, sizeof *p);
    if (!p)
        return SIM_ERR_NOMEM;
    int rc = read_keys(d, s, p);
    if (rc == SIM_OK)
        rc = mps_fo_fields_get(d, s, fields_of(p), &f);
    if (rc == SIM_OK) {
        p->name = sim_strdup(dict_name(d));
        p->warned = sim_calloc((size_t)p->n, 1);
        rc = p->name && p->warned ? SIM_OK : SIM_ERR_NOMEM;
    }
    if (rc != SIM_OK) {
        destroy(p);
        return rc;
    }
    *data = p;
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    struct probes *p = data;
    (void)s;
    fprintf(f, "# probes: %s, %s within %g m\n",
            p->field == FIELD_U ? "velocity [m/s]" : "pressure [Pa]",
            interp_words[p->interp], p->radius);
    for (int k = 0; k < p->n; k++)
        fprintf(f, "# probe %d (%.9g %.9g %.9g)\n", k, p->pt[3 * k],
                p->pt[3 * k + 1], p->pt[3 * k + 2]);
    fprintf(f, "# time");
    for (int k = 0; k < p->n; k++)
        if (p->field == FIELD_U)
            fprintf(f, " Ux%d Uy%d Uz%d", k, k, k);
        else
            fprintf(f, " p%d", k);
    fprintf(f, "\n");
    return SIM_OK;
}

static double dist2(const double *a, const double *b)
{
    double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return dx * dx + dy * dy + dz * dz;
}

/* Shepard average at c of the pressure (fluid and wall particles) or,
 * with f->u set, of the velocity (fluid only) into v[0] (v[0..2]). */
static void shepard(const struct mps_fo_fields *f, const double *c,
                    double R, double *v)
{
    const int vel = f->u != NULL;
    double sw = 0, s0 = 0, s1 = 0, s2 = 0;
    long n = (long)f->n;
#pragma omp parallel for reduction(+ : sw, s0, s1, s2) schedule(static)
    for (long i = 0; i < n; i++) {
        if (f->type[i] != 0 && (vel || f->type[i] != 1))
            continue;
        double r2 = dist2(f->x + 3 * i, c);
        if (r2 >= R * R)
            continue;
        double w = R / (0.85 * sqrt(r2) + 0.15 * R) - 1;
        sw += w;
        if (vel) {
            s0 += w * f->u[3 * i];
            s1 += w * f->u[3 * i + 1];
            s2 += w * f->u[3 * i + 2];
        } else {
            s0 += w * f->p[i];
        }
    }
    v[0] = sw > 0 ? s0 / sw : NAN;
    v[1] = sw > 0 ? s1 / sw : NAN;
    v[2] = sw > 0 ? s2 / sw : NAN;
}

/* Is (r2, id) a better candidate than (b_r2, b_id)? */
static int closer(double r2, int64_t id, double b_r2, int64_t b_id)
{
    return r2 < b_r2 || (r2 == b_r2 && id < b_id);
}

static double nearest_wall(const struct mps_fo_fields *f, const double *c,
                           double R)
{
    double best_r2 = R * R;
    int64_t best_id = INT64_MAX;
    double best_p = NAN;
    long n = (long)f->n;
#pragma omp parallel
    {
        double r2_t = R * R, p_t = NAN;
        int64_t id_t = INT64_MAX;
#pragma omp for schedule(static)
        for (long i = 0; i < n; i++) {
            if (f->type[i] != 1)
                continue;
            double r2 = dist2(f->x + 3 * i, c);
            if (r2 < R * R && closer(r2, f->id[i], r2_t, id_t)) {
                r2_t = r2;
                id_t = f->id[i];
                p_t = f->p[i];
            }
        }
#pragma omp critical(fo_probes_nearest)
        if (id_t != INT64_MAX && closer(r2_t, id_t, best_r2, best_id)) {
            best_r2 = r2_t;
            best_id = id_t;
            best_p = p_t;
        }
    }
    return best_p;
}

static int execute(void *data, const struct fo_scene *s, FILE *out)
{
    struct probes *p = data;
    struct mps_fo_fields f;
    TRY(mps_fo_fields_get(NULL, s, fields_of(p), &f));
    fprintf(out, "%.15g", s->time);
    for (int k = 0; k < p->n; k++) {
        const double *c = p->pt + 3 * k;
        double v[3];
        if (p->interp == SHEPARD)
            shepard(&f, c, p->radius, v);
        else
            v[0] = nearest_wall(&f, c, p->radius);
        if (isnan(v[0]) && !p->warned[k]) {
            p->warned[k] = 1;
            log_warn("%s: probe %d (%g %g %g) has no %s particle within %g m "
                     "at time %g; it writes nan while dry (warned once)",
                     p->name, k, c[0], c[1], c[2],
                     p->field == FIELD_U ? "fluid"
                     : p->interp == SHEPARD ? "fluid or wall" : "wall",
                     p->radius, s->time);
        }
        for (int q = 0; q < (p->field == FIELD_U ? 3 : 1); q++)
            fprintf(out, " %.15g", v[q]);
    }
    fprintf(out, "\n");
    return SIM_OK;
}

const struct fo_ops fo_mps_probes = {
    .name = "probes",
    .reference = "doc/theory.md A.9 (Zhang, Wan and Hino 2014 kernel)",
    .file = "probes",
    .create = create,
    .header = header,
    .execute = execute,
    .destroy = destroy,
};
