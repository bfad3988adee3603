/*
 * pairs.c — grain / MPS-particle pairs by cells of size >= r_e,s
 * (METHODS.md A.10 step 1); see pairs.h for the layout and guarantees.
 *
 * Only the box around the grains is binned, so a dam break with a small
 * sediment patch pays for the particles near the patch. The cell count is
 * capped at a few times the number of points (the cells are then made
 * larger), so that grains spread thinly over a large domain cannot make
 * the grid larger than the clouds themselves.
 */
#include "coupling/pairs.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "coupling/porosity.h"

/* Make *p hold at least `need` elements of `size` bytes; *cap counts them.
 * Grows by 1.5x so that slowly rising counts do not reallocate each step. */
static int reserve(void **p, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap && *p)
        return SIM_OK;
    size_t n = need + need / 2 + 16;
    void *q = sim_realloc(*p, n * size);
    if (!q)
        return SIM_ERR_NOMEM;
    *p = q;
    *cap = n;
    return SIM_OK;
}

static int reserve_pairs(struct coupling_pairs *P, size_t n)
{
    size_t c0 = P->cap_pair, c;
    c = c0;
    TRY(reserve((void **)&P->gj, &c, n, sizeof *P->gj));
    c = c0;
    TRY(reserve((void **)&P->gw, &c, n, sizeof *P->gw));
    c = c0;
    TRY(reserve((void **)&P->pk, &c, n, sizeof *P->pk));
    c = c0;
    TRY(reserve((void **)&P->pw, &c, n, sizeof *P->pw));
    P->cap_pair = c;
    return SIM_OK;
}

static int reserve_points(struct coupling_pairs *P, int ng, int np)
{
    size_t c0 = P->cap_p, c = c0;
    TRY(reserve((void **)&P->gstart, &P->cap_g, (size_t)ng + 1,
                sizeof *P->gstart));
    TRY(reserve((void **)&P->gwork, &P->cap_gw, 3 * (size_t)ng + 3,
                sizeof *P->gwork));
    TRY(reserve((void **)&P->pstart, &c, (size_t)np + 1, sizeof *P->pstart));
    c = c0;
    TRY(reserve((void **)&P->pcell, &c, (size_t)np + 1, sizeof *P->pcell));
    c = c0;
    TRY(reserve((void **)&P->cidx, &c, (size_t)np + 1, sizeof *P->cidx));
    P->cap_p = c;
    return SIM_OK;
}

static int check_input(int dim, double re, int ng, const double *xg, int np)
{
    if (dim != 2 && dim != 3)
        return sim_error(SIM_ERR_INPUT, "coupling pairs: dimension %d", dim);
    if (!(re > 0) || !isfinite(re))
        return sim_error(SIM_ERR_INPUT,
                         "coupling pairs: kernel radius %g must be > 0", re);
    if (ng < 0 || np < 0)
        return sim_error(SIM_ERR_INPUT, "coupling pairs: negative count");
    for (int k = 0; k < ng; k++)
        for (int d = 0; d < dim; d++)
            if (!isfinite(xg[3 * k + d]))
                return sim_error(SIM_ERR_NUMERIC,
                                 "coupling pairs: grain %d has a non-finite "
                                 "position", k);
    return SIM_OK;
}

/* Pairs of grain k with the particles of the cells around it, written to
 * (j, w) when j is not NULL; returns their number. */
static int64_t grain_row_cells(const struct coupling_pairs *P, const double *xk,
                               const double *xp, int32_t *j, double *w)
{
    int lo[3] = { 0, 0, 0 }, hi[3] = { 0, 0, 0 };
    for (int d = 0; d < P->dim; d++) {
        int c = (int)floor((xk[d] - P->lo[d]) / P->h);
        lo[d] = c > 0 ? c - 1 : 0;
        hi[d] = c + 1 < P->nc[d] ? c + 1 : P->nc[d] - 1;
    }
    const double re2 = P->re * P->re;
    int64_t m = 0;
    for (int cz = lo[2]; cz <= hi[2]; cz++)
        for (int cy = lo[1]; cy <= hi[1]; cy++)
            for (int cx = lo[0]; cx <= hi[0]; cx++) {
                int64_t c = ((int64_t)cz * P->nc[1] + cy) * P->nc[0] + cx;
                for (int64_t e = P->cstart[c]; e < P->cstart[c + 1]; e++) {
                    int32_t i = P->cidx[e];
                    double dx = xp[3 * i] - xk[0], dy = xp[3 * i + 1] - xk[1];
                    double dz = P->dim == 3 ? xp[3 * i + 2] - xk[2] : 0.0;
                    double r2 = dx * dx + dy * dy + dz * dz;
                    if (!(r2 < re2))
                        continue;
                    if (j) {
                        j[m] = i;
                        w[m] = coupling_ws(sqrt(r2), P->re);
                    }
                    m++;
                }
            }
    return m;
}

