/* cells.c — see cells.h. Counting sort of particles into uniform cells;
 * the runs of cells a neighbour search visits. */
#include "particles/cells.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"

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
        if (!(s >= 0) || s >= g->lim[k])
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
        /* round-off overshoot of a point on the box's upper face */
        g->lim[k] = g->nc[k] + 1e-9 * g->nc[k] + 1e-12;
    }
    if (ncell > 2147483647.0)
        return sim_error(SIM_ERR_INPUT, "cell grid needs %.3g cells "
                         "(box too large for cell size %g m)", ncell, h);
    g->ncell = (int64_t)ncell;
    return SIM_OK;
}

/* Counting sort of the n points into the grid whose geometry is set. */
static int bin(struct cell_grid *g, const double *x, int n)
{
    TRY(sim_reserve((void **)&g->start, &g->cap_cells, (size_t)g->ncell + 2,
                    sizeof *g->start));
    TRY(sim_reserve((void **)&g->order, &g->cap_n, (size_t)n + 1,
                    sizeof *g->order));
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
    return bin(g, x, n);
}

int cells_build_grid(struct cell_grid *g, int dim, const double *x, int n,
                     double h, const double lo[3], const int nc[3],
                     double over)
{
    if (!(h > 0) || (dim != 2 && dim != 3) || n < 0 || !(over >= 0))
        return sim_error(SIM_ERR_INPUT, "cells_build_grid: bad cell size "
                         "%g, dimension %d, count %d or overshoot %g", h,
                         dim, n, over);
    double ncell = 1;
    g->dim = dim;
    g->h = h;
    for (int k = 0; k < 3; k++) {
        g->lo[k] = k < dim ? lo[k] : 0;
        g->nc[k] = k < dim ? nc[k] : 1;
        if (g->nc[k] < 1)
            return sim_error(SIM_ERR_INPUT, "cells_build_grid: %d cells "
                             "along axis %d", g->nc[k], k);
        g->lim[k] = g->nc[k] + over;
        ncell *= g->nc[k];
    }
    if (ncell > 2147483647.0)
        return sim_error(SIM_ERR_INPUT, "cell grid needs %.3g cells", ncell);
    g->ncell = (int64_t)ncell;
    return bin(g, x, n);
}

void cells_free(struct cell_grid *g)
{
    free(g->start);
    free(g->order);
    free(g->cell_of);
    memset(g, 0, sizeof *g);
}

/* Relative widening of the cell ranges, far above the round-off of the
 * cell coordinates, so that no pair within the cut-off is missed. */
#define RANGE_EPS 1e-9

/* Cells [*c0, *c1] along axis k that can hold a point within d of p. */
static void axis_range(const struct cell_grid *g, int k, double p, double d,
                       int *c0, int *c1)
{
    double s0 = floor((p - d - g->lo[k]) / g->h);
    double s1 = floor((p + d - g->lo[k]) / g->h);
    *c0 = s0 < 0 ? 0 : s0 >= g->nc[k] ? g->nc[k] : (int)s0;
    *c1 = s1 >= g->nc[k] - 1 ? g->nc[k] - 1 : s1 < 0 ? -1 : (int)s1;
}

/* Distance from p to the slab of cell c along axis k; the last cell is
 * open above (cells_locate clamps overshoot into it). */
static double slab_gap(const struct cell_grid *g, int k, double p, int c)
{
    double a = g->lo[k] + c * g->h, b = a + g->h;
    if (p < a)
        return a - p;
    return p > b && c < g->nc[k] - 1 ? p - b : 0.0;
}

int cells_runs(const struct cell_grid *g, const double *p, double rc,
               struct cell_run *rn, int64_t *len)
{
    const double d = rc * (1 + RANGE_EPS);
    int y0, y1, z0 = 0, z1 = 0, m = 0;
    axis_range(g, 1, p[1], d, &y0, &y1);
    if (g->dim == 3)
        axis_range(g, 2, p[2], d, &z0, &z1);
    *len = 0;
    for (int kz = z0; kz <= z1; kz++) {
        double gz = g->dim == 3 ? slab_gap(g, 2, p[2], kz) : 0.0;
        for (int ky = y0; ky <= y1; ky++) {
            double gy = slab_gap(g, 1, p[1], ky);
            double rem = d * d - gy * gy - gz * gz;
            if (rem < 0 || m == CELLS_MAX_RUNS)
                continue;
            int x0, x1;
            axis_range(g, 0, p[0], sqrt(rem), &x0, &x1);
            if (x0 > x1)
                continue;
            /* The x-neighbours of one row are contiguous in cell order. */
            int64_t base = (int64_t)g->nc[0] * (ky + (int64_t)g->nc[1] * kz);
            rn[m].a = g->start[base + x0];
            rn[m].b = g->start[base + x1 + 1];
            *len += rn[m].b - rn[m].a;
            m++;
        }
    }
    return m;
}

int cells_runs_box(const struct cell_grid *g, const int ic[3], int reach,
                   struct cell_run *rn, int64_t *len)
{
    int lo[3] = { 0, 0, 0 }, hi[3] = { 0, 0, 0 }, m = 0;
    for (int k = 0; k < g->dim; k++) {
        lo[k] = ic[k] > reach ? ic[k] - reach : 0;
        hi[k] = ic[k] + reach < g->nc[k] ? ic[k] + reach : g->nc[k] - 1;
    }
    *len = 0;
    for (int kz = lo[2]; kz <= hi[2]; kz++)
        for (int ky = lo[1]; ky <= hi[1]; ky++) {
            int64_t base = (int64_t)g->nc[0] * (ky + (int64_t)g->nc[1] * kz);
            rn[m].a = g->start[base + lo[0]];
            rn[m].b = g->start[base + hi[0] + 1];
            *len += rn[m].b - rn[m].a;
            m++;
        }
    return m;
}

void cells_gather(const struct cell_grid *g, const double *x, double *xs)
{
    const int64_t nb = g->start[g->ncell];
#pragma omp parallel for schedule(static)
    for (int64_t e = 0; e < nb; e++)
        for (int k = 0; k < 3; k++)
            xs[3 * e + k] = x[3 * (size_t)g->order[e] + k];
}
