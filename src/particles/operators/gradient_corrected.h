/*
 * gradient_corrected.h — corrective-matrix gradient (Khayyer and Gotoh
 * 2011 GC; Lind et al. 2012), shared by every solver (MPS:
 * `pressureGradient corrected;`). See gradient_corrected.c for the
 * equations.
 */
#ifndef MPSDEM_PARTICLES_GRADIENT_CORRECTED_H
#define MPSDEM_PARTICLES_GRADIENT_CORRECTED_H

#include <stdint.h>

#include "particles/operators/weights.h"

struct neighbour_list;

/* grad phi_i = C_i sum_j (phi_j - phi_i) r_ij w_ij / (|r_ij|^2 eps_j),
 * C_i the inverse moment matrix; exact for linear phi wherever C_i exists
 * (else the uncorrected form with normalisation c, MPS: d/n0). Other
 * arguments as pop_gradient (operators.h). */
void pop_gradient_corrected(const struct neighbour_list *nl,
                            const struct pop_weights *W, int dim, double c,
                            const double *x, const double *phi,
                            const double *inv_eps, const uint8_t *rows,
                            double *out);

/* Solve m g = v for the symmetric moment matrix m (row-major 3x3; the
 * z row and column unused when dim = 2); returns 0 (g untouched) when the
 * smallest eigenvalue is below 0.05 of the largest. */
int pop_moment_solve(int dim, const double m[9], const double v[3],
                     double g[3]);

#endif
