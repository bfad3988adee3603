/*
 * tangential_none.c — frictionless contacts: no tangential force, no history.
 */
#include "dem/contact/contact.h"

static void eval_none(const struct contact_coeffs *c,
                      const struct contact_geom *g, double fn, double kt,
                      double eta_t, const double h[3], double tau,
                      double hnew[3], double ft[3])
{
    (void)c, (void)g, (void)fn, (void)kt, (void)eta_t, (void)h, (void)tau;
    hnew[0] = hnew[1] = hnew[2] = 0;
    ft[0] = ft[1] = ft[2] = 0;
}

const struct contact_tangential_ops contact_tangential_none = {
    .name = "none", .reference = "", .history = 0, .eval = eval_none,
};
