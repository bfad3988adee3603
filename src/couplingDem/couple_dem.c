/*
 * couple_dem.c — the DEM side of the sequential MPS-DEM step (Xie et al.
 * 2025 eqs. 25-28, 34, 35; doc/theory.md A.7, A.8 (MSS), A.10 step 4).
 *
 *   A: F^int_k = F^d_k - V_k gradP_k                                   (34)
 *   B: F^int_k = F^d_k / eps_k - V_k rho_f g                           (35)
 *   F^d_k = K(eps_k, |u_k - v_k|, d_k) V_k (u_k - v_k)                 (25)
 *
 * The pressure-gradient / buoyancy part is constant over the interval and
 * goes to the DEM as an external force; the drag part is a function of the
 * grain's current velocity, evaluated by the DEM at every sub-step and
 * stage with u_k, eps_k frozen (A.8). dem_mean_drag() returns the time
 * average of what the grains received; for Model B that is F^d/eps_k with
 * eps_k constant over the interval, so multiplying back by eps_k gives the
 * average of F^d of eq. (25) exactly, which is what the fluid's reaction
 * (36) spreads (reaction.h).
 */
#include "couplingDem/couple_dem.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/dict.h"
#include "core/app.h"
#include "core/error.h"
#include "core/log.h"
#include "coupling/channel.h"
#include "coupling/protocol.h"
#include "dem/dem.h"

static const int DIM_RHO[7] = { 1, -3, 0, 0, 0, 0, 0 };
static const int DIM_NU[7] = { 0, 2, -1, 0, 0, 0, 0 };

static int grow(struct couple_dem *cd, size_t n)
{
    if (n <= cd->cap && cd->uf)
        return SIM_OK;
    size_t cap = n > 2 * cd->cap ? n : 2 * cd->cap;
    SIM_GROW(cd->uf, 3 * cap);
    SIM_GROW(cd->eps, cap);
    SIM_GROW(cd->gradp, 3 * cap);
    SIM_GROW(cd->wet, cap);
    SIM_GROW(cd->fext, 3 * cap);
    SIM_GROW(cd->V, cap);
    SIM_GROW(cd->d, cap);
    SIM_GROW(cd->Fapplied, 3 * cap);
    SIM_GROW(cd->Fsend, 3 * cap);
    SIM_GROW(cd->work, 3 * cap);
    SIM_GROW(cd->slip, 3 * cap);
    cd->cap = cap;
    return SIM_OK;
}

int couple_dem_init(struct couple_dem *cd, const struct dict *coupling,
                    const struct dict *transport, const double g[3])
{
    static const char *const schemes[] = { "sequential", "concurrent", NULL };
    double nu;
    memset(cd, 0, sizeof *cd);
    TRY(coupling_settings_read(coupling, &cd->cs));
    TRY(dict_get_word_or(coupling, "scheme", schemes, 0, &cd->concurrent));
    TRY(dict_get_scalar_dim(transport, "rho", DIM_RHO, &cd->fl.rho));
    if (!(cd->fl.rho > 0) || !(cd->fl.rho < 1e6))
        return dict_error(transport, "rho", SIM_ERR_DICT, "fluid density "
                          "rho = %g must lie in (0, 1e6)", cd->fl.rho);
    TRY(dict_get_scalar_dim(transport, "nu", DIM_NU, &nu));
    if (!(nu > 0) || !(nu < 1e3))
        return dict_error(transport, "nu", SIM_ERR_DICT, "kinematic "
                          "viscosity nu = %g must lie in (0, 1e3)", nu);
    cd->fl.mu = cd->fl.rho * nu;
    memcpy(cd->g, g, sizeof cd->g);
    return SIM_OK;
}

/* dem_drag_fn: what the grains receive from the drag at their current
 * velocity v; dry grains nothing. */
