/*
 * damping_xie2025.c — the dashpot of Xie et al. (2025) eqs. (23)-(24) with
 * the tangent stiffness (doc/theory.md A0-09 (H), A0-22) and the effective
 * mass (A0-10):
 *
 *   eta^n = -2 ln(e) sqrt( kn m* / (ln^2 e + pi^2) ) = 2 beta sqrt(kn m*)
 *   eta^t = 2 beta sqrt(kt m*),      beta = -ln e / sqrt(ln^2 e + pi^2)
 *
 * kn is the tangent normal stiffness (linear: chi^n; Hertz: 1.5 chi^n
 * delta^{1/2}), kt the tangential spring stiffness. Exact for the linear
 * law; for Hertz the rebound is e' = 0.891, 0.783, 0.466, 0.262 for
 * e = 0.9, 0.8, 0.5, 0.3, independent of the impact speed (A0-22): use
 * `restitution` to get e. Kept by name because the coupled cases that
 * reproduce the paper were validated with it (until 2026-11 it was the
 * `restitution` default).
 * Reference: Xie et al. (2025) eqs. (23)-(24); Zhang et al. (2009).
 */
#include <math.h>

#include "dem/contact/contact.h"

static double zeta_xie2025(double e, double p)
{
    (void)p;
    double le = log(e);
    return -le / sqrt(le * le + M_PI * M_PI);
}

static void eval_xie2025(const struct contact_coeffs *c,
                         const struct contact_geom *g, double kn, double kt,
                         double *eta_n, double *eta_t)
{
    *eta_n = 2.0 * c->zeta * sqrt(kn * g->mstar);
    *eta_t = 2.0 * c->zeta * sqrt(kt * g->mstar);
}

const struct contact_damping_ops contact_damping_xie2025 = {
    .name = "xie2025",
    .reference = "Xie et al. 2025 eqs. 23-24 with the tangent stiffness "
                 "(doc/theory.md A0-22)",
    .zeta = zeta_xie2025,
    .eval = eval_xie2025,
};
