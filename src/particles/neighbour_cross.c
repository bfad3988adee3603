/*
 * neighbour_cross.c — cross lists between two clouds through the cell grid
 * (neighbour_cross.h).
 *
 * A build is: bin the points of B in the box of A (cells_build_grid) with
 * a cell-ordered copy of their positions (cells_gather); one pass per A
 * point over its runs of cells (cells_runs) into per-thread row buffers
 * (each buffer first grown to hold every candidate, so rows are never
 * computed twice); a prefix sum over A; then a copy into place and a
 * transpose by contiguous chunks of A whose per-B-point cursors keep every
 * B-major row in ascending A order, so the result does not depend on the
 * number of threads.
 *
 * neighbour_cross_update() searches with rc + skin and then, while both
 * clouds have moved less than the skin in total, only recomputes the
 * distances of the kept candidates (about 2.3x cheaper than a search on
 * the dam-break layout of the coupling, test/bench/couplingPhysicsBench).
 *
 * The cell count is capped at a few times the number of points (the cells
 * are then made larger), so that points of A spread thinly over a large
 * domain cannot make the grid larger than the clouds themselves.
 */
#include "particles/neighbour_cross.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"

static int reserve_pairs(struct neighbour_cross *X, size_t n)
{
    size_t c0 = X->cap_pair, c;
    c = c0;
    TRY(sim_reserve((void **)&X->aj, &c, n, sizeof *X->aj));
    c = c0;
    TRY(sim_reserve((void **)&X->ar, &c, n, sizeof *X->ar));
    c = c0;
    TRY(sim_reserve((void **)&X->bk, &c, n, sizeof *X->bk));
    c = c0;
    TRY(sim_reserve((void **)&X->bmap, &c, n, sizeof *X->bmap));
    X->cap_pair = c;
    return SIM_OK;
}

static int reserve_points(struct neighbour_cross *X, int na, int nb)
{
    TRY(sim_reserve((void **)&X->astart, &X->cap_a, (size_t)na + 1,
                    sizeof *X->astart));
    TRY(sim_reserve((void **)&X->bstart, &X->cap_b, (size_t)nb + 1,
                    sizeof *X->bstart));
    return sim_reserve((void **)&X->xs, &X->cap_xs, 3 * ((size_t)nb + 1),
                       sizeof *X->xs);
}

static int check_input(int dim, double rc, int na, const double *xa, int nb)
{
    if (dim != 2 && dim != 3)
        return sim_error(SIM_ERR_INPUT, "neighbour_cross: dimension %d",
                         dim);
    if (!(rc > 0) || !isfinite(rc))
        return sim_error(SIM_ERR_INPUT,
                         "neighbour_cross: cut-off %g must be > 0", rc);
    if (na < 0 || nb < 0)
        return sim_error(SIM_ERR_INPUT, "neighbour_cross: negative count");
    for (int k = 0; k < na; k++)
        for (int d = 0; d < dim; d++)
            if (!isfinite(xa[3 * k + d]))
                return sim_error(SIM_ERR_NUMERIC,
                                 "neighbour_cross: point %d of the first "
                                 "cloud has a non-finite position", k);
    return SIM_OK;
}

/* Pairs of A point xk with the B points of its runs, written to (j, r);
 * returns their number. */
static int64_t row_cells(const struct neighbour_cross *X, const double *xk,
                         const struct cell_run *rn, int nrun, int32_t *j,
                         double *r)
{
    const double rs2 = X->rs * X->rs;
    const int32_t *order = X->grid.order;
    int64_t m = 0;
    for (int q = 0; q < nrun; q++)
        for (int64_t e = rn[q].a; e < rn[q].b; e++) {
            const double *x = X->xs + 3 * e;
            double dx = x[0] - xk[0], dy = x[1] - xk[1];
            double dz = X->dim == 3 ? x[2] - xk[2] : 0.0;
            double r2 = dx * dx + dy * dy + dz * dz;
            if (r2 < rs2) {
                j[m] = order[e];
                r[m] = sqrt(r2);
                m++;
            }
        }
    return m;
}

/* Box of A expanded by rs, cut into cells of rs/2 (or larger under the
 * cell cap); the points of B in it binned, up to one cell past the box's
 * upper faces clamped into the last cells (floor() leaves the box's end
 * inside them). */
