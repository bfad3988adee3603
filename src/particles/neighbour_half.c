/*
 * neighbour_half.c — half self lists through the cell grid
 * (neighbour_half.h).
 *
 * The grid covers the bounding box of the points with cells of side at
 * least 2 R_max + skin, so that every partner of a point lies in the 27
 * cells around it (cells_runs_box: cheaper than trimming rows of cells
 * this large, which saves few candidates); the cell count
 * is capped near the point count so that a few points far apart cannot
 * blow up memory (the cells just get larger). Rows are sorted, so neither
 * the grid nor the traversal order shows in the list.
 */
#include "particles/neighbour_half.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"

/* Displacement checks over fewer points than this run on one thread. */
#define HALF_OMP_MIN 2000

void neighbour_half_init(struct neighbour_half *nl, double skin)
{
    memset(nl, 0, sizeof *nl);
    nl->skin = skin;
}

void neighbour_half_free(struct neighbour_half *nl)
{
    free(nl->start);
    free(nl->j);
    free(nl->x0);
    cells_free(&nl->grid);
    double skin = nl->skin;
    neighbour_half_init(nl, skin);
}

static int reserve_points(struct neighbour_half *nl, size_t n)
{
    if (n <= nl->ncap && nl->start)
        return SIM_OK;
    size_t cap = n + n / 2 + 16;
    size_t *s = sim_realloc(nl->start, (cap + 1) * sizeof *s);
    if (!s)
        return SIM_ERR_NOMEM;
    nl->start = s;
    double *x0 = sim_realloc(nl->x0, 3 * cap * sizeof *x0);
    if (!x0)
        return SIM_ERR_NOMEM;
    nl->x0 = x0;
    nl->ncap = cap;
    return SIM_OK;
}

static int push_pair(struct neighbour_half *nl, uint32_t j)
{
    if (nl->npairs == nl->cap) {
        size_t cap = nl->cap ? 2 * nl->cap : 1024;
        uint32_t *p = sim_realloc(nl->j, cap * sizeof *p);
        if (!p)
            return SIM_ERR_NOMEM;
        nl->j = p;
        nl->cap = cap;
    }
    nl->j[nl->npairs++] = j;
    return SIM_OK;
}

static void sort_row(uint32_t *a, size_t m)
{
    for (size_t k = 1; k < m; k++) {
        uint32_t v = a[k];
        size_t q = k;
        while (q > 0 && a[q - 1] > v) {
            a[q] = a[q - 1];
            q--;
        }
        a[q] = v;
    }
}

/* Within the cut-off of the pair (i, j): the one test of both builds. */
static int within(const struct neighbour_half *nl, size_t i, size_t j,
                  const double *x, const double *r)
{
    double d2 = 0;
    for (int a = 0; a < 3; a++) {
        double d = x[3 * j + a] - x[3 * i + a];
        d2 += d * d;
    }
    double cut = r[i] + r[j] + nl->skin;
    return d2 < cut * cut;
}

/* Bounding box of the points and the cell side: at least hmin, larger
 * while the box would need more than 4 n + 64 cells. */
static int grid_box(size_t n, const double *x, double hmin, double lo[3],
                    double hi[3], double *h)
{
    for (int a = 0; a < 3; a++)
        lo[a] = INFINITY, hi[a] = -INFINITY;
    for (size_t i = 0; i < n; i++)
        for (int a = 0; a < 3; a++) {
            /* tested one by one: fmin and fmax would pass over a NaN */
            if (!isfinite(x[3 * i + a]))
                return sim_error(SIM_ERR_NUMERIC, "neighbour_half_build: "
                                 "point %zu has a non-finite position", i);
            lo[a] = fmin(lo[a], x[3 * i + a]);
            hi[a] = fmax(hi[a], x[3 * i + a]);
        }
    *h = hmin;
    for (;;) {
        double cells = 1;
        for (int a = 0; a < 3; a++)
            cells *= floor((hi[a] - lo[a]) / *h) + 1;
        if (cells <= 4.0 * (double)n + 64)
            break;
        *h *= 1.26;
    }
    return SIM_OK;
}

