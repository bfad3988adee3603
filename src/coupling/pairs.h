/*
 * pairs.h — grain / MPS-particle pairs within the coupling radius r_e,s
 * (doc/theory.md A.10 step 1) and their weights w_s(r) of eq. (29).
 *
 * The pairs are a cross list of the particle layer
 * (particles/neighbour_cross.h: grains are cloud A, MPS particles cloud B,
 * cut-off r_e,s; r_e,s + skin in coupling_pairs_update); this file adds
 * the weights. The list is read twice, because eqs. (32), (33) and (36)
 * sum over the particles of one grain and eq. (31) over the grains of one
 * particle, and each loop is then a race-free gather under OpenMP:
 *   grain-major     gstart[k]..gstart[k+1]: particle gj[], weight gw[]
 *   particle-major  pstart[i]..pstart[i+1]: grain pk[],    weight pw[]
 * (gstart, gj, pstart and pk are the cross list's arrays.)
 * coupling_pairs_build() stores no pair with r >= r_e,s,
 * coupling_pairs_update() may keep some with weight 0. The particle-major
 * rows list grains in ascending order, and the content of the grain-major
 * rows does not depend on the number of threads, so every sum below is
 * reproducible run to run (a restart reproduces a continuous run bit for
 * bit when every step searches, i.e. skin 0).
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

#include "particles/neighbour_cross.h"

struct coupling_pairs {
    struct neighbour_cross X; /* the pairs (grains A, particles B)      */
    int dim;              /* 2 or 3                                     */
    double re;            /* coupling radius r_e,s [m]                  */
    int ng, np;           /* grains and MPS particles of the last build */
    int64_t npair;
    const int64_t *gstart;  /* ng+1 (X.astart)                          */
    const int32_t *gj;      /* npair particle indices (X.aj)            */
    double *gw;             /* npair weights w_s                        */
    const int64_t *pstart;  /* np+1 (X.bstart)                          */
    const int32_t *pk;      /* npair grain indices (X.bk)               */
    double *pw;             /* npair weights w_s                        */
    double *gwork;        /* 3 ng scratch for per-grain sums (reaction) */
    size_t cap_w, cap_gw;
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