static int make_grid(struct neighbour_cross *X, int na, const double *xa,
                     int nb, const double *xb)
{
    double lo[3] = { 0, 0, 0 }, hi[3] = { 0, 0, 0 }, h;
    int nc[3] = { 1, 1, 1 };
    for (int d = 0; d < X->dim; d++) {
        lo[d] = INFINITY;
        hi[d] = -INFINITY;
        for (int k = 0; k < na; k++) {
            lo[d] = fmin(lo[d], xa[3 * k + d]);
            hi[d] = fmax(hi[d], xa[3 * k + d]);
        }
        lo[d] -= X->rs;
        hi[d] += X->rs;
    }
    double max_cells = fmax(1024.0, 4.0 * ((double)na + nb));
    h = 0.5 * X->rs;
    for (;;) {
        double n[3] = { 1, 1, 1 }, ncell = 1;
        for (int d = 0; d < X->dim; d++) {
            n[d] = fmax(1.0, floor((hi[d] - lo[d]) / h));
            ncell *= n[d];
        }
        if (ncell <= max_cells) {
            for (int d = 0; d < 3; d++)
                nc[d] = (int)n[d];
            break;
        }
        h *= 1.26;
    }
    TRY(cells_build_grid(&X->grid, X->dim, xb, nb, h, lo, nc, 1.0));
    cells_gather(&X->grid, xb, X->xs);
    return SIM_OK;
}

/* B-major copy of the A-major rows; A ascending per row (serial). */
static void transpose(struct neighbour_cross *X)
{
    memset(X->bstart, 0, ((size_t)X->nb + 1) * sizeof *X->bstart);
    for (int64_t e = 0; e < X->npair; e++)
        X->bstart[X->aj[e] + 1]++;
    for (int i = 0; i < X->nb; i++)
        X->bstart[i + 1] += X->bstart[i];
    for (int k = 0; k < X->na; k++)
        for (int64_t e = X->astart[k]; e < X->astart[k + 1]; e++) {
            int64_t at = X->bstart[X->aj[e]]++;
            X->bk[at] = k;
            X->bmap[at] = e;
        }
    for (int i = X->nb; i > 0; i--)
        X->bstart[i] = X->bstart[i - 1];
    X->bstart[0] = 0;
}

static int prefix_and_reserve(struct neighbour_cross *X)
{
    X->astart[0] = 0;
    for (int k = 0; k < X->na; k++)
        X->astart[k + 1] += X->astart[k];
    X->npair = X->astart[X->na];
    if (X->npair >= INT32_MAX)
        return sim_error(SIM_ERR_INPUT, "neighbour_cross: %lld pairs "
                         "exceed the 32-bit index range",
                         (long long)X->npair);
    return reserve_pairs(X, (size_t)X->npair + 1);
}

static int setup(struct neighbour_cross *X, int dim, double rc, int na,
                 const double *xa, int nb)
{
    TRY(check_input(dim, rc, na, xa, nb));
    X->dim = dim;
    X->rc = rc;
    X->rs = rc;
    X->skin = -1.0;
    X->na = na;
    X->nb = nb;
    return reserve_points(X, na, nb);
}

/* Per-thread row buffers and transpose counts for nt threads. */
static int reserve_threads(struct neighbour_cross *X, int nt, int nb)
{
    if (nt > X->nthr) {
        struct neighbour_cross_buf *t =
            sim_realloc(X->tbuf, (size_t)nt * sizeof *t);
        if (!t)
            return SIM_ERR_NOMEM;
        memset(t + X->nthr, 0, (size_t)(nt - X->nthr) * sizeof *t);
        X->tbuf = t;
        X->nthr = nt;
    }
    return sim_reserve((void **)&X->tcount, &X->cap_tcount,
                       (size_t)nt * ((size_t)nb + 1), sizeof *X->tcount);
}

/* Points of A of chunk t of T: contiguous, ascending. */
static void chunk(int na, int t, int T, int *k0, int *k1)
{
    *k0 = (int)((int64_t)na * t / T);
    *k1 = (int)((int64_t)na * (t + 1) / T);
}

/* Rows of the A points of chunk t into the thread's buffer (one pass over
 * the cells: the buffer is grown to hold every candidate first). */
