/*
 * porosity.c — porosity of MPS particles from the DEM grains
 * (Xie et al. 2025 eqs. 29-31, after Sun et al. 2014; doc/theory.md A.7).
 *
 *   eps_i = 1 - (1/n_s) sum_k w_s(|r_ik|) V_k                        (31)
 *
 * with the kernel (29) and its normaliser (30),
 *
 *   n_s(3-D) = int_0^r_e w_s(r) 4 pi r^2 dr
 *            = 4 pi r_e^3 (4/8 - 5/7 + 1/3) = (10 pi/21) r_e^3
 *   n_s(2-D) = int_0^r_e w_s(r) 2 pi r dr
 *            = 2 pi r_e^2 (4/7 - 5/6 + 1/2) = (10 pi/21) r_e^2
 *
 * (the 2-D analogue is ours; the same coefficient 10 pi/21 appears by
 * coincidence of the two moment sums, 5/42 x 4 pi = 10/42 x 2 pi). With
 * this normaliser one grain spreads exactly its volume over space:
 * int (1 - eps) dV = V_k, which is what makes the mean porosity of a
 * packing right (check E1-10: 1 - pi/6 inside a simple-cubic packing).
 *
 * The raw value can fall below zero where kernels of a dense packing
 * overlap at a small r_e,s, so eps is clamped to [eps_min, 1] (doc/theory.md
 * A.3, eps_min = 0.3 by default); the number clamped is returned for the
 * run-time guard.
 */
#include "coupling/porosity.h"

#include <math.h>

#include "core/error.h"
#include "coupling/pairs.h"

double coupling_ns(int dim, double re)
{
    if (dim == 3)
        return 10.0 * M_PI / 21.0 * re * re * re;
    if (dim == 2)
        return 10.0 * M_PI / 21.0 * re * re;
    return 0.0;
}

int coupling_porosity(const struct coupling_pairs *P, const double *Vg,
                      double eps_min, double *eps, double *inv_eps,
                      long *n_clamped)
{
    if (!(eps_min > 0 && eps_min < 1))
        return sim_error(SIM_ERR_INPUT,
                         "porosity floor %g must lie in (0, 1)", eps_min);
    const double inv_ns = 1.0 / coupling_ns(P->dim, P->re);
    long nclamp = 0;
#pragma omp parallel for schedule(static) reduction(+ : nclamp)
    for (int i = 0; i < P->np; i++) {
        double s = 0.0;
        for (int64_t e = P->pstart[i]; e < P->pstart[i + 1]; e++)
            s += P->pw[e] * Vg[P->pk[e]];
        double e_i = 1.0 - s * inv_ns;
        if (e_i < eps_min) {
            e_i = eps_min;
            nclamp++;
        }
        eps[i] = e_i;
        if (inv_eps)
            inv_eps[i] = 1.0 / e_i;
    }
    if (n_clamped)
        *n_clamped = nclamp;
    return SIM_OK;
}
