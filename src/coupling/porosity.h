/*
 * porosity.h — the coupling kernel w_s and the porosity of MPS particles
 * from the DEM grains (Xie et al. 2025 eqs. 29-31; doc/theory.md A.7).
 *
 *   w_s(r) = 4 (r/r_e)^5 - 5 (r/r_e)^4 + 1    r < r_e,  0 otherwise (29)
 *   n_s    = int w_s dV = (10 pi/21) r_e^3 (3-D)  or  (10 pi/21) r_e^2 (2-D)
 *   eps_i  = 1 - (1/n_s) sum_k w_s(|r_ik|) V_k, clamped to [eps_min, 1] (31)
 *
 * r_e here is the coupling radius r_e,s, a parameter separate from the MPS
 * operator radii (A0-13). In 2-D, V_k must be the grain's area per unit
 * depth (pi R^2 for a disc): eq. (31) then gives the area fraction.
 */
#ifndef MPSDEM_COUPLING_POROSITY_H
#define MPSDEM_COUPLING_POROSITY_H

#include <math.h>
#include <stdint.h>

struct coupling_pairs;

/* w_s(r; re), eq. (29); 1 at r = 0, 0 for r >= re, C^1 at r = re. */
static inline double coupling_ws(double r, double re)
{
    if (r >= re)
        return 0.0;
    double q = r / re, q4 = (q * q) * (q * q);
    return q4 * (4.0 * q - 5.0) + 1.0;
}

/* V_k of eq. (31) for a sphere of radius r: its volume in 3-D; in 2-D the
 * area V/dp of the slab one dp deep that the 2-D fluid stands for. */
static inline double coupling_grain_measure(int dim, double r, double dp)
{
    double V = 4.0 / 3.0 * M_PI * r * r * r;
    return dim == 3 ? V : V / dp;
}

/* n_s of eq. (30) for dim = 2 or 3 [m^dim]; 0 for another dim. */
double coupling_ns(int dim, double re);

/*
 * Porosity at every MPS particle of the last pair build (eq. 31).
 *   Vg       grain volumes [m^3] (areas [m^2] in 2-D), one per grain
 *   eps_min  lower clamp (doc/theory.md A.3, default 0.3), in (0, 1)
 *   eps      out: np values in [eps_min, 1]
 *   inv_eps  out (may be NULL): np values 1/eps, what MPS operators take
 *   n_clamped out (may be NULL): particles whose raw value was < eps_min,
 *            for the run-time guard "porosity below a floor"
 * Returns SIM_ERR_INPUT for eps_min outside (0, 1).
 */
int coupling_porosity(const struct coupling_pairs *P, const double *Vg,
                      double eps_min, double *eps, double *inv_eps,
                      long *n_clamped);

#endif
