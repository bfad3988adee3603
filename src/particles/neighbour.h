/*
 * neighbour.h — neighbour lists in CSR form, built once per step from a
 * cell grid and shared by every operator of the step.
 *
 * Row i holds every j != i with |x_j - x_i| < rc, in cell-traversal order,
 * and the distance r_ij. Particles in the grid's outside bucket have empty
 * rows and appear in no row. The list is rebuilt in place; storage grows
 * but is never released until neighbour_free(), so that the time loop does
 * not allocate once sizes have settled.
 *
 * neighbour_build_brute() is the O(n^2) reference the fast build is tested
 * against (SWIFT test27cells): same contract, rows in increasing j.
 */
#ifndef MPSDEM_PARTICLES_NEIGHBOUR_H
#define MPSDEM_PARTICLES_NEIGHBOUR_H

#include <stddef.h>
#include <stdint.h>

struct cell_grid;

struct neighbour_list {
    int n;            /* rows                                           */
    double rc;        /* cut-off radius [m]                             */
    int64_t nnz;      /* entries                                        */
    int64_t *start;   /* n+1: row i is [start[i], start[i+1])           */
    int32_t *j;       /* nnz neighbour indices                          */
    double *r;        /* nnz distances [m]                              */
    size_t cap_n, cap_nnz;
};

/* Build from a grid of the same positions (g->h >= rc is required). */
int neighbour_build(struct neighbour_list *nl, const struct cell_grid *g,
                    const double *x, double rc);

/* O(n^2) reference; particles with non-finite positions have no
 * neighbours. */
int neighbour_build_brute(struct neighbour_list *nl, int dim, const double *x,
                          int n, double rc);

void neighbour_free(struct neighbour_list *nl);

#endif
