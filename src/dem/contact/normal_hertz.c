/*
 * normal_hertz.c — Hertz law, option (H) of doc/theory.md A0-09 (the default):
 *
 *   F_el = chi^n delta^{3/2},        chi^n = (4/3) E* sqrt(R*)        (21)
 *   kn   = dF_el/d delta = (3/2) chi^n delta^{1/2}
 *   kt   = chi^t delta^{1/2},        chi^t = ratio_t chi^n            (22)
 *
 * ratio_t from tangentialStiffness (A0-21): mindlin (default)
 * 3 (1 - nu)/(2 - nu), i.e. kt = 8 G* sqrt(R* delta); xie2025 1/(2 + nu),
 * eq. (22) as printed. kn, the tangent stiffness, enters the damping
 * (A0-09, A0-22) and the stability bound. Reference: Hertz (1882); Xie et al. (2025) eqs. (19)-(22)
 * with the Hertz reading of A0-09. Valid for small elastic overlaps
 * (delta << R).
 */
#include <math.h>

#include "dem/contact/contact.h"

static void eval_hertz(const struct contact_coeffs *c,
                       const struct contact_geom *g, double *fel, double *kn,
                       double *kt)
{
    double chi = contact_chi(c, g->rstar);
    double sd = sqrt(g->delta);
    *fel = chi * g->delta * sd;
    *kn = 1.5 * chi * sd;
    *kt = c->ratio_t * chi * sd;
}

const struct contact_normal_ops contact_normal_hertz = {
    .name = "hertz",
    .exponent = 1.5,
    .reference = "Hertz 1882; Xie et al. 2025 eqs. 19-22, "
                 "doc/theory.md A0-09 (H)",
    .eval = eval_hertz,
};
