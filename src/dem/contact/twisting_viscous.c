/*
 * twisting_viscous.c — viscous resistance to rotation about the contact
 * normal (doc/theory.md A0-23):
 *
 *   M_tw = -eta_tw (w_rel . n) n,   w_rel = w_k - w_l (wall: w_k)
 *
 * A spin w about n then decays as exp(-eta_tw t/I) on a single contact.
 * Dictionary: twistingViscousCoeffs { twistingViscosity eta_tw; } [N m s].
 * Reference: the viscous torsion torque of Luding (2008), Granular Matter
 * 10:235, without its Coulomb limit.
 */
#include "dem/contact/contact.h"

static void eval_viscous(const struct contact_coeffs *c,
                         const struct contact_geom *g, double fel, double m[3])
{
    (void)fel;
    const double *n = g->n;
    double wn = g->wrel[0] * n[0] + g->wrel[1] * n[1] + g->wrel[2] * n[2];
    for (int a = 0; a < 3; a++)
        m[a] = -c->eta_twist * wn * n[a];
}

const struct contact_twisting_ops contact_twisting_viscous = {
    .name = "viscous",
    .reference = "viscous twisting torque (Luding 2008, without the "
                 "Coulomb limit)",
    .eval = eval_viscous,
};
