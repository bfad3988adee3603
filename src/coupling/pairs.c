/*
 * pairs.c — grain / MPS-particle pairs by cells of size r_e,s/2
 * (doc/theory.md A.10 step 1); see pairs.h for the layout and guarantees.
 *
 * A build is: bin the particles of the grain box (counting sort, with a
 * cell-ordered copy of their positions); one pass per grain over its
 * stencil into per-thread row buffers (each buffer first grown to hold
 * every candidate, so rows are never computed twice); a prefix sum over
 * grains; then a copy into place and a transpose by contiguous grain
 * chunks whose per-particle cursors keep every particle row in ascending
 * grain order, so the result does not depend on the number of threads.
 *
 * coupling_pairs_update() searches with r_e,s + skin and then, while the
 * grains and particles have moved less than the skin in total, only
 * recomputes the weights of the kept candidates (about 2.3x cheaper than
 * a search on the dam-break layout, test/bench/couplingPhysicsBench).
 *
 * Only the box around the grains is binned, so a dam break with a small
 * sediment patch pays for the particles near the patch. The cell count is
 * capped at a few times the number of points (the cells are then made
 * larger), so that grains spread thinly over a large domain cannot make
 * the grid larger than the clouds themselves.
 */
#include "coupling/pairs.h"

#include <math.h>
#include <omp.h>
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
    c = c0;
    TRY(reserve((void **)&P->pmap, &c, n, sizeof *P->pmap));
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
    c = c0;
    TRY(reserve((void **)&P->xs, &c, (size_t)np + 1, 3 * sizeof *P->xs));
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

/* Cells around a grain: lo..hi per axis (inclusive). */
static void stencil(const struct coupling_pairs *P, const double *xk,
                    int lo[3], int hi[3])
{
    for (int d = 0; d < 3; d++)
        lo[d] = hi[d] = 0;
    for (int d = 0; d < P->dim; d++) {
        int c = (int)floor((xk[d] - P->lo[d]) / P->h);
        lo[d] = c > P->reach ? c - P->reach : 0;
        hi[d] = c + P->reach < P->nc[d] ? c + P->reach : P->nc[d] - 1;
    }
}

/* Cells lo[0]..hi[0] of one (y, z) row are contiguous in cidx, so a
 * stencil is a few contiguous ranges of particles. */
static void row_range(const struct coupling_pairs *P, const int lo[3],
                      const int hi[3], int cy, int cz, int64_t *e0,
                      int64_t *e1)
{
    int64_t c = ((int64_t)cz * P->nc[1] + cy) * P->nc[0];
    *e0 = P->cstart[c + lo[0]];
    *e1 = P->cstart[c + hi[0] + 1];
}

static int64_t candidates(const struct coupling_pairs *P, const int lo[3],
                          const int hi[3])
{
    int64_t n = 0, e0, e1;
    for (int cz = lo[2]; cz <= hi[2]; cz++)
        for (int cy = lo[1]; cy <= hi[1]; cy++) {
            row_range(P, lo, hi, cy, cz, &e0, &e1);
            n += e1 - e0;
        }
    return n;
}

/* Pairs of grain k with the particles of its stencil, written to (j, w);
 * returns their number. */
static int64_t grain_row_cells(const struct coupling_pairs *P, const double *xk,
                               const int lo[3], const int hi[3], int32_t *j,
                               double *w)
{
    const double rs2 = P->rs * P->rs;
    int64_t m = 0, e0, e1;
    for (int cz = lo[2]; cz <= hi[2]; cz++)
        for (int cy = lo[1]; cy <= hi[1]; cy++) {
            row_range(P, lo, hi, cy, cz, &e0, &e1);
            for (int64_t e = e0; e < e1; e++) {
                const double *x = P->xs + 3 * e;
                double dx = x[0] - xk[0], dy = x[1] - xk[1];
                double dz = P->dim == 3 ? x[2] - xk[2] : 0.0;
                double r2 = dx * dx + dy * dy + dz * dz;
                if (r2 < rs2) {
                    j[m] = P->cidx[e];
                    w[m] = coupling_ws(sqrt(r2), P->re);
                    m++;
                }
            }
        }
    return m;
}

/* Box of the grains expanded by re, cut into cells of size h = re/2 (or
 * larger under the cell cap), with a stencil of `reach` cells. */
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
        lo[d] -= P->rs;
        hi[d] += P->rs;
    }
    double max_cells = fmax(1024.0, 4.0 * ((double)ng + np));
    P->h = 0.5 * P->rs;
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
    /* |floor(a) - floor(b)| <= ceil(|a - b|): reach cells hold every
     * particle within re of the grain. */
    P->reach = (int)ceil(P->rs / P->h - 1e-12);
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
    int64_t nb = P->cstart[ncell];
#pragma omp parallel for schedule(static)
    for (int64_t e = 0; e < nb; e++)
        for (int d = 0; d < 3; d++)
            P->xs[3 * e + d] = xp[3 * (size_t)P->cidx[e] + d];
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
            P->pmap[at] = e;
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
    if (P->npair >= INT32_MAX)
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
    P->rs = re;
    P->skin = -1.0;
    P->ng = ng;
    P->np = np;
    return reserve_points(P, ng, np);
}

