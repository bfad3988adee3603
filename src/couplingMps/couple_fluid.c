/*
 * couple_fluid.c — the fluid side of the sequential MPS-DEM step (Xie et al.
 * 2025 eqs. 31-33, 36 with the momentum sources of eqs. 2 and 5;
 * doc/theory.md A.7, A.8 (MSS), A.10 steps 2-3 and 5-7, A0-13 to A0-15).
 *
 *   eps_i   = 1 - (1/n_s) sum_k w_s(|r_ik|) V_k                        (31)
 *   eps_k, u_k = Shepard averages of eps_i, u_i over fluid and wall   (32-33)
 *   f_A,i   = (1/V_i) sum_k F_bar_k w_s(|r_ki|) / sum_j w_s(|r_kj|)    (36)
 *   f_ext,i = A: -f_A,i/(rho eps_i)   B: -f_A,i/(rho eps_i^2) + g(1/eps_i - 1)
 *
 * Time levels (A0-15, DEM first): the fields sent at t^m are interpolated
 * with the porosity eps^m of both phases' positions at t^m; the DEM answers
 * with its state at t^{m+1}; eps^{m+1} and f_A are then computed at the new
 * grain positions and held frozen through mps_step().
 */
#include "couplingMps/couple_fluid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/dict.h"
#include "core/app.h"
#include "core/error.h"
#include "core/log.h"
#include "coupling/channel.h"
#include "coupling/porosity.h"
#include "coupling/protocol.h"
#include "coupling/reaction.h"
#include "mps/mps.h"

static int grow_grains(struct couple_fluid *cf, int ng)
{
    if (ng <= cf->cap_g && cf->xg)
        return SIM_OK;
    int cap = ng > 2 * cf->cap_g ? ng : 2 * cf->cap_g;
    SIM_GROW(cf->xg, 3 * cap);
    SIM_GROW(cf->vg, 3 * cap);
    SIM_GROW(cf->rg, cap);
    SIM_GROW(cf->Vg, cap);
    SIM_GROW(cf->Vs, cap);
    SIM_GROW(cf->Fbar, 3 * cap);
    SIM_GROW(cf->Fin, 3 * cap);
    SIM_GROW(cf->eps_k, cap);
    SIM_GROW(cf->u_k, 3 * cap);
    SIM_GROW(cf->gradp_k, 3 * cap);
    SIM_GROW(cf->wet, cap);
    SIM_GROW(cf->gsum, COUPLING_SUMS * cap);
    cf->cap_g = cap;
    return SIM_OK;
}

static int grow_particles(struct couple_fluid *cf, int cap)
{
    if (cap <= cf->cap_p && cf->eps)
        return SIM_OK;
    SIM_GROW(cf->eps, cap);
    SIM_GROW(cf->fA, 3 * cap);
    SIM_GROW(cf->gradp_p, 3 * cap);
    SIM_GROW(cf->mask, cap);
    SIM_GROW(cf->id_seen, cap);
    cf->cap_p = cap;
    return SIM_OK;
}

int couple_fluid_init(struct couple_fluid *cf, const struct dict *coupling,
                      struct mps_solver *s)
{
    struct mps_particles *P = &s->P;
    memset(cf, 0, sizeof *cf);
    cf->dict = coupling;
    static const char *const schemes[] = { "sequential", "concurrent", NULL };
    TRY(coupling_settings_read(coupling, &cf->cs));
    TRY(dict_get_word_or(coupling, "scheme", schemes, 0, &cf->concurrent));
    cf->dim = P->dim;
    cf->dp = s->dp;
    cf->re = cf->cs.radius * s->dp;
    cf->Vp = s->dp * s->dp * s->dp;
    cf->rho = s->S.rho;
    memcpy(cf->g, s->S.g, sizeof cf->g);
    int cap = P->cap > P->n ? P->cap : P->n;
    TRY(grow_particles(cf, cap));
    /* Model A's factors are 1: its solver gets no hooks for them. */
    TRY(mps_particles_add(P, MPS_P_INV_EPS | MPS_P_F_EXT
                             | (cf->cs.model == COUPLING_MODEL_B
                                ? MPS_P_PPE_SCALE | MPS_P_CORR_SCALE : 0)));
    for (int i = 0; i < cap; i++) {
        P->inv_eps[i] = 1.0;
        cf->eps[i] = 1.0;
        if (P->ppe_scale)
            P->ppe_scale[i] = P->corr_scale[i] = 1.0;
    }
    log_info("Coupling: r_e,s = %g m (%g dp), porosity floor %g, pair skin "
             "%g dp%s", cf->re, cf->cs.radius, cf->cs.eps_min, cf->cs.skin,
             cf->dim == 2 ? "; 2-D slab one dp deep" : "");
    s->S.phi_relax_time = cf->cs.phi_relax;
    s->S.scaled_divergence = cf->cs.superficial;
    if (cf->cs.phi_relax > 0) {
        if (P->phi)
            log_info("Coupling: water content phi/eps relaxed over %g s "
                     "(volumeFractionRelaxation)", cf->cs.phi_relax);
        else {
            char at[512];
            log_warn("%s: volumeFractionRelaxation %g has no effect: the "
                     "fluid particles hold no volumeFraction (genParticles "
                     "grainVolume scale)",
                     dict_where(coupling, "volumeFractionRelaxation", at,
                                sizeof at), cf->cs.phi_relax);
        }
    }
    return SIM_OK;
}

