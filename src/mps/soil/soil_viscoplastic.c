/*
 * soil_viscoplastic.c — soil as a regularised Drucker-Prager viscoplastic
 * fluid (doc/theory.md K.6, K0-11 ... K0-15): the yield stress that Kim's
 * solid-soil model lacks (its friction acts as a viscosity of ~4e-3 m^2/s,
 * so slopes flatten for ever). Coulomb friction written as a viscosity,
 * in the convention of the mu(I) rheology (Jop, Forterre and Pouliquen
 * 2006, Nature 441, 727: |tau| = mu p, with mu = tan of the angle of
 * repose):
 *
 *   tau_y,i  = c + mu max(p'_i, 0)                 yield stress   (K.6a)
 *   |D|_i    = sqrt(D:D / 2),  D = (grad v + grad v^T)/2          (K.6b)
 *   nu_i     = min(tau_y,i / (2 rho_s |D|_i), nu_max)             (K.6c)
 *
 * p' is the pressure of the last step, or its stand-in at the free surface
 * (soil_step.c, K0-12). An infinite slope of angle theta yields when
 * tan theta > mu + c/p'. The velocity gradient is the corrective-matrix
 * one (exact for linear fields, also at the free surface). The viscous
 * term is implicit, since nu_max dt/l0^2 is 10^3-10^5:
 *
 *   v'_i - dt c_L sum_j nu_ij w_ij (v'_j - v'_i) = v_i                (K.6d)
 *
 * over the soil particles i, c_L = 2d/(n0 lambda); neighbours that are
 * not soil (water, walls, dummies) enter with their own velocity on the
 * right-hand side. Pair viscosities (K0-13): the arithmetic mean between
 * soil particles (the stress across a layer is that of the layer, not of
 * its weakest particle: the harmonic mean let a layer on a 20 deg incline
 * flow, mu = 0.577); the harmonic mean between soil and water (the water
 * shears the soil with ~2 nu_w); against a wall, the soil's own with the
 * yield stress at the contact, p' + rho_s |g| l0/2 (the half particle
 * between its centre and the wall), acting on the tangential velocity
 * only: the normal motion is the pressure's (a no-slip wall has no
 * normal viscous stress). The matrix is symmetric and strictly diagonally
 * dominant: PCG applies.
 */
#include <math.h>

#include "core/error.h"
#include "mps/soil/soil.h"
#include "particles/neighbour.h"
#include "particles/operators/gradient_corrected.h"

void soil_vp_viscosity(const struct soil_vp_params *p, int dim,
                       const struct neighbour_list *nl, const double *w,
                       double n0, const double *x, const double *v,
                       const double *pres, const uint8_t *role, double *nu,
                       double *nu_w)
{
#pragma omp parallel for schedule(static)
    for (int i = 0; i < nl->n; i++) {
        if (role[i] != SOIL_SOIL) {
            nu[i] = nu_w[i] = 0.0;
            continue;
        }
        double m[9] = { 0 }, g[3][3] = { { 0 } }, s[3][3] = { { 0 } };
        const int64_t k0 = nl->start[i], k1 = neighbour_row_end(nl, i);
        const double *rr = neighbour_row_r(nl, i, k0, k1);
        for (int64_t k = k0; k < k1; k++) {
            if (!(w[k] > 0))
                continue;
            const int j = nl->j[k];
            double r[3];
            for (int a = 0; a < 3; a++)
                r[a] = x[3 * j + a] - x[3 * i + a];
            const double f = w[k] / (rr[k - k0] * rr[k - k0]);
            for (int a = 0; a < 3; a++) {
                const double dv = v[3 * j + a] - v[3 * i + a];
                for (int b = 0; b < 3; b++) {
                    m[3 * a + b] += f * r[a] * r[b];
                    s[a][b] += f * dv * r[b];     /* d v_a along x_b */
                }
            }
        }
        for (int a = 0; a < dim; a++)
            if (!pop_moment_solve(dim, m, s[a], g[a]))
                for (int b = 0; b < 3; b++)
                    g[a][b] = dim / n0 * s[a][b];
        double dd = 0.0;
        for (int a = 0; a < dim; a++)
            for (int b = 0; b < dim; b++) {
                const double d = 0.5 * (g[a][b] + g[b][a]);
                dd += d * d;
            }
        const double rate = 2.0 * sqrt(0.5 * dd);  /* 2 |D| [1/s] */
        const double tau = p->cohesion + p->mu * fmax(pres[i], 0.0);
        const double tau_w = tau + p->mu * p->p_wall;
        const double cap = p->nu_max * p->rho * rate;
        nu[i] = tau < cap ? tau / (p->rho * rate) : p->nu_max;
        nu_w[i] = tau_w < cap ? tau_w / (p->rho * rate) : p->nu_max;
    }
}

static double pair_nu(const uint8_t *role, const double *nu,
                      const double *nu_w, double nu_f, int i, int j)
{
    if (role[j] == SOIL_WALL || role[j] == SOIL_OTHER)
        return nu_w[i];
    if (role[j] == SOIL_SOIL)
        return 0.5 * (nu[i] + nu[j]);
    return nu[i] + nu_f > 0 ? 2.0 * nu[i] * nu_f / (nu[i] + nu_f) : 0.0;
}

void soil_vp_system(const struct neighbour_list *nl, const double *w,
                    double c_dt, double nu_f, const double *nu,
                    const double *nu_w, const uint8_t *role, const int32_t *unk,
                    const double *v, const double *wn,
                    const int64_t *rowptr, int32_t *col, double *val,
                    double *b)
{
#pragma omp parallel for schedule(static)
    for (int i = 0; i < nl->n; i++) {
        const int r = unk[i];
        if (r < 0)
            continue;
        int64_t pos = rowptr[r] + 1;
        double diag = 1.0, rhs[3] = { v[3 * i], v[3 * i + 1], v[3 * i + 2] };
        /* the range of pop_matrix_rowptr, which sized the row */
        for (int64_t k = nl->start[i]; k < nl->start[i + 1]; k++) {
            if (!(w[k] > 0))
                continue;
            const int j = nl->j[k];
            const double a = c_dt * pair_nu(role, nu, nu_w, nu_f, i, j) * w[k];
            diag += a;
            if (unk[j] >= 0) {
                col[pos] = unk[j];
                val[pos++] = -a;
            } else if (role[j] != SOIL_FLUID) {
                /* K0-13: the wall drags the tangential velocity only */
                const double *n = wn + 3 * j;
                double un = 0;
                for (int q = 0; q < 3; q++)
                    un += n[q] * (v[3 * i + q] - v[3 * j + q]);
                for (int q = 0; q < 3; q++)
                    rhs[q] += a * (v[3 * j + q] + un * n[q]);
            } else {
                for (int q = 0; q < 3; q++)
                    rhs[q] += a * v[3 * j + q];
            }
        }
        col[rowptr[r]] = r;
        val[rowptr[r]] = diag;
        for (int q = 0; q < 3; q++)
            b[3 * (size_t)r + q] = rhs[q];
    }
}