static int drag_fn(void *ctx, size_t n, const double *r, const double *v,
                   const double *uf, const double *eps, double *fd)
{
    struct couple_dem *cd = ctx;
    (void)r;
    cd->cs.drag->force_all(&cd->fl, (int)n, eps, cd->d, cd->V, uf, v, fd);
    int b = cd->cs.model == COUPLING_MODEL_B;
#pragma omp parallel for schedule(static) if (n > 2048)
    for (size_t k = 0; k < n; k++) {
        double s = !cd->wet[k] ? 0.0 : b ? 1.0 / eps[k] : 1.0;
        for (int c = 0; c < 3; c++)
            fd[3 * k + c] *= s;
    }
    return SIM_OK;
}

int couple_dem_apply(struct couple_dem *cd, struct dem *d,
                     const struct proto_fluid_state *fs)
{
    size_t n = d->n;
    if (fs->n != n)
        return sim_error(SIM_ERR_PEER, "coupling: the fluid state describes "
                         "%zu grains, the DEM has %zu", fs->n, n);
    if (cd->cs.model == COUPLING_MODEL_A && !fs->grad_p)
        return sim_error(SIM_ERR_PEER, "coupling: model A but the fluid "
                         "state carries no pressure gradient (do both "
                         "programs read the same system/couplingDict?)");
    TRY(grow(cd, n));
    memcpy(cd->uf, fs->velocity, 3 * n * sizeof *cd->uf);
    memcpy(cd->eps, fs->porosity, n * sizeof *cd->eps);
    if (fs->grad_p)
        memcpy(cd->gradp, fs->grad_p, 3 * n * sizeof *cd->gradp);
    /* interp.h: a dry grain (no fluid or wall particle in reach) is sent
     * with eps_k = 1. A wet grain always has eps_k < 1, because its own
     * volume lowers eq. (31) at every particle that contributes to (32),
     * so eps_k = 1 identifies the dry grains without another field. */
    for (size_t k = 0; k < n; k++) {
        if (!(cd->eps[k] > 0 && cd->eps[k] <= 1.0))
            return sim_error(SIM_ERR_PEER, "coupling: porosity %g at grain "
                             "%zu is outside (0, 1]", cd->eps[k], k);
        cd->wet[k] = (uint8_t)(cd->eps[k] < 1.0);
        cd->d[k] = 2 * d->r[k];
        cd->V[k] = 4.0 / 3.0 * M_PI * d->r[k] * d->r[k] * d->r[k];
    }
    memset(cd->work, 0, 3 * n * sizeof *cd->work);   /* drag: drag_fn */
    coupling_grain_force(cd->cs.model, (int)n, cd->work,
                         cd->eps, cd->gradp, cd->V, cd->fl.rho, cd->g,
                         cd->wet, cd->fext);
    dem_coupling_set(d, cd->fext, cd->uf, cd->eps,
                     cd->cs.drag == &drag_none ? NULL : drag_fn, cd);
    cd->n = n;
    return SIM_OK;
}

int couple_dem_after(struct couple_dem *cd, struct dem *d)
{
    size_t n = d->n;
    TRY(grow(cd, n));
    if (d->cpl.drag)
        dem_mean_drag(d, cd->Fapplied);
    else
        memset(cd->Fapplied, 0, 3 * n * sizeof *cd->Fapplied);
    int b = cd->cs.model == COUPLING_MODEL_B;
    for (size_t k = 0; k < n; k++) {
        double s = b && k < cd->n ? cd->eps[k] : 1.0;
        for (int c = 0; c < 3; c++)
            cd->Fsend[3 * k + c] = s * cd->Fapplied[3 * k + c];
    }
    return SIM_OK;
}

void couple_dem_state(const struct couple_dem *cd, const struct dem *d,
                      struct proto_dem_state *st)
{
    *st = (struct proto_dem_state){ .n = d->n, .position = d->x,
                                    .velocity = d->v, .radius = d->r,
                                    .drag = cd->Fsend };
}

