/* neighbour.c — see neighbour.h.
 *
 * Build: each particle visits only the runs of cells that can hold a point
 * within the cut-off (per row of cells along x, the x-extent left by the
 * row's distance in y and z): corner rows of the 27 cells of side rc are
 * skipped, and cells down to rc/2 are allowed (fewer candidates, another
 * particle order). Each thread writes the rows of its contiguous block
 * into its own buffer in a single branch-free pass (no count pass, no
 * locks); the candidates stay there, the block's row offsets counted from
 * its first candidate (no copy into one array: memory). Rows keep the
 * cell-traversal order (z, then y, then x), so that on the same grid the
 * rows, and every sum over them, are those of a full 27-cell scan.
 *
 * Update: one pass over each thread's block of candidates keeps the
 * indices of those within the cut-off in a scratch laid out like the
 * candidates; once the blocks' counts are known, a second pass writes them
 * into place with their distances (recomputed: cheaper than storing them
 * for every candidate). With measure_r (the lean list) the first pass
 * stores a class per candidate instead (beyond the cut-off, within it,
 * within the inner radius: one byte where an index takes four) and the
 * second writes the kept indices from it; that costs 20-40 % more update
 * time (a pass over every candidate again) for 3 bytes per candidate.
 * The update goes by the build's blocks, so any thread count reads the
 * candidates where the build left them. */
#include "particles/neighbour.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "particles/cells.h"


/* Entries between two blocks' slots for the candidates beyond rc: a
 * cache line of indices. */
#define TRASH 16

static int reserve_rows(struct neighbour_list *nl, int n)
{
    if ((size_t)n + 1 > nl->cap_n) {
        size_t c = (size_t)n + n / 4 + 16;
        int64_t *s = sim_realloc(nl->start, c * sizeof *s);
        if (!s)
            return SIM_ERR_NOMEM;
        nl->start = s;
        s = sim_realloc(nl->cstart, c * sizeof *s);
        if (!s)
            return SIM_ERR_NOMEM;
        nl->cstart = s;
        s = sim_realloc(nl->mid, c * sizeof *s);
        if (!s)
            return SIM_ERR_NOMEM;
        nl->mid = s;
        nl->cap_n = c;
    }
    nl->n = n;
    return SIM_OK;
}

static int reserve_entries(struct neighbour_list *nl, int64_t nnz)
{
    const int want_r = !nl->measure_r;
    if ((size_t)nnz <= nl->cap_nnz && (!want_r || nl->r))
        return SIM_OK;
    /* sized to the pairs within rc (about 2/3 of the candidates at a
     * skin of 0.5 dp in 3-D), with room for the growth between builds */
    size_t c = (size_t)nnz + (size_t)nnz / 8 + 64;
    c = c > nl->cap_nnz ? c : nl->cap_nnz;
    SIM_GROW(nl->j, c);
    if (want_r)
        SIM_GROW(nl->r, c);
    nl->cap_nnz = c;
    return SIM_OK;
}

/* measure_r: the positions of this update and room for the longest row
 * per thread. */
static int keep_positions(struct neighbour_list *nl, const double *x)
{
    if (!nl->measure_r)
        return SIM_OK;
    const size_t n3 = 3 * (size_t)nl->n;
    TRY(sim_reserve((void **)&nl->xr, &nl->cap_xr, n3, sizeof *nl->xr));
    memcpy(nl->xr, x, n3 * sizeof *x);
    return neighbour_grow_rows(nl, 1, &nl->rbuf, &nl->cap_rbuf,
                               &nl->rbuf_threads);
}

int neighbour_grow_rows(const struct neighbour_list *nl, int nbuf,
                        double **buf, int64_t *cap, int *threads)
{
    const int nth = omp_get_max_threads();
    const int64_t want = nl->max_row + 1;
    if (want <= *cap && nth <= *threads)
        return SIM_OK;
    int64_t c = want > *cap ? want + want / 4 : *cap;
    int t = nth > *threads ? nth : *threads;
    double *b = sim_realloc(*buf, (size_t)nbuf * (size_t)t * (size_t)c
                                  * sizeof *b);
    if (!b)
        return SIM_ERR_NOMEM;
    *buf = b;
    *cap = c;
    *threads = t;
    return SIM_OK;
}

