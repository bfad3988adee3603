/*
 * damping_restitution_constant.c — eqs. (23)-(24) of Xie et al. 2025 as
 * printed, with the Hertz coefficient chi^n of eq. (21) taken as the
 * stiffness (doc/theory.md A.6, A0-09; effective mass, A0-10):
 *
 *   eta^n = 2 beta sqrt(chi^n m*),  eta^t = 2 beta sqrt(chi^t m*),
 *   beta = -ln e / sqrt(ln^2 e + pi^2),  chi^t = chi^n ratio_t
 *
 * with ratio_t from tangentialStiffness (xie2025: 1/(2 + nu), eq. 22;
 * mindlin: 2 p (1 - nu)/(2 - nu), doc/theory.md A0-21).
 *
 * i.e. the dashpot of the linear law, constant over a contact, used with
 * whichever normal law is selected. With `normal linear` it is the same as
 * `restitution`. With `normal hertz` (chi^n in N/m^1.5 read as N/m: 1.8e6
 * for Table 1) the dashpot no longer vanishes at small overlap, as the
 * tangent-stiffness form (restitution, eta ~ delta^1/4) does: the
 * collisions are far more dissipative than e says (e = 0.04 at 0.5 m/s,
 * 0.10 at 1 m/s for Table 1 beads head-on), and lightly loaded contacts,
 * such as those near the top of a packed column, are damped instead of
 * ringing for seconds (the collective modes of a column of Hertz contacts
 * have a damping ratio of ~beta x their frequency/the contact frequency,
 * 0.0025 for the 15-bead columns of doc/theory.md A.12.1 with restitution).
 * Use it to reproduce the paper's DEM (with tangentialStiffness xie2025);
 * `restitution` reproduces e.
 */
#include <math.h>

#include "dem/contact/contact.h"

static double zeta_beta(double e, double p)
{
    (void)p;
    double le = log(e);
    return -le / sqrt(le * le + M_PI * M_PI);
}

static void eval_restitution_constant(const struct contact_coeffs *c,
                                      const struct contact_geom *g,
                                      double kn, double kt, double *eta_n,
                                      double *eta_t)
{
    (void)kn;
    (void)kt;
    double chi = c->kn_linear > 0 ? c->kn_linear : contact_chi(c, g->rstar);
    *eta_n = 2.0 * c->beta * sqrt(chi * g->mstar);
    *eta_t = 2.0 * c->beta * sqrt(c->ratio_t * chi * g->mstar);
}

const struct contact_damping_ops contact_damping_restitution_constant = {
    .name = "restitutionConstant",
    .reference = "Xie et al. 2025 eqs. 23-24 with chi^n of eq. 21 as the "
                 "stiffness (doc/theory.md A0-09)",
    .zeta = zeta_beta,
    .eval = eval_restitution_constant,
};
