/*
 * integrator_arkode.c — error-controlled explicit Runge-Kutta sub-stepping
 * with SUNDIALS ARKode ERKStep 6.4.1 (doc/libraries.md §1), for
 *
 *   y = (x, v, w),  dx/dt = v,  dv/dt = a(x, v, w),  dw/dt = alpha(x, v, w)
 *
 * (doc/theory.md A.6, eqs. 17-18). Step size: ARKode's error control with
 * rtol and a vector atol (positions, velocities, spins), bounded by a
 * stability function:
 *
 *   h_stab = safety * min( dt_R (eq. 38, coefficient 0.1631),
 *                          2/omega_max, h_move ) while a contact is active,
 *            omega_max^2 = max over contacts of kn/m* (stiffest contact);
 *   h_move = min_i (max(gap_i, 0) + R_i/4) / |v_i|    (gap_i: distance to
 *            the nearest wall) and (skin/2 - max displacement)/|v|_max for
 *            pairs, so that no stage skips a wall or leaves the skin.
 *
 * With no contact only h_move and accuracy limit the step: a ballistic phase
 * takes large steps (gravity alone is integrated exactly by any RK method).
 * Every call ends exactly at t_end (SetStopTime). Tangential springs are
 * extrapolated inside a step, delta^t = delta^t_n + (t - t_n) v^t, and
 * committed at accepted steps by one extra force evaluation at the accepted
 * state (post-step hook), counted separately (hist_evals).
 *
 * With a drag law set, the state carries a fourth block, the drag impulse J_k = int F^d_k dt
 * (excluded from the error test by a huge atol): integrated by the same
 * Runge-Kutta weights as the momentum, its increment over an advance is
 * exactly the drag the grains received, so the averaged drag returned to
 * the fluid (eq. 36) balances the momentum to round-off.
 */
#include <arkode/arkode_erkstep.h>
#include <math.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "dem/dem.h"
#include "dem/integrators/integrator.h"

struct ark {
    SUNContext sun;
    void *mem;
    N_Vector y, atol, scratch;
    size_t n;                  /* grains the vectors were made for */
    double t_acc;              /* last accepted time               */
    struct dem *d;
    struct dem_integrator_params p;
    char msg[512];             /* last SUNDIALS error message      */
    int reset;                 /* re-create at the next advance    */
    int impulse;               /* state carries the drag impulse   */
};

static int rhs(realtype t, N_Vector y, N_Vector ydot, void *ud)
{
    struct ark *a = ud;
    struct dem *d = a->d;
    size_t n3 = 3 * d->n;
    double *yy = N_VGetArrayPointer(y), *yd = N_VGetArrayPointer(ydot);
    memcpy(yd, yy + n3, n3 * sizeof *yd);
    int rc = dem_forces(d, t, yy, yy + n3, yy + 2 * n3, t - a->t_acc, 0,
                        yd + n3, yd + 2 * n3);
    if (a->impulse)
        memcpy(yd + 3 * n3, d->cpl.fd, n3 * sizeof *yd);
    return rc == SIM_OK ? 0 : -1;
}

/* Largest step for which no grain moves past a wall or out of the skin.
 * A wall closes the gap at the grain's speed relative to it (a moving wall
 * can overtake a grain at rest). */
static double move_limit(struct dem *d, const double *x, const double *v)
{
    double h = INFINITY, vmax = 0;
    for (size_t i = 0; i < d->n; i++) {
        const double *vi = &v[3 * i];
        double s = sqrt(vi[0] * vi[0] + vi[1] * vi[1] + vi[2] * vi[2]);
        vmax = fmax(vmax, s);
        for (int w = 0; w < d->nwalls; w++) {
            const double *vw = d->walls[w].vel;
            double dv[3] = {vi[0] - vw[0], vi[1] - vw[1], vi[2] - vw[2]};
            double sr = sqrt(dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2]);
            double gap = wall_distance(&d->walls[w], &x[3 * i]) - d->r[i];
            if (sr > 0 && isfinite(gap))
                h = fmin(h, (fmax(gap, 0) + 0.25 * d->r[i]) / sr);
        }
    }
    if (d->n > 1 && vmax > 0) {
        double room = 0.5 * d->nl.skin - nlist_max_displacement(&d->nl, x);
        h = fmin(h, fmax(room, 0.05 * d->nl.skin) / vmax);
    }
    return h;
}

static int stability(N_Vector y, realtype t, realtype *hstab, void *ud)
{
    (void)t;
    struct ark *a = ud;
    struct dem *d = a->d;
    double *yy = N_VGetArrayPointer(y);
    double h = move_limit(d, yy, yy + 3 * d->n);
    double hc = dem_contact_step(d);
    if (hc > 0)
        h = fmin(h, hc);
    *hstab = isfinite(h) ? h : 0.0;  /* <= 0 means "no limit" */
    return 0;
}

