/*
 * csr.h — helpers for the CSR matrices of linsolve.h: checks, products, and
 * the jittered-lattice MPS Laplacian used by the tests and by ppeBench.
 */
#ifndef MPSDEM_LINSOLVE_CSR_H
#define MPSDEM_LINSOLVE_CSR_H

#include <stdint.h>

#include "linsolve/linsolve.h"

/* Check the structure (n > 0, rowptr non-decreasing from 0 to nnz, columns
 * in range), finite values, and a positive diagonal in every row (the PPE's
 * diagonal is a sum of positive weights, or 1 in a Dirichlet row).
 * diag (n, may be NULL) receives the diagonal. SIM_ERR_INPUT or
 * SIM_ERR_NUMERIC with the offending row in the message. */
int csr_validate(const struct csr_matrix *A, double *diag);

/* y = A x (OpenMP over rows). */
void csr_spmv(const struct csr_matrix *A, const double *x, double *y);

/* 1 when a_ij == a_ji within rtol*(|a_ij| + |a_ji|) for every stored entry
 * (a missing partner counts as 0), else 0; *row receives the first
 * offending row. A must be valid. */
int csr_is_symmetric(const struct csr_matrix *A, double rtol, int *row);

int csr_alloc(struct csr_matrix *A, int n, int64_t nnz);
/* Grow col and val of A to hold nnz entries (with a quarter spare, so a
 * matrix assembled every step reallocates seldom); *cap: their capacity,
 * updated. The entries kept are undefined. */
int csr_reserve(struct csr_matrix *A, size_t *cap, int64_t nnz);
/* Free the arrays of a matrix made by csr_alloc()/csr_lattice_ppe(). */
void csr_free(struct csr_matrix *A);

/*
 * The doc/libraries.md §2 benchmark matrix: particles on a square/cubic lattice
 * of spacing 1 with nside points per direction, each coordinate jittered by
 * U(-jitter, jitter) and then moved by U(-move, move); neighbours j with
 * r_ij < re; MPS weight w = re/r - 1; row i: a_ii = sum_j w_ij over all
 * neighbours, a_ij = -w_ij. The top layer (last coordinate index nside-1) is
 * the free surface: identity row, b = 0, couplings to it dropped on both
 * sides, so A is an SPD, irreducibly diagonally dominant M-matrix.
 * With porous != 0 every particle gets a porosity eps_j in [0.4, 1) and the
 * weights become w_ij/eps_j (doc/theory.md §A.4, Model B): a non-symmetric
 * matrix, still diagonally dominant.
 * b_i = 1 + 0.1 U(-1, 1) (0 on the surface), from rhs_seed.
 */
struct csr_lattice {
    int dim;            /* 2 or 3                                   */
    int nside;          /* particles per direction                  */
    double re;          /* effective radius, in lattice spacings    */
    double jitter;      /* 0.1 in the benchmark                     */
    double move;        /* 0, or 0.02 for the benchmark's "step 2"  */
    unsigned long seed; /* positions                                */
    unsigned long move_seed, rhs_seed;
    int porous;
};
int csr_lattice_ppe(const struct csr_lattice *L, struct csr_matrix *A,
                    double **b);

#endif
