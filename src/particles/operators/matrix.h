/*
 * matrix.h — the sparsity pattern of an implicit neighbour-list operator
 * (a pressure Poisson equation of MPS, ISPH or MLPG_R), shared by every
 * solver; the values are the solver's (src/mps/ppe.c).
 */
#ifndef MPSDEM_PARTICLES_OPERATORS_MATRIX_H
#define MPSDEM_PARTICLES_OPERATORS_MATRIX_H

#include <stdint.h>

#include "particles/operators/weights.h"

struct neighbour_list;

/* Row pointers over the unknowns: particle i with unk[i] >= 0 is row
 * unk[i] (0 <= unk[i] < m, each once), holding its diagonal and one entry
 * per neighbour j with w[k] > 0 and unk[j] >= 0 (the diagonal first is
 * the caller's convention). rowptr has m + 1 entries; returns the number
 * of entries, rowptr[m]. Particles 0 .. n-1 of the list are visited. */
int64_t pop_matrix_rowptr(const struct neighbour_list *nl, int n,
                          const struct pop_weights *W, const int32_t *unk,
                          int m, int64_t *rowptr);

#endif
