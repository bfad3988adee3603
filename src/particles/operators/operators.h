/*
 * operators.h — particle operators on a CSR neighbour list, shared by every
 * solver (the `pop_` prefix: particle operator). They depend on positions,
 * a neighbour list (particles/neighbour.h), weights and fields only, never
 * on a solver's state; the MPS forms of Xie et al. (2025, eqs. 7-11, 15;
 * doc/theory.md A.3, A.5) are these sums with the normalisation
 * c = d/n0 or 2d/(n0 lambda) passed in (src/mps/operators.h wraps them).
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
#ifndef MPSDEM_PARTICLES_OPERATORS_H
#define MPSDEM_PARTICLES_OPERATORS_H

#include <stdint.h>

#include "particles/operators/weights.h"

struct neighbour_list;

/* A kernel w(r; re): 0 for r >= re (mps_kernel_ops.w is one). */
typedef double pop_weight_fn(double r, double re);

struct pop_lattice {
    double n0;      /* number density of an interior particle (eq. 7)     */
    double lambda;  /* eq. (11) [m^2]                                      */
    double f0;      /* |F| (eq. 15) on a flat free surface (A0-06)         */
    double n_surf;  /* number density of that surface particle             */
    int nnb;        /* neighbours of an interior particle                  */
};

/* Lattice constants for kernel w, dimension dim, spacing dp and radius re
 * [m]. The surface particle has the half-space z <= 0 (3-D) or y <= 0
 * (2-D) filled, the plane itself included. */
int pop_lattice_constants(pop_weight_fn *w, int dim, double dp, double re,
                          struct pop_lattice *out);

/* n_i = sum_j w_ij / eps_j  (eq. 7). */
void pop_number_density(const struct neighbour_list *nl,
                        const struct pop_weights *W, const double *inv_eps,
                        const uint8_t *rows, double *n);

/* grad phi_i = c sum_j (phi_j + phi_i) r_ij w_ij / (|r_ij|^2 eps_j)
 * (eq. 8 with c = d/n0); out is 3 values per particle (z = 0 in 2-D). */
void pop_gradient(const struct neighbour_list *nl, const struct pop_weights *W,
                  double c, const double *x, const double *phi,
                  const double *inv_eps, const uint8_t *rows, double *out);

/* Koshizuka and Oka (1996) eq. (11): the stable first-order form
 * grad phi_i = c sum_j (phi_j - phi_min,i) r_ij w_ij / (|r_ij|^2 eps_j),
 * phi_min,i the smallest phi among i and its neighbours within the radius:
 * every pair term is repulsive, so particles cannot cluster (tensile
 * instability), at the price of momentum conservation. */
void pop_gradient_pmin(const struct neighbour_list *nl,
                       const struct pop_weights *W, double c, const double *x,
                       const double *phi, const double *inv_eps,
                       const uint8_t *rows, double *out);

/* div u_i = c sum_j (u_j - u_i).r_ij w_ij / (|r_ij|^2 eps_j)
 * (eq. 9 with c = d/n0). */
void pop_divergence(const struct neighbour_list *nl,
                    const struct pop_weights *W, double c, const double *x,
                    const double *u, const double *inv_eps,
                    const uint8_t *rows, double *out);

/* lap phi_i = c sum_j (phi_j - phi_i) w_ij / eps_j (eq. 10 with
 * c = 2d/(n0 lambda)), for ncomp interleaved components (1 for pressure,
 * 3 for velocity). Whole rows: no view (neighbour_inner) is honoured. */
void pop_laplacian(const struct neighbour_list *nl,
                   const struct pop_weights *W, double c, int ncomp,
                   const double *phi, const double *inv_eps,
                   const uint8_t *rows, double *out);

/* F_i = c sum_j r_ij / |r_ij| w_ij / eps_j  (eq. 15 with c = d/n0),
 * 3 per particle; pop_surface_vector_row: the sum of row i alone,
 * unscaled (c = 1), for a caller that needs it for a few particles. */
void pop_surface_vector_row(const struct neighbour_list *nl,
                            const struct pop_weights *W, const double *x,
                            const double *inv_eps, int i, double F[3]);
void pop_surface_vector(const struct neighbour_list *nl,
                        const struct pop_weights *W, double c, const double *x,
                        const double *inv_eps, const uint8_t *rows,
                        double *out);

/* Concentration gradient and free-surface vector of particle i alone
 * (Lind et al. 2012 sect. 3 with a unit concentration, as written in
 * src/mps/stabiliser/shifting_lind2012.c; Xie et al. 2025 eq. 15), from the
 * positions, with the weights evaluated here for radius re:
 *   G = c sum_j r_ij / |r_ij|^2 w(|r_ij|) / eps_j,
 *   F =   sum_j r_ij / |r_ij|   w(|r_ij|) / eps_j   (unscaled),
 * over row i (0 < |r_ij| < re). n = -F/|F| is the outward surface normal.
 * For a caller that moves particles while it goes (distances re-measured). */
void pop_concentration_gradient(const struct neighbour_list *nl,
                                const double *x, const double *inv_eps,
                                pop_weight_fn *w, double re, double c, int i,
                                double G[3], double F[3]);

/* The Fickian shift of one particle (Lind et al. 2012 eqs. 20-24) from
 * its concentration gradient G and surface vector F
 * (pop_concentration_gradient): d = -D G; with `tangential` (a particle at
 * or next to the free surface) and |F| > 0 only its part across
 * n = -F/|F|; then capped at |d| <= cap. Shared by mpsFluid's `shifting
 * lind2012` and mlpgFluid's. */
void pop_fickian_shift(const double G[3], const double F[3], double D,
                       int tangential, double cap, double d[3]);

#endif
