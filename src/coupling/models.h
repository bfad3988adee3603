/*
 * models.h — Model A and Model B of the unresolved coupling (Xie et al.
 * 2025 eqs. 1-5, 12-13, 34-36; doc/theory.md A.2, A.4, A.7, A.10), as small
 * array functions that the two solvers call, plus the coupling settings of
 * system/couplingDict and the run-time validity guards.
 *
 * Grain side (demSolid, at every sub-step):
 *   A: F^int_k = F^d_k - V_k gradP_k                                   (34)
 *   B: F^int_k = F^d_k / eps_k - V_k rho_f g                           (35)
 *
 * Fluid side (mpsFluid), with intrinsic velocity u stored and eps_i frozen
 * over the step (A0-01), u_d = eps u:
 *   step 6, reaction    f_A,i of eq. (36) distributes per grain
 *       A, B: F_bar_k      B with conservativeReaction: F_bar_k / eps_k
 *   step 7, prediction  u* = u^m + dt [ visc + g + a_i ]
 *       A: a_i = -f_A,i / (rho_f eps_i)
 *       B: a_i = -f_A,i / (rho_f eps_i^2) + g (1/eps_i - 1)
 *       B conservative: a_i = -f_i / (rho_f eps_i) + g (1/eps_i - 1)
 *   step 9, PPE source  s_i x [ (1-gamma)(rho/dt) div u* - gamma (rho/dt^2)
 *                               (n - n0)/n0 ]
 *       A: s_i = 1 (12)         B: s_i = eps_i (13)
 *   step 10, correction u^{m+1} = u* - (dt/rho_f) c_i grad P
 *       A: c_i = 1              B: c_i = 1/eps_i
 * "visc" is the viscous term of the MPS solver, nu lap(u_d)/eps_i.
 *
 * Call sequence of one fluid step m -> m+1 (doc/theory.md A.10, sequential):
 *   mpsFluid  coupling_pairs_update(P, dim, radius*dp, skin*dp, ng, x_k,
 *                                   np, x_i, &searched)
 *             coupling_porosity(P, V_k, eps_min, eps, inv_eps, &nclamp)
 *             (Model A: coupling_gradient_consistent -> gradP_i)
 *             coupling_interp_grains(P, fluid|wall mask, eps, u, gradP_i, G)
 *             -> send eps_k, u_k (gradP_k), wet_k to demSolid
 *   demSolid  N_sub times: drag->force_all(eps_k, d, V, u_k, v_k) -> F^d;
 *             coupling_grain_force(model, F^d, ...) -> F^int (+ contacts);
 *             coupling_drag_mean_add(M, F^d); integrate
 *             -> send x_k(m+1), v_k, mean drag to mpsFluid
 *   mpsFluid  coupling_pairs_update and coupling_porosity at the new x_k;
 *             coupling_reaction_input(model, conservative, F_bar, eps_k)
 *             coupling_reaction(P, mask, ..., dp^3, f_A)
 *             coupling_mps_accel -> f_ext of the prediction;
 *             coupling_ppe_source_factor, coupling_correction_factor.
 * (After renumbering particles or grains: coupling_pairs_invalidate.)
 * Guards: coupling_guard_grain_size once at start; coupling_guard_porosity
 * and coupling_guard_relaxation at the solver's report interval.
 */
#ifndef MPSDEM_COUPLING_MODELS_H
#define MPSDEM_COUPLING_MODELS_H

#include "core/select.h"

#include <stdint.h>

struct dict;
struct drag_ops;
struct drag_fluid;

enum coupling_model { COUPLING_MODEL_A = 0, COUPLING_MODEL_B = 1 };

