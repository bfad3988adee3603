/*
 * drag_di_felice.c — Di Felice (1994) drag with the voidage function
 * eps^-chi:
 *
 *   F^d_k = 1/2 C_d rho A |u-v| (u-v) eps^(2 - chi),   A = pi d^2/4
 *   C_d   = (0.63 + 4.8 / sqrt(Re))^2          (Dallavalle)
 *   chi   = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2 / 2)
 *   Re    = eps rho d |u - v| / mu             (superficial slip, eq. 28)
 *
 * As a coefficient K = F/(V (u - v)) = 0.75 (C_d |u-v|) rho eps^(2-chi)/d
 * with C_d |u-v| = (0.63 sqrt|u-v| + 4.8 sqrt(mu/(eps rho d)))^2, exact and
 * finite as |u - v| -> 0 (then chi -> 3.7). At eps = 1 it is the single
 * sphere drag with Dallavalle's C_d. F is continuous in eps and in |u-v|,
 * and monotone in |u-v| for eps > ~0.01 (d chi/d ln Re <= 0.17 in size).
 *
 * Reference: R. Di Felice (1994) The voidage function for fluid-particle
 * interaction systems, Int. J. Multiphase Flow 20, 153-159 (the C_d and
 * chi correlations as quoted above).
 * Validity: fitted for 1e-2 < Re < 1e4 and 0.4 <= eps <= 1 (fixed and
 * fluidised beds, suspensions).
 * Dictionary: none.
 */
#include "coupling/drag/drag.h"

static inline double k_di_felice(const struct drag_fluid *f, double eps,
                                 double slip, double d)
{
    double re = eps * f->rho * d * slip / f->mu;
    double chi = 3.7;
    if (re > 0) {
        double t = 1.5 - log10(re);
        chi -= 0.65 * exp(-0.5 * t * t);
    }
    double a = 0.63 * sqrt(slip) + 4.8 * sqrt(f->mu / (eps * f->rho * d));
    return 0.75 * a * a * f->rho * pow(eps, 2.0 - chi) / d;
}

static double coeff(const struct drag_fluid *f, double eps, double slip,
                    double d)
{
    return k_di_felice(f, eps, slip, d);
}

DRAG_DEFINE_FORCE_ALL(force_all, k_di_felice)

const struct drag_ops drag_di_felice = {
    .name = "diFelice",
    .reference = "Di Felice 1994, Int. J. Multiphase Flow 20:153",
    .validity = "1e-2 < Re < 1e4, 0.4 <= eps <= 1",
    .coeff = coeff,
    .force_all = force_all,
    .jump_eps = 0.0,
};