/* Room for ng grains; those added since the last state get the fields
 * of a dry grain (nothing was sent for them). */
static int room_for_grains(struct couple_fluid *cf, int ng)
{
    TRY(grow_grains(cf, ng));
    for (int k = cf->ng; k < ng; k++) {
        cf->eps_k[k] = 1.0;
        cf->wet[k] = 0;
    }
    return SIM_OK;
}

/* Sphere volumes and the measures of eq. (31) from the radii. */
static int grain_volumes(struct couple_fluid *cf, int ng)
{
    for (int k = 0; k < ng; k++) {
        double r = cf->rg[k];
        if (!(r > 0) || !isfinite(r))
            return sim_error(SIM_ERR_PEER, "DEM state: grain %d has radius "
                             "%g", k, r);
        cf->Vs[k] = 4.0 / 3.0 * M_PI * r * r * r;
        cf->Vg[k] = coupling_grain_measure(cf->dim, r, cf->dp);
    }
    return SIM_OK;
}

int couple_fluid_set_grains(struct couple_fluid *cf,
                            const struct proto_dem_state *st, double t)
{
    if (st->n > 1000000000)
        return sim_error(SIM_ERR_PEER, "DEM state with %zu grains", st->n);
    int ng = (int)st->n, grew = ng != cf->ng;
    TRY(room_for_grains(cf, ng));
    memcpy(cf->xg, st->position, 3 * (size_t)ng * sizeof *cf->xg);
    memcpy(cf->vg, st->velocity, 3 * (size_t)ng * sizeof *cf->vg);
    memcpy(cf->rg, st->radius, (size_t)ng * sizeof *cf->rg);
    memcpy(cf->Fbar, st->drag, 3 * (size_t)ng * sizeof *cf->Fbar);
    TRY(grain_volumes(cf, ng));
    if (grew && ng > 0) {
        double *d = malloc((size_t)ng * sizeof *d);
        if (!d)
            return SIM_ERR_NOMEM;
        for (int k = 0; k < ng; k++)
            d[k] = 2 * cf->rg[k];
        coupling_guard_grain_size(ng, d, cf->re);
        free(d);
    }
    cf->ng = ng;
    cf->dem_time = t;
    return SIM_OK;
}

/* Particle order changes at every renumbering (and particles leave): a
 * pair list with a skin is only reusable while the ids are unchanged. */
static void check_order(struct couple_fluid *cf, const struct mps_particles *P)
{
    if (P->n != cf->n_seen
        || memcmp(P->id, cf->id_seen, (size_t)P->n * sizeof *P->id) != 0) {
        coupling_pairs_invalidate(&cf->pairs);
        memcpy(cf->id_seen, P->id, (size_t)P->n * sizeof *P->id);
        cf->n_seen = P->n;
    }
}

/* The grain-particle pairs at the current positions and particle order.
 * pairSkin 0: a search at every call (twice a step), so that a restart,
 * which starts from the positions alone, repeats the continuous run to the
 * bit. pairSkin > 0: the list of the last search while the particle order
 * is the same and both clouds moved less than the skin since (a search
 * every few steps, when the MPS list renumbers), its pairs measured again
 * in between, at the price of that bit-identity. */
