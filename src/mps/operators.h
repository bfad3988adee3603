/*
 * operators.h — MPS particle operators on a CSR neighbour list
 * (Xie et al. 2025 eqs. 7-11, 15; doc/theory.md A.3, A.5).
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
 *
 * Lattice constants (n0, lambda, |F0|, surface number density) are
 * computed on the ideal lattice of spacing dp (simple cubic / square), with
 * the same kernel and radius as the operator that uses them (A.3).
 */
#ifndef MPSDEM_MPS_OPERATORS_H
#define MPSDEM_MPS_OPERATORS_H

#include <stdint.h>

struct neighbour_list;
struct mps_kernel_ops;

struct mps_lattice {
    double n0;      /* number density of an interior particle (eq. 7)     */
    double lambda;  /* eq. (11) [m^2]                                      */
    double f0;      /* |F| (eq. 15) on a flat free surface (A0-06)         */
    double n_surf;  /* number density of that surface particle             */
    int nnb;        /* neighbours of an interior particle                  */
};

/* Lattice constants for kernel k, dimension dim, spacing dp and radius re
 * [m]. The surface particle has the half-space z <= 0 (3-D) or y <= 0
 * (2-D) filled, the plane itself included. */
int mps_lattice_constants(const struct mps_kernel_ops *k, int dim, double dp,
                          double re, struct mps_lattice *out);

/* n_i = sum_j w_ij / eps_j  (eq. 7). */
void mps_number_density(const struct neighbour_list *nl, const double *w,
                        const double *inv_eps, const uint8_t *rows,
                        double *n);

/* grad phi_i = (d/n0) sum_j (phi_j + phi_i) r_ij w_ij / (|r_ij|^2 eps_j)
 * (eq. 8); out is 3 values per particle (z = 0 in 2-D). */
void mps_gradient(const struct neighbour_list *nl, const double *w, int dim,
                  double n0, const double *x, const double *phi,
                  const double *inv_eps, const uint8_t *rows, double *out);

/* Koshizuka and Oka (1996) eq. (11): the stable first-order form
 * grad phi_i = (d/n0) sum_j (phi_j - phi_min,i) r_ij w_ij / (|r_ij|^2 eps_j),
 * phi_min,i the smallest phi among i and its neighbours within the radius:
 * every pair term is repulsive, so particles cannot cluster (tensile
 * instability), at the price of momentum conservation. */
void mps_gradient_pmin(const struct neighbour_list *nl, const double *w,
                       int dim, double n0, const double *x, const double *phi,
                       const double *inv_eps, const uint8_t *rows,
                       double *out);

/* div u_i = (d/n0) sum_j (u_j - u_i).r_ij w_ij / (|r_ij|^2 eps_j)  (eq. 9). */
void mps_divergence(const struct neighbour_list *nl, const double *w, int dim,
                    double n0, const double *x, const double *u,
                    const double *inv_eps, const uint8_t *rows, double *out);

/* lap phi_i = (2d/(n0 lambda)) sum_j (phi_j - phi_i) w_ij / eps_j (eq. 10),
 * for ncomp interleaved components (1 for pressure, 3 for velocity). */
void mps_laplacian(const struct neighbour_list *nl, const double *w, int dim,
                   double n0, double lambda, int ncomp, const double *phi,
                   const double *inv_eps, const uint8_t *rows, double *out);

/* F_i = (d/n0) sum_j r_ij / |r_ij| w_ij / eps_j  (eq. 15), 3 per particle. */
void mps_surface_vector(const struct neighbour_list *nl, const double *w,
                        int dim, double n0, const double *x,
                        const double *inv_eps, const uint8_t *rows,
                        double *out);

#endif
