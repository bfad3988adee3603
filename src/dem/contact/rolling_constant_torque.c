/*
 * rolling_constant_torque.c — constant directional torque (model A of Ai et
 * al. 2011; LIGGGHTS rolling_friction cdt):
 *
 *   M_r = -mu_r R* |F^n| w_rel/|w_rel|,   w_rel = w_k - w_l
 *
 * Dictionary: constantTorqueCoeffs { rollingFriction mu_r; }. Known
 * limitation of the model (Ai et al. 2011): the torque chatters around
 * w_rel = 0; below |w_rel| R* = 1e-9 m/s it is scaled down linearly.
 * Reference: Ai, Chen, Rotter, Ooi (2011), Powder Technol. 206, eq. (9).
 */
#include <math.h>

#include "dem/contact/contact.h"

static void eval_cdt(const struct contact_coeffs *c,
                     const struct contact_geom *g, double fn, double m[3])
{
    double w = sqrt(g->wrel[0] * g->wrel[0] + g->wrel[1] * g->wrel[1]
                    + g->wrel[2] * g->wrel[2]);
    double wref = 1e-9 / g->rstar;
    double scale = c->mu_roll * g->rstar * fabs(fn) / fmax(w, wref);
    for (int a = 0; a < 3; a++)
        m[a] = -scale * g->wrel[a];
}

const struct contact_rolling_ops contact_rolling_constant_torque = {
    .name = "constantTorque",
    .reference = "Ai et al. 2011 model A, eq. 9",
    .eval = eval_cdt,
};