int couple_dem_open(struct couple_dem *cd, const struct dict *coupling,
                    const char *case_dir, const char *program, int dim,
                    double end_time)
{
    struct channel_settings cs;
    TRY(channel_signals_install());
    TRY(channel_settings_default(&cs, CHANNEL_SOLID, program, case_dir));
    TRY(channel_settings_from_dict(coupling, &cs));
    cs.dimension = dim;
    cs.end_time = end_time;
    return channel_open(&cs, &cd->ch);
}

int couple_dem_send(struct couple_dem *cd, struct dem *d, long step,
                    double t)
{
    struct proto_dem_state st;
    TRY(grow(cd, d->n));
    if (cd->exchanges == 0)
        memset(cd->Fsend, 0, 3 * d->n * sizeof *cd->Fsend);
    couple_dem_state(cd, d, &st);
    return proto_send_dem_state(cd->ch, (uint64_t)step, t, &st);
}

int couple_dem_recv(struct couple_dem *cd, struct dem *d)
{
    struct channel_frame f;
    const void *pl;
    struct proto_fluid_state fs;
    double t0 = app_wall_time();
    TRY(channel_recv(cd->ch, &f, &pl));
    cd->wait += app_wall_time() - t0;
    int rc = proto_view_fluid_state(&f, pl, &fs);
    if (!rc && fabs(f.time - d->t) > 1e-9 * (1.0 + fabs(d->t)))
        rc = sim_error(SIM_ERR_INPUT, "coupling: the fluid is at t = %.9g s, "
                       "the DEM at %.9g s: startTime and deltaT of "
                       "system/controlDict must agree for mpsFluid and "
                       "demSolid", f.time, d->t);
    if (!rc)
        rc = couple_dem_apply(cd, d, &fs);
    /* Guard (models.h): every 100 intervals, from the second on (the
     * interval is known then). The DEM sub-steps the drag anyway, so this
     * only tells the user why its step count is what it is. */
    if (!rc && cd->exchanges % 100 == 1 && d->n > 0 && cd->cs.drag->coeff)
        coupling_guard_relaxation(cd->cs.drag, &cd->fl, (int)d->n, cd->eps,
                                  cd->uf, d->v, cd->d, d->law.c.rho,
                                  f.time - cd->fluid_time, NULL);
    cd->fluid_time = f.time;
    cd->exchanges++;
    int rc2 = channel_recv_done(cd->ch);
    return rc ? rc : rc2;
}

void couple_dem_totals(const struct couple_dem *cd, const struct dem *d,
                       double drag[3], double press[3], double *slip_max,
                       double *eps_min, double *wet)
{
    size_t n = cd->n < d->n ? cd->n : d->n;
    double smax = 0, emin = 1, nw = 0;
    for (int c = 0; c < 3; c++)
        drag[c] = press[c] = 0;
    for (size_t k = 0; k < n; k++) {
        double s2 = 0;
        for (int c = 0; c < 3; c++) {
            drag[c] += cd->Fsend[3 * k + c];
            press[c] += cd->fext[3 * k + c];
            double du = cd->uf[3 * k + c] - d->v[3 * k + c];
            s2 += du * du;
        }
        if (!cd->wet[k])
            continue;
        nw++;
        smax = fmax(smax, sqrt(s2));
        emin = fmin(emin, cd->eps[k]);
    }
    *slip_max = smax;
    *eps_min = emin;
    *wet = nw;
}

void couple_dem_close(struct couple_dem *cd, int rc)
{
    if (cd->ch)
        channel_close(cd->ch, rc);
    cd->ch = NULL;
}

void couple_dem_free(struct couple_dem *cd)
{
    couple_dem_close(cd, SIM_OK);
    free(cd->uf); free(cd->eps); free(cd->gradp); free(cd->wet);
    free(cd->fext); free(cd->V); free(cd->d); free(cd->Fapplied);
    free(cd->Fsend); free(cd->work); free(cd->slip);
    memset(cd, 0, sizeof *cd);
}
