/*
 * neighbour_cross.h — cross lists between two clouds: the pairs (k, i) of
 * a point k of cloud A (rows; DEM grains for the coupling) and a point i
 * of cloud B (MPS particles) with |x_i - x_k| < rc, searched through the
 * cell grid (cells.h).
 *
 * Only the box around A (expanded by the search radius) is binned, in
 * cells of rc/2 (larger when the box would hold more than a few cells per
 * point), so a small cloud A in a large cloud B pays for the points of B
 * near A, not for the domain.
 *
 * The list is stored twice, so that a sum over the B points of an A point
 * and a sum over the A points of a B point are both race-free gathers:
 *   A-major  astart[k]..astart[k+1]: B point aj[], distance ar[]
 *   B-major  bstart[i]..bstart[i+1]: A point bk[], A-major entry bmap[]
 * A-major rows are in cell-traversal order (z, y, x, then index), B-major
 * rows list A points in ascending order; neither depends on the number of
 * threads, so every sum over them is reproducible run to run.
 *
 * Positions are interleaved x[3*i] (z = 0 in 2-D). A point of B with a
 * non-finite position has no pairs; a point of A with one is an error
 * (SIM_ERR_NUMERIC).
 *
 * Memory: the struct owns every array; a search grows them when it needs
 * more room and otherwise allocates nothing. Zero the struct before its
 * first use.
 */
#ifndef MPSDEM_PARTICLES_NEIGHBOUR_CROSS_H
#define MPSDEM_PARTICLES_NEIGHBOUR_CROSS_H

#include <stddef.h>
#include <stdint.h>

#include "particles/cells.h"

struct neighbour_cross_buf {
    int32_t *j;
    double *r;
    size_t n, cap;
};

struct neighbour_cross {
    int dim;              /* 2 or 3                                     */
    double rc;            /* cut-off [m]                                */
    double rs;            /* search radius: rc, or rc + skin (update)   */
    int na, nb;           /* points of A and B at the last build        */
    int64_t npair;
    int64_t *astart;      /* na+1                                       */
    int32_t *aj;          /* npair B indices                            */
    double *ar;           /* npair distances [m]                        */
    int64_t *bstart;      /* nb+1                                       */
    int32_t *bk;          /* npair A indices                            */
    int64_t *bmap;        /* npair: A-major entry of each B-major entry */
    /* work storage: B binned in the box of A */
    struct cell_grid grid;
    double *xs;           /* binned B positions in cell order (3 each)  */
    double *xa0, *xb0;    /* positions at the last search (update)      */
    double skin;          /* skin of the last search; < 0: none kept    */
    size_t cap_a, cap_b, cap_xs, cap_pair, cap_a0, cap_b0;
    /* per-thread storage of the parallel build (one pass over the cells,
     * then a transpose by contiguous ranges of A) */
    int nthr;
    struct neighbour_cross_buf *tbuf;
    int32_t *tcount;      /* nthr x nb counts, then cursors             */
    size_t cap_tcount;
};

/* Pairs of na points of A at xa and nb points of B at xb within rc, in
 * dim dimensions (cell search). */
int neighbour_cross_build(struct neighbour_cross *X, int dim, double rc,
                          int na, const double *xa, int nb, const double *xb);

/* The same pairs by an O(na nb) loop (A-major rows in ascending B order;
 * reference for tests). */
int neighbour_cross_build_brute(struct neighbour_cross *X, int dim,
                                double rc, int na, const double *xa, int nb,
                                const double *xb);

/*
 * Verlet-skin variant: the search keeps every pair within rc + skin, and
 * later calls only recompute the distances of those candidates while the
 * largest displacement in A plus the largest in B since the search stays
 * below skin (then no pair can have come within rc). A change of na, nb,
 * dim, rc or skin forces a search. *searched (may be NULL) is set to 1
 * when a search ran, else 0. The order of the entries is that of the last
 * search.
 */
int neighbour_cross_update(struct neighbour_cross *X, int dim, double rc,
                           double skin, int na, const double *xa, int nb,
                           const double *xb, int *searched);

/* Make the next neighbour_cross_update() search. */
void neighbour_cross_invalidate(struct neighbour_cross *X);

void neighbour_cross_free(struct neighbour_cross *X);

#endif
