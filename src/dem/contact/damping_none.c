/*
 * damping_none.c — no viscous damping (eta^n = eta^t = 0): perfectly elastic
 * contacts whatever e says. Used to check energy conservation (E2-03).
 */
#include "dem/contact/contact.h"

static void eval_none(const struct contact_coeffs *c,
                      const struct contact_geom *g, double kn, double kt,
                      double *eta_n, double *eta_t)
{
    (void)c, (void)g, (void)kn, (void)kt;
    *eta_n = 0;
    *eta_t = 0;
}

const struct contact_damping_ops contact_damping_none = {
    .name = "none",
    .reference = "",
    .eval = eval_none,
};
