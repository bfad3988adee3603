/*
 * drag_ergun_wen_yu.c — Ergun (dense) / Wen-Yu (dilute) drag with the hard
 * switch of Xie et al. (2025) eqs. (25)-(28), doc/theory.md A.7:
 *
 *   F^d_k = beta_k/(1 - eps_k) (u_k - v_k) V_k                          (25)
 *   beta  = 150 (1-eps)^2/eps mu/d^2 + 1.75 (1-eps) rho |u-v|/d  eps <= 0.8
 *   beta  = 0.75 C_d eps (1-eps)/d rho eps^-2.65 |u-v|           eps >  0.8
 *                                                                       (26)
 *   C_d   = 24/Re (1 + 0.15 Re^0.687)  Re <= 1000;  0.44  Re > 1000     (27)
 *   Re    = eps rho d |u - v| / mu                                      (28)
 *
 * so that K = beta/(1 - eps) is
 *   K = 150 (1-eps)/eps mu/d^2 + 1.75 rho |u-v|/d              eps <= 0.8
 *   K = 0.75 (C_d |u-v|) rho eps^-1.65 / d                     eps >  0.8
 * with C_d |u-v| evaluated without dividing by Re (finite as u -> v).
 *
 * At eps = 1 the Wen-Yu branch is the single-sphere drag
 * 1/2 C_d rho (pi d^2/4) |u-v| (u-v) (check E1-12).
 *
 * The switch at eps = 0.8 is discontinuous (A0-12): K_Ergun/K_WenYu = 2.23
 * for 2.7 mm beads in water at |u-v| = 0.1 m/s (test_drag_laws.c measures
 * and reports it). It is kept because it is the paper's law; gidaspowBlend
 * is the smooth alternative. The Schiller-Naumann C_d also jumps by 0.4 %
 * at Re = 1000 (0.4384 -> 0.44), upward, so F stays monotone in |u-v|.
 *
 * References: S. Ergun (1952) Chem. Eng. Prog. 48, 89-94; C.Y. Wen and
 * Y.H. Yu (1966) Chem. Eng. Prog. Symp. Ser. 62, 100-111; L. Schiller and
 * A. Naumann (1933); as combined by Xie, Pan, Zhao and Wan (2025) Ocean
 * Eng. 120601, eqs. (25)-(28).
 * Validity: Ergun for packed beds (eps <= 0.8); Wen-Yu for dilute
 * suspensions, Re up to ~1e3 (C_d then constant, Newton regime).
 * Dictionary: none (fluid properties come from transportProperties).
 */
#include "coupling/drag/drag.h"

#define ERGUN_WEN_YU_SWITCH 0.8

static inline double k_ergun_wen_yu(const struct drag_fluid *f, double eps,
                                    double slip, double d)
{
    return eps <= ERGUN_WEN_YU_SWITCH ? drag_k_ergun(f, eps, slip, d)
                                      : drag_k_wen_yu(f, eps, slip, d);
}

static double coeff(const struct drag_fluid *f, double eps, double slip,
                    double d)
{
    return k_ergun_wen_yu(f, eps, slip, d);
}

DRAG_DEFINE_FORCE_ALL(force_all, k_ergun_wen_yu)

const struct drag_ops drag_ergun_wen_yu = {
    .name = "ergunWenYu",
    .reference = "Ergun 1952 / Wen & Yu 1966, switch at eps = 0.8; "
                 "Xie et al. 2025 eqs. 25-28",
    .validity = "Ergun eps <= 0.8 (packed bed); Wen-Yu eps > 0.8, "
                "Re <= ~1e3 (C_d = 0.44 above)",
    .coeff = coeff,
    .force_all = force_all,
    .jump_eps = ERGUN_WEN_YU_SWITCH,
};
