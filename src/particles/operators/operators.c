/*
 * operators.c — particle operators in the MPS forms of Xie et al. (2025)
 * eqs. (7)-(11) and (15) (doc/theory.md A.3, A.5), on a CSR neighbour list,
 * with the normalisation (d/n0, 2d/(n0 lambda)) passed in as c:
 *
 *   (7)  <n>_i       = sum_{j!=i} w_ij / eps_j
 *   (8)  <grad p>_i  = (d/n0) sum (p_j + p_i) r_ij / |r_ij|^2 w_ij / eps_j
 *   (9)  <div u>_i   = (d/n0) sum (u_j - u_i).r_ij / |r_ij|^2 w_ij / eps_j
 *   (10) <lap p>_i   = (2d/(n0 lambda)) sum (p_j - p_i) w_ij / eps_j
 *   (11) lambda      = sum w |r|^2 / sum w     (interior lattice particle)
 *   (15) <F>_i       = (d/n0) sum r_ij / |r_ij| w_ij / eps_j
 *
 * with r_ij = r_j - r_i. (8) is the momentum-conserving (p_i + p_j) form: it
 * is exact for a linear field on a symmetric lattice but not zeroth-order
 * consistent (a constant field gives a force towards the fluid at a free
 * surface), which is what keeps particles apart (doc/theory.md E1-05).
 * A zero distance (coincident particles) contributes nothing to the
 * direction-dependent sums: its direction is undefined.
 *
 * The concentration gradient of particle shifting (Lind et al. 2012,
 * J. Comput. Phys. 231, 1499, eqs. 20-24) is the sum of (8) for a unit
 * concentration without the pair factor, G = c sum r_ij/|r_ij|^2 w_ij/eps_j,
 * evaluated per particle from the positions.
 */
#include "particles/operators/operators.h"

#include <math.h>
#include <stddef.h>

#include "core/error.h"
#include "particles/neighbour.h"

#define IEPS(j) (inv_eps ? inv_eps[j] : 1.0)

int pop_lattice_constants(pop_weight_fn *wf, int dim, double dp, double re,
                          struct pop_lattice *out)
{
    if ((dim != 2 && dim != 3) || !(dp > 0) || !(re > dp))
        return sim_error(SIM_ERR_INPUT, "lattice constants need dim 2|3 and "
                         "r_e > dp (got r_e = %g, dp = %g)", re, dp);
    int m = (int)ceil(re / dp) + 1, mz = dim == 3 ? m : 0;
    double n0 = 0, wr2 = 0, ns = 0, F[3] = { 0, 0, 0 };
    int nnb = 0;
    for (int a = -m; a <= m; a++)
        for (int b = -m; b <= m; b++)
            for (int c = -mz; c <= mz; c++) {
                if (!a && !b && !c)
                    continue;
                double v[3] = { a * dp, b * dp, c * dp };
                double r = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
                double w = wf(r, re);
                if (w <= 0)
                    continue;
                nnb++;
                n0 += w;
                wr2 += w * r * r;
                /* the vertical axis is the last one */
                if ((dim == 3 ? c : b) <= 0) {
                    ns += w;
                    for (int q = 0; q < 3; q++)
                        F[q] += v[q] / r * w;
                }
            }
    out->n0 = n0;
    out->lambda = wr2 / n0;
    out->n_surf = ns;
    out->f0 = dim / n0 * sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]);
    out->nnb = nnb;
    return SIM_OK;
}

void pop_number_density(const struct neighbour_list *nl,
                        const struct pop_weights *W, const double *inv_eps,
                        const uint8_t *rows, double *n)
{
#pragma omp parallel for schedule(static)
    for (int i = 0; i < nl->n; i++) {
        if (rows && !rows[i])
            continue;
        double s = 0;
        const int64_t k0 = nl->start[i], k1 = neighbour_row_end(nl, i);
        const double *w = pop_weights_of(W, nl, i, k0, k1);
        for (int64_t k = k0; k < k1; k++)
            s += w[k - k0] * IEPS(nl->j[k]);
        n[i] = s;
    }
}

