/*
 * integrator_arkode.c — error-controlled explicit Runge-Kutta sub-stepping
 * with SUNDIALS ARKode ERKStep 6.4.1 (doc/libraries.md §1), for
 *
 *   y = (x, v, w, [J], S),  dx/dt = v,  dv/dt = a(x, v, w, S),
 *   dw/dt = alpha(x, v, w, S),
 *   dS_c/dt = v^t_c - n_c (S_c . dn_c/dt)   while contact c is active,
 *           = 0                             otherwise
 *
 * (doc/theory.md A.6, eqs. 17-20). S holds the tangential spring of every
 * contact slot (the pairs of the neighbour list, then every grain-wall
 * pair), so the springs are integrated by the same Runge-Kutta method as
 * the motion and are part of the error test (atol: atol_x); a contact that
 * starts inside a step starts from 0 at its onset. The transport term keeps
 * a pair spring in the turning tangent plane (dem_forces.c).
 *
 * The Coulomb slider is a phase per slot (dem.h slip_mode): it starts where
 * |F^t| reaches mu |F^n| and ends where the spring stops loading
 * (s^.v^t = 0); inside it the force is -mu |F^n| s^ whatever the state's
 * length. Both are events located by ERKStep's root finding (one function
 * per slot, dem.h slip_g); the step is redone from its start to the event
 * (ARKode's state at a root is an interpolant of a step taken with the old
 * phase), the spring put at the limit there, and the integration restarted
 * (ERKStepReset). Without this the slider acts one step late, a first-order
 * error outside the error test. At accepted steps the springs are projected
 * as the contact law implies (rotation, limit, 0 out of contact: post-step
 * hook, one committing force evaluation counted as hist_evals, after which
 * ARKode re-evaluates the right-hand side), and the phases found there take
 * effect. When the neighbour list is rebuilt the slots change: the springs
 * are carried by the list (nlist_carry) and S is re-laid out
 * (ERKStepResize, which keeps the step size).
 *
 * Step size: ARKode's error control with rtol and a vector atol
 * (positions and springs, velocities, spins), bounded by a stability
 * function:
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
 * Every call ends exactly at t_end (SetStopTime).
 *
 * With a drag law set, the state carries the drag impulse J_k = int F^d_k dt
 * (excluded from the error test by a huge atol): integrated by the same
 * Runge-Kutta weights as the momentum, its increment over an advance is
 * exactly the drag the grains received, so the averaged drag returned to
 * the fluid (eq. 36) balances the momentum to round-off.
 */
#include <arkode/arkode_erkstep.h>
#include <math.h>
#include <nvector/nvector_serial.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "dem/dem.h"
#include "dem/integrators/integrator.h"

struct ark {
    SUNContext sun;
    void *mem;
    N_Vector y, atol, scratch, yprev;
    size_t n;                  /* grains the vectors were made for      */
    size_t npairs;             /* pair slots of the spring block        */
    long nbuilds;              /* neighbour list the slots belong to    */
    struct dem *d;
    struct dem_integrator_params p;
    char msg[512];             /* last SUNDIALS error message           */
    int reset;                 /* re-create at the next advance         */
    int impulse;               /* state carries the drag impulse        */
    int need_eval;             /* no evaluation since the set-up        */
    unsigned char *mode;       /* slip phase per slot (dem.h)           */
    unsigned char *mode_next;  /* as found at the last accepted state   */
    int *rootdir;              /* -1 per slot: slip ends only           */
    int *rootinfo;             /* slots whose slip phase just ended     */
    double *gcache;            /* switching functions of the last
                                  projection, for ARKode's root check at
                                  the same accepted state               */
    double t_gcache;
    int gcache_ok;
    size_t rootdir_cap;
    long events;               /* slip starts and ends located          */
    size_t nroots;             /* armed root functions                  */
};

/* Offset of the spring block in the state. */
static size_t spring_offset(const struct ark *a)
{
    return (a->impulse ? 12 : 9) * a->n;
}

static size_t spring_len(const struct dem *d)
{
    return 3 * (d->nl.npairs + d->n * (size_t)d->nwalls);
}