/* Per-thread row buffers and transpose counts for nt threads. */
static int reserve_threads(struct coupling_pairs *P, int nt, int np)
{
    if (nt > P->nthr) {
        struct coupling_pair_buf *t =
            sim_realloc(P->tbuf, (size_t)nt * sizeof *t);
        if (!t)
            return SIM_ERR_NOMEM;
        memset(t + P->nthr, 0, (size_t)(nt - P->nthr) * sizeof *t);
        P->tbuf = t;
        P->nthr = nt;
    }
    return reserve((void **)&P->tcount, &P->cap_tcount,
                   (size_t)nt * ((size_t)np + 1), sizeof *P->tcount);
}

/* Grains of chunk t of T: contiguous, ascending. */
static void chunk(int ng, int t, int T, int *k0, int *k1)
{
    *k0 = (int)((int64_t)ng * t / T);
    *k1 = (int)((int64_t)ng * (t + 1) / T);
}

/* Rows of the grains of chunk t into the thread's buffer (one pass over
 * the cells: the buffer is grown to hold every candidate first). */
static int rows_of_chunk(struct coupling_pairs *P, int t, int T,
                         const double *xg)
{
    struct coupling_pair_buf *b = &P->tbuf[t];
    int k0, k1, lo[3], hi[3];
    chunk(P->ng, t, T, &k0, &k1);
    b->n = 0;
    for (int k = k0; k < k1; k++) {
        const double *xk = xg + 3 * (size_t)k;
        stencil(P, xk, lo, hi);
        size_t need = b->n + (size_t)candidates(P, lo, hi);
        if (need > b->cap) {
            /* plain realloc: sim_error's message is thread-local and
             * this runs on a worker thread; the caller reports */
            size_t cap = need + need / 2 + 1024;
            int32_t *j = realloc(b->j, cap * sizeof *j);
            if (j)
                b->j = j;
            double *w = realloc(b->w, cap * sizeof *w);
            if (w)
                b->w = w;
            if (!j || !w)
                return SIM_ERR_NOMEM;
            b->cap = cap;
        }
        int64_t m = grain_row_cells(P, xk, lo, hi, b->j + b->n, b->w + b->n);
        P->gstart[k + 1] = m;
        b->n += (size_t)m;
    }
    return SIM_OK;
}

/* Copy the thread rows into place and transpose them. Thread t counts
 * the particles of its contiguous grain range; the counts become cursors
 * laid out so that every particle row lists grains in ascending order,
 * whatever T is. */
static void gather_and_transpose(struct coupling_pairs *P, int T)
{
    const size_t np = (size_t)P->np;
#pragma omp parallel for schedule(static, 1)
    for (int t = 0; t < T; t++) {
        int k0, k1;
        chunk(P->ng, t, T, &k0, &k1);
        struct coupling_pair_buf *b = &P->tbuf[t];
        if (b->n) {
            memcpy(P->gj + P->gstart[k0], b->j, b->n * sizeof *b->j);
            memcpy(P->gw + P->gstart[k0], b->w, b->n * sizeof *b->w);
        }
        int32_t *cnt = P->tcount + (size_t)t * np;
        memset(cnt, 0, np * sizeof *cnt);
        for (int64_t e = P->gstart[k0]; e < P->gstart[k1]; e++)
            cnt[P->gj[e]]++;
    }
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < np; i++) {
        int64_t n = 0;
        for (int t = 0; t < T; t++)
            n += P->tcount[(size_t)t * np + i];
        P->pstart[i + 1] = n;
    }
    P->pstart[0] = 0;
    for (size_t i = 0; i < np; i++)
        P->pstart[i + 1] += P->pstart[i];
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < np; i++) {
        int64_t run = P->pstart[i];
        for (int t = 0; t < T; t++) {
            int32_t c = P->tcount[(size_t)t * np + i];
            P->tcount[(size_t)t * np + i] = (int32_t)run;
            run += c;
        }
    }
#pragma omp parallel for schedule(static, 1)
    for (int t = 0; t < T; t++) {
        int k0, k1;
        chunk(P->ng, t, T, &k0, &k1);
        int32_t *cur = P->tcount + (size_t)t * np;
        for (int k = k0; k < k1; k++)
            for (int64_t e = P->gstart[k]; e < P->gstart[k + 1]; e++) {
                int32_t at = cur[P->gj[e]]++;
                P->pk[at] = k;
                P->pw[at] = P->gw[e];
                P->pmap[at] = e;
            }
    }
}