static int post_step(realtype t, N_Vector y, void *ud)
{
    struct ark *a = ud;
    struct dem *d = a->d;
    size_t n3 = 3 * d->n;
    double *yy = N_VGetArrayPointer(y), *s = N_VGetArrayPointer(a->scratch);
    double h = t - a->t_acc;
    if (dem_forces(d, t, yy, yy + n3, yy + 2 * n3, h, 1, s + n3, s + 2 * n3))
        return -1;
    d->stats.fevals--;
    d->stats.hist_evals++;
    a->t_acc = t;
    return dem_update_neighbours(d, yy) == SIM_OK ? 0 : -1;
}

static void err_handler(int code, const char *module, const char *func,
                        char *msg, void *ud)
{
    struct ark *a = ud;
    snprintf(a->msg, sizeof a->msg, "%s %s (%d): %s", module, func, code, msg);
}

#define ARKCHECK(call)                                                    \
    do {                                                                  \
        int f_ = (call);                                                  \
        if (f_ < 0)                                                       \
            return sim_error(SIM_ERR_EXTERNAL, "%s failed: %s %s", #call,  \
                             ERKStepGetReturnFlagName(f_), a->msg);       \
    } while (0)

static void free_vectors(struct ark *a)
{
    if (a->mem)
        ERKStepFree(&a->mem);
    if (a->y) N_VDestroy(a->y);
    if (a->atol) N_VDestroy(a->atol);
    if (a->scratch) N_VDestroy(a->scratch);
    a->y = a->atol = a->scratch = NULL;
}

/* (Re)create the ERKStep memory for the current grains and state. */
static int setup(struct ark *a, struct dem *d)
{
    free_vectors(a);
    /* the drag-impulse block only when a drag law is set: the stage
     * arithmetic of ERK grows with the state, and dominates in dense packs */
    a->impulse = d->cpl.drag != NULL;
    size_t n3 = 3 * d->n, len = (a->impulse ? 12 : 9) * (d->n ? d->n : 1);
    a->y = N_VNew_Serial((sunindextype)len, a->sun);
    a->atol = N_VNew_Serial((sunindextype)len, a->sun);
    a->scratch = N_VNew_Serial((sunindextype)len, a->sun);
    if (!a->y || !a->atol || !a->scratch)
        return sim_error(SIM_ERR_NOMEM, "ARKode vectors of length %zu", len);
    /* fused stage combinations: the vector arithmetic of a 7-stage pair is
     * as costly as the contact forces of a dense pack otherwise */
    N_VEnableFusedOps_Serial(a->y, SUNTRUE);
    double *yy = N_VGetArrayPointer(a->y), *at = N_VGetArrayPointer(a->atol);
    memcpy(yy, d->x, n3 * sizeof *yy);
    memcpy(yy + n3, d->v, n3 * sizeof *yy);
    memcpy(yy + 2 * n3, d->w, n3 * sizeof *yy);
    for (size_t k = 0; k < n3; k++) {
        at[k] = a->p.atol_x;
        at[n3 + k] = a->p.atol_v;
        at[2 * n3 + k] = a->p.atol_w;
        if (a->impulse) {
            yy[3 * n3 + k] = 0;
            at[3 * n3 + k] = 1e300;   /* the impulse takes no part in
                                         the error test */
        }
    }
    a->mem = ERKStepCreate(rhs, d->t, a->y, a->sun);
    if (!a->mem)
        return sim_error(SIM_ERR_EXTERNAL, "ERKStepCreate failed");
    ARKCHECK(ERKStepSetErrHandlerFn(a->mem, err_handler, a));
    ARKCHECK(ERKStepSetUserData(a->mem, a));
    ARKCHECK(ERKStepSVtolerances(a->mem, a->p.rtol, a->atol));
    if (a->p.table && a->p.table[0])
        ARKCHECK(ERKStepSetTableName(a->mem, a->p.table));
    ARKCHECK(ERKStepSetStabilityFn(a->mem, stability, a));
    ARKCHECK(ERKStepSetCFLFraction(a->mem, a->p.safety));
    ARKCHECK(ERKStepSetPostprocessStepFn(a->mem, post_step));
    ARKCHECK(ERKStepSetMaxNumSteps(a->mem, a->p.max_steps));
    if (d->h_next > 0)
        ARKCHECK(ERKStepSetInitStep(a->mem, d->h_next));
    a->reset = 0;
    a->n = d->n;
    a->t_acc = d->t;
    return SIM_OK;
}

