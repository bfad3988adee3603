/*
 * operators.h — the MPS operators (Xie et al. 2025 eqs. 7-11, 15;
 * doc/theory.md A.3, A.5): the shared particle operators of
 * src/particles/operators with the MPS normalisations d/n0 and
 * 2d/(n0 lambda) and the MPS lattice constants.
 *
 * Every operator takes the weights of its own radius as an array aligned
 * with the neighbour list (w[k] for entry k of nl, zero beyond that
 * operator's r_e), so that one neighbour list built with the largest r_e
 * serves all operators of a step.
 *
 * Porosity hook: `inv_eps` is the per-particle 1/eps_j of the locally
 * averaged equations (eqs. 7-10, 15 weight every neighbour sum by 1/eps_j).
 * A single-phase case passes NULL and nothing is read or allocated.
 *
 * `rows` (may be NULL = every row) restricts the output to particles with
 * rows[i] != 0; other outputs are left untouched.
 */
#ifndef MPSDEM_MPS_OPERATORS_H
#define MPSDEM_MPS_OPERATORS_H

#include <stdint.h>

#include "particles/operators/gradient_corrected.h"
#include "particles/operators/operators.h"

struct mps_kernel_ops;

/* Lattice constants for kernel k (pop_lattice_constants: n0, lambda,
 * |F0|, surface number density, neighbours). */
int mps_lattice_constants(const struct mps_kernel_ops *k, int dim, double dp,
                          double re, struct pop_lattice *out);

/* n_i = sum_j w_ij / eps_j  (eq. 7). */
void mps_number_density(const struct neighbour_list *nl,
                        const struct pop_weights *W, const double *inv_eps,
                        const uint8_t *rows, double *n);

/* eq. (8), (d/n0) sum_j (phi_j + phi_i) ...; 3 values per particle. */
void mps_gradient(const struct neighbour_list *nl, const struct pop_weights *W,
                  int dim, double n0, const double *x, const double *phi,
                  const double *inv_eps, const uint8_t *rows, double *out);

/* Koshizuka and Oka (1996) eq. (11), the p_min form. */
void mps_gradient_pmin(const struct neighbour_list *nl,
                       const struct pop_weights *W, int dim, double n0,
                       const double *x, const double *phi,
                       const double *inv_eps, const uint8_t *rows,
                       double *out);

/* Corrective matrix (Khayyer and Gotoh 2011; gradient_corrected.h). */
void mps_gradient_corrected(const struct neighbour_list *nl,
                            const struct pop_weights *W, int dim, double n0,
                            const double *x, const double *phi,
                            const double *inv_eps, const uint8_t *rows,
                            double *out);

/* eq. (9). */
void mps_divergence(const struct neighbour_list *nl,
                    const struct pop_weights *W, int dim, double n0,
                    const double *x, const double *u, const double *inv_eps,
                    const uint8_t *rows, double *out);

/* eq. (10), ncomp interleaved components (1 pressure, 3 velocity). */
void mps_laplacian(const struct neighbour_list *nl,
                   const struct pop_weights *W, int dim, double n0,
                   double lambda, int ncomp, const double *phi,
                   const double *inv_eps, const uint8_t *rows, double *out);

/* eq. (15), 3 per particle. */
void mps_surface_vector(const struct neighbour_list *nl,
                        const struct pop_weights *W, int dim, double n0,
                        const double *x, const double *inv_eps,
                        const uint8_t *rows, double *out);

#endif