/* system/couplingDict, the physics part (channel settings: channel.h). */
struct coupling_settings {
    enum coupling_model model;      /* `model A|B;` (default B)           */
    const struct drag_ops *drag;    /* `dragModel` (default ergunWenYu)   */
    double radius;                  /* `kernelRadius` r_e,s / dp (4.1)    */
    double eps_min;                 /* `porosityMin` (0.3)                */
    int conservative;               /* `conservativeReaction` (no), B only */
    double skin;                    /* `pairSkin` / dp (0): pairs.h update */
    double phi_relax;               /* `volumeFractionRelaxation` [s] (0:
                                       off), mps/volume_exchange.c        */
    int superficial;                /* `ppeDivergence superficial` (B only,
                                       B's default): (rho/dt) div(eps u*),
                                       A0-04 (b); intrinsic: the paper's */
    int porous_walls;               /* `porousWalls` (no, the default): wall
                                       and dummy particles weigh 1 in the
                                       MPS sums; yes (the paper's reading,
                                       A0-03): they weigh 1/eps_j         */
};

/* The model choices of system/couplingDict (-listModels). */
extern const struct model_choice coupling_choices[];

/* Whether a case is coupled: system/couplingDict present (coupling may be
 * NULL) and `coupled` (default yes); `scheme sequential|concurrent` is
 * checked here (the DEM side does the same in both, couple_fluid.h says
 * what differs), and so are the channel's keys (timeout, ...). Both
 * programs call this before anything of the other phase is allocated and
 * before any output. */
int couple_enabled(const struct dict *coupling, int *on);

/* Read the entries above; errors cite couplingDict's file and line. */
int coupling_settings_read(const struct dict *d,
                           struct coupling_settings *s);

/* Hydrodynamic force on every grain, eq. (34) or (35) [N].
 *   Fd (3 ng) drag of eq. (25) at this sub-step; eps_k (ng) and, for A,
 *   gradp_k (3 ng) from interp.h; V (ng) grain volumes; g (3) gravity;
 *   wet (may be NULL = all) dry grains (wet[k] = 0) get Fint = 0. */
void coupling_grain_force(enum coupling_model m, int ng, const double *Fd,
                          const double *eps_k, const double *gradp_k,
                          const double *V, double rho_f, const double g[3],
                          const uint8_t *wet, double *Fint);

/* What eq. (36) distributes (step 6), 3 ng [N]: F_bar_k, or F_bar_k/eps_k
 * for Model B with conservative set (the fluid then receives exactly the
 * drag part of (35), to round-off, instead of sum_i V_i f_A,i/eps_i, which
 * differs from sum_k F_k/eps_k by ~2 % in a packed bed: see models.c). */
void coupling_reaction_input(enum coupling_model m, int conservative, int ng,
                             const double *Fbar, const double *eps_k,
                             double *out);

/* Extra acceleration a_i of the prediction (step 7), 3 np [m/s^2], from
 * the reaction fA (3 np) of eq. (36) (computed from
 * coupling_reaction_input with the same conservative flag); rows (may be
 * NULL) limits the particles written. */
void coupling_mps_accel(enum coupling_model m, int conservative, int np,
                        const double *eps, const double *fA, double rho_f,
                        const double g[3], const uint8_t *rows, double *a);

/* PPE source factor s_i (step 9) and correction factor c_i (step 10), np. */
void coupling_ppe_source_factor(enum coupling_model m, int np,
                                const double *eps, double *s);
void coupling_correction_factor(enum coupling_model m, int np,
                                const double *eps, double *c);

/* Run-time guards (warnings, counts returned):
 * grains too large for the kernel (d > r_e,s / 3, doc/theory.md A0-13). */
int coupling_guard_grain_size(int ng, const double *d, double re_s);
/* MPS particles whose porosity (31) fell below porosityMin and was
 * clamped (n_clamped from coupling_porosity) out of np: a warning naming
 * the floor. Returns n_clamped. */
long coupling_guard_porosity(long n_clamped, int np, double eps_min);
/* Drag relaxation time tau = rho_s eps_k / K (Model B's, the shorter;
 * Model A's is rho_s / K) shorter than the fluid step dt for
 * grains at porosity eps_k and slip |u_k - v_k| (an explicit exchange over
 * dt would overshoot; sub-stepping the drag on the DEM side is then
 * essential). Returns the count; *tau_min the shortest time [s]. */
int coupling_guard_relaxation(const struct drag_ops *drag,
                              const struct drag_fluid *f, int ng,
                              const double *eps_k, const double *u_k,
                              const double *v_k, const double *d,
                              double rho_s, double dt, double *tau_min);

#endif