static int rows_of_chunk(struct neighbour_cross *X, int t, int T,
                         const double *xa)
{
    struct neighbour_cross_buf *b = &X->tbuf[t];
    struct cell_run rn[CELLS_MAX_RUNS];
    int k0, k1;
    chunk(X->na, t, T, &k0, &k1);
    b->n = 0;
    for (int k = k0; k < k1; k++) {
        const double *xk = xa + 3 * (size_t)k;
        int64_t len;
        int nrun = cells_runs(&X->grid, xk, X->rs, rn, &len);
        size_t need = b->n + (size_t)len;
        if (need > b->cap) {
            /* plain realloc: sim_error's message is thread-local and
             * this runs on a worker thread; the caller reports */
            size_t cap = need + need / 2 + 1024;
            int32_t *j = realloc(b->j, cap * sizeof *j);
            if (j)
                b->j = j;
            double *r = realloc(b->r, cap * sizeof *r);
            if (r)
                b->r = r;
            if (!j || !r)
                return SIM_ERR_NOMEM;
            b->cap = cap;
        }
        int64_t m = row_cells(X, xk, rn, nrun, b->j + b->n, b->r + b->n);
        X->astart[k + 1] = m;
        b->n += (size_t)m;
    }
    return SIM_OK;
}

/* Copy the thread rows into place and transpose them. Thread t counts
 * the B points of its contiguous A range; the counts become cursors laid
 * out so that every B-major row lists A points in ascending order,
 * whatever T is. */
static void gather_and_transpose(struct neighbour_cross *X, int T)
{
    const size_t nb = (size_t)X->nb;
#pragma omp parallel for schedule(static, 1)
    for (int t = 0; t < T; t++) {
        int k0, k1;
        chunk(X->na, t, T, &k0, &k1);
        struct neighbour_cross_buf *b = &X->tbuf[t];
        if (b->n) {
            memcpy(X->aj + X->astart[k0], b->j, b->n * sizeof *b->j);
            memcpy(X->ar + X->astart[k0], b->r, b->n * sizeof *b->r);
        }
        int32_t *cnt = X->tcount + (size_t)t * nb;
        memset(cnt, 0, nb * sizeof *cnt);
        for (int64_t e = X->astart[k0]; e < X->astart[k1]; e++)
            cnt[X->aj[e]]++;
    }
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < nb; i++) {
        int64_t n = 0;
        for (int t = 0; t < T; t++)
            n += X->tcount[(size_t)t * nb + i];
        X->bstart[i + 1] = n;
    }
    X->bstart[0] = 0;
    for (size_t i = 0; i < nb; i++)
        X->bstart[i + 1] += X->bstart[i];
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < nb; i++) {
        int64_t run = X->bstart[i];
        for (int t = 0; t < T; t++) {
            int32_t c = X->tcount[(size_t)t * nb + i];
            X->tcount[(size_t)t * nb + i] = (int32_t)run;
            run += c;
        }
    }
#pragma omp parallel for schedule(static, 1)
    for (int t = 0; t < T; t++) {
        int k0, k1;
        chunk(X->na, t, T, &k0, &k1);
        int32_t *cur = X->tcount + (size_t)t * nb;
        for (int k = k0; k < k1; k++)
            for (int64_t e = X->astart[k]; e < X->astart[k + 1]; e++) {
                int32_t at = cur[X->aj[e]]++;
                X->bk[at] = k;
                X->bmap[at] = e;
            }
    }
}

/* The cell search with radius X->rs (after setup). */
static int search(struct neighbour_cross *X, int na, const double *xa,
                  int nb, const double *xb)
{
    if (na == 0) {
        X->astart[0] = 0;
        X->npair = 0;
        TRY(reserve_pairs(X, 1));
        transpose(X);
        return SIM_OK;
    }
    TRY(make_grid(X, na, xa, nb, xb));
    /* Chunks, not threads, carry the work, so T is fixed before the
     * parallel regions whatever number of threads the runtime grants. */
    int T = omp_get_max_threads();
    if (T > na)
        T = na;
    TRY(reserve_threads(X, T, nb));
    int fail = 0;
#pragma omp parallel for schedule(static, 1) reduction(| : fail)
    for (int t = 0; t < T; t++)
        fail |= rows_of_chunk(X, t, T, xa) != SIM_OK;
    if (fail)
        return sim_error(SIM_ERR_NOMEM, "neighbour_cross: out of memory "
                         "for the rows of %d points", na);
    TRY(prefix_and_reserve(X));
    gather_and_transpose(X, T);
    return SIM_OK;
}