static int eval(struct ark *a, double t, N_Vector y, N_Vector ydot)
{
    struct dem *d = a->d;
    size_t n3 = 3 * d->n, off = spring_offset(a);
    double *yy = N_VGetArrayPointer(y), *yd = N_VGetArrayPointer(ydot);
    memcpy(yd, yy + n3, n3 * sizeof *yd);
    d->spring_in = yy + off;
    d->spring_rate = yd + off;
    d->slip_mode = a->mode;
    int rc = dem_forces(d, t, yy, yy + n3, yy + 2 * n3, 0.0, 0, yd + n3,
                        yd + 2 * n3);
    d->spring_in = NULL;
    d->spring_rate = NULL;
    d->slip_mode = NULL;
    if (a->impulse)
        memcpy(yd + 3 * n3, d->cpl.fd, n3 * sizeof *yd);
    return rc;
}

static int rhs(realtype t, N_Vector y, N_Vector ydot, void *ud)
{
    return eval(ud, t, y, ydot) == SIM_OK ? 0 : -1;
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

/* Accepted step: the springs the contact law implies at the accepted
 * state (rotated onto the tangent plane, limited by the slider, 0 out of
 * contact) replace the spring block; ARKode re-evaluates f after this. */
static int post_step(realtype t, N_Vector y, void *ud)
{
    struct ark *a = ud;
    struct dem *d = a->d;
    size_t n3 = 3 * d->n, off = spring_offset(a);
    double *yy = N_VGetArrayPointer(y), *s = N_VGetArrayPointer(a->scratch);
    /* the slip phases found here take effect between steps (ark_advance):
     * ARKode has yet to evaluate the switching functions at t with the
     * phases the step was taken with */
    size_t nslot = spring_len(d) / 3;
    memcpy(a->mode_next, a->mode, nslot);
    d->spring_in = yy + off;
    d->slip_mode = a->mode_next;
    d->slip_g = a->gcache;   /* unchanged by the projection below: it
                                rescales slipping springs only */
    int rc = dem_forces(d, t, yy, yy + n3, yy + 2 * n3, 0.0, 1, s + n3,
                        s + 2 * n3);
    d->spring_in = NULL;
    d->slip_mode = NULL;
    d->slip_g = NULL;
    a->t_gcache = t;
    a->gcache_ok = a->gcache != NULL;
    if (rc)
        return -1;
    d->stats.fevals--;
    d->stats.hist_evals++;
    memcpy(yy + off, d->hist, 3 * d->nl.npairs * sizeof *yy);
    memcpy(yy + off + 3 * d->nl.npairs, d->whist,
           3 * d->n * (size_t)d->nwalls * sizeof *yy);
    return 0;
}

/* ARKode root function: the slip switching function of every slot
 * (dem.h, slip_g), whose zeros from above are the ends of slip phases. */
static int slip_roots(realtype t, N_Vector y, realtype *gout, void *ud)
{
    struct ark *a = ud;
    struct dem *d = a->d;
    size_t n3 = 3 * d->n, off = spring_offset(a);
    if (a->gcache_ok && t == a->t_gcache) {
        /* ARKode's check at the accepted state the hook has just
         * evaluated (arkode.c: arkCompleteStep, then arkRootCheck3) */
        memcpy(gout, a->gcache, spring_len(d) / 3 * sizeof *gout);
        a->gcache_ok = 0;
        return 0;
    }
    double *yy = N_VGetArrayPointer(y), *s = N_VGetArrayPointer(a->scratch);
    d->spring_in = yy + off;
    d->slip_g = gout;
    d->slip_mode = a->mode;
    int rc = dem_forces(d, t, yy, yy + n3, yy + 2 * n3, 0.0, 0, s + n3,
                        s + 2 * n3);
    d->spring_in = NULL;
    d->slip_g = NULL;
    d->slip_mode = NULL;
    d->stats.fevals--;
    d->stats.hist_evals++;
    return rc == SIM_OK ? 0 : -1;
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
    if (a->y) N_VDestroy(a->y);
    if (a->atol) N_VDestroy(a->atol);
    if (a->scratch) N_VDestroy(a->scratch);
    if (a->yprev) N_VDestroy(a->yprev);
    a->y = a->atol = a->scratch = a->yprev = NULL;
}

/* New state vectors for the current grains and neighbour list: x, v, w and
 * J from old (NULL: from d, J = 0), the springs from d->hist, d->whist. */
static int new_vectors(struct ark *a, struct dem *d, const double *old)
{
    size_t n3 = 3 * d->n, ns = spring_len(d);
    a->impulse = d->cpl.drag != NULL;
    a->n = d->n;
    size_t off = spring_offset(a), len = off + ns;
    len = len ? len : 1;
    N_Vector y = N_VNew_Serial((sunindextype)len, a->sun);
    N_Vector at = N_VNew_Serial((sunindextype)len, a->sun);
    N_Vector sc = N_VNew_Serial((sunindextype)len, a->sun);
    N_Vector yp = N_VNew_Serial((sunindextype)len, a->sun);
    if (!y || !at || !sc || !yp) {
        if (y) N_VDestroy(y);
        if (at) N_VDestroy(at);
        if (sc) N_VDestroy(sc);
        if (yp) N_VDestroy(yp);
        return sim_error(SIM_ERR_NOMEM, "ARKode vectors of length %zu", len);
    }
    free_vectors(a);
    a->y = y, a->atol = at, a->scratch = sc, a->yprev = yp;
    /* fused stage combinations: the vector arithmetic of a 7-stage pair is
     * as costly as the contact forces of a dense pack otherwise */
    N_VEnableFusedOps_Serial(a->y, SUNTRUE);
    double *yy = N_VGetArrayPointer(a->y), *tol = N_VGetArrayPointer(a->atol);
    if (old) {
        memcpy(yy, old, off * sizeof *yy);
    } else {
        memcpy(yy, d->x, n3 * sizeof *yy);
        memcpy(yy + n3, d->v, n3 * sizeof *yy);
        memcpy(yy + 2 * n3, d->w, n3 * sizeof *yy);
        if (a->impulse)
            memset(yy + 3 * n3, 0, n3 * sizeof *yy);
    }
    memcpy(yy + off, d->hist, 3 * d->nl.npairs * sizeof *yy);
    memcpy(yy + off + 3 * d->nl.npairs, d->whist,
           3 * d->n * (size_t)d->nwalls * sizeof *yy);
    for (size_t k = 0; k < n3; k++) {
        tol[k] = a->p.atol_x;
        tol[n3 + k] = a->p.atol_v;
        tol[2 * n3 + k] = a->p.atol_w;
        if (a->impulse)   /* the impulse takes no part in the error test */
            tol[3 * n3 + k] = 1e300;
    }
    /* springs are lengths: the positions' atol (10^-3 of it made a
     * settling pack of 64 grains take 10 times the steps) */
    for (size_t k = off; k < off + ns; k++)
        tol[k] = a->p.atol_x;
    if (off + ns == 0)
        yy[0] = 0, tol[0] = 1;
    a->npairs = d->nl.npairs;
    a->nbuilds = d->nl.nbuilds;
    return SIM_OK;
}

static int init_roots(struct ark *a, struct dem *d);

/* After a set-up or relayout (before ARKode's first step from the new
 * state): the slip phases and the contact state the stability function
 * needs, springs projected as at an accepted step; ARKode is told of the
 * projection by a reset. */
static int commit(struct ark *a, double t)
{
    if (post_step(t, a->y, a))
        return sim_error(SIM_ERR_NUMERIC, "arkode: force evaluation "
                         "failed at t = %.9g s", t);
    memcpy(a->mode, a->mode_next, spring_len(a->d) / 3);
    a->gcache_ok = 0;
    ARKCHECK(ERKStepReset(a->mem, t, a->y));
    return SIM_OK;
}

/* (Re)create the ERKStep memory for the current grains and state. */
static int setup(struct ark *a, struct dem *d)
{
    if (a->mem)
        ERKStepFree(&a->mem);
    TRY(new_vectors(a, d, NULL));
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
    TRY(init_roots(a, d));
    a->reset = 0;
    a->need_eval = 1;
    return SIM_OK;
}

/* The neighbour list was rebuilt: the spring slots changed. Same grains,
 * same time; ERKStepResize keeps the step size and its history. */
static int relayout(struct ark *a, struct dem *d, double t)
{
    N_Vector old = a->y;
    a->y = NULL;   /* kept for the copy */
    int rc = new_vectors(a, d, N_VGetArrayPointer(old));
    N_VDestroy(old);
    TRY(rc);
    ARKCHECK(ERKStepResize(a->mem, a->y, 1.0, t, NULL, NULL));
    ARKCHECK(ERKStepSVtolerances(a->mem, a->p.rtol, a->atol));
    return init_roots(a, d);
}

/* One root per spring slot (none without friction springs). */
/* Arm (on) or disarm the root functions. */
static int arm_roots(struct ark *a, struct dem *d, int on)
{
    size_t nr = spring_len(d) / 3;
    int use = a->p.slip_events == 1
              || (a->p.slip_events == 0 && d->n <= DEM_SLIP_EVENTS_MAX);
    if (!on || !use || d->law.tangential->history == 0
        || !(d->law.c.mu > 0))
        nr = 0;
    a->nroots = nr;
    if (nr > (size_t)INT32_MAX)
        return sim_error(SIM_ERR_INPUT, "arkode: %zu contact slots", nr);
    ARKCHECK(ERKStepRootInit(a->mem, (int)nr, nr ? slip_roots : NULL));
    if (nr == 0)
        return SIM_OK;
    for (size_t k = 0; k < nr; k++)
        a->rootdir[k] = -1;
    ARKCHECK(ERKStepSetRootDirection(a->mem, a->rootdir));
    ARKCHECK(ERKStepSetNoInactiveRootWarn(a->mem));
    return SIM_OK;
}

static int init_roots(struct ark *a, struct dem *d)
{
    size_t nr = spring_len(d) / 3, cap = nr ? nr : 1;
    /* the slot numbering changed: slip phases are found again by the
     * committing evaluation that follows every set-up */
    if (cap > a->rootdir_cap) {
        unsigned char *m = sim_realloc(a->mode, cap);
        if (!m)
            return SIM_ERR_NOMEM;
        a->mode = m;
        m = sim_realloc(a->mode_next, cap);
        if (!m)
            return SIM_ERR_NOMEM;
        a->mode_next = m;
        int *r = sim_realloc(a->rootdir, cap * sizeof *r);
        if (!r)
            return SIM_ERR_NOMEM;
        a->rootdir = r;
        r = sim_realloc(a->rootinfo, cap * sizeof *r);
        if (!r)
            return SIM_ERR_NOMEM;
        a->rootinfo = r;
        double *g = sim_realloc(a->gcache, cap * sizeof *g);
        if (!g)
            return SIM_ERR_NOMEM;
        a->gcache = g;
        a->rootdir_cap = cap;
    }
    memset(a->mode, 0, nr);
    a->need_eval = 1;
    return arm_roots(a, d, 1);
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
    int fresh = a->reset || state_changed(a, d);
    TRY(dem_update_neighbours(d, d->x));
    if (fresh)
        TRY(setup(a, d));
    else if (d->nl.nbuilds != a->nbuilds)
        TRY(relayout(a, d, d->t));
    /* After a set-up, one evaluation gives the contact state the stability
     * function needs; otherwise it is that of ARKode's last evaluation,
     * which was at this very state. */
    if (a->need_eval) {
        TRY(commit(a, d->t));
        a->need_eval = 0;
    }
    size_t n3 = 3 * d->n;
    double *yy = N_VGetArrayPointer(a->y);
    for (size_t k = 0; k < n3; k++)
        d->cpl.fd_sum[k] -= a->impulse ? yy[3 * n3 + k] : 0.0;
    long ex0, acc0, att, fe, rej0;
    ERKStepGetTimestepperStats(a->mem, &ex0, &acc0, &att, &fe, &rej0);
    long steps = 0, stab = 0, rej = 0;
    ARKCHECK(ERKStepSetStopTime(a->mem, t_end));
    double t = d->t, t_prev = t;
    while (t < t_end) {
        /* one step at a time: a rebuild of the neighbour list (which
         * changes the spring slots) is done between steps */
        t_prev = t;
        N_VScale(1.0, a->y, a->yprev);
        int flag = ERKStepEvolve(a->mem, t_end, a->y, &t, ARK_ONE_STEP);
        if (flag < 0)
            return sim_error(SIM_ERR_EXTERNAL,
                             "arkode: ERKStepEvolve failed at t = %.9g s: %s "
                             "%s", t, ERKStepGetReturnFlagName(flag), a->msg);
        if (flag == ARK_ROOT_RETURN) {
            /* A slip phase starts or ends at t. ARKode's step went past
             * it with the old phase, and its interpolant at t carries
             * that: redo the step from its start to t exactly, then
             * switch the phase (the spring at the limit) and restart. */
            double troot = t;
            size_t nr = spring_len(d) / 3;
            ARKCHECK(ERKStepGetRootInfo(a->mem, a->rootinfo));
            ARKCHECK(ERKStepReset(a->mem, t_prev, a->yprev));
            TRY(arm_roots(a, d, 0));
            ARKCHECK(ERKStepSetStopTime(a->mem, troot));
            t = t_prev;
            while (t < troot) {
                flag = ERKStepEvolve(a->mem, troot, a->y, &t, ARK_NORMAL);
                if (flag < 0)
                    return sim_error(SIM_ERR_EXTERNAL, "arkode: "
                                     "ERKStepEvolve failed at t = %.9g s: "
                                     "%s %s", t,
                                     ERKStepGetReturnFlagName(flag), a->msg);
                if (flag == ARK_TSTOP_RETURN)
                    break;
            }
            t = troot;
            if (post_step(t, a->y, a))
                return sim_error(SIM_ERR_NUMERIC, "arkode: projection of "
                                 "the springs failed at t = %.9g s", t);
            /* the commit cannot see the switch itself (it happens at the
             * limit): the slots whose function vanished change phase */
            for (size_t k = 0; k < nr; k++)
                a->mode[k] = a->rootinfo[k] ? !a->mode[k] : a->mode_next[k];
            a->gcache_ok = 0;
            TRY(arm_roots(a, d, 1));
            ARKCHECK(ERKStepReset(a->mem, t, a->y));
            ARKCHECK(ERKStepSetStopTime(a->mem, t_end));
            a->events++;
            continue;
        }
        yy = N_VGetArrayPointer(a->y);
        size_t nslot = spring_len(d) / 3;
        if (nslot && memcmp(a->mode, a->mode_next, nslot)) {
            /* slip phases began or ended at this accepted step: ARKode
             * re-evaluates the switching functions with them */
            memcpy(a->mode, a->mode_next, nslot);
            a->gcache_ok = 0;
            if (flag != ARK_TSTOP_RETURN && a->nroots) {
                ARKCHECK(ERKStepReset(a->mem, t, a->y));
                ARKCHECK(ERKStepSetStopTime(a->mem, t_end));
            }
        }
        if (flag != ARK_TSTOP_RETURN && t < t_end
            && nlist_stale(&d->nl, d->n, yy)) {
            long ex1, acc1, rej1;
            ERKStepGetTimestepperStats(a->mem, &ex1, &acc1, &att, &fe, &rej1);
            steps += (ex1 + acc1) - (ex0 + acc0);
            stab += ex1 - ex0;
            rej += rej1 - rej0;
            TRY(dem_update_neighbours(d, yy));
            TRY(relayout(a, d, t));
            TRY(commit(a, t));
            a->need_eval = 0;
            ARKCHECK(ERKStepSetStopTime(a->mem, t_end));
            ERKStepGetTimestepperStats(a->mem, &ex0, &acc0, &att, &fe, &rej0);
        }
        if (flag == ARK_TSTOP_RETURN)
            break;
    }
    long ex1, acc1, rej1;
    ERKStepGetTimestepperStats(a->mem, &ex1, &acc1, &att, &fe, &rej1);
    d->stats.steps += steps + (ex1 + acc1) - (ex0 + acc0);
    d->stats.stab_limited += stab + ex1 - ex0;
    d->stats.rejected += rej + rej1 - rej0;
    yy = N_VGetArrayPointer(a->y);
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
    if (a->mem)
        ERKStepFree(&a->mem);
    free_vectors(a);
    free(a->rootdir);
    free(a->rootinfo);
    free(a->gcache);
    free(a->mode);
    free(a->mode_next);
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