static int start_build(struct neighbour_half *nl, size_t n)
{
    TRY(reserve_points(nl, n));
    if (n > INT32_MAX)
        return sim_error(SIM_ERR_INPUT, "neighbour_half_build: %zu points",
                         n);
    nl->n = n;
    nl->npairs = 0;
    nl->start[0] = 0;
    nl->nbuilds++;
    return SIM_OK;
}

int neighbour_half_build(struct neighbour_half *nl, size_t n, const double *x,
                         const double *r)
{
    TRY(start_build(nl, n));
    if (n == 0)
        return SIM_OK;
    double rmax = 0, lo[3], hi[3], h = 0;
    for (size_t i = 0; i < n; i++)
        rmax = fmax(rmax, r[i]);
    TRY(grid_box(n, x, fmax(2 * rmax + nl->skin, 1e-12), lo, hi, &h));
    struct cell_grid *g = &nl->grid;
    TRY(cells_build(g, 3, x, (int)n, h, lo, hi));
    struct cell_run rn[CELLS_MAX_RUNS];
    for (size_t i = 0; i < n; i++) {
        int64_t len;
        int ic[3];
        cells_coords(g, (int)i, ic);
        int nrun = cells_runs_box(g, ic, 1, rn, &len);
        for (int q = 0; q < nrun; q++)
            for (int64_t s = rn[q].a; s < rn[q].b; s++) {
                size_t j = (size_t)g->order[s];
                if (j > i && within(nl, i, j, x, r))
                    TRY(push_pair(nl, (uint32_t)j));
            }
        nl->start[i + 1] = nl->npairs;
        sort_row(&nl->j[nl->start[i]], nl->start[i + 1] - nl->start[i]);
    }
    memcpy(nl->x0, x, 3 * n * sizeof *x);
    return SIM_OK;
}

int neighbour_half_build_brute(struct neighbour_half *nl, size_t n,
                               const double *x, const double *r)
{
    TRY(start_build(nl, n));
    for (size_t i = 0; i < n; i++) {
        for (size_t j = i + 1; j < n; j++)
            if (within(nl, i, j, x, r))
                TRY(push_pair(nl, (uint32_t)j));
        nl->start[i + 1] = nl->npairs;
    }
    memcpy(nl->x0, x, 3 * n * sizeof *x);
    return SIM_OK;
}

double neighbour_half_max_displacement(const struct neighbour_half *nl,
                                       const double *x)
{
    double m2 = 0;
    #pragma omp parallel for reduction(max : m2) schedule(static) \
        if (nl->n > HALF_OMP_MIN)
    for (size_t i = 0; i < nl->n; i++) {
        double d2 = 0;
        for (int a = 0; a < 3; a++) {
            double d = x[3 * i + a] - nl->x0[3 * i + a];
            d2 += d * d;
        }
        m2 = fmax(m2, d2);
    }
    return sqrt(m2);
}

int neighbour_half_stale(const struct neighbour_half *nl, size_t n,
                         const double *x)
{
    if (n != nl->n || !nl->start)
        return 1;
    return neighbour_half_max_displacement(nl, x) > 0.5 * nl->skin;
}

void neighbour_half_carry(const struct neighbour_half *nl,
                          const size_t *ostart, const uint32_t *oj, size_t on,
                          const double *oval, int w, double *val)
{
    for (size_t i = 0; i < nl->n; i++) {
        size_t a = nl->start[i], ae = nl->start[i + 1];
        size_t b = i < on ? ostart[i] : 0, be = i < on ? ostart[i + 1] : 0;
        for (; a < ae; a++) {
            while (b < be && oj[b] < nl->j[a])
                b++;
            int hit = b < be && oj[b] == nl->j[a];
            for (int k = 0; k < w; k++)
                val[a * w + k] = hit ? oval[b * w + k] : 0.0;
        }
    }
}
