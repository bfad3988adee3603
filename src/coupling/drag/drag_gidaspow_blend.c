/*
 * drag_gidaspow_blend.c — the Ergun and Wen-Yu laws of Xie et al. (2025)
 * eqs. (26)-(28) blended smoothly in the solid fraction (Huilin and
 * Gidaspow 2003), doc/theory.md A0-12 option [P]:
 *
 *   beta  = phi beta_Ergun + (1 - phi) beta_WenYu
 *   phi   = 1/2 + atan(262.5 (eps_s - 0.2)) / pi,   eps_s = 1 - eps
 *   F^d_k = beta/(1 - eps) (u_k - v_k) V_k                              (25)
 *
 * with beta_Ergun, beta_WenYu, C_d and Re exactly as in drag_ergun_wen_yu.c.
 * phi goes from ~0 (dilute) to ~1 (dense) over a porosity band of about
 * +-0.01 around 0.8, so the law is continuous (and smooth) in eps, which
 * removes the factor ~2 jump of the hard switch.
 *
 * Note: phi does not vanish at eps = 1 (phi(1) = 1/2 - atan(52.5)/pi =
 * 0.00606), so this law exceeds the single-sphere drag by 0.6 % of
 * (K_Ergun - K_WenYu) at eps = 1 (K_Ergun stays 1.75 rho |u-v|/d there).
 * That is the published blend, kept as is; check E1-12 therefore applies
 * to ergunWenYu and not to this law.
 *
 * Reference: L. Huilin and D. Gidaspow (2003) Hydrodynamics of binary
 * fluidization in a riser: CFD simulation using two granular temperatures,
 * Chem. Eng. Sci. 58, 3777-3792.
 * Validity: as the two parent laws (Re <= ~1e3 for Wen-Yu's C_d).
 * Dictionary: none.
 */
#include "coupling/drag/drag.h"

static inline double k_gidaspow_blend(const struct drag_fluid *f, double eps,
                                      double slip, double d)
{
    double phi = 0.5 + atan(262.5 * ((1.0 - eps) - 0.2)) / M_PI;
    return phi * drag_k_ergun(f, eps, slip, d) +
           (1.0 - phi) * drag_k_wen_yu(f, eps, slip, d);
}

static double coeff(const struct drag_fluid *f, double eps, double slip,
                    double d)
{
    return k_gidaspow_blend(f, eps, slip, d);
}

DRAG_DEFINE_FORCE_ALL(force_all, k_gidaspow_blend)

const struct drag_ops drag_gidaspow_blend = {
    .name = "gidaspowBlend",
    .reference = "Huilin & Gidaspow 2003 blend of Ergun / Wen-Yu",
    .validity = "all eps in (0, 1]; Re <= ~1e3 (C_d = 0.44 above)",
    .coeff = coeff,
    .force_all = force_all,
    .jump_eps = 0.0,
};
