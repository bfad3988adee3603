/*
 * twisting_none.c — no resistance to rotation about the contact normal
 * (the default, doc/theory.md A0-23): a grain spinning about the vertical
 * on a floor keeps spinning, as with the rolling models of Ai et al. (2011)
 * and LIGGGHTS' cdt and epsd.
 */
#include "dem/contact/contact.h"

static void eval_none(const struct contact_coeffs *c,
                      const struct contact_geom *g, double fel, double m[3])
{
    (void)c, (void)g, (void)fel;
    m[0] = m[1] = m[2] = 0;
}

const struct contact_twisting_ops contact_twisting_none = {
    .name = "none", .reference = "", .eval = eval_none,
};
