/*
 * rolling_constant_torque.c — constant directional torque, model A of Ai
 * et al. (2011) (LIGGGHTS rolling_friction cdt), doc/theory.md A0-23:
 *
 *   M_r = -mu_r R* F_el w_r/|w_r|,   w_r = w_rel - (w_rel . n) n,
 *   w_rel = w_k - w_l (wall: w_k)
 *
 * w_r is the relative rolling angular velocity: the part of w_rel in the
 * tangent plane. Rotation about n (twisting) is not resisted here (a
 * separate sub-model, key `twisting`), and F_el is the elastic normal
 * force, without the dashpot. LIGGGHTS normalises by |w_rel| before it
 * removes the normal part, so a grain that spins about n while it rolls
 * gets a torque smaller by |w_r|/|w_rel|; Ai et al. define the torque by
 * the rolling velocity alone, which is what is done here.
 * Dictionary: constantTorqueCoeffs { rollingFriction mu_r; }. Known
 * limitation of the model (Ai et al. 2011): the torque chatters around
 * w_r = 0; below |w_r| R* = 1e-9 m/s it is scaled down linearly.
 * Reference: Ai, Chen, Rotter, Ooi (2011), Powder Technol. 206:269,
 * eqs. (9)-(10).
 */
#include <math.h>

#include "dem/contact/contact.h"

static void eval_cdt(const struct contact_coeffs *c,
                     const struct contact_geom *g, double fel, double m[3])
{
    const double *n = g->n;
    double wn = g->wrel[0] * n[0] + g->wrel[1] * n[1] + g->wrel[2] * n[2];
    double wr[3];
    for (int a = 0; a < 3; a++)
        wr[a] = g->wrel[a] - wn * n[a];
    double w = sqrt(wr[0] * wr[0] + wr[1] * wr[1] + wr[2] * wr[2]);
    double wref = 1e-9 / g->rstar;
    double scale = c->mu_roll * g->rstar * fabs(fel) / fmax(w, wref);
    for (int a = 0; a < 3; a++)
        m[a] = -scale * wr[a];
}

const struct contact_rolling_ops contact_rolling_constant_torque = {
    .name = "constantTorque",
    .reference = "Ai et al. 2011 model A, eq. 9 (rolling velocity, "
                 "elastic normal force)",
    .eval = eval_cdt,
};
