/*
 * pairs.h — grain / MPS-particle pairs within the coupling radius r_e,s
 * (doc/theory.md A.10 step 1, "MPS-DEM (cells of r_e,s)").
 *
 * The MPS neighbour list holds particle-particle pairs only, so the
 * coupling keeps its own list, built by binning the MPS particles into
 * cells of size r_e,s/2 over the box of the grains (expanded by r_e,s;
 * r_e,s + skin in coupling_pairs_update),
 * with a copy of their positions in cell order so that the candidates of
 * a grain are read as 25 contiguous runs (a 5x5x5-cell stencil covers
 * 2.5^3 = 15.6 r_e,s^3 against 27 r_e,s^3 for cells of r_e,s): work is
 * proportional to the particles near grains, not to the domain.
 *
 * The list is stored twice, because eqs. (32), (33) and (36) sum over the
 * particles of one grain and eq. (31) over the grains of one particle, and
 * each loop is then a race-free gather under OpenMP:
 *   grain-major     gstart[k]..gstart[k+1]: particle gj[], weight gw[]
 *   particle-major  pstart[i]..pstart[i+1]: grain pk[],    weight pw[]
 * Weights are w_s(r) of eq. (29); coupling_pairs_build() stores no pair
 * with r >= r_e,s, coupling_pairs_update() may keep some with weight 0.
 * The particle-major rows list grains in ascending order, and the content
 * of the grain-major rows does not depend on the number of threads, so
 * every sum below is reproducible run to run (a restart reproduces a
 * continuous run bit for bit when every step searches, i.e. skin 0).
 *
 * Positions are interleaved x[3*i] (z = 0 in 2-D). A particle with a
 * non-finite position has no pairs; a grain with one is an error (the DEM
 * side blew up and should say so).
 *
 * Memory: the struct owns every array. A search grows them when it needs
 * more room and otherwise allocates nothing, so after the first steps a
 * run does no allocation here.
 */
#ifndef MPSDEM_COUPLING_PAIRS_H
#define MPSDEM_COUPLING_PAIRS_H

#include <stddef.h>
#include <stdint.h>

struct coupling_pair_buf {
    int32_t *j;
    double *w;
    size_t n, cap;
};

struct coupling_pairs {
    int dim;              /* 2 or 3                                     */
    double re;            /* coupling radius r_e,s [m]                  */
    double rs;            /* search radius: re, or re + skin (update)   */
    int ng, np;           /* grains and MPS particles of the last build */
    int64_t npair;
    int64_t *gstart;      /* ng+1                                       */
    int32_t *gj;          /* npair particle indices                     */
    double *gw;           /* npair weights w_s                          */
    int64_t *pstart;      /* np+1                                       */
    int32_t *pk;          /* npair grain indices                        */
    double *pw;           /* npair weights w_s                          */
    /* work storage: cells of the grain box */
    double lo[3], h;      /* box origin and cell size                   */
    int nc[3], reach;     /* cells per axis; stencil half-width          */
    int64_t *cstart;      /* ncell+1                                    */
    int32_t *cidx;        /* binned particles, cell by cell             */
    double *xs;           /* their positions in the same order (3 each) */
    int32_t *pcell;       /* cell of each particle, -1 outside the box  */
    double *gwork;        /* 3 ng scratch for per-grain sums (reaction) */
    int64_t *pmap;        /* npair: grain-major entry of each particle-
                           * major entry (weight refresh)               */
    double *xg0, *xp0;    /* positions at the last search (update)      */
    double skin;          /* skin of the last search; < 0: none kept    */
    size_t cap_g0, cap_p0;
    size_t cap_g, cap_gw, cap_p, cap_pair, cap_cell;
    /* per-thread storage of the parallel build (one pass over the cells,
     * then a transpose by contiguous grain ranges) */
    int nthr;                       /* threads the storage is sized for */
    struct coupling_pair_buf *tbuf; /* nthr row buffers                  */
    int32_t *tcount;                /* nthr x np counts, then cursors    */
    size_t cap_tcount;
};

/* Build the pairs of ng grains at xg and np MPS particles at xp with the
 * coupling radius re [m] in dim dimensions (cell search). P must be zeroed
 * before its first use. */
int coupling_pairs_build(struct coupling_pairs *P, int dim, double re,
                         int ng, const double *xg, int np, const double *xp);

/* The same pairs by an O(ng np) loop (reference for tests). */
int coupling_pairs_build_brute(struct coupling_pairs *P, int dim, double re,
                               int ng, const double *xg, int np,
                               const double *xp);

/*
 * Verlet-skin variant for the solvers' time loop: the search keeps every
 * pair within re + skin (weights are w_s(r; re), hence 0 beyond re) and
 * later calls only refresh the weights of those candidates, as long as the
 * largest grain displacement plus the largest particle displacement since
 * the search stays below skin (then no pair can have entered the kernel
 * radius). A change of ng, np, dim, re or skin forces a search.
 * *searched (may be NULL) is set to 1 when a search ran, else 0.
 * Sums over a refreshed list equal those over a fresh build to round-off
 * (the order of the terms is that of the last search).
 */
int coupling_pairs_update(struct coupling_pairs *P, int dim, double re,
                          double skin, int ng, const double *xg, int np,
                          const double *xp, int *searched);

/* Make the next coupling_pairs_update() search. */
void coupling_pairs_invalidate(struct coupling_pairs *P);

void coupling_pairs_free(struct coupling_pairs *P);

#endif