static int find_pairs(struct couple_fluid *cf, const struct mps_particles *P)
{
    if (cf->cs.skin > 0)
        check_order(cf, P);
    int searched;
    TRY(coupling_pairs_update(&cf->pairs, cf->dim, cf->re,
                              cf->cs.skin * cf->dp, cf->ng, cf->xg, P->n,
                              P->x, &searched));
    cf->searches += searched;
    return SIM_OK;
}

/* The particles that contribute to the grains' sums and take a share of
 * their reaction: fluid and wall (A0-13). own_only: of a distributed run,
 * only this rank's own particles, so that a sum over the ranks counts
 * each particle once. */
static void share_mask(struct couple_fluid *cf, const struct mps_solver *s,
                       int own_only)
{
    const struct mps_particles *P = &s->P;
    const int n = own_only ? mps_own(s) : P->n;
    for (int i = 0; i < P->n; i++)
        cf->mask[i] = i < n && P->type[i] != MPS_DUMMY;
}

int couple_fluid_update(struct couple_fluid *cf, struct mps_solver *s)
{
    struct mps_particles *P = &s->P;
    double t0 = app_wall_time();
    TRY(grow_particles(cf, P->cap > P->n ? P->cap : P->n));
    TRY(find_pairs(cf, P));
    TRY(coupling_porosity(&cf->pairs, cf->Vg, cf->cs.eps_min, cf->eps,
                          P->inv_eps, &cf->n_clamped));
    /* Particles that hold phi_i dp^d of fluid (genParticles grainVolume
     * scale) count phi_j/eps_j in every neighbour sum (eq. 7 and the
     * operators), so that a packed bed starts at <n> = n0. */
    /* porousWalls no: a wall or dummy particle stands for dp^d of wall
     * whatever grains lie near it, so it counts 1 in <n>_i and the
     * operators, as a fluid particle at phi = eps does (with 1/eps_w the
     * floor under a bed counts up to twice). Its porosity still scales its
     * PPE row (Model B) and still feeds the grains' Shepard averages. */
    for (int i = 0; i < P->n; i++)
        if (!cf->cs.porous_walls && P->type[i] != MPS_FLUID)
            P->inv_eps[i] = 1.0;
        else if (P->phi)
            P->inv_eps[i] *= P->phi[i];
    coupling_reaction_input(cf->cs.model, cf->cs.conservative, cf->ng,
                            cf->Fbar, cf->eps_k, cf->Fin);
    if (s->halo) {
        /* each grain's weight over every rank's own particles; then every
         * particle held here, ghosts too, takes its share */
        share_mask(cf, s, 1);
        coupling_reaction_weights(&cf->pairs, cf->mask, cf->gsum);
        s->halo->ops->reduce(s->halo, cf->gsum, cf->ng, POP_SUM);
        share_mask(cf, s, 0);
        TRY(coupling_reaction_given(&cf->pairs, cf->gsum, cf->mask, cf->Fin,
                                    cf->Vp, P->phi, cf->fA, &cf->n_orphan));
        long clamped = 0;
        for (int i = 0; i < mps_own(s); i++)
            clamped += cf->eps[i] <= cf->cs.eps_min;
        cf->n_clamped = (long)pop_halo_reduce1(s->halo, (double)clamped,
                                               POP_SUM);
    } else {
        share_mask(cf, s, 0);
        TRY(coupling_reaction(&cf->pairs, cf->mask, cf->Fin, cf->Vp, P->phi,
                              cf->fA, &cf->n_orphan));
    }
    memset(P->f_ext, 0, 3 * (size_t)P->n * sizeof *P->f_ext);
    for (int i = 0; i < P->n; i++)
        cf->mask[i] = P->type[i] == MPS_FLUID;
    coupling_mps_accel(cf->cs.model, cf->cs.conservative, P->n, cf->eps,
                       cf->fA, cf->rho, cf->g, cf->mask, P->f_ext);
    if (P->ppe_scale) {
        coupling_ppe_source_factor(cf->cs.model, P->n, cf->eps, P->ppe_scale);
        coupling_correction_factor(cf->cs.model, P->n, cf->eps,
                                   P->corr_scale);
    }
    cf->wall += app_wall_time() - t0;
    return SIM_OK;
}

/* Porosity below which a start is "among grains": a fluid particle that
 * fills its site at eps = 0.95 reads as 5 % compressed, which the PPE
 * turns into a pressure of order the hydrostatic one in the first step. */