int neighbour_cross_build(struct neighbour_cross *X, int dim, double rc,
                          int na, const double *xa, int nb, const double *xb)
{
    TRY(setup(X, dim, rc, na, xa, nb));
    return search(X, na, xa, nb, xb);
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

/* New distances of the kept candidates, computed exactly as the search
 * computes them. */
static void refresh(struct neighbour_cross *X, const double *xa,
                    const double *xb)
{
#pragma omp parallel for schedule(dynamic, 16)
    for (int k = 0; k < X->na; k++) {
        const double *xk = xa + 3 * (size_t)k;
        for (int64_t e = X->astart[k]; e < X->astart[k + 1]; e++) {
            const double *x = xb + 3 * (size_t)X->aj[e];
            double dx = x[0] - xk[0], dy = x[1] - xk[1];
            double dz = X->dim == 3 ? x[2] - xk[2] : 0.0;
            X->ar[e] = sqrt(dx * dx + dy * dy + dz * dz);
        }
    }
}

int neighbour_cross_update(struct neighbour_cross *X, int dim, double rc,
                           double skin, int na, const double *xa, int nb,
                           const double *xb, int *searched)
{
    if (!(skin >= 0) || !isfinite(skin))
        return sim_error(SIM_ERR_INPUT, "neighbour_cross: skin %g must be "
                         ">= 0", skin);
    if (X->skin == skin && X->dim == dim && X->rc == rc && X->na == na &&
        X->nb == nb) {
        TRY(check_input(dim, rc, na, xa, nb));
        double sa = sqrt(max_shift2(dim, na, xa, X->xa0));
        double sb = sqrt(max_shift2(dim, nb, xb, X->xb0));
        if (sa + sb < skin) {
            refresh(X, xa, xb);
            if (searched)
                *searched = 0;
            return SIM_OK;
        }
    }
    TRY(setup(X, dim, rc, na, xa, nb));
    X->rs = rc + skin;
    TRY(search(X, na, xa, nb, xb));
    TRY(sim_reserve((void **)&X->xa0, &X->cap_a0, (size_t)na + 1,
                    3 * sizeof *X->xa0));
    TRY(sim_reserve((void **)&X->xb0, &X->cap_b0, (size_t)nb + 1,
                    3 * sizeof *X->xb0));
    if (na)
        memcpy(X->xa0, xa, 3 * (size_t)na * sizeof *xa);
    if (nb)
        memcpy(X->xb0, xb, 3 * (size_t)nb * sizeof *xb);
    X->skin = skin;
    if (searched)
        *searched = 1;
    return SIM_OK;
}

static int64_t row_brute(const struct neighbour_cross *X, const double *xk,
                         const double *xb, int32_t *j, double *r)
{
    int64_t m = 0;
    for (int i = 0; i < X->nb; i++) {
        double r2 = 0;
        for (int d = 0; d < X->dim; d++)
            r2 += (xb[3 * i + d] - xk[d]) * (xb[3 * i + d] - xk[d]);
        if (!(r2 < X->rs * X->rs))
            continue;
        if (j) {
            j[m] = i;
            r[m] = sqrt(r2);
        }
        m++;
    }
    return m;
}

int neighbour_cross_build_brute(struct neighbour_cross *X, int dim,
                                double rc, int na, const double *xa, int nb,
                                const double *xb)
{
    TRY(setup(X, dim, rc, na, xa, nb));
    for (int k = 0; k < na; k++)
        X->astart[k + 1] = row_brute(X, xa + 3 * (size_t)k, xb, NULL, NULL);
    TRY(prefix_and_reserve(X));
    for (int k = 0; k < na; k++)
        row_brute(X, xa + 3 * (size_t)k, xb, X->aj + X->astart[k],
                  X->ar + X->astart[k]);
    transpose(X);
    return SIM_OK;
}

void neighbour_cross_invalidate(struct neighbour_cross *X)
{
    X->skin = -1.0;
}

void neighbour_cross_free(struct neighbour_cross *X)
{
    free(X->astart);
    free(X->aj);
    free(X->ar);
    free(X->bstart);
    free(X->bk);
    free(X->bmap);
    cells_free(&X->grid);
    free(X->xs);
    free(X->xa0);
    free(X->xb0);
    for (int t = 0; t < X->nthr; t++) {
        free(X->tbuf[t].j);
        free(X->tbuf[t].r);
    }
    free(X->tbuf);
    free(X->tcount);
    memset(X, 0, sizeof *X);
}
