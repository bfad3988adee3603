/* cells.c — see cells.h. Counting sort of particles into uniform cells. */
#include "particles/cells.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"

static int grow(void **p, size_t *cap, size_t want, size_t size)
{
    if (want <= *cap)
        return SIM_OK;
    size_t c = want + want / 4 + 16;
    void *q = sim_realloc(*p, c * size);
    if (!q)
        return SIM_ERR_NOMEM;
    *p = q;
    *cap = c;
    return SIM_OK;
}

static void bounding_box(int dim, const double *x, int n, double *lo,
                         double *hi)
{
    for (int k = 0; k < 3; k++) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    for (int i = 0; i < n; i++) {
        const double *p = x + 3 * i;
        if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]))
            continue;
        for (int k = 0; k < dim; k++) {
            lo[k] = fmin(lo[k], p[k]);
            hi[k] = fmax(hi[k], p[k]);
        }
    }
    for (int k = 0; k < 3; k++)
        if (k >= dim || lo[k] > hi[k])
            lo[k] = hi[k] = 0;
}

int cells_locate(const struct cell_grid *g, const double *p, int ic[3])
{
    ic[0] = ic[1] = ic[2] = 0;
    for (int k = 0; k < g->dim; k++) {
        double s = (p[k] - g->lo[k]) / g->h;
        if (!(s >= 0) || s >= g->nc[k] + 1e-9 * g->nc[k] + 1e-12)
            return 0;           /* also catches NaN */
        int c = (int)s;
        ic[k] = c < g->nc[k] ? c : g->nc[k] - 1;
    }
    return 1;
}

static int set_geometry(struct cell_grid *g, int dim, double h,
                        const double *lo, const double *hi)
{
    double ncell = 1;
    g->dim = dim;
    g->h = h;
    for (int k = 0; k < 3; k++) {
        g->lo[k] = k < dim ? lo[k] : 0;
        g->nc[k] = 1;
        if (k < dim) {
            double len = hi[k] - lo[k];
            if (!(len >= 0))
                return sim_error(SIM_ERR_INPUT, "cell box has hi < lo");
            double m = floor(len / h) + 1;
            if (m > 1e9)
                return sim_error(SIM_ERR_INPUT, "cell grid too large");
            g->nc[k] = (int)m;
            ncell *= m;
        }
    }
    if (ncell > 2147483647.0)
        return sim_error(SIM_ERR_INPUT, "cell grid needs %.3g cells "
                         "(box too large for cell size %g m)", ncell, h);
    g->ncell = (int64_t)ncell;
    return SIM_OK;
}

int cells_build(struct cell_grid *g, int dim, const double *x, int n, double h,
                const double *lo, const double *hi)
{
    double blo[3], bhi[3];
    if (!(h > 0) || (dim != 2 && dim != 3) || n < 0)
        return sim_error(SIM_ERR_INPUT, "cells_build: bad cell size %g, "
                         "dimension %d or count %d", h, dim, n);
    if (!lo || !hi) {
        bounding_box(dim, x, n, blo, bhi);
        lo = blo;
        hi = bhi;
    }
    TRY(set_geometry(g, dim, h, lo, hi));
    TRY(grow((void **)&g->start, &g->cap_cells, (size_t)g->ncell + 2,
             sizeof *g->start));
    TRY(grow((void **)&g->order, &g->cap_n, (size_t)n + 1, sizeof *g->order));
    size_t capn = g->cap_n;   /* both per-particle arrays share one capacity */
    void *c = sim_realloc(g->cell_of, capn * sizeof *g->cell_of);
    if (!c)
        return SIM_ERR_NOMEM;
    g->cell_of = c;
    g->n = n;

    const int64_t nx = g->nc[0], ny = g->nc[1];
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; i++) {
        int ic[3];
        g->cell_of[i] = cells_locate(g, x + 3 * i, ic)
                      ? ic[0] + nx * (ic[1] + ny * (int64_t)ic[2]) : g->ncell;
    }
    /* Counting sort; serial scatter keeps the order stable, which makes
     * renumbering deterministic and idempotent. */
    memset(g->start, 0, ((size_t)g->ncell + 2) * sizeof *g->start);
    for (int i = 0; i < n; i++)
        g->start[g->cell_of[i] + 1]++;
    for (int64_t k = 0; k <= g->ncell; k++)
        g->start[k + 1] += g->start[k];
    g->n_outside = (int)(g->start[g->ncell + 1] - g->start[g->ncell]);
    int64_t *fill = g->start; /* reuse: shift back afterwards */
    for (int i = 0; i < n; i++)
        g->order[fill[g->cell_of[i]]++] = i;
    for (int64_t k = g->ncell + 1; k > 0; k--)
        g->start[k] = g->start[k - 1];
    g->start[0] = 0;
    return SIM_OK;
}

void cells_free(struct cell_grid *g)
{
    free(g->start);
    free(g->order);
    free(g->cell_of);
    memset(g, 0, sizeof *g);
}

void cells_permute(void *a, size_t size, const int32_t *perm, int n,
                   void *scratch)
{
    char *dst = scratch;
    const char *src = a;
    if (size == 8) {
        const double *s = a;
        double *d = scratch;
#pragma omp parallel for schedule(static)
        for (int i = 0; i < n; i++)
            d[i] = s[perm[i]];
    } else {
#pragma omp parallel for schedule(static)
        for (int i = 0; i < n; i++)
            memcpy(dst + (size_t)i * size, src + (size_t)perm[i] * size, size);
    }
    memcpy(a, scratch, (size_t)n * size);
}