/* Box of the grains expanded by re, cut into cells of size h >= re. */
static int make_grid(struct coupling_pairs *P, int ng, const double *xg,
                     int np)
{
    double lo[3] = { 0, 0, 0 }, hi[3] = { 0, 0, 0 };
    for (int d = 0; d < P->dim; d++) {
        lo[d] = INFINITY;
        hi[d] = -INFINITY;
        for (int k = 0; k < ng; k++) {
            lo[d] = fmin(lo[d], xg[3 * k + d]);
            hi[d] = fmax(hi[d], xg[3 * k + d]);
        }
        lo[d] -= P->re;
        hi[d] += P->re;
    }
    double max_cells = fmax(1024.0, 4.0 * ((double)ng + np));
    P->h = P->re;
    for (;;) {
        double n[3] = { 1, 1, 1 }, ncell = 1;
        for (int d = 0; d < P->dim; d++) {
            n[d] = fmax(1.0, floor((hi[d] - lo[d]) / P->h));
            ncell *= n[d];
        }
        if (ncell <= max_cells) {
            for (int d = 0; d < 3; d++)
                P->nc[d] = (int)n[d];
            break;
        }
        P->h *= 1.26;
    }
    memcpy(P->lo, lo, sizeof lo);
    size_t ncell = (size_t)P->nc[0] * P->nc[1] * P->nc[2];
    TRY(reserve((void **)&P->cstart, &P->cap_cell, ncell + 1,
                sizeof *P->cstart));
    return SIM_OK;
}

static int cell_of(const struct coupling_pairs *P, const double *x)
{
    int64_t c = 0;
    for (int d = P->dim - 1; d >= 0; d--) {
        double s = (x[d] - P->lo[d]) / P->h;
        /* The last cell absorbs the remainder of the box, shorter than h
         * because nc = floor(L/h); points beyond it are not binned. */
        if (!(s >= 0) || s >= P->nc[d] + 1.0)
            return -1;
        int64_t ic = (int64_t)s;
        if (ic >= P->nc[d])
            ic = P->nc[d] - 1;
        c = c * P->nc[d] + ic;
    }
    return (int)c;
}

static void bin_particles(struct coupling_pairs *P, int np, const double *xp)
{
    size_t ncell = (size_t)P->nc[0] * P->nc[1] * P->nc[2];
#pragma omp parallel for schedule(static)
    for (int i = 0; i < np; i++)
        P->pcell[i] = cell_of(P, xp + 3 * (size_t)i);
    memset(P->cstart, 0, (ncell + 1) * sizeof *P->cstart);
    for (int i = 0; i < np; i++)
        if (P->pcell[i] >= 0)
            P->cstart[P->pcell[i] + 1]++;
    for (size_t c = 0; c < ncell; c++)
        P->cstart[c + 1] += P->cstart[c];
    for (int i = 0; i < np; i++)
        if (P->pcell[i] >= 0)
            P->cidx[P->cstart[P->pcell[i]]++] = i;
    for (size_t c = ncell; c > 0; c--)
        P->cstart[c] = P->cstart[c - 1];
    P->cstart[0] = 0;
}