/* One candidate buffer per block, the blocks' first rows and counts. */
static int reserve_buffers(struct neighbour_list *nl, int nth)
{
    if (nth <= nl->nbuf)
        return SIM_OK;
    int32_t **b = sim_realloc(nl->buf, (size_t)nth * sizeof *b);
    if (!b)
        return SIM_ERR_NOMEM;
    nl->buf = b;
    size_t *c = sim_realloc(nl->cap_buf, (size_t)nth * sizeof *c);
    if (!c)
        return SIM_ERR_NOMEM;
    nl->cap_buf = c;
    int64_t *k = sim_realloc(nl->blk, (size_t)nth * sizeof *k);
    if (!k)
        return SIM_ERR_NOMEM;
    nl->blk = k;
    int *r = sim_realloc(nl->blk_row, ((size_t)nth + 1) * sizeof *r);
    if (!r)
        return SIM_ERR_NOMEM;
    nl->blk_row = r;
    for (int t = nl->nbuf; t < nth; t++) {
        nl->buf[t] = NULL;
        nl->cap_buf[t] = 0;
    }
    nl->nbuf = nth;
    return SIM_OK;
}

#define dist2 neighbour_dist2

/* The update's scratch for acc candidates: the kept indices (4 bytes per
 * candidate), or with measure_r their classes (1 byte). */
static int reserve_scratch(struct neighbour_list *nl, int64_t acc)
{
    size_t c = (size_t)acc + (size_t)acc / 8 + 64;
    if (nl->measure_r) {
        if ((size_t)acc > nl->cap_cls) {
            SIM_GROW(nl->cls, c);
            nl->cap_cls = c;
        }
    } else if ((size_t)acc > nl->cap_sj) {
        SIM_GROW(nl->sj, c);
        nl->cap_sj = c;
    }
    return SIM_OK;
}

/* Candidates of particle i into out (room for every particle of the runs
 * is guaranteed by the caller); returns how many. */
static int64_t scan(const struct cell_grid *g, const double *x, int i,
                    double rc2, const struct cell_run *rn, int nrun,
                    int32_t *out)
{
    int64_t m = 0;
    const double *xi = x + 3 * i;
    /* branch-free: the store past the last kept one stays in the room */
    for (int q = 0; q < nrun; q++)
        for (int64_t s = rn[q].a; s < rn[q].b; s++) {
            int j = g->order[s];
            out[m] = j;
            m += (j != i) & (dist2(xi, x + 3 * j) < rc2);
        }
    return m;
}

/* Rows [a, b) of this thread into its buffer; counts in cstart[i]. */
static int scan_block(struct neighbour_list *nl, const struct cell_grid *g,
                      const double *x, double rc, int t, int a, int b,
                      int64_t *used)
{
    struct cell_run rn[CELLS_MAX_RUNS];
    const double rc2 = rc * rc;
    int64_t m = 0;
    for (int i = a; i < b; i++) {
        nl->cstart[i] = 0;
        if (g->cell_of[i] == g->ncell || (nl->rows && !nl->rows[i]))
            continue;
        int64_t len;
        int nrun = cells_runs(g, x + 3 * i, rc, rn, &len);
        if ((size_t)(m + len) > nl->cap_buf[t]) {
            size_t c = (size_t)(m + len) + (size_t)(m + len) / 4 + 1024;
            int32_t *p = sim_realloc(nl->buf[t], c * sizeof *p);
            if (!p)
                return SIM_ERR_NOMEM;
            nl->buf[t] = p;
            nl->cap_buf[t] = c;
        }
        nl->cstart[i] = scan(g, x, i, rc2, rn, nrun, nl->buf[t] + m);
        m += nl->cstart[i];
    }
    *used = m;
    return SIM_OK;
}

static int build_candidates(struct neighbour_list *nl,
                            const struct cell_grid *g, const double *x,
                            double rl)
{
    const int n = g->n;
    TRY(reserve_buffers(nl, omp_get_max_threads()));
    int64_t *used = nl->blk;
    int err = SIM_OK;
#pragma omp parallel
    {
        int t = omp_get_thread_num(), nt = omp_get_num_threads();
        int a = (int)((int64_t)n * t / nt), b = (int)((int64_t)n * (t + 1) / nt);
        nl->blk_row[t] = a;
        int rc = scan_block(nl, g, x, rl, t, a, b, &used[t]);
        if (rc) {
#pragma omp atomic write
            err = rc;
        }
#pragma omp barrier
#pragma omp single
        {
            int64_t acc = 0;
            for (int i = 0; i < n; i++) {
                int64_t c = nl->cstart[i];
                nl->cstart[i] = acc;
                acc += c;
            }
            nl->cstart[n] = acc;
            nl->nnz_cand = acc;
            nl->nblk = nt;
            nl->blk_row[nt] = n;
            if (!err)
                err = reserve_scratch(nl, acc);
        }
    }
    return err;
}

