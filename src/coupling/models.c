/*
 * models.c — Model A and Model B source terms (Xie et al. 2025; doc/theory.md
 * A.2 eqs. 1-5, A.4 eqs. 12-13, A.7 eqs. 34-36, A.10 steps 7, 9, 10).
 *
 * Model A (pressure drop shared by both phases):
 *   rho Du_d/Dt = -eps grad P + mu lap u_d - f_A + eps rho g            (2)
 *   F^int_k = F^d_k - V_k grad P|_k                                     (34)
 * Model B (pressure drop on the fluid only, Feng and Yu 2004):
 *   rho Du_d/Dt = -grad P + mu lap u_d - f_A/eps + rho g                (5)
 *   F^int_k = F^d_k / eps_k - V_k rho_f g                               (35)
 *
 * With u_d = eps u and eps frozen over the step (A0-01: u stored), divide
 * by rho eps to get the intrinsic-velocity form the MPS solver advances:
 *   A: Du/Dt = -(1/rho) grad P + visc + g - f_A/(rho eps)
 *   B: Du/Dt = -(1/(rho eps)) grad P + visc + g/eps - f_A/(rho eps^2)
 * so the prediction adds a_A = -f_A/(rho eps) or
 * a_B = -f_A/(rho eps^2) + g (1/eps - 1) to the single-phase terms, and the
 * correction scales grad P by c = 1 (A) or 1/eps (B). Both keep a fluid at
 * rest in a fixed bed exactly at rest when grad P = rho g (hydrostatics is
 * the fluid's own weight in both models: in B because the grain weight is
 * carried by contacts and explicit buoyancy, in A because eps cancels).
 * PPE sources (12)/(13): B multiplies both terms by eps_i (A0-04 (a), the
 * literal form with the intrinsic u*), A does not.
 * The exact projection of each model keeps a fluid at rest in a bed whose
 * porosity varies (u* = g dt/eps in B, g dt in A; grad P = rho g):
 *   A: u = u* - (dt/rho) grad P,       div(eps u) = 0
 *      -> div(eps grad P) = (rho/dt) div(eps u*),
 *   B: eps u = eps u* - (dt/rho) grad P,  div(eps u) = 0
 *      -> lap P = (rho/dt) div(eps u*)                       (A.8 for B).
 * A's form (12) drops grad eps . grad P against eps u*'s own gradient
 * term, and both vanish at rest: (12) is hydrostatic. B's literal form
 * eps_i (rho/dt) div u* is not: at rest it gives lap P = -rho g . grad
 * eps/eps, which bends the pressure profile across a bed top by
 * rho g ln(eps_above/eps_below) in its slope; with the floor's
 * no-penetration condition (grad P = rho g there in both forms) the floor
 * pressure comes out wrong by a third one step from rest in a tank half
 * filled by a bed of eps 0.5 (test_step); in the settled 5 mm
 * sedimentation case it is one of three causes of a floor pressure 21 %
 * too high (tutorials/mpsDem/multipleParticleSedimentation/README.md).
 * `ppeDivergence superficial;` (B only) takes the divergence of eps u*
 * (A0-04 (b)) and keeps eps_i on the density term; for a uniform eps the
 * two forms are the same.
 *
 * Momentum: with fluid mass rho eps_i V_i per particle, Model A's exchange
 * sum_i rho eps_i V_i a_A,i = -sum_i V_i f_A,i = -sum_k F_bar_k is exact
 * (E1-13). Model B's fluid side -sum_i V_i f_A,i/eps_i and the grains'
 * sum_k F_k/eps_k agree only up to the difference between eps_i and eps_k
 * within a kernel radius: that is the model as published, and the default.
 * For the 7425-bead block of the dam break with a uniform drag the two
 * differ by 2.2 % (r_e,s = 4.1 dp), 1.8 % (3.0 dp), 1.4 % (2.1 dp).
 * `conservativeReaction yes;` [P] distributes F_bar_k/eps_k instead and
 * drops one 1/eps_i on the fluid side, so that the fluid receives exactly
 * what the grains feel in (35): sum_i rho eps_i V_i a_i = -sum_k F_k/eps_k.
 * (Buoyancy, -V_k rho_f g on the grains and g (1/eps_i - 1) on the fluid,
 * balances only as far as sum_i V_i w_s(r_ik) approximates n_s.)
 */
#include "coupling/models.h"

#include <math.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "core/select.h"
#include "coupling/channel.h"
#include "coupling/drag/drag.h"

/* The choices without ops (core/select.h), in enum order. */
static const struct model_head model_a = {
    "A", "Xie et al. 2025 eqs. 1-2, 12, 34" };
static const struct model_head model_b = {
    "B", "Xie et al. 2025 eqs. 3-5, 13, 35" };
static const struct model_head *const model_table[] = {
    &model_a, &model_b, NULL };