/* Particle-major copy of the grain-major rows; grains ascending per row. */
static void transpose(struct coupling_pairs *P)
{
    memset(P->pstart, 0, ((size_t)P->np + 1) * sizeof *P->pstart);
    for (int64_t e = 0; e < P->npair; e++)
        P->pstart[P->gj[e] + 1]++;
    for (int i = 0; i < P->np; i++)
        P->pstart[i + 1] += P->pstart[i];
    for (int k = 0; k < P->ng; k++)
        for (int64_t e = P->gstart[k]; e < P->gstart[k + 1]; e++) {
            int64_t at = P->pstart[P->gj[e]]++;
            P->pk[at] = k;
            P->pw[at] = P->gw[e];
        }
    for (int i = P->np; i > 0; i--)
        P->pstart[i] = P->pstart[i - 1];
    P->pstart[0] = 0;
}

static int prefix_and_reserve(struct coupling_pairs *P)
{
    P->gstart[0] = 0;
    for (int k = 0; k < P->ng; k++)
        P->gstart[k + 1] += P->gstart[k];
    P->npair = P->gstart[P->ng];
    if (P->npair > INT32_MAX)
        return sim_error(SIM_ERR_INPUT, "coupling pairs: %lld pairs exceed "
                         "the 32-bit index range", (long long)P->npair);
    return reserve_pairs(P, (size_t)P->npair + 1);
}

static int setup(struct coupling_pairs *P, int dim, double re, int ng,
                 const double *xg, int np)
{
    TRY(check_input(dim, re, ng, xg, np));
    P->dim = dim;
    P->re = re;
    P->ng = ng;
    P->np = np;
    return reserve_points(P, ng, np);
}

int coupling_pairs_build(struct coupling_pairs *P, int dim, double re,
                         int ng, const double *xg, int np, const double *xp)
{
    TRY(setup(P, dim, re, ng, xg, np));
    if (ng == 0) {
        P->gstart[0] = 0;
        P->npair = 0;
        TRY(reserve_pairs(P, 1));
        transpose(P);
        return SIM_OK;
    }
    TRY(make_grid(P, ng, xg, np));
    bin_particles(P, np, xp);
#pragma omp parallel for schedule(dynamic, 16)
    for (int k = 0; k < ng; k++)
        P->gstart[k + 1] = grain_row_cells(P, xg + 3 * (size_t)k, xp, NULL,
                                           NULL);
    TRY(prefix_and_reserve(P));
#pragma omp parallel for schedule(dynamic, 16)
    for (int k = 0; k < ng; k++)
        grain_row_cells(P, xg + 3 * (size_t)k, xp, P->gj + P->gstart[k],
                        P->gw + P->gstart[k]);
    transpose(P);
    return SIM_OK;
}

static int64_t grain_row_brute(const struct coupling_pairs *P,
                               const double *xk, const double *xp, int32_t *j,
                               double *w)
{
    int64_t m = 0;
    for (int i = 0; i < P->np; i++) {
        double r2 = 0;
        for (int d = 0; d < P->dim; d++)
            r2 += (xp[3 * i + d] - xk[d]) * (xp[3 * i + d] - xk[d]);
        if (!(r2 < P->re * P->re))
            continue;
        if (j) {
            j[m] = i;
            w[m] = coupling_ws(sqrt(r2), P->re);
        }
        m++;
    }
    return m;
}

int coupling_pairs_build_brute(struct coupling_pairs *P, int dim, double re,
                               int ng, const double *xg, int np,
                               const double *xp)
{
    TRY(setup(P, dim, re, ng, xg, np));
    for (int k = 0; k < ng; k++)
        P->gstart[k + 1] = grain_row_brute(P, xg + 3 * (size_t)k, xp, NULL,
                                           NULL);
    TRY(prefix_and_reserve(P));
    for (int k = 0; k < ng; k++)
        grain_row_brute(P, xg + 3 * (size_t)k, xp, P->gj + P->gstart[k],
                        P->gw + P->gstart[k]);
    transpose(P);
    return SIM_OK;
}

void coupling_pairs_free(struct coupling_pairs *P)
{
    free(P->gstart);
    free(P->gj);
    free(P->gw);
    free(P->pstart);
    free(P->pk);
    free(P->pw);
    free(P->cstart);
    free(P->cidx);
    free(P->pcell);
    free(P->gwork);
    memset(P, 0, sizeof *P);
}