void pop_gradient(const struct neighbour_list *nl, const struct pop_weights *W,
                  double c, const double *x, const double *phi,
                  const double *inv_eps, const uint8_t *rows, double *out)
{
#pragma omp parallel for schedule(static)
    for (int i = 0; i < nl->n; i++) {
        if (rows && !rows[i])
            continue;
        double g[3] = { 0, 0, 0 };
        const double *xi = x + 3 * i;
        const int64_t k0 = nl->start[i], k1 = neighbour_row_end(nl, i);
        const double *rr = neighbour_row_r(nl, i, k0, k1);
        const double *w = pop_weights_row(W, k0, rr, k1 - k0);
        for (int64_t k = k0; k < k1; k++) {
            int j = nl->j[k];
            double r = rr[k - k0], wk = w[k - k0];
            if (wk == 0 || r == 0)
                continue;
            double f = (phi[j] + phi[i]) * wk * IEPS(j) / (r * r);
            for (int q = 0; q < 3; q++)
                g[q] += f * (x[3 * j + q] - xi[q]);
        }
        for (int q = 0; q < 3; q++)
            out[3 * i + q] = c * g[q];
    }
}

void pop_gradient_pmin(const struct neighbour_list *nl,
                       const struct pop_weights *W, double c, const double *x,
                       const double *phi, const double *inv_eps,
                       const uint8_t *rows, double *out)
{
#pragma omp parallel for schedule(static)
    for (int i = 0; i < nl->n; i++) {
        if (rows && !rows[i])
            continue;
        double g[3] = { 0, 0, 0 }, pmin = phi[i];
        const double *xi = x + 3 * i;
        const int64_t k0 = nl->start[i], k1 = neighbour_row_end(nl, i);
        const double *rr = neighbour_row_r(nl, i, k0, k1);
        const double *w = pop_weights_row(W, k0, rr, k1 - k0);
        for (int64_t k = k0; k < k1; k++)
            if (w[k - k0] > 0)
                pmin = fmin(pmin, phi[nl->j[k]]);
        for (int64_t k = k0; k < k1; k++) {
            int j = nl->j[k];
            double r = rr[k - k0], wk = w[k - k0];
            if (wk == 0 || r == 0)
                continue;
            double f = (phi[j] - pmin) * wk * IEPS(j) / (r * r);
            for (int q = 0; q < 3; q++)
                g[q] += f * (x[3 * j + q] - xi[q]);
        }
        for (int q = 0; q < 3; q++)
            out[3 * i + q] = c * g[q];
    }
}

void pop_divergence(const struct neighbour_list *nl,
                    const struct pop_weights *W, double c, const double *x,
                    const double *u, const double *inv_eps,
                    const uint8_t *rows, double *out)
{
#pragma omp parallel for schedule(static)
    for (int i = 0; i < nl->n; i++) {
        if (rows && !rows[i])
            continue;
        double s = 0;
        const double *xi = x + 3 * i, *ui = u + 3 * i;
        const int64_t k0 = nl->start[i], k1 = neighbour_row_end(nl, i);
        const double *rr = neighbour_row_r(nl, i, k0, k1);
        const double *w = pop_weights_row(W, k0, rr, k1 - k0);
        for (int64_t k = k0; k < k1; k++) {
            int j = nl->j[k];
            double r = rr[k - k0], wk = w[k - k0];
            if (wk == 0 || r == 0)
                continue;
            double d = 0;
            for (int q = 0; q < 3; q++)
                d += (u[3 * j + q] - ui[q]) * (x[3 * j + q] - xi[q]);
            s += d * wk * IEPS(j) / (r * r);
        }
        out[i] = c * s;
    }
}

/* One row of (10) for nc components; nc a constant after inlining, so
 * that the component loop unrolls, and the porosity test leaves the loop. */
static inline void laplacian_row(const struct neighbour_list *nl,
                                 const struct pop_weights *W, int nc,
                                 const double *phi, const double *inv_eps,
                                 int i, double *s)
{
    const int64_t k0 = nl->start[i], k1 = nl->start[i + 1];
    const double *w = pop_weights_of(W, nl, i, k0, k1);
    const double *pi = phi + (size_t)nc * i;
    if (inv_eps)
        for (int64_t k = k0; k < k1; k++) {
            int j = nl->j[k];
            double f = w[k - k0] * inv_eps[j];
            for (int q = 0; q < nc; q++)
                s[q] += (phi[(size_t)nc * j + q] - pi[q]) * f;
        }
    else
        for (int64_t k = k0; k < k1; k++) {
            int j = nl->j[k];
            for (int q = 0; q < nc; q++)
                s[q] += (phi[(size_t)nc * j + q] - pi[q]) * w[k - k0];
        }
}