int neighbour_build_skin(struct neighbour_list *nl, const struct cell_grid *g,
                         const double *x, double rc, double skin)
{
    const double rl = rc + skin;
    if (!(rc > 0) || !(skin >= 0) || g->h < 0.5 * rl * (1 - 1e-12))
        return sim_error(SIM_ERR_INPUT, "neighbour_build: cut-off %g (skin "
                         "%g) more than twice the cell size %g", rc, skin,
                         g->h);
    TRY(reserve_rows(nl, g->n));
    nl->rc = rc;
    nl->skin = skin;
    TRY(build_candidates(nl, g, x, rl));
    return neighbour_update(nl, x);
}

int neighbour_build(struct neighbour_list *nl, const struct cell_grid *g,
                    const double *x, double rc)
{
    return neighbour_build_skin(nl, g, x, rc, 0.0);
}

/* Fast update (distances stored). Candidates of rows [a, b) (block t)
 * within rc2: their indices into the scratch at the candidate offsets,
 * counts into start[i], the longest into *longest. Branch-free (about half
 * the candidates are kept, in no predictable pattern); the store one past
 * a full row lands in the next row's first slot, rewritten afterwards,
 * except past the block's last row, which another thread owns: that row
 * takes the branch. */
static int64_t select_block(struct neighbour_list *nl, const double *x,
                            double rc2, int t, int64_t *longest)
{
    const int a = nl->blk_row[t], b = nl->blk_row[t + 1];
    const int32_t *cj = nl->buf[t];   /* from candidate cstart[a] on */
    const int64_t base = nl->cstart[a];
    int64_t tot = 0, big = 0;
    for (int i = a; i < b; i++) {
        const double *xi = x + 3 * i;
        int64_t k0 = nl->cstart[i], k1 = nl->cstart[i + 1], pos = k0;
        if (i < b - 1) {
            for (int64_t k = k0; k < k1; k++) {
                int j = cj[k - base];
                nl->sj[pos] = j;
                pos += dist2(xi, x + 3 * j) < rc2;
            }
        } else {
            for (int64_t k = k0; k < k1; k++) {
                int j = cj[k - base];
                if (dist2(xi, x + 3 * j) < rc2)
                    nl->sj[pos++] = j;
            }
        }
        nl->start[i] = pos - k0;
        tot += pos - k0;
        big = pos - k0 > big ? pos - k0 : big;
    }
    *longest = big;
    return tot;
}

/* Rows of block t into place from entry off, from the kept indices: the
 * pairs within r_inner from the front, the others from the back (without
 * a branch: which it is does not follow a pattern), with their distances. */
static void write_kept(struct neighbour_list *nl, const double *x,
                       double ri2, int t, int64_t off)
{
    for (int i = nl->blk_row[t]; i < nl->blk_row[t + 1]; i++) {
        int64_t len = nl->start[i], k0 = nl->cstart[i];
        nl->start[i] = off;
        const double *xi = x + 3 * i;
        int64_t front = off, back = off + len - 1;
        for (int64_t m = 0; m < len; m++) {
            int j = nl->sj[k0 + m];
            double d2 = dist2(xi, x + 3 * j);
            int in = d2 < ri2;
            int64_t pos = in ? front : back;
            front += in;
            back -= !in;
            nl->j[pos] = j;
            nl->r[pos] = sqrt(d2);
        }
        nl->mid[i] = front;
        off += len;
    }
}

/* Lean update (measure_r). Class of each candidate of rows [a, b) (block
 * t): 0 beyond rc2, 1 within, 2 within ri2 (<= rc2) too; the rows' pairs
 * within rc2 into start[i], the longest into *longest. */
static int64_t count_block(struct neighbour_list *nl, const double *x,
                           double rc2, double ri2, int t, int64_t *longest)
{
    const int a = nl->blk_row[t], b = nl->blk_row[t + 1];
    /* local pointers: stores through nl's would make every load of them
     * again (aliasing) */
    const int32_t *restrict cj = nl->buf[t] - nl->cstart[a];
    const int64_t *restrict cs = nl->cstart;
    uint8_t *restrict cls = nl->cls;
    int64_t tot = 0, big = 0;
    for (int i = a; i < b; i++) {
        const double *xi = x + 3 * i;
        int64_t len = 0;
        for (int64_t k = cs[i]; k < cs[i + 1]; k++) {
            double d2 = dist2(xi, x + 3 * cj[k]);
            uint8_t c = (uint8_t)((d2 < rc2) + (d2 < ri2));
            cls[k] = c;
            len += c != 0;
        }
        nl->start[i] = len;
        tot += len;
        big = len > big ? len : big;
    }
    *longest = big;
    return tot;
}

