/*
 * randomPack.c — `lattice random;` in a grains region: non-overlapping
 * spheres at a target solid fraction by random sequential addition (RSA;
 * Widom 1966, "Random sequential addition of hard spheres to a volume",
 * J. Chem. Phys. 44, 3888). The diameters are drawn first, until their
 * volume reaches solidFraction times the region's volume (to within half a
 * grain); the grains are then placed one at a time, largest first (the
 * small ones fill the gaps the large ones leave), each at uniformly random
 * positions until one lies wholly inside the region and overlaps no grain
 * already placed. Placed grains never move.
 *
 * RSA cannot pass its saturation fraction, about 0.383 for equal spheres
 * in 3-D (Torquato, Uche & Stillinger 2006, Phys. Rev. E 74, 061308) and
 * 0.547 for equal disks in 2-D (Hinrichsen, Feder & Jossang 1986, J. Stat.
 * Phys. 44, 793), and the attempts it needs grow without bound on the way
 * there: solidFraction is limited to 0.35 in 3-D and 0.50 in 2-D (where
 * the fraction is that of the area, pi r^2 per grain), and each grain gets
 * maxAttempts tries. A grain cannot stick out of the region, so a region
 * only a few diameters wide stops lower; the message says how far it got.
 *
 * The packing is loose and no two grains touch: a realistic bed needs a
 * settling run of demSolid after it (gravity, a few tenths of a second).
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "genParticles.h"
#include "rng.h"

/* Largest solid fraction accepted, by dimension (see the header). */
static double fraction_limit(int dim)
{
    return dim == 2 ? 0.50 : 0.35;
}

int gen_random_read(const struct gen_case *c, struct region *r)
{
    const struct dict *d = r->d;
    int fixed = dict_has(d, "diameter");
    double lo[3], hi[3], lim = fraction_limit(c->dim);

    if (fixed && dict_has(d, "diameterDistribution"))
        return dict_error(d, "diameterDistribution", SIM_ERR_DICT, "region "
                          "'%s': give diameter (all grains alike) or "
                          "diameterDistribution, not both", r->name);
    if (!fixed && !dict_has(d, "diameterDistribution"))
        return dict_error(d, "lattice", SIM_ERR_DICT, "region '%s': lattice "
                          "random needs diameter (all grains alike) or "
                          "diameterDistribution (uniform (min max) or "
                          "normal (mean standardDeviation) (min max))",
                          r->name);
    TRY(size_dist_read(d, "diameterDistribution", r->diameter, &r->dist));
    r->diameter = r->dist.max;
    TRY(dict_get_scalar(d, "solidFraction", &r->solid_fraction));
    if (!(r->solid_fraction > 0 && r->solid_fraction <= lim))
        return dict_error(d, "solidFraction", SIM_ERR_DICT, "region '%s': "
                          "solidFraction %g is not in (0, %g]: random "
                          "sequential addition stalls towards its "
                          "saturation, %s; for a denser bed, pack at %g or "
                          "less and let demSolid settle it under gravity",
                          r->name, r->solid_fraction, lim, c->dim == 2
                          ? "0.547 for disks in 2-D" : "0.383 in 3-D", lim);
    TRY(dict_get_label_or(d, "seed", 1, &r->seed));
    TRY(dict_get_label_or(d, "maxAttempts", 100000, &r->max_attempts));
    if (r->max_attempts < 1)
        return dict_error(d, "maxAttempts", SIM_ERR_DICT, "maxAttempts must "
                          "be at least 1, not %ld", r->max_attempts);
    if (!geom_bbox(&r->g, lo, hi))
        return dict_error(d, "shape", SIM_ERR_DICT, "grains need a bounded "
                          "shape (box, cylinder or sphere)");
    return SIM_OK;
}

double gen_region_volume(const struct region *r)
{
    const struct geom *g = &r->g;
    switch (g->shape) {
    case GEOM_BOX: {
        double v = 1;
        for (int d = 0; d < g->dim; d++)
            v *= g->hi[d] - g->lo[d];
        return v;
    }
    case GEOM_SPHERE:
        return g->dim == 2 ? M_PI * g->radius * g->radius
                           : 4.0 / 3.0 * M_PI * pow(g->radius, 3);
    case GEOM_CYLINDER: /* in 2-D its axis lies in the plane: a rectangle */
        return g->dim == 2 ? 2 * g->radius * g->length
                           : M_PI * g->radius * g->radius * g->length;
    case GEOM_HALFSPACE:
        break;
    }
    return HUGE_VAL;
}

