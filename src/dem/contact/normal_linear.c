/*
 * normal_linear.c — linear spring, doc/theory.md A.6 eq. (19), option (L) of
 * A0-09:
 *
 *   F_el = chi^n delta,   kn = chi^n,   kt = chi^t = ratio_t chi^n   (22)
 *
 * with chi^n from eq. (21), (4/3) E* sqrt(R*), read as N/m (1.80e6 N/m for
 * Table 1 data), unless linearCoeffs { stiffness k; } fixes k [N/m].
 * ratio_t from tangentialStiffness (A0-21): mindlin (default)
 * 2 (1 - nu)/(2 - nu), the Hertz-Mindlin ratio of tangent stiffnesses;
 * xie2025 1/(2 + nu), eq. (22) as printed.
 * Reference: Xie, Pan, Zhao, Wan (2025), Ocean Eng. 120601, eqs. (19), (21),
 * (22); Cundall and Strack (1979). Valid for small overlaps; the contact time
 * pi sqrt(m* / k) does not depend on the impact speed.
 */
#include "dem/contact/contact.h"

static void eval_linear(const struct contact_coeffs *c,
                        const struct contact_geom *g, double *fel, double *kn,
                        double *kt)
{
    double k = c->kn_linear > 0 ? c->kn_linear : contact_chi(c, g->rstar);
    *fel = k * g->delta;
    *kn = k;
    *kt = c->ratio_t * k;
}

const struct contact_normal_ops contact_normal_linear = {
    .name = "linear",
    .exponent = 1.0,
    .reference = "Xie et al. 2025 eqs. 19, 21, 22 read as linear",
    .eval = eval_linear,
};
