/*
 * interp.h — fluid fields at the grain centres (Xie et al. 2025 eqs. 32-33
 * and, for Model A, the pressure gradient of doc/theory.md A0-14).
 *
 *   eps_k = sum_i eps_i w_s(|r_ki|) / sum_i w_s(|r_ki|)               (32)
 *   u_k   = sum_i u_i   w_s(|r_ki|) / sum_i w_s(|r_ki|)               (33)
 *   gradP_k = the same Shepard average of the consistent MPS gradient
 *     <grad P>_i = (d/n0) sum_j (P_j - P_i) r_ij w(|r_ij|)/(|r_ij|^2 eps_j)
 *
 * A grain with no contributing particle in reach ("dry": above the free
 * surface, or out of the fluid) has wsum = 0; it gets eps_k = 1, u_k = 0,
 * gradP_k = 0 and wet[k] = 0, and coupling_grain_force() gives it no
 * hydrodynamic force at all (the paper does not say; a grain in air must
 * not feel water drag or water buoyancy).
 */
#ifndef MPSDEM_COUPLING_INTERP_H
#define MPSDEM_COUPLING_INTERP_H

#include <stdint.h>

#include "particles/operators/weights.h"

struct coupling_pairs;

/*
 * Shepard average to every grain of an ncomp-component field f given at the
 * MPS particles (f[ncomp*i + c]). mask (may be NULL = all) selects the
 * particles that contribute (doc/theory.md A0-13 default: fluid and wall, not
 * dummy). Grains with no contributor get def[c] (def may be NULL = 0).
 * wsum (may be NULL) receives sum_i w_s per grain.
 */
void coupling_shepard(const struct coupling_pairs *P, int ncomp,
                      const double *f, const uint8_t *mask, const double *def,
                      double *out, double *wsum);

/* Per-grain fluid fields, arrays owned by the caller (ng or 3 ng); all
 * but gradp are required. */
struct coupling_grain_fields {
    double *eps;    /* ng   porosity at the centre, eq. (32)           */
    double *u;      /* 3 ng intrinsic fluid velocity [m/s], eq. (33)   */
    double *gradp;  /* 3 ng grad P [Pa/m] (Model A), or NULL           */
    uint8_t *wet;   /* ng   1 when some particle contributed           */
};

/*
 * Fill out from the MPS fields of the last pair build: eps (np), intrinsic
 * velocity u (3 np) and, when both gradp_p and out->gradp are not NULL,
 * the consistent pressure gradient at the particles (3 np).
 */
void coupling_interp_grains(const struct coupling_pairs *P,
                            const uint8_t *mask, const double *eps,
                            const double *u, const double *gradp_p,
                            struct coupling_grain_fields *out);

/* The same in two halves, for a cloud spread over ranks (particles/
 * halo.h): per grain the weighted sums over the particles of mask,
 * COUPLING_SUMS values (sum w, sum w eps, sum w u, sum w gradp), which the
 * caller adds over the ranks; then the fields from those sums. */
enum { COUPLING_SUMS = 8 };
void coupling_interp_sums(const struct coupling_pairs *P,
                          const uint8_t *mask, const double *eps,
                          const double *u, const double *gradp_p,
                          double *sums);
void coupling_interp_finish(int ng, const double *sums, int with_gradp,
                            struct coupling_grain_fields *out);

/*
 * Consistent (zeroth-order exact) MPS gradient at particles, for A0-14,
 * over the whole rows of a neighbour list with the weights W of the
 * gradient radius (stored or computed from the list's distances,
 * particles/operators/weights.h). inv_eps may be NULL (eps = 1);
 * rows may be NULL (all). out is 3 per particle (z = 0 in 2-D).
 */
void coupling_gradient_consistent(const struct neighbour_list *nl,
                                  const struct pop_weights *W, int dim,
                                  double n0, const double *x, const double *p,
                                  const double *inv_eps, const uint8_t *rows,
                                  double *out);

#endif