/* Rows of block t into place from entry off: the pairs within r_inner
 * from the front, the others from the back, in candidate order. Without a
 * branch (neither test follows a pattern): a candidate beyond rc goes to
 * the block's own slot past the entries, overwritten by the next one; the
 * blocks' slots TRASH entries apart, so that no two threads write one
 * cache line (that sharing made the update twice as slow). */
static void write_block(struct neighbour_list *nl, int t, int64_t off)
{
    const int a = nl->blk_row[t], b = nl->blk_row[t + 1];
    const int32_t *restrict cj = nl->buf[t] - nl->cstart[a];
    const int64_t *restrict cs = nl->cstart;
    const uint8_t *restrict cls = nl->cls;
    int32_t *restrict jj = nl->j;
    const int64_t trash = (int64_t)nl->cap_nnz - TRASH * (t + 1);
    for (int i = a; i < b; i++) {
        int64_t len = nl->start[i];
        nl->start[i] = off;
        int64_t front = off, back = off + len - 1;
        for (int64_t k = cs[i]; k < cs[i + 1]; k++) {
            int keep = cls[k] != 0, in = cls[k] == 2;
            int64_t pos = !keep ? trash : in ? front : back;
            front += keep & in;
            back -= keep & !in;
            jj[pos] = cj[k];
        }
        nl->mid[i] = front;
        off += len;
    }
}

int neighbour_update(struct neighbour_list *nl, const double *x)
{
    const int n = nl->n, nb = nl->nblk;
    const double rc2 = nl->rc * nl->rc;
    /* with no split every pair is "inner" */
    const double ri2 = nl->r_inner > 0 ? nl->r_inner * nl->r_inner : rc2;
    int64_t *cnt = nl->blk;
    if (nb < 1)
        return SIM_OK;   /* brute-force list: no candidates */
    int err = SIM_OK;
    int64_t longest = 0;
    /* by the build's blocks, whose candidates are in their buffers: one
     * block per thread when the thread count is the build's */
#pragma omp parallel
    {
#pragma omp for schedule(static) reduction(max : longest)
        for (int t = 0; t < nb; t++) {
            int64_t big;
            cnt[t] = nl->measure_r ? count_block(nl, x, rc2, ri2, t, &big)
                                   : select_block(nl, x, rc2, t, &big);
            longest = big > longest ? big : longest;
        }
#pragma omp single
        {
            int64_t tot = 0;
            for (int u = 0; u < nb; u++)
                tot += cnt[u];
            err = reserve_entries(nl, tot + TRASH * nb); /* + the slots */
            nl->start[n] = tot;
            nl->nnz = tot;
            nl->max_row = longest;
        }
        if (!err) {
#pragma omp for schedule(static)
            for (int t = 0; t < nb; t++) {
                int64_t off = 0;
                for (int u = 0; u < t; u++)
                    off += cnt[u];
                if (nl->measure_r)
                    write_block(nl, t, off);
                else
                    write_kept(nl, x, ri2, t, off);
            }
        }
    }
    return err ? err : keep_positions(nl, x);
}

static void prefix(struct neighbour_list *nl)
{
    int64_t acc = 0;
    nl->max_row = 0;
    for (int i = 0; i < nl->n; i++) {
        int64_t c = nl->start[i];
        nl->start[i] = acc;
        acc += c;
        nl->max_row = c > nl->max_row ? c : nl->max_row;
    }
    nl->start[nl->n] = acc;
    nl->nnz = acc;
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
    nl->measure_r = 0;  /* the reference stores its distances */
    nl->nnz_cand = 0;   /* no candidates: not for neighbour_update */
    nl->nblk = 0;
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
    for (int i = 0; i < n; i++) /* no split: every pair counts as inner */
        nl->mid[i] = nl->start[i + 1];
    return SIM_OK;
}

struct neighbour_list neighbour_inner(const struct neighbour_list *nl)
{
    struct neighbour_list v = *nl;
    v.end = nl->mid;
    return v;
}

void neighbour_free(struct neighbour_list *nl)
{
    free(nl->start);
    free(nl->j);
    free(nl->r);
    free(nl->xr);
    free(nl->cls);
    free(nl->sj);
    free(nl->rbuf);
    free(nl->cstart);
    free(nl->mid);
    for (int t = 0; t < nl->nbuf; t++)
        free(nl->buf[t]);
    free(nl->buf);
    free(nl->cap_buf);
    free(nl->blk);
    free(nl->blk_row);
    memset(nl, 0, sizeof *nl);
}
