/* neighbour.c — see neighbour.h. Two passes over the cells (count, fill) so
 * that rows are written in parallel without locks. */
#include "particles/neighbour.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "particles/cells.h"

static int reserve_rows(struct neighbour_list *nl, int n)
{
    if ((size_t)n + 1 > nl->cap_n) {
        size_t c = (size_t)n + n / 4 + 16;
        int64_t *s = sim_realloc(nl->start, c * sizeof *s);
        if (!s)
            return SIM_ERR_NOMEM;
        nl->start = s;
        nl->cap_n = c;
    }
    nl->n = n;
    return SIM_OK;
}

static int reserve_entries(struct neighbour_list *nl, int64_t nnz)
{
    if ((size_t)nnz <= nl->cap_nnz)
        return SIM_OK;
    size_t c = (size_t)nnz + (size_t)nnz / 4 + 64;
    int32_t *j = sim_realloc(nl->j, c * sizeof *j);
    if (!j)
        return SIM_ERR_NOMEM;
    nl->j = j;
    double *r = sim_realloc(nl->r, c * sizeof *r);
    if (!r)
        return SIM_ERR_NOMEM;
    nl->r = r;
    nl->cap_nnz = c;
    return SIM_OK;
}

/* Visit the 3^d cells around particle i; count (out == NULL) or fill. */
static int64_t scan(const struct cell_grid *g, const double *x, int i,
                    double rc2, int32_t *oj, double *or_)
{
    int64_t m = 0;
    int64_t c = g->cell_of[i];
    if (c == g->ncell)
        return 0;
    const int nx = g->nc[0], ny = g->nc[1], nz = g->nc[2];
    int ic[3] = { (int)(c % nx), (int)(c / nx % ny), (int)(c / nx / ny) };
    const double *xi = x + 3 * i;
    int zlo = g->dim == 3 ? -1 : 0, zhi = g->dim == 3 ? 1 : 0;
    for (int dz = zlo; dz <= zhi; dz++) {
        int kz = ic[2] + dz;
        if (kz < 0 || kz >= nz)
            continue;
        for (int dy = -1; dy <= 1; dy++) {
            int ky = ic[1] + dy;
            if (ky < 0 || ky >= ny)
                continue;
            int kx0 = ic[0] > 0 ? ic[0] - 1 : 0;
            int kx1 = ic[0] < nx - 1 ? ic[0] + 1 : nx - 1;
            /* The x-neighbours of one row are contiguous in cell order. */
            int64_t base = (int64_t)nx * (ky + (int64_t)ny * kz);
            for (int64_t s = g->start[base + kx0]; s < g->start[base + kx1 + 1];
                 s++) {
                int j = g->order[s];
                if (j == i)
                    continue;
                const double *xj = x + 3 * j;
                double dx = xj[0] - xi[0], dy2 = xj[1] - xi[1],
                       dz2 = xj[2] - xi[2];
                double r2 = dx * dx + dy2 * dy2 + dz2 * dz2;
                if (r2 < rc2) {
                    if (oj) {
                        oj[m] = j;
                        or_[m] = sqrt(r2);
                    }
                    m++;
                }
            }
        }
    }
    return m;
}

static void prefix(struct neighbour_list *nl)
{
    int64_t acc = 0;
    for (int i = 0; i < nl->n; i++) {
        int64_t c = nl->start[i];
        nl->start[i] = acc;
        acc += c;
    }
    nl->start[nl->n] = acc;
    nl->nnz = acc;
}

int neighbour_build(struct neighbour_list *nl, const struct cell_grid *g,
                    const double *x, double rc)
{
    if (!(rc > 0) || g->h < rc * (1 - 1e-12))
        return sim_error(SIM_ERR_INPUT, "neighbour_build: cut-off %g larger "
                         "than the cell size %g", rc, g->h);
    const int n = g->n;
    const double rc2 = rc * rc;
    TRY(reserve_rows(nl, n));
    nl->rc = rc;
#pragma omp parallel for schedule(dynamic, 256)
    for (int i = 0; i < n; i++)
        nl->start[i] = scan(g, x, i, rc2, NULL, NULL);
    prefix(nl);
    TRY(reserve_entries(nl, nl->nnz));
#pragma omp parallel for schedule(dynamic, 256)
    for (int i = 0; i < n; i++)
        scan(g, x, i, rc2, nl->j + nl->start[i], nl->r + nl->start[i]);
    return SIM_OK;
}

static int finite3(const double *p)
{
    return isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]);
}

int neighbour_build_brute(struct neighbour_list *nl, int dim, const double *x,
                          int n, double rc)
{
    (void)dim;
    TRY(reserve_rows(nl, n));
    nl->rc = rc;
    for (int pass = 0; pass < 2; pass++) {
        for (int i = 0; i < n; i++) {
            int64_t m = 0, base = pass ? nl->start[i] : 0;
            for (int j = 0; j < n && finite3(x + 3 * i); j++) {
                if (j == i || !finite3(x + 3 * j))
                    continue;
                double d[3], r2 = 0;
                for (int k = 0; k < 3; k++) {
                    d[k] = x[3 * j + k] - x[3 * i + k];
                    r2 += d[k] * d[k];
                }
                if (r2 < rc * rc) {
                    if (pass) {
                        nl->j[base + m] = j;
                        nl->r[base + m] = sqrt(r2);
                    }
                    m++;
                }
            }
            if (!pass)
                nl->start[i] = m;
        }
        if (!pass) {
            prefix(nl);
            TRY(reserve_entries(nl, nl->nnz));
        }
    }
    return SIM_OK;
}

void neighbour_free(struct neighbour_list *nl)
{
    free(nl->start);
    free(nl->j);
    free(nl->r);
    memset(nl, 0, sizeof *nl);
}
