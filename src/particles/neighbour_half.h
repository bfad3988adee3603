/*
 * neighbour_half.h — half self lists with per-pair history: pairs i < j
 * with |x_i - x_j| < R_i + R_j + skin (R: a radius per point), searched
 * through the cell grid (cells.h), reused until some point has moved more
 * than half the skin since the build (Verlet 1967). What DEM needs: one
 * entry per contact, and contact history (tangential springs) that
 * survives rebuilds.
 *
 * Rows are in CSR form with partners sorted ascending, so that the list
 * does not depend on the grid or the number of threads, and per-pair data
 * is carried from an old list to the new one by a merge
 * (neighbour_half_carry).
 *
 * Positions are interleaved x y z. A non-finite position is an error
 * (SIM_ERR_NUMERIC): every point must be somewhere.
 */
#ifndef MPSDEM_PARTICLES_NEIGHBOUR_HALF_H
#define MPSDEM_PARTICLES_NEIGHBOUR_HALF_H

#include <stddef.h>
#include <stdint.h>

#include "particles/cells.h"

struct neighbour_half {
    size_t n;          /* points at the last build                       */
    size_t *start;     /* n + 1 row offsets                              */
    uint32_t *j;       /* npairs partners, j > i, ascending per row      */
    size_t npairs, cap;
    double skin;       /* [m]                                            */
    double *x0;        /* 3n positions at the build                      */
    size_t ncap;       /* capacity of per-point arrays                   */
    struct cell_grid grid;
    long nbuilds;
};

void neighbour_half_init(struct neighbour_half *nl, double skin);
void neighbour_half_free(struct neighbour_half *nl);

/* Build from positions x (3n) and radii r. */
int neighbour_half_build(struct neighbour_half *nl, size_t n, const double *x,
                         const double *r);

/* O(n^2) reference with the same contract (tests). */
int neighbour_half_build_brute(struct neighbour_half *nl, size_t n,
                               const double *x, const double *r);

/* Largest displacement since the build [m]. */
double neighbour_half_max_displacement(const struct neighbour_half *nl,
                                       const double *x);

/* Non-zero when a rebuild is due (some point moved more than skin/2, or
 * the count changed). */
int neighbour_half_stale(const struct neighbour_half *nl, size_t n,
                         const double *x);

/* Carry per-pair data of width w (doubles) from an old list (ostart, oj,
 * on rows, indices in the new numbering, rows sorted) to the list nl:
 * pairs present in both keep their values, new pairs get zeros. */
void neighbour_half_carry(const struct neighbour_half *nl,
                          const size_t *ostart, const uint32_t *oj, size_t on,
                          const double *oval, int w, double *val);

#endif