void pop_laplacian(const struct neighbour_list *nl,
                   const struct pop_weights *W, double c, int ncomp,
                   const double *phi, const double *inv_eps,
                   const uint8_t *rows, double *out)
{
#pragma omp parallel for schedule(static)
    for (int i = 0; i < nl->n; i++) {
        if (rows && !rows[i])
            continue;
        double s[3] = { 0, 0, 0 };
        if (ncomp == 3)
            laplacian_row(nl, W, 3, phi, inv_eps, i, s);
        else if (ncomp == 1)
            laplacian_row(nl, W, 1, phi, inv_eps, i, s);
        else
            laplacian_row(nl, W, ncomp, phi, inv_eps, i, s);
        for (int q = 0; q < ncomp; q++)
            out[ncomp * i + q] = c * s[q];
    }
}

void pop_surface_vector_row(const struct neighbour_list *nl,
                            const struct pop_weights *W, const double *x,
                            const double *inv_eps, int i, double F[3])
{
    const double *xi = x + 3 * i;
    const int64_t k0 = nl->start[i], k1 = neighbour_row_end(nl, i);
    const double *rr = neighbour_row_r(nl, i, k0, k1);
    const double *w = pop_weights_row(W, k0, rr, k1 - k0);
    F[0] = F[1] = F[2] = 0;
    for (int64_t k = k0; k < k1; k++) {
        int j = nl->j[k];
        double r = rr[k - k0], wk = w[k - k0];
        if (wk == 0 || r == 0)
            continue;
        double f = wk * IEPS(j) / r;
        for (int q = 0; q < 3; q++)
            F[q] += f * (x[3 * j + q] - xi[q]);
    }
}

void pop_surface_vector(const struct neighbour_list *nl,
                        const struct pop_weights *W, double c,
                        const double *x, const double *inv_eps,
                        const uint8_t *rows, double *out)
{
#pragma omp parallel for schedule(static)
    for (int i = 0; i < nl->n; i++) {
        if (rows && !rows[i])
            continue;
        double F[3];
        pop_surface_vector_row(nl, W, x, inv_eps, i, F);
        for (int q = 0; q < 3; q++)
            out[3 * i + q] = c * F[q];
    }
}

void pop_concentration_gradient(const struct neighbour_list *nl,
                                const double *x, const double *inv_eps,
                                pop_weight_fn *wf, double re, double c, int i,
                                double G[3], double F[3])
{
    for (int q = 0; q < 3; q++)
        G[q] = F[q] = 0;
    const int64_t k1 = neighbour_row_end(nl, i);
    for (int64_t k = nl->start[i]; k < k1; k++) {
        int j = nl->j[k];
        double d[3], r2 = 0;
        for (int q = 0; q < 3; q++) {
            d[q] = x[3 * j + q] - x[3 * i + q];
            r2 += d[q] * d[q];
        }
        double r = sqrt(r2);
        if (r == 0 || r >= re)
            continue;
        double w = wf(r, re) * IEPS(j);
        for (int q = 0; q < 3; q++) {
            G[q] += w * d[q] / r2;
            F[q] += w * d[q] / r;
        }
    }
    for (int q = 0; q < 3; q++)
        G[q] *= c;
}

void pop_fickian_shift(const double G[3], const double F[3], double D,
                       int tangential, double cap, double d[3])
{
    for (int q = 0; q < 3; q++)
        d[q] = -D * G[q];
    double fm = sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]);
    if (tangential && fm > 0) {
        double dn = (d[0] * F[0] + d[1] * F[1] + d[2] * F[2]) / fm;
        for (int q = 0; q < 3; q++)
            d[q] -= dn * F[q] / fm;
    }
    double m = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (m > cap)
        for (int q = 0; q < 3; q++)
            d[q] *= cap / m;
}
