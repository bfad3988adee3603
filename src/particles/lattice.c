/*
 * lattice.c — cubic and hexagonal site lattices, region filling and
 * jitter (lattice.h).
 *
 * Hexagonal close packing, nearest-neighbour distance s: rows of a layer
 * are s sqrt(3)/2 apart and odd rows shifted by s/2; layers are
 * s sqrt(2/3) apart and odd (B) layers shifted by (s/2, s/(2 sqrt 3)),
 * which puts a B site at distance s from three A sites below it.
 */
#include "particles/lattice.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"

const char *const lattice_kind_names[] = { "cubic", "hexagonal", NULL };

/* Distances between rows (j) and layers (k). */
static void steps(const struct lattice *l, double h[3])
{
    double s = l->spacing;
    h[0] = s;
    h[1] = l->kind == LATTICE_HEXAGONAL ? s * sqrt(3.0) / 2.0 : s;
    h[2] = l->kind == LATTICE_HEXAGONAL ? s * sqrt(2.0 / 3.0) : s;
}

void lattice_site(const struct lattice *l, long i, long j, long k,
                  double x[3])
{
    double h[3], s = l->spacing;
    steps(l, h);
    x[0] = l->origin[0] + h[0] * (double)i;
    x[1] = l->origin[1] + h[1] * (double)j;
    x[2] = l->dim == 3 ? l->origin[2] + h[2] * (double)k : 0.0;
    if (l->kind == LATTICE_HEXAGONAL) {
        x[0] += 0.5 * s * (double)(j & 1);
        if (l->dim == 3 && (k & 1)) {
            x[0] += 0.5 * s;
            x[1] += s / (2.0 * sqrt(3.0));
        }
    }
}

int lattice_range(const struct lattice *l, const double lo[3],
                  const double hi[3], long first[3], long count[3],
                  double *nsites)
{
    double h[3];

    if ((l->dim != 2 && l->dim != 3) || !(l->spacing > 0) ||
        !isfinite(l->spacing))
        return sim_error(SIM_ERR_INPUT, "bad lattice (dimension %d, spacing "
                         "%g)", l->dim, l->spacing);
    steps(l, h);
    *nsites = 1.0;
    for (int d = 0; d < 3; d++) {
        double a, b;
        if (d >= l->dim) {
            first[d] = 0;
            count[d] = 1;
            continue;
        }
        if (!isfinite(lo[d]) || !isfinite(hi[d]) || hi[d] < lo[d])
            return sim_error(SIM_ERR_INPUT, "cannot fill an unbounded or "
                             "empty box in %c", "xyz"[d]);
        /* One extra index each side covers the hexagonal shifts (< h). */
        a = floor((lo[d] - l->origin[d]) / h[d]) - 1.0;
        b = ceil((hi[d] - l->origin[d]) / h[d]) + 1.0;
        *nsites *= b - a + 1.0;
        if (*nsites > 1099511627776.0 || fabs(a) > 1e15 || fabs(b) > 1e15)
            return sim_error(SIM_ERR_INPUT, "the box [%g, %g] in %c holds "
                             "too many sites at spacing %g", lo[d], hi[d],
                             "xyz"[d], l->spacing);
        first[d] = (long)a;
        count[d] = (long)(b - a) + 1;
    }
    return SIM_OK;
}

/* Is site x in the box and kept? */
static int keep(const struct lattice *l, const double lo[3],
                const double hi[3], const double x[3],
                lattice_accept_fn accept, void *ctx)
{
    double tol = 1e-9 * l->spacing;
    for (int d = 0; d < l->dim; d++)
        if (x[d] < lo[d] - tol || x[d] > hi[d] + tol)
            return 0;
    return accept ? accept(x, ctx) : 1;
}

/* Visit the sites of slab s (the outermost index, k in 3-D, j in 2-D);
 * count them, and store them when out is not NULL. */
static size_t slab(const struct lattice *l, const long first[3],
                   const long count[3], long s, const double lo[3],
                   const double hi[3], lattice_accept_fn accept, void *ctx,
                   double *out)
{
    size_t n = 0;
    long nj = l->dim == 3 ? count[1] : 1;
    for (long jj = 0; jj < nj; jj++) {
        long j = l->dim == 3 ? first[1] + jj : first[1] + s;
        long k = l->dim == 3 ? first[2] + s : 0;
        for (long i = first[0]; i < first[0] + count[0]; i++) {
            double x[3];
            lattice_site(l, i, j, k, x);
            if (!keep(l, lo, hi, x, accept, ctx))
                continue;
            if (out)
                memcpy(out + 3 * n, x, sizeof x);
            n++;
        }
    }
    return n;
}

int lattice_fill(const struct lattice *l, const double lo[3],
                 const double hi[3], lattice_accept_fn accept, void *ctx,
                 double **x, size_t *n)
{
    long first[3], count[3], ns;
    double nsites;
    size_t *off;

    *x = NULL;
    *n = 0;
    TRY(lattice_range(l, lo, hi, first, count, &nsites));
    ns = l->dim == 3 ? count[2] : count[1];
    off = sim_calloc((size_t)ns + 1, sizeof *off);
    if (!off)
        return SIM_ERR_NOMEM;
    /* Two passes (count, then store at prefix offsets) keep the order
     * fixed whatever the number of threads. */
#pragma omp parallel for schedule(dynamic, 1)
    for (long s = 0; s < ns; s++)
        off[s + 1] = slab(l, first, count, s, lo, hi, accept, ctx, NULL);
    for (long s = 0; s < ns; s++)
        off[s + 1] += off[s];
    *x = sim_malloc(3 * off[ns] * sizeof **x);
    if (!*x) {
        free(off);
        return SIM_ERR_NOMEM;
    }
#pragma omp parallel for schedule(dynamic, 1)
    for (long s = 0; s < ns; s++)
        slab(l, first, count, s, lo, hi, accept, ctx, *x + 3 * off[s]);
    *n = off[ns];
    free(off);
    return SIM_OK;
}

/* SplitMix64 (Steele, Lea and Flood 2014): a counter-based generator, so
 * that point i gets the same numbers on any thread. */
static uint64_t splitmix64(uint64_t z)
{
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

void lattice_jitter(double *x, size_t n, int dim, double amplitude,
                    uint64_t seed)
{
    uint64_t base = splitmix64(seed);
#pragma omp parallel for
    for (size_t i = 0; i < n; i++) {
        for (int d = 0; d < dim; d++) {
            uint64_t r = splitmix64(base ^ splitmix64(3 * (uint64_t)i +
                                                      (uint64_t)d));
            double u = (double)(r >> 11) * 0x1.0p-53; /* [0, 1) */
            x[3 * i + d] += amplitude * (2.0 * u - 1.0);
        }
    }
}

int lattice_read_patches(const struct dict *patches, int *dim, double *dp)
{
    long d;
    TRY(dict_get_label(patches, "dimension", &d));
    if (d != 2 && d != 3)
        return dict_error(patches, "dimension", SIM_ERR_DICT,
                          "dimension must be 2 or 3");
    TRY(dict_get_scalar(patches, "dp", dp));
    if (!(*dp > 0))
        return dict_error(patches, "dp", SIM_ERR_DICT, "dp must be > 0");
    *dim = (int)d;
    return SIM_OK;
}