static const struct model_head div_intrinsic = {
    "intrinsic", "Xie et al. 2025 eq. 13 as printed, A0-04 (a)" };
static const struct model_head div_superficial = {
    "superficial", "div(eps u*), A0-04 (b)" };
static const struct model_head *const divergence_table[] = {
    &div_intrinsic, &div_superficial, NULL };

#define TABLE(t) ((const void *const *)(t))

const struct model_choice coupling_choices[] = {
    { "system/couplingDict", "model", TABLE(model_table) },
    { "system/couplingDict", "ppeDivergence", TABLE(divergence_table) },
    { "system/couplingDict", "dragModel", TABLE(drag_table) },
    { NULL, NULL, NULL }
};

int coupling_settings_read(const struct dict *d, struct coupling_settings *s)
{
    int idx;
    TRY(model_select_index(d, "model", "coupling model", TABLE(model_table),
                           "B", &idx));
    s->model = (enum coupling_model)idx;
    TRY(drag_select(d, &s->drag));
    TRY(dict_get_scalar_or(d, "kernelRadius", 4.1, &s->radius));
    if (!(s->radius > 0) || !isfinite(s->radius))
        return dict_error(d, "kernelRadius", SIM_ERR_DICT,
                          "kernelRadius %g (coupling kernel radius in units "
                          "of dp) must be > 0", s->radius);
    TRY(dict_get_bool_or(d, "conservativeReaction", 0, &s->conservative));
    if (s->conservative && s->model == COUPLING_MODEL_A)
        return dict_error(d, "conservativeReaction", SIM_ERR_DICT,
                          "conservativeReaction applies to model B only "
                          "(model A's reaction is already exact)");
    /* 0 searches twice a step, so that a restart reproduces a continuous
     * run bit for bit; a skin searches when the particles were renumbered
     * or either cloud moved more than the skin (every few steps) and
     * otherwise measures the kept pairs again, at the price of that
     * bit-identity (couple_fluid_grain_fields). */
    TRY(dict_get_scalar_or(d, "pairSkin", 0.0, &s->skin));
    if (!(s->skin >= 0) || !isfinite(s->skin))
        return dict_error(d, "pairSkin", SIM_ERR_DICT,
                          "pairSkin %g (Verlet skin of the grain-particle "
                          "pairs in units of dp) must be >= 0", s->skin);
    TRY(dict_get_scalar_or(d, "volumeFractionRelaxation", 0.0,
                           &s->phi_relax));
    if (!(s->phi_relax >= 0) || !isfinite(s->phi_relax))
        return dict_error(d, "volumeFractionRelaxation", SIM_ERR_DICT,
                          "volumeFractionRelaxation %g (relaxation time of "
                          "the water content phi/eps [s]; 0 = off) must be "
                          ">= 0", s->phi_relax);
    /* Defaults (issue 23): the forms that keep a fluid at rest in a bed of
     * grains at rest (A0-04 (b) for B; A's eq. 12 is already consistent)
     * and wall particles of weight 1 in the MPS sums (A0-03; their
     * porosity still scales their PPE rows). The paper's literal forms
     * stay selectable: ppeDivergence intrinsic, porousWalls yes. */
    TRY(model_select_index(d, "ppeDivergence", "PPE divergence",
                           TABLE(divergence_table),
                           s->model == COUPLING_MODEL_B ? "superficial"
                                                        : "intrinsic",
                           &s->superficial));
    if (s->superficial && s->model == COUPLING_MODEL_A)
        return dict_error(d, "ppeDivergence", SIM_ERR_DICT,
                          "ppeDivergence superficial applies to model B only "
                          "(model A's hydrostatic state needs the intrinsic "
                          "form: models.c)");
    TRY(dict_get_bool_or(d, "porousWalls", 0, &s->porous_walls));
    TRY(dict_get_scalar_or(d, "porosityMin", 0.3, &s->eps_min));
    if (!(s->eps_min > 0 && s->eps_min < 1))
        return dict_error(d, "porosityMin", SIM_ERR_DICT,
                          "porosityMin %g must lie in (0, 1)",
                          s->eps_min);
    return SIM_OK;
}

void coupling_grain_force(enum coupling_model m, int ng, const double *Fd,
                          const double *eps_k, const double *gradp_k,
                          const double *V, double rho_f, const double g[3],
                          const uint8_t *wet, double *Fint)
{
#pragma omp parallel for schedule(static) if (ng > 512)
    for (int k = 0; k < ng; k++) {
        for (int c = 0; c < 3; c++) {
            double f;
            if (wet && !wet[k])
                f = 0.0;
            else if (m == COUPLING_MODEL_A)
                f = Fd[3 * k + c] - V[k] * gradp_k[3 * k + c];
            else
                f = Fd[3 * k + c] / eps_k[k] - V[k] * rho_f * g[c];
            Fint[3 * k + c] = f;
        }
    }
}

