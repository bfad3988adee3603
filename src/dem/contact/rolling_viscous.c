/*
 * rolling_viscous.c — viscous rolling resistance (model C-type damping of
 * Ai et al. 2011, without the spring):
 *
 *   M_r = -eta_r w_rel,    w_rel = w_k - w_l,   while in contact
 *
 * Dictionary: viscousCoeffs { rollingViscosity eta_r; } [N m s].
 * Reference: Ai, Chen, Rotter, Ooi (2011), Powder Technol. 206, sect. 2.3.
 */
#include "dem/contact/contact.h"

static void eval_viscous(const struct contact_coeffs *c,
                         const struct contact_geom *g, double fn, double m[3])
{
    (void)fn;
    for (int a = 0; a < 3; a++)
        m[a] = -c->eta_roll * g->wrel[a];
}

const struct contact_rolling_ops contact_rolling_viscous = {
    .name = "viscous",
    .reference = "Ai et al. 2011 sect. 2.3 (viscous part)",
    .eval = eval_viscous,
};