/* Fraction of the region's volume where the centre of a grain of radius
 * rad may lie (the region shrunk by rad). */
static double centre_room(const struct region *r, double rad)
{
    const struct geom *g = &r->g;
    double f = 1;
    switch (g->shape) {
    case GEOM_BOX:
        for (int d = 0; d < g->dim; d++)
            f *= fmax(0, 1 - 2 * rad / (g->hi[d] - g->lo[d]));
        return f;
    case GEOM_SPHERE:
        return pow(fmax(0, 1 - rad / g->radius), g->dim);
    case GEOM_CYLINDER:
        f = fmax(0, 1 - 2 * rad / g->length);
        return f * pow(fmax(0, 1 - rad / g->radius), g->dim == 2 ? 1 : 2);
    case GEOM_HALFSPACE:
        break;
    }
    return 1;
}

/* Volume (3-D) or area (2-D) of a grain of diameter d. */
static double grain_measure(int dim, double d)
{
    return dim == 2 ? M_PI * d * d / 4 : M_PI * d * d * d / 6;
}

static int descending(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x < y) - (x > y);
}

/* The grains placed so far, binned in cells of side h >= 2 R_max so that
 * a grain can touch only grains of the 3^dim cells around its own. */
struct pack_grid {
    int dim, nc[3];
    double lo[3], h;
    int32_t *head, *next;
};

static int64_t cell_of(const struct pack_grid *p, const double x[3],
                       int ic[3])
{
    for (int d = 0; d < 3; d++) {
        int k = d < p->dim ? (int)floor((x[d] - p->lo[d]) / p->h) : 0;
        ic[d] = k < 0 ? 0 : k >= p->nc[d] ? p->nc[d] - 1 : k;
    }
    return ic[0] + (int64_t)p->nc[0] * (ic[1] + (int64_t)p->nc[1] * ic[2]);
}

static int overlaps(const struct pack_grid *p, const double *x,
                    const double *rad, const double xi[3], double ri)
{
    int ic[3];
    cell_of(p, xi, ic);
    for (int z = ic[2] - 1; z <= ic[2] + 1; z++)
        for (int y = ic[1] - 1; y <= ic[1] + 1; y++)
            for (int w = ic[0] - 1; w <= ic[0] + 1; w++) {
                if (w < 0 || y < 0 || z < 0 || w >= p->nc[0] ||
                    y >= p->nc[1] || z >= p->nc[2])
                    continue;
                int64_t c = w + (int64_t)p->nc[0] *
                                    (y + (int64_t)p->nc[1] * z);
                for (int32_t j = p->head[c]; j >= 0; j = p->next[j]) {
                    const double *xj = x + 3 * j;
                    double dx = xi[0] - xj[0], dy = xi[1] - xj[1],
                           dz = xi[2] - xj[2], s = ri + rad[j];
                    if (dx * dx + dy * dy + dz * dz < s * s)
                        return 1;
                }
            }
    return 0;
}

/* The diameters, sorted largest first, whose volume is the target. */
static int draw_diameters(const struct gen_case *c, const struct region *r,
                          struct gen_rng *g, double **out, size_t *n,
                          double *solid)
{
    double target = r->solid_fraction * gen_region_volume(r), sum = 0;
    double *d = NULL;
    size_t cap = 0;

    *n = 0;
    for (;;) {
        double di = size_dist_draw(&r->dist, g);
        double v = grain_measure(c->dim, di);
        if (sum + 0.5 * v > target)
            break;
        if (*n == cap) {
            cap = cap ? 2 * cap : 1024;
            double *nd = cap < 2147483647u
                             ? sim_realloc(d, cap * sizeof *nd) : NULL;
            if (!nd) {
                free(d);
                return cap < 2147483647u ? SIM_ERR_NOMEM
                                         : dict_error(r->d, "solidFraction",
                                                      SIM_ERR_DICT, "region "
                                                      "'%s': over 2^31 "
                                                      "grains", r->name);
            }
            d = nd;
        }
        d[(*n)++] = di;
        sum += v;
    }
    if (*n == 0) {
        free(d);
        return dict_error(r->d, "solidFraction", SIM_ERR_DICT, "region '%s' "
                          "(volume %g m^%d) holds less than half a grain at "
                          "solidFraction %g", r->name,
                          gen_region_volume(r), c->dim, r->solid_fraction);
    }
    qsort(d, *n, sizeof *d, descending);
    *out = d;
    *solid = sum;
    return SIM_OK;
}