/* The cell search with radius P->rs (after setup). */
static int search(struct coupling_pairs *P, int ng, const double *xg, int np,
                  const double *xp)
{
    if (ng == 0) {
        P->gstart[0] = 0;
        P->npair = 0;
        TRY(reserve_pairs(P, 1));
        transpose(P);
        return SIM_OK;
    }
    TRY(make_grid(P, ng, xg, np));
    bin_particles(P, np, xp);
    /* Chunks, not threads, carry the work, so T is fixed before the
     * parallel regions whatever number of threads the runtime grants. */
    int T = omp_get_max_threads();
    if (T > ng)
        T = ng;
    TRY(reserve_threads(P, T, np));
    int fail = 0;
#pragma omp parallel for schedule(static, 1) reduction(| : fail)
    for (int t = 0; t < T; t++)
        fail |= rows_of_chunk(P, t, T, xg) != SIM_OK;
    if (fail)
        return sim_error(SIM_ERR_NOMEM, "coupling pairs: out of memory for "
                         "the pair rows of %d grains", ng);
    TRY(prefix_and_reserve(P));
    gather_and_transpose(P, T);
    return SIM_OK;
}

int coupling_pairs_build(struct coupling_pairs *P, int dim, double re,
                         int ng, const double *xg, int np, const double *xp)
{
    TRY(setup(P, dim, re, ng, xg, np));
    return search(P, ng, xg, np, xp);
}

static int finite_point(int dim, const double *x)
{
    for (int d = 0; d < dim; d++)
        if (!isfinite(x[d]))
            return 0;
    return 1;
}

/* Largest displacement since the search of n points, squared; +inf when
 * a point became non-finite or finite again (fmax would hide a NaN). A
 * point non-finite at both times had and has no pairs: no change. */
static double max_shift2(int dim, int n, const double *x, const double *x0)
{
    double m = 0;
    int bad = 0;
#pragma omp parallel for schedule(static) reduction(max : m) reduction(| : bad)
    for (int i = 0; i < n; i++) {
        const double *a = x + 3 * (size_t)i, *b = x0 + 3 * (size_t)i;
        double d2 = 0;
        for (int d = 0; d < dim; d++)
            d2 += (a[d] - b[d]) * (a[d] - b[d]);
        if (!isfinite(d2)) {
            bad |= finite_point(dim, a) || finite_point(dim, b);
            continue;
        }
        if (d2 > m)
            m = d2;
    }
    return bad ? INFINITY : m;
}

/* New weights of the kept candidates, computed exactly as the search
 * computes them, then copied to the particle-major rows. */
static void refresh(struct coupling_pairs *P, const double *xg,
                    const double *xp)
{
#pragma omp parallel for schedule(dynamic, 16)
    for (int k = 0; k < P->ng; k++) {
        const double *xk = xg + 3 * (size_t)k;
        for (int64_t e = P->gstart[k]; e < P->gstart[k + 1]; e++) {
            const double *x = xp + 3 * (size_t)P->gj[e];
            double dx = x[0] - xk[0], dy = x[1] - xk[1];
            double dz = P->dim == 3 ? x[2] - xk[2] : 0.0;
            P->gw[e] = coupling_ws(sqrt(dx * dx + dy * dy + dz * dz), P->re);
        }
    }
#pragma omp parallel for schedule(static)
    for (int64_t e = 0; e < P->npair; e++)
        P->pw[e] = P->gw[P->pmap[e]];
}

int coupling_pairs_update(struct coupling_pairs *P, int dim, double re,
                          double skin, int ng, const double *xg, int np,
                          const double *xp, int *searched)
{
    if (!(skin >= 0) || !isfinite(skin))
        return sim_error(SIM_ERR_INPUT, "coupling pairs: skin %g must be "
                         ">= 0", skin);
    if (P->skin == skin && P->dim == dim && P->re == re && P->ng == ng &&
        P->np == np) {
        TRY(check_input(dim, re, ng, xg, np));
        double sg = sqrt(max_shift2(dim, ng, xg, P->xg0));
        double sp = sqrt(max_shift2(dim, np, xp, P->xp0));
        if (sg + sp < skin) {
            refresh(P, xg, xp);
            if (searched)
                *searched = 0;
            return SIM_OK;
        }
    }
    TRY(setup(P, dim, re, ng, xg, np));
    P->rs = re + skin;
    TRY(search(P, ng, xg, np, xp));
    TRY(reserve((void **)&P->xg0, &P->cap_g0, (size_t)ng + 1,
                3 * sizeof *P->xg0));
    TRY(reserve((void **)&P->xp0, &P->cap_p0, (size_t)np + 1,
                3 * sizeof *P->xp0));
    if (ng)
        memcpy(P->xg0, xg, 3 * (size_t)ng * sizeof *xg);
    if (np)
        memcpy(P->xp0, xp, 3 * (size_t)np * sizeof *xp);
    P->skin = skin;
    if (searched)
        *searched = 1;
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
        if (!(r2 < P->rs * P->rs))
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

void coupling_pairs_invalidate(struct coupling_pairs *P)
{
    P->skin = -1.0;
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
    free(P->xs);
    free(P->pcell);
    free(P->gwork);
    free(P->pmap);
    free(P->xg0);
    free(P->xp0);
    for (int t = 0; t < P->nthr; t++) {
        free(P->tbuf[t].j);
        free(P->tbuf[t].w);
    }
    free(P->tbuf);
    free(P->tcount);
    memset(P, 0, sizeof *P);
}