static int ark_create(struct dem *d, const struct dem_integrator_params *p,
                      void **ctx)
{
    if (!(p->rtol > 0) || !(p->atol_x > 0) || !(p->atol_v > 0)
        || !(p->atol_w > 0))
        return sim_error(SIM_ERR_INPUT,
                         "arkode: rtol and atol must be > 0 (rtol %g, "
                         "atol x/v/w %g %g %g)", p->rtol, p->atol_x, p->atol_v,
                         p->atol_w);
    if (!(p->safety > 0 && p->safety < 1))
        return sim_error(SIM_ERR_INPUT,
                         "arkode: stabilitySafety %g must be in (0, 1)",
                         p->safety);
    struct ark *a = sim_calloc(1, sizeof *a);
    if (!a)
        return SIM_ERR_NOMEM;
    a->p = *p;
    a->d = d;
    /* a stage may carry a grain well past skin/2 towards a wall (the step
     * is limited by the wall gap, not the skin): check every wall */
    d->use_wlist = 0;
    if (SUNContext_Create(NULL, &a->sun)) {
        free(a);
        return sim_error(SIM_ERR_EXTERNAL, "SUNContext_Create failed");
    }
    *ctx = a;
    int rc = setup(a, d);
    return rc;
}

/* Non-zero when the grains changed since the vectors were filled. */
static int state_changed(struct ark *a, struct dem *d)
{
    if (a->n != d->n || !a->mem || a->impulse != (d->cpl.drag != NULL))
        return 1;
    size_t n3 = 3 * d->n;
    const double *yy = N_VGetArrayPointer(a->y);
    return memcmp(yy, d->x, n3 * sizeof *yy)
           || memcmp(yy + n3, d->v, n3 * sizeof *yy)
           || memcmp(yy + 2 * n3, d->w, n3 * sizeof *yy);
}

static int ark_advance(void *ctx, struct dem *d, double t_end)
{
    struct ark *a = ctx;
    a->d = d;
    if (!(t_end > d->t))
        return SIM_OK;
    if (a->reset || state_changed(a, d))
        TRY(setup(a, d));
    TRY(dem_update_neighbours(d, N_VGetArrayPointer(a->y)));
    /* One evaluation at the start sets the contact state the stability
     * function needs (and the forces, if the coupling changed them). */
    double *yy = N_VGetArrayPointer(a->y), *s = N_VGetArrayPointer(a->scratch);
    size_t n3 = 3 * d->n;
    TRY(dem_forces(d, d->t, yy, yy + n3, yy + 2 * n3, d->t - a->t_acc, 0,
                   s + n3, s + 2 * n3));
    for (size_t k = 0; k < n3; k++)
        d->cpl.fd_sum[k] -= a->impulse ? yy[3 * n3 + k] : 0.0;
    long ex0, acc0, att, fe, rej0;
    ERKStepGetTimestepperStats(a->mem, &ex0, &acc0, &att, &fe, &rej0);
    ARKCHECK(ERKStepSetStopTime(a->mem, t_end));
    double t = d->t;
    while (t < t_end) {
        int flag = ERKStepEvolve(a->mem, t_end, a->y, &t, ARK_NORMAL);
        if (flag < 0)
            return sim_error(SIM_ERR_EXTERNAL,
                             "arkode: ERKStepEvolve failed at t = %.9g s: %s "
                             "%s", t, ERKStepGetReturnFlagName(flag), a->msg);
        if (flag == ARK_TSTOP_RETURN)
            break;
    }
    long ex1, acc1, rej1;
    ERKStepGetTimestepperStats(a->mem, &ex1, &acc1, &att, &fe, &rej1);
    d->stats.steps += (ex1 + acc1) - (ex0 + acc0);
    d->stats.stab_limited += ex1 - ex0;
    d->stats.rejected += rej1 - rej0;
    for (size_t k = 0; k < n3; k++)
        d->cpl.fd_sum[k] += a->impulse ? yy[3 * n3 + k] : 0.0;
    if (d->cpl.drag)
        d->cpl.sum_time += t_end - d->t;
    memcpy(d->x, yy, n3 * sizeof *yy);
    memcpy(d->v, yy + n3, n3 * sizeof *yy);
    memcpy(d->w, yy + 2 * n3, n3 * sizeof *yy);
    d->t = t_end;
    return SIM_OK;
}

static int ark_checkpoint(void *ctx, struct dem *d)
{
    struct ark *a = ctx;
    double h = 0;
    if (a->mem && ERKStepGetCurrentStep(a->mem, &h) == ARK_SUCCESS && h > 0)
        d->h_next = h;
    a->reset = 1;
    return SIM_OK;
}

static void ark_destroy(void *ctx)
{
    struct ark *a = ctx;
    if (!a)
        return;
    free_vectors(a);
    SUNContext_Free(&a->sun);
    free(a);
}

const struct dem_integrator_ops dem_integrator_arkode = {
    .name = "arkode",
    .reference = "SUNDIALS ARKode ERKStep 6.4.1 (Reynolds et al. 2023)",
    .create = ark_create,
    .advance = ark_advance,
    .checkpoint = ark_checkpoint,
    .destroy = ark_destroy,
};
