/*
 * nlist.c — cell-grid construction of the half neighbour list (nlist.h).
 *
 * The grid covers the bounding box of the grains with cubic cells of side
 * at least 2 R_max + skin, so that every candidate lies in the 27 cells
 * around a grain; the cell count is capped near the grain count so that a
 * few grains far apart cannot blow up memory (the cells just get larger).
 */
#include "dem/neighbour/nlist.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"

void nlist_init(struct dem_nlist *nl, double skin)
{
    memset(nl, 0, sizeof *nl);
    nl->skin = skin;
}

void nlist_free(struct dem_nlist *nl)
{
    free(nl->start);
    free(nl->j);
    free(nl->x0);
    free(nl->head);
    free(nl->next);
    double skin = nl->skin;
    nlist_init(nl, skin);
}

static int reserve_grains(struct dem_nlist *nl, size_t n)
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
    int64_t *nx = sim_realloc(nl->next, cap * sizeof *nx);
    if (!nx)
        return SIM_ERR_NOMEM;
    nl->next = nx;
    nl->ncap = cap;
    return SIM_OK;
}

static int push_pair(struct dem_nlist *nl, uint32_t j)
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

struct grid {
    double lo[3], h;
    long nc[3];
};

static int grid_setup(struct grid *g, size_t n, const double *x, double hmin)
{
    double hi[3];
    for (int a = 0; a < 3; a++)
        g->lo[a] = INFINITY, hi[a] = -INFINITY;
    for (size_t i = 0; i < n; i++)
        for (int a = 0; a < 3; a++) {
            g->lo[a] = fmin(g->lo[a], x[3 * i + a]);
            hi[a] = fmax(hi[a], x[3 * i + a]);
        }
    for (int a = 0; a < 3; a++)
        if (!isfinite(g->lo[a]) || !isfinite(hi[a]))
            return sim_error(SIM_ERR_NUMERIC,
                             "grain positions are not finite: the "
                             "integration blew up (a time step above the "
                             "contact stability limit?)");
    g->h = hmin;
    for (;;) {
        double cells = 1;
        for (int a = 0; a < 3; a++) {
            g->nc[a] = (long)((hi[a] - g->lo[a]) / g->h) + 1;
            cells *= (double)g->nc[a];
        }
        if (cells <= 4.0 * (double)n + 64)
            break;
        g->h *= 1.26;
    }
    return SIM_OK;
}

static long cell_of(const struct grid *g, const double *xi, long c[3])
{
    for (int a = 0; a < 3; a++) {
        c[a] = (long)((xi[a] - g->lo[a]) / g->h);
        if (c[a] < 0) c[a] = 0;
        if (c[a] >= g->nc[a]) c[a] = g->nc[a] - 1;
    }
    return (c[2] * g->nc[1] + c[1]) * g->nc[0] + c[0];
}

static int fill_row(struct dem_nlist *nl, const struct grid *g, size_t i,
                    const double *x, const double *r)
{
    long c[3];
    cell_of(g, &x[3 * i], c);
    for (long dz = -1; dz <= 1; dz++)
        for (long dy = -1; dy <= 1; dy++)
            for (long dx = -1; dx <= 1; dx++) {
                long cx = c[0] + dx, cy = c[1] + dy, cz = c[2] + dz;
                if (cx < 0 || cy < 0 || cz < 0 || cx >= g->nc[0]
                    || cy >= g->nc[1] || cz >= g->nc[2])
                    continue;
                long cell = (cz * g->nc[1] + cy) * g->nc[0] + cx;
                for (int64_t j = nl->head[cell]; j >= 0; j = nl->next[j]) {
                    if ((size_t)j <= i)
                        continue;
                    double d2 = 0;
                    for (int a = 0; a < 3; a++) {
                        double d = x[3 * j + a] - x[3 * i + a];
                        d2 += d * d;
                    }
                    double cut = r[i] + r[j] + nl->skin;
                    if (d2 < cut * cut)
                        TRY(push_pair(nl, (uint32_t)j));
                }
            }
    return SIM_OK;
}

int nlist_build(struct dem_nlist *nl, size_t n, const double *x,
                const double *r)
{
    TRY(reserve_grains(nl, n));
    nl->n = n;
    nl->npairs = 0;
    nl->start[0] = 0;
    nl->nbuilds++;
    if (n == 0)
        return SIM_OK;
    double rmax = 0;
    for (size_t i = 0; i < n; i++)
        rmax = fmax(rmax, r[i]);
    struct grid g;
    TRY(grid_setup(&g, n, x, fmax(2 * rmax + nl->skin, 1e-12)));
    size_t ncells = (size_t)(g.nc[0] * g.nc[1] * g.nc[2]);
    if (ncells > nl->ncells_cap) {
        int64_t *h = sim_realloc(nl->head, ncells * sizeof *h);
        if (!h)
            return SIM_ERR_NOMEM;
        nl->head = h;
        nl->ncells_cap = ncells;
    }
    for (size_t c = 0; c < ncells; c++)
        nl->head[c] = -1;
    long cc[3];
    for (size_t i = n; i-- > 0;) {
        long cell = cell_of(&g, &x[3 * i], cc);
        nl->next[i] = nl->head[cell];
        nl->head[cell] = (int64_t)i;
    }
    for (size_t i = 0; i < n; i++) {
        TRY(fill_row(nl, &g, i, x, r));
        nl->start[i + 1] = nl->npairs;
        sort_row(&nl->j[nl->start[i]], nl->start[i + 1] - nl->start[i]);
    }
    memcpy(nl->x0, x, 3 * n * sizeof *x);
    return SIM_OK;
}

double nlist_max_displacement(const struct dem_nlist *nl, const double *x)
{
    double m2 = 0;
    #pragma omp parallel for reduction(max : m2) schedule(static) \
        if (nl->n > DEM_OMP_MIN)
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

int nlist_stale(const struct dem_nlist *nl, size_t n, const double *x)
{
    if (n != nl->n || !nl->start)
        return 1;
    return nlist_max_displacement(nl, x) > 0.5 * nl->skin;
}

void nlist_carry(const struct dem_nlist *nl, const size_t *ostart,
                 const uint32_t *oj, size_t on, const double *oval, int w,
                 double *val)
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