int gen_random_pack(const struct gen_case *c, const struct region *r,
                    double **xout, double **rout, size_t *nout)
{
    struct gen_rng g;
    struct pack_grid p = { c->dim, { 1, 1, 1 }, { 0, 0, 0 }, 0, NULL, NULL };
    double *diam = NULL, *x = NULL, *rad = NULL, hi[3], solid;
    double ncell = 1, tries = 0;
    size_t n;
    int rc = SIM_OK;

    gen_rng_seed(&g, (uint64_t)r->seed);
    TRY(draw_diameters(c, r, &g, &diam, &n, &solid));
    geom_bbox(&r->g, p.lo, hi);
    p.h = diam[0]; /* the largest: 2 R_max */
    for (int d = 0; d < c->dim; d++) {
        p.nc[d] = (int)fmin(ceil((hi[d] - p.lo[d]) / p.h), 2147483647.0);
        p.nc[d] = p.nc[d] > 0 ? p.nc[d] : 1;
        ncell *= p.nc[d];
    }
    if (ncell > 2147483647.0) {
        free(diam);
        return dict_error(r->d, "shape", SIM_ERR_DICT, "region '%s': %.3g "
                          "cells of one grain diameter: region too large "
                          "for its grains", r->name, ncell);
    }
    p.head = sim_malloc((size_t)ncell * sizeof *p.head);
    p.next = sim_malloc(n * sizeof *p.next);
    x = sim_calloc(3 * n, sizeof *x);
    rad = sim_malloc(n * sizeof *rad);
    if (!p.head || !p.next || !x || !rad) {
        rc = SIM_ERR_NOMEM;
        goto fail;
    }
    memset(p.head, 0xff, (size_t)ncell * sizeof *p.head); /* all -1 */
    for (size_t i = 0; i < n; i++) {
        double ri = 0.5 * diam[i], xi[3] = { 0, 0, 0 }, span[3] = { 0, 0, 0 };
        long a;
        for (int d = 0; d < c->dim; d++) {
            span[d] = hi[d] - p.lo[d] - 2 * ri;
            if (span[d] < 0) {
                rc = dict_error(r->d, "shape", SIM_ERR_DICT, "region '%s': a "
                                "grain of diameter %g does not fit in it",
                                r->name, diam[i]);
                goto fail;
            }
        }
        for (a = 0; a < r->max_attempts; a++) {
            for (int d = 0; d < c->dim; d++)
                xi[d] = p.lo[d] + ri + span[d] * gen_rng_uniform(&g);
            if (geom_distance(&r->g, xi) <= -ri &&
                !overlaps(&p, x, rad, xi, ri))
                break;
        }
        tries += (double)(a < r->max_attempts ? a + 1 : a);
        if (a == r->max_attempts) {
            double got = 0, v = gen_region_volume(r);
            for (size_t k = 0; k < i; k++)
                got += grain_measure(c->dim, 2 * rad[k]);
            double sat = c->dim == 2 ? 0.547 : 0.383;
            rc = dict_error(r->d, "solidFraction", SIM_ERR_DICT, "region "
                            "'%s': random sequential addition placed %zu of "
                            "%zu grains (solid fraction %.4g of the %g asked) "
                            "and found no free place for the next (diameter "
                            "%g) in maxAttempts %ld tries. It saturates near "
                            "%.3g x %.3g = %.3g here (the centres of grains "
                            "of this size have %.3g of the region's volume, "
                            "as no grain sticks out of it): lower "
                            "solidFraction, widen the region or raise "
                            "maxAttempts", r->name, i, n, got / v,
                            r->solid_fraction, diam[i], r->max_attempts, sat,
                            centre_room(r, ri), sat * centre_room(r, ri),
                            centre_room(r, ri));
            goto fail;
        }
        int ic[3];
        int64_t cell = cell_of(&p, xi, ic);
        memcpy(x + 3 * i, xi, sizeof xi);
        rad[i] = ri;
        p.next[i] = p.head[cell];
        p.head[cell] = (int32_t)i;
    }
    log_info("Region %s: random sequential addition of %zu grains, solid "
             "fraction %.4g (asked %g), %.3g tries per grain", r->name, n,
             solid / gen_region_volume(r), r->solid_fraction, tries / n);
    *xout = x;
    *rout = rad;
    *nout = n;
    free(diam);
    free(p.head);
    free(p.next);
    return SIM_OK;
fail:
    free(diam);
    free(p.head);
    free(p.next);
    free(x);
    free(rad);
    return rc;
}
