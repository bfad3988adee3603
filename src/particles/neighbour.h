/*
 * neighbour.h — neighbour lists in CSR form, built once per step from a
 * cell grid and shared by every operator of the step.
 *
 * Row i holds every j != i with |x_j - x_i| < rc, in cell-traversal order
 * (split rows: those within r_inner in that order, then the others in the
 * reverse order), and the distance r_ij. Particles in the grid's outside
 * bucket have empty rows and appear in no row. The list is rebuilt in
 * place; storage grows but is never released until neighbour_free(), so
 * that the time loop does not allocate once sizes have settled.
 *
 * Skin (Verlet list): neighbour_build_skin() also keeps the candidate
 * pairs within rc + skin (indices only). neighbour_update() re-selects the
 * rows from them at new positions: every pair within rc, with its distance,
 * which is exact while no particle has moved more than skin/2 since the
 * build. The rows then hold only pairs within rc, so that the operators
 * never loop over the skin's zero-weight pairs; the update costs one pass
 * over the candidates, and allocates only when more pairs than ever
 * before lie within rc (the entries hold the pairs within rc, not the
 * candidates, with 1/8 room to grow).
 *
 * neighbour_build_brute() is the O(n^2) reference the fast build is tested
 * against (SWIFT test27cells): same contract, rows in increasing j.
 */
#ifndef MPSDEM_PARTICLES_NEIGHBOUR_H
#define MPSDEM_PARTICLES_NEIGHBOUR_H

#include <math.h>
#include <omp.h>
#include <stddef.h>
#include <stdint.h>

struct cell_grid;

struct neighbour_list {
    int n;            /* rows                                           */
    double rc;        /* cut-off radius [m]                             */
    int64_t nnz;      /* entries                                        */
    int64_t max_row;  /* entries of the longest row                     */
    int64_t *start;   /* n+1: row i is [start[i], start[i+1])           */
    int32_t *j;       /* nnz neighbour indices                          */
    double *r;        /* nnz distances [m]; NULL with measure_r         */
    size_t cap_n, cap_nnz;
    /* candidates within rc + skin (neighbour_build_skin) */
    double skin;      /* [m]                                            */
    int64_t nnz_cand; /* candidate pairs; nnz <= nnz_cand               */
    int64_t *cstart;  /* n+1: row i's candidates are [cstart[i],
                         cstart[i+1]), held by the buffer of its block  */
    int32_t *sj;      /* cap_sj: kept candidates (update scratch), or   */
    size_t cap_sj;
    uint8_t *cls;     /* cap_cls: with measure_r, their classes         */
    size_t cap_cls;
    int nblk;         /* blocks of rows of the last build (its threads) */
    int *blk_row;     /* nblk+1: first row of each block                */
    int32_t **buf;    /* per block: its candidates from cstart[blk_row] */
    size_t *cap_buf;
    int nbuf;         /* buffers allocated (>= nblk)                    */
    int64_t *blk;     /* nbuf: entries of each block                    */
    /* NULL, or one flag per particle read by the build: rows[i] == 0
     * leaves row i empty (i still appears in the rows of others), for
     * particles whose own sums nobody reads (MPS dummy layers). */
    const uint8_t *rows;
    /* Optional split of the rows, for operators of a smaller radius than
     * rc (MPS: number density and gradient at 2.1 dp in a list of the
     * Laplacian's 3.1 dp): with r_inner > 0 (set before a build) every
     * row holds its pairs with r < r_inner first, [start[i], mid[i]),
     * then the others. neighbour_build_brute() does not split: there
     * mid[i] is the row's end and the view holds whole rows. */
    double r_inner;
    int64_t *mid;     /* n                                              */
    /* NULL for a list; in a view made by neighbour_inner() the end of
     * each row, which operators read through neighbour_row_end(). */
    const int64_t *end;
    /* With measure_r set before the first build (and kept), no distances
     * are stored (r is NULL): neighbour_row_r() measures a row's again
     * from a copy of the positions of the last build or update, bit for
     * bit the values the list would have stored (mpsFluid: 8 bytes less
     * per pair, about a fifth of its peak memory in 3-D).
     * neighbour_build_brute() always stores them. */
    int measure_r;
    double *xr;       /* 3n: positions of the last build/update          */
    size_t cap_xr;
    double *rbuf;     /* rbuf_threads rows of cap_rbuf distances         */
    int64_t cap_rbuf;
    int rbuf_threads;
};

/* |b - a|^2, the one formula of the build, the update and
 * neighbour_row_r (so that their distances agree to the bit). */
static inline double neighbour_dist2(const double *a, const double *b)
{
    return (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1])
         + (b[2] - a[2]) * (b[2] - a[2]);
}

/* Distances of entries [k0, k1) of row i (d[k - k0]): the stored ones, or
 * measured into the calling thread's row of rbuf, valid until the thread
 * asks for the next row. */
static inline const double *neighbour_row_r(const struct neighbour_list *nl,
                                            int i, int64_t k0, int64_t k1)
{
    if (nl->r)
        return nl->r + k0;
    double *d = nl->rbuf + (size_t)omp_get_thread_num() * (size_t)nl->cap_rbuf;
    const double *xi = nl->xr + 3 * (size_t)i;
#pragma omp simd
    for (int64_t k = k0; k < k1; k++)
        d[k - k0] = sqrt(neighbour_dist2(xi, nl->xr + 3 * (size_t)nl->j[k]));
    return d;
}

/* End of row i: start[i + 1], or the view's end[i]. */
static inline int64_t neighbour_row_end(const struct neighbour_list *nl,
                                        int i)
{
    return nl->end ? nl->end[i] : nl->start[i + 1];
}

/* A view of nl whose rows hold only the pairs within nl->r_inner (the
 * whole rows when nl has no split). It shares nl's arrays: make it again
 * after every build or update. */
struct neighbour_list neighbour_inner(const struct neighbour_list *nl);

/* Build from a grid of the same positions (g->h >= rc / 2 is required). */
int neighbour_build(struct neighbour_list *nl, const struct cell_grid *g,
                    const double *x, double rc);

/* The same with candidates within rc + skin for neighbour_update()
 * (g->h >= (rc + skin) / 2). */
int neighbour_build_skin(struct neighbour_list *nl, const struct cell_grid *g,
                         const double *x, double rc, double skin);

/* Rows from the candidates at positions x (see above); the entries grow
 * when more pairs than ever before are within rc. */
int neighbour_update(struct neighbour_list *nl, const double *x);

/* O(n^2) reference; particles with non-finite positions have no
 * neighbours. It keeps no candidates (no neighbour_update). */
int neighbour_build_brute(struct neighbour_list *nl, int dim, const double *x,
                          int n, double rc);

/* Room in *buf for nbuf x *threads rows of *cap doubles: *cap above the
 * list's longest row, *threads at least omp_get_max_threads() (per-thread
 * rows of the operators: neighbour_row_r, particles/operators/weights.h). */
int neighbour_grow_rows(const struct neighbour_list *nl, int nbuf,
                        double **buf, int64_t *cap, int *threads);

void neighbour_free(struct neighbour_list *nl);

#endif
