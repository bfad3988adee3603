/*
 * rolling_viscous.c — viscous rolling resistance (the damping part of model
 * C of Ai et al. 2011, without the spring), doc/theory.md A0-23:
 *
 *   M_r = -eta_r w_r,   w_r = w_rel - (w_rel . n) n,   while in contact
 *
 * w_rel = w_k - w_l (wall: w_k); only its rolling part w_r, in the tangent
 * plane, is resisted: twisting about n is the `twisting` sub-model's.
 * Dictionary: viscousCoeffs { rollingViscosity eta_r; } [N m s].
 * Reference: Ai, Chen, Rotter, Ooi (2011), Powder Technol. 206:269,
 * sect. 2.3.
 */
#include "dem/contact/contact.h"

static void eval_viscous(const struct contact_coeffs *c,
                         const struct contact_geom *g, double fel, double m[3])
{
    (void)fel;
    const double *n = g->n;
    double wn = g->wrel[0] * n[0] + g->wrel[1] * n[1] + g->wrel[2] * n[2];
    for (int a = 0; a < 3; a++)
        m[a] = -c->eta_roll * (g->wrel[a] - wn * n[a]);
}

const struct contact_rolling_ops contact_rolling_viscous = {
    .name = "viscous",
    .reference = "Ai et al. 2011 sect. 2.3 (viscous part, rolling velocity)",
    .eval = eval_viscous,
};
