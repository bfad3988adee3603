/*
 * rolling_none.c — no rolling resistance (the choice of Xie et al. 2025,
 * doc/theory.md A.6).
 */
#include "dem/contact/contact.h"

static void eval_none(const struct contact_coeffs *c,
                      const struct contact_geom *g, double fn, double m[3])
{
    (void)c, (void)g, (void)fn;
    m[0] = m[1] = m[2] = 0;
}

const struct contact_rolling_ops contact_rolling_none = {
    .name = "none", .reference = "", .eval = eval_none,
};
