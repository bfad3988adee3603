/*
 * stiffness_xie2025.c — the tangential stiffness of Xie et al. (2025)
 * eq. (22) read literally (doc/theory.md A0-08, A0-21):
 *
 *   chi^t = chi^n/(2 + nu),   kt = chi^t delta^{1/2} (Hertz), chi^t (linear)
 *
 * 0.35 times Mindlin's stiffness at nu = 0.3 (0.34 at nu = 0.2). Kept by
 * name for the coupled cases that reproduce the paper.
 * Reference: Xie et al. (2025) eq. (22), after Yu et al. (2023).
 */
#include "dem/contact/contact.h"

static double ratio_xie2025(double nu, double p)
{
    (void)p;
    return 1.0 / (2.0 + nu);
}

const struct contact_stiffness_ops contact_stiffness_xie2025 = {
    .name = "xie2025",
    .reference = "Xie et al. 2025 eq. 22: chi^t = chi^n/(2 + nu)",
    .ratio = ratio_xie2025,
};