#define PACKED_EPS 0.95

/* Before the first step: warn, naming the keys, when the grains meet one of
 * the combinations that the sedimentation case and a 9 % suspension showed
 * to be unstable or wrong (doc/theory.md A0-03, A0-04, A0-16): fluid
 * particles that fill the pores (grainVolume fill), the literal Model B
 * PPE source (ppeDivergence intrinsic) or walls weighted 1/eps (porousWalls
 * yes), each where the porosity is below PACKED_EPS. */
static void check_start(const struct couple_fluid *cf,
                        const struct mps_solver *s)
{
    const struct mps_particles *P = &s->P;
    int nf = 0, nfill = 0, nw = 0;
    double ef = 1, ew = 1;
    for (int i = 0; i < mps_own(s); i++) {
        if (cf->eps[i] >= PACKED_EPS)
            continue;
        if (P->type[i] == MPS_FLUID) {
            nf++;
            ef = fmin(ef, cf->eps[i]);
            nfill += !P->phi || P->phi[i] > cf->eps[i] + 0.02;
        } else {
            nw++;
            ew = fmin(ew, cf->eps[i]);
        }
    }
    if (s->halo) {
        double n[3] = { nf, nfill, nw }, e[2] = { ef, ew };
        s->halo->ops->reduce(s->halo, n, 3, POP_SUM);
        s->halo->ops->reduce(s->halo, e, 2, POP_MIN);
        nf = (int)n[0], nfill = (int)n[1], nw = (int)n[2];
        ef = e[0], ew = e[1];
    }
    char at[512];
    if (nfill)
        log_warn("%d fluid particle(s) fill their site where the grains "
                 "leave a porosity down to %.2f: they start compressed by "
                 "up to %.0f %% and the pressure equation will throw the "
                 "water out of the grains. Regenerate the particles with "
                 "`grainVolume scale;` in the fluid region of "
                 "system/particleDict (the default when system/couplingDict "
                 "exists; `fill` is the paper's reading, A0-16)", nfill, ef,
                 100 * (1 / ef - 1));
    if (nf && cf->cs.model == COUPLING_MODEL_B && !cf->cs.superficial)
        log_warn("%s: ppeDivergence intrinsic (the paper's eq. 13 read "
                 "literally) with %d fluid particle(s) among grains (porosity "
                 "down to %.2f): it is not hydrostatic where the porosity "
                 "varies (+21 %% on the floor of the sedimentation case); "
                 "`superficial` (the default) keeps it hydrostatic",
                 dict_where(cf->dict, "ppeDivergence", at, sizeof at), nf,
                 ef);
    if (nw && cf->cs.porous_walls)
        log_warn("%s: porousWalls yes with %d wall or dummy particle(s) "
                 "among grains (porosity down to %.2f): they count up to "
                 "%.1f times in the number density and the water over a bed "
                 "rings; `no` (the default) weighs them 1",
                 dict_where(cf->dict, "porousWalls", at, sizeof at), nw, ew,
                 1 / ew);
}

int couple_fluid_grain_fields(struct couple_fluid *cf, struct mps_solver *s)
{
    struct mps_particles *P = &s->P;
    double t0 = app_wall_time();
    /* the step renumbered and moved the particles (and brought ghosts to
     * a distributed run); the grains are where the porosity was computed
     * for */
    TRY(grow_particles(cf, P->cap > P->n ? P->cap : P->n));
    TRY(find_pairs(cf, P));
    /* eps^m at the current positions of both phases (A.10 step 2), not
     * the values the last step used (computed before the particles moved):
     * then a restart, which starts from the positions alone, repeats the
     * continuous run. */
    TRY(coupling_porosity(&cf->pairs, cf->Vg, cf->cs.eps_min, cf->eps, NULL,
                          NULL));
    share_mask(cf, s, 0);
    const double *gp = NULL;
    /* Model A: consistent gradient (A0-14) on the solver's last list; its
     * weights are one step old (positions moved by dt u), and before the
     * first step there is no list: then no gradient is sent. */
    if (cf->cs.model == COUPLING_MODEL_A && s->nl.start && s->nl.n == P->n) {
        const struct pop_weights Wg = mps_w(s, MPS_W_G);
        coupling_gradient_consistent(&s->nl, &Wg,
                                     cf->dim, s->Lg.n0, P->x, P->p,
                                     P->inv_eps, cf->mask, cf->gradp_p);
        gp = cf->gradp_p;
    }
    struct coupling_grain_fields G = { .eps = cf->eps_k, .u = cf->u_k,
                                       .gradp = gp ? cf->gradp_k : NULL,
                                       .wet = cf->wet };
    if (s->halo) {
        share_mask(cf, s, 1);
        coupling_interp_sums(&cf->pairs, cf->mask, cf->eps, P->u, gp,
                             cf->gsum);
        s->halo->ops->reduce(s->halo, cf->gsum, COUPLING_SUMS * cf->ng,
                             POP_SUM);
        coupling_interp_finish(cf->ng, cf->gsum, gp != NULL, &G);
    } else {
        coupling_interp_grains(&cf->pairs, cf->mask, cf->eps, P->u, gp, &G);
    }
    if (cf->cs.model == COUPLING_MODEL_A && !gp)
        memset(cf->gradp_k, 0, 3 * (size_t)cf->ng * sizeof *cf->gradp_k);
    cf->wall += app_wall_time() - t0;
    return SIM_OK;
}

