/*
 * damping_restitution.c — viscous damping from the restitution coefficient,
 * doc/theory.md A.6 eqs. (23)-(24) with the effective mass (A0-10):
 *
 *   eta^n = -2 ln(e) sqrt( kn m* / (ln^2 e + pi^2) ) = 2 beta sqrt(kn m*)
 *   eta^t = 2 beta sqrt(kt m*)
 *
 * kn is the tangent normal stiffness (linear: chi^n; Hertz: 1.5 chi^n
 * delta^{1/2}). For the linear law this reproduces e exactly; for Hertz it is
 * an approximation whose error depends weakly on the impact speed (E2-04).
 * Reference: Zhang et al. (2009); Tsuji et al. (1992) for the Hertz form.
 */
#include <math.h>

#include "dem/contact/contact.h"

static void eval_restitution(const struct contact_coeffs *c,
                             const struct contact_geom *g, double kn,
                             double kt, double *eta_n, double *eta_t)
{
    *eta_n = 2.0 * c->beta * sqrt(kn * g->mstar);
    *eta_t = 2.0 * c->beta * sqrt(kt * g->mstar);
}

const struct contact_damping_ops contact_damping_restitution = {
    .name = "restitution",
    .reference = "Zhang et al. 2009; Xie et al. 2025 eqs. 23-24",
    .eval = eval_restitution,
};
