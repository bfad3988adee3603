/*
 * damping_tsuji.c — the Hertzian dashpot of Tsuji, Tanaka and Ishida (1992)
 * in the form LIGGGHTS uses (`model hertz`, doc/theory.md A0-22):
 *
 *   eta^n = 2 sqrt(5/6) beta sqrt(S_n m*),   S_n = 2 E* sqrt(R* delta)
 *   eta^t = 2 sqrt(5/6) beta sqrt(S_t m*),   S_t = 8 G* sqrt(R* delta)
 *   beta  = -ln e / sqrt(ln^2 e + pi^2)
 *
 * S_n is the tangent normal stiffness kn, S_t the tangential spring kt of
 * the selected tangentialStiffness (mindlin: exactly LIGGGHTS' S_t). For
 * Hertz this is the exact dashpot within the accuracy of the impact ODE
 * of damping_restitution.c: zeta_exact/beta = sqrt(5/6) to 2e-7 for
 * e = 0.1 ... 0.99, so e is returned to 5e-7 (A0-22,
 * test_hertz_mindlin.c). With the linear law the factor under-damps:
 * e' = 0.134, 0.338, 0.533, 0.816, 0.908 for e = 0.1, 0.3, 0.5, 0.8, 0.9.
 * Reference: Tsuji et al. (1992) Powder Technol. 71:239; LIGGGHTS
 * documentation of pair gran model hertz.
 */
#include <math.h>

#include "dem/contact/contact.h"

static double zeta_tsuji(double e, double p)
{
    (void)p;
    double le = log(e);
    return sqrt(5.0 / 6.0) * -le / sqrt(le * le + M_PI * M_PI);
}

static void eval_tsuji(const struct contact_coeffs *c,
                       const struct contact_geom *g, double kn, double kt,
                       double *eta_n, double *eta_t)
{
    *eta_n = 2.0 * c->zeta * sqrt(kn * g->mstar);
    *eta_t = 2.0 * c->zeta * sqrt(kt * g->mstar);
}

const struct contact_damping_ops contact_damping_tsuji = {
    .name = "tsuji",
    .reference = "Tsuji et al. 1992; LIGGGHTS hertz (sqrt(5/6) dashpot)",
    .zeta = zeta_tsuji,
    .eval = eval_tsuji,
};