void couple_fluid_reaction_total(const struct couple_fluid *cf,
                                 const struct mps_solver *s, double F[3])
{
    F[0] = F[1] = F[2] = 0;
    for (int i = 0; i < mps_own(s) && i < cf->pairs.np; i++)
        for (int c = 0; c < 3; c++)
            F[c] += cf->Vp * cf->fA[3 * i + c];
    if (s->halo)
        s->halo->ops->reduce(s->halo, F, 3, POP_SUM);
}

void couple_fluid_reaction_field(const struct couple_fluid *cf,
                                 const struct mps_particles *P, double *F)
{
    int m = P->n < cf->pairs.np ? P->n : cf->pairs.np;
    for (int i = 0; i < m; i++) {
        double V = P->phi ? cf->Vp * P->phi[i] : cf->Vp; /* V_i of eq. (36) */
        for (int c = 0; c < 3; c++)
            F[3 * i + c] = -V * cf->fA[3 * i + c];
    }
    memset(F + 3 * (size_t)m, 0, 3 * (size_t)(P->n - m) * sizeof *F);
}

int couple_fluid_open(struct couple_fluid *cf, const struct mps_solver *s,
                      const struct dict *coupling, const char *case_dir,
                      const char *program, double end_time)
{
    struct channel_settings cs;
    TRY(channel_signals_install());
    if (s->halo && s->halo->rank > 0)
        return SIM_OK;          /* rank 0 holds the channel */
    TRY(channel_settings_default(&cs, CHANNEL_FLUID, program, case_dir));
    TRY(channel_settings_from_dict(coupling, &cs));
    cs.dimension = cf->dim;
    cs.end_time = end_time;
    return channel_open(&cs, &cf->ch);
}

/* A distributed run: rank 0 holds the channel, and the outcome of each
 * of its channel operations reaches every rank, so that the ranks stop
 * together (and write their state together) or go on together. */
static int agree(const struct mps_solver *s, int rc)
{
    struct pop_halo *h = s->halo;
    if (!h)
        return rc;
    int v = rc;
    h->ops->bcast(h, &v, sizeof v);
    if (h->rank > 0 && v)
        return sim_error(v, "coupling: the exchange with demSolid failed on "
                         "rank 0 (its log says why)");
    return rc;
}

/* Rank 0's grains to the other ranks of a distributed run. */
static int share_grains(struct couple_fluid *cf, const struct mps_solver *s)
{
    struct pop_halo *h = s->halo;
    double head[2] = { cf->ng, cf->dem_time };
    h->ops->bcast(h, head, sizeof head);
    int ng = (int)head[0];
    if (h->rank > 0)
        TRY(room_for_grains(cf, ng));
    h->ops->bcast(h, cf->xg, 3 * (size_t)ng * sizeof *cf->xg);
    h->ops->bcast(h, cf->vg, 3 * (size_t)ng * sizeof *cf->vg);
    h->ops->bcast(h, cf->rg, (size_t)ng * sizeof *cf->rg);
    h->ops->bcast(h, cf->Fbar, 3 * (size_t)ng * sizeof *cf->Fbar);
    if (h->rank > 0) {
        TRY(grain_volumes(cf, ng));
        cf->ng = ng;
        cf->dem_time = head[1];
    }
    return SIM_OK;
}

