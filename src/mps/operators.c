/*
 * operators.c — the MPS operators of Xie et al. (2025) eqs. (7)-(11) and
 * (15) (doc/theory.md A.3, A.5) as the shared particle operators
 * (src/particles/operators/operators.c, where the equations are) with the
 * MPS normalisations:
 *
 *   (8), (9), (15)  c = d/n0
 *   (10)            c = 2d/(n0 lambda)
 *
 * and the lattice constants of the MPS kernel (A.3).
 */
#include "mps/operators.h"

#include "mps/kernel/kernel.h"

int mps_lattice_constants(const struct mps_kernel_ops *k, int dim, double dp,
                          double re, struct pop_lattice *out)
{
    return pop_lattice_constants(k->w, dim, dp, re, out);
}

void mps_number_density(const struct neighbour_list *nl,
                        const struct pop_weights *W, const double *inv_eps,
                        const uint8_t *rows, double *n)
{
    pop_number_density(nl, W, inv_eps, rows, n);
}

void mps_gradient(const struct neighbour_list *nl, const struct pop_weights *W,
                  int dim, double n0, const double *x, const double *phi,
                  const double *inv_eps, const uint8_t *rows, double *out)
{
    pop_gradient(nl, W, dim / n0, x, phi, inv_eps, rows, out);
}

void mps_gradient_pmin(const struct neighbour_list *nl,
                       const struct pop_weights *W, int dim, double n0,
                       const double *x, const double *phi,
                       const double *inv_eps, const uint8_t *rows, double *out)
{
    pop_gradient_pmin(nl, W, dim / n0, x, phi, inv_eps, rows, out);
}

void mps_gradient_corrected(const struct neighbour_list *nl,
                            const struct pop_weights *W, int dim, double n0,
                            const double *x, const double *phi,
                            const double *inv_eps, const uint8_t *rows,
                            double *out)
{
    pop_gradient_corrected(nl, W, dim, dim / n0, x, phi, inv_eps, rows, out);
}

void mps_divergence(const struct neighbour_list *nl,
                    const struct pop_weights *W, int dim, double n0,
                    const double *x, const double *u, const double *inv_eps,
                    const uint8_t *rows, double *out)
{
    pop_divergence(nl, W, dim / n0, x, u, inv_eps, rows, out);
}

void mps_laplacian(const struct neighbour_list *nl,
                   const struct pop_weights *W, int dim, double n0,
                   double lambda, int ncomp, const double *phi,
                   const double *inv_eps, const uint8_t *rows, double *out)
{
    pop_laplacian(nl, W, 2.0 * dim / (n0 * lambda), ncomp, phi, inv_eps,
                  rows, out);
}

void mps_surface_vector(const struct neighbour_list *nl,
                        const struct pop_weights *W, int dim, double n0,
                        const double *x, const double *inv_eps,
                        const uint8_t *rows, double *out)
{
    pop_surface_vector(nl, W, dim / n0, x, inv_eps, rows, out);
}