void coupling_reaction_input(enum coupling_model m, int conservative, int ng,
                             const double *Fbar, const double *eps_k,
                             double *out)
{
    int divide = m == COUPLING_MODEL_B && conservative;
    for (int k = 0; k < ng; k++)
        for (int c = 0; c < 3; c++)
            out[3 * k + c] = divide ? Fbar[3 * k + c] / eps_k[k]
                                    : Fbar[3 * k + c];
}

void coupling_mps_accel(enum coupling_model m, int conservative, int np,
                        const double *eps, const double *fA, double rho_f,
                        const double g[3], const uint8_t *rows, double *a)
{
    /* Model B divides the reaction by eps_i once more, unless the grains
     * already did (conservative form). */
    int extra = m == COUPLING_MODEL_B && !conservative;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < np; i++) {
        if (rows && !rows[i])
            continue;
        double inv = 1.0 / eps[i];
        for (int c = 0; c < 3; c++) {
            double f = fA[3 * (int64_t)i + c] / rho_f * inv;
            if (extra)
                f *= inv;
            a[3 * (int64_t)i + c] = m == COUPLING_MODEL_A
                                        ? -f
                                        : -f + g[c] * (inv - 1.0);
        }
    }
}

void coupling_ppe_source_factor(enum coupling_model m, int np,
                                const double *eps, double *s)
{
#pragma omp parallel for schedule(static)
    for (int i = 0; i < np; i++)
        s[i] = m == COUPLING_MODEL_A ? 1.0 : eps[i];
}

void coupling_correction_factor(enum coupling_model m, int np,
                                const double *eps, double *c)
{
#pragma omp parallel for schedule(static)
    for (int i = 0; i < np; i++)
        c[i] = m == COUPLING_MODEL_A ? 1.0 : 1.0 / eps[i];
}

int coupling_guard_grain_size(int ng, const double *d, double re_s)
{
    int n = 0;
    double dmax = 0;
    for (int k = 0; k < ng; k++)
        if (d[k] * 3.0 > re_s) {
            n++;
            dmax = fmax(dmax, d[k]);
        }
    if (n)
        log_warn("%d grains are larger than a third of the coupling kernel "
                 "radius (largest d = %g m, r_e,s = %g m): porosity (31) "
                 "will be noisy; raise kernelRadius in system/couplingDict "
                 "to at least 3 d/dp", n, dmax, re_s);
    return n;
}

long coupling_guard_porosity(long n_clamped, int np, double eps_min)
{
    if (n_clamped > 0)
        log_warn("porosity below the floor porosityMin = %g at %ld of %d "
                 "MPS particles (clamped): grains overlap within the "
                 "coupling kernel; a larger kernelRadius smooths eq. (31)",
                 eps_min, n_clamped, np);
    return n_clamped;
}

int coupling_guard_relaxation(const struct drag_ops *drag,
                              const struct drag_fluid *f, int ng,
                              const double *eps_k, const double *u_k,
                              const double *v_k, const double *d,
                              double rho_s, double dt, double *tau_min)
{
    int n = 0;
    double tmin = INFINITY;
    for (int k = 0; k < ng; k++) {
        double s2 = 0;
        for (int c = 0; c < 3; c++)
            s2 += (u_k[3 * k + c] - v_k[3 * k + c]) *
                  (u_k[3 * k + c] - v_k[3 * k + c]);
        double K = drag->coeff(f, eps_k[k], sqrt(s2), d[k]);
        /* Model B's grains feel F^d/eps: the shorter of the two times */
        double tau = K > 0 ? rho_s * eps_k[k] / K : INFINITY;
        tmin = fmin(tmin, tau);
        n += tau < dt;
    }
    if (n)
        log_warn("%d grains have a drag relaxation time shorter than the "
                 "fluid step (shortest %g s < dt = %g s): the drag must be "
                 "sub-stepped on the DEM side", n, tmin, dt);
    if (tau_min)
        *tau_min = tmin;
    return n;
}

int couple_enabled(const struct dict *coupling, int *on)
{
    static const char *const schemes[] = { "sequential", "concurrent", NULL };
    int idx;
    *on = 0;
    if (!coupling)
        return SIM_OK;
    TRY(dict_get_bool_or(coupling, "coupled", 1, on));
    TRY(dict_get_word_or(coupling, "scheme", schemes, 0, &idx));
    if (*on) {
        /* The channel opens after the first output is written; a bad
         * timeout must stop the run before it touches anything. */
        struct channel_settings cs;
        TRY(channel_settings_default(&cs, CHANNEL_SOLID, "", "."));
        TRY(channel_settings_from_dict(coupling, &cs));
    }
    return SIM_OK;
}