static int receive_channel(struct couple_fluid *cf, double t_expect,
                           double tol)
{
    struct channel_frame f;
    const void *pl;
    struct proto_dem_state st;
    double t0 = app_wall_time();
    TRY(channel_recv(cf->ch, &f, &pl));
    cf->wait += app_wall_time() - t0;
    int rc = proto_view_dem_state(&f, pl, &st);
    if (!rc && fabs(f.time - t_expect) > tol)
        rc = sim_error(SIM_ERR_INPUT, "coupling: the DEM side is at t = %.9g "
                       "s, the fluid expects %.9g s: deltaT, startTime and "
                       "endTime of system/controlDict must agree for "
                       "mpsFluid and demSolid (fixed deltaT; the DEM deltaT "
                       "is the coupling interval)", f.time, t_expect);
    if (!rc)
        rc = couple_fluid_set_grains(cf, &st, f.time);
    int rc2 = channel_recv_done(cf->ch);
    return rc ? rc : rc2;
}

static int receive_dem(struct couple_fluid *cf, const struct mps_solver *s,
                       double t_expect, double tol)
{
    int root = !s->halo || s->halo->rank == 0;
    TRY(agree(s, root ? receive_channel(cf, t_expect, tol) : SIM_OK));
    return s->halo ? share_grains(cf, s) : SIM_OK;
}

static int send_fluid(struct couple_fluid *cf, const struct mps_solver *s,
                      long step, double t)
{
    struct proto_fluid_state fs = {
        .n = (size_t)cf->ng, .velocity = cf->u_k, .porosity = cf->eps_k,
        .grad_p = cf->cs.model == COUPLING_MODEL_A ? cf->gradp_k : NULL };
    if (s->halo && s->halo->rank > 0)
        return agree(s, SIM_OK);
    return agree(s, proto_send_fluid_state(cf->ch, (uint64_t)step, t, &fs));
}

int couple_fluid_exchange(struct couple_fluid *cf, struct mps_solver *s,
                          long step, double t, double dt)
{
    double tol = 1e-6 * dt;
    if (cf->concurrent) {
        /* DEM state at t (drag of the interval before), then our state at
         * t: the DEM advances while we step */
        TRY(receive_dem(cf, s, t, tol));
        if (cf->exchanges == 0)
            for (int k = 0; k < cf->ng; k++)
                cf->eps_k[k] = 1.0;
        TRY(couple_fluid_update(cf, s));
        if (cf->exchanges == 0)
            check_start(cf, s);
        TRY(couple_fluid_grain_fields(cf, s));
        TRY(send_fluid(cf, s, step, t));
        cf->exchanges++;
        return SIM_OK;
    }
    if (cf->exchanges == 0) {
        /* initial state at t: porosity eps^m before the first send */
        TRY(receive_dem(cf, s, t, tol));
        for (int k = 0; k < cf->ng; k++)
            cf->eps_k[k] = 1.0;
        TRY(couple_fluid_update(cf, s));
        check_start(cf, s);
    }
    TRY(couple_fluid_grain_fields(cf, s));
    TRY(send_fluid(cf, s, step, t));
    TRY(receive_dem(cf, s, t + dt, tol));
    TRY(couple_fluid_update(cf, s));
    if (cf->n_clamped > 0 && cf->exchanges % 100 == 0)
        coupling_guard_porosity(cf->n_clamped, s->halo
                                ? (long)pop_halo_reduce1(s->halo, mps_own(s),
                                                         POP_SUM)
                                : s->P.n, cf->cs.eps_min);
    cf->exchanges++;
    return SIM_OK;
}

void couple_fluid_close(struct couple_fluid *cf, int rc)
{
    if (cf->ch)
        channel_close(cf->ch, rc);
    cf->ch = NULL;
}

void couple_fluid_free(struct couple_fluid *cf)
{
    couple_fluid_close(cf, SIM_OK);
    coupling_pairs_free(&cf->pairs);
    free(cf->xg); free(cf->vg); free(cf->rg); free(cf->Vg); free(cf->Vs);
    free(cf->Fbar); free(cf->Fin); free(cf->eps_k); free(cf->u_k);
    free(cf->gradp_k); free(cf->wet); free(cf->gsum);
    free(cf->eps); free(cf->fA); free(cf->gradp_p);
    free(cf->mask); free(cf->id_seen);
    memset(cf, 0, sizeof *cf);
}
