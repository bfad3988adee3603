/*
 * stiffness_mindlin.c — tangential stiffness of Mindlin (1949) for a
 * no-slip Hertz contact, the Hertz-Mindlin law of LIGGGHTS and of
 * Thornton's analyses (doc/theory.md A0-21):
 *
 *   kt = 8 G* sqrt(R* delta),   G* = G/(2 (2 - nu)),  G = E/(2 (1 + nu))
 *
 * i.e. kt/kn = 2 (1 - nu)/(2 - nu) with kn = 2 E* sqrt(R* delta) the
 * tangent normal stiffness, single material. In the secant notation of
 * eq. (22), kt = chi^t delta^{1/2}: chi^t/chi^n = 3 (1 - nu)/(2 - nu).
 * For the linear law (p = 1) the same ratio of tangential to normal
 * stiffness is kept, kt = 2 (1 - nu)/(2 - nu) kn: switching the normal law
 * then leaves the ratio of the tangential to the normal contact
 * frequency, which decides the tangential rebound (Maw et al. 1976), as it
 * was. General p: kt = p chi^n delta^(p-1) 2 (1 - nu)/(2 - nu).
 * Reference: Mindlin (1949) J. Appl. Mech. 16:259; Mindlin and
 * Deresiewicz (1953); Di Renzo and Di Maio (2004) Chem. Eng. Sci. 59:525.
 * The full Mindlin-Deresiewicz load history (kt falling with the
 * tangential load) is not modelled: the slider caps the force instead.
 */
#include "dem/contact/contact.h"

static double ratio_mindlin(double nu, double p)
{
    return p * 2.0 * (1.0 - nu) / (2.0 - nu);
}

const struct contact_stiffness_ops contact_stiffness_mindlin = {
    .name = "mindlin",
    .reference = "Mindlin 1949: kt = 8 G* sqrt(R* delta) "
                 "(doc/theory.md A0-21)",
    .ratio = ratio_mindlin,
};
