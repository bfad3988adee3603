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
 * The Coulomb slider is a phase per slot (dem.h slip_mode; doc/theory.md
 * A0-24): it starts where the stick force |kt S + eta^t v^t| or the
 * spring's force kt |S| reaches mu |F^n| (the cone of the contact law),
 * and lasts while the stick force from the spring at the limit,
 * |mu |F^n| s^ + eta^t v^t|, is still outside the cone or the spring
 * would leave it,
 *
 *   D = d/dt (kt |S| - mu |F^n|) > 0   along the stick flow, at the limit
 *
 * (dem_slip_rates, after the accelerations are known). Ending it where
 * the spring merely stops loading (s^.v^t = 0, until 2026-11-27) left a
 * spring whose limit shrank faster than it unloaded outside the cone, and
 * stick and slip chattered near gross slip (60 deg impacts). Inside a
 * phase the force is -mu |F^n| s^ whatever the state's length; it holds
 * for the whole step, its end being an event. Events (slipEvents): after
 * each accepted step the switching functions (dem.h slip_g) and F^n at its
 * end are compared with those at its start; where a switching function
 * fell through 0, F^n changed sign (a kink of the limit) or a contact
 * ended, the event is located on exact re-integrations from the step's
 * start (locate_event: ARKode's own root finding works on its
 * interpolant, which was not accurate enough), the state taken just past
 * it, where the post-step hook has projected the springs (which puts a
 * slipping spring at the limit) and found the phases from the state
 * before that projection, and the integration restarted (ERKStepReset).
 * A new slip phase whose switching function is not positive at once is a
 * slip of zero length (the dashpot drove the stick force out of the cone
 * against the spring): the projection was all of it, and stick goes on;
 * such jumps come faster and faster up to the point where slip proper
 * starts, and one within 1e-9/omega of the slot's last is taken as that
 * point. A phase that starts and ends inside a step shows in the
 * switching functions at the stages (eval; slots that start the step on
 * the cone are left out): the step is redone in quarters. Without events
 * a phase changes at the next accepted step (slipEvents off, large
 * systems), a first-order error outside the error test. At accepted
 * steps the springs are projected as the contact law implies (rotation,
 * limit, 0 out of contact: post-step hook, one committing force
 * evaluation counted as hist_evals, after which ARKode re-evaluates the
 * right-hand side), and the phases found there take effect. When the
 * neighbour list is rebuilt the slots change: the springs are carried by
 * the list (neighbour_half_carry) and S is re-laid out (ERKStepResize, which keeps
 * the step size).
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
    N_Vector y, atol, scratch, yprev, yhi;
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
    unsigned char *mode_hi;    /* mode_next at the event (locate_event) */
    double *gcache;            /* switching functions at the state of the
                                  last projection (post_step), with the
                                  phases the step was taken with        */
    double *g0;                /* the same at the start of the current
                                  step, with the current phases         */
    double *glo;               /* scratch for the event search          */
    double *gst;               /* switching functions of the last stage */
    double *gmin;              /* their minimum over the current step's
                                  stages (g_val)                        */
    double *fcache, *f0;       /* F^n per slot at the last projection and
                                  at the start of the current step      */
    double *treset;            /* time of the slot's last slip of zero
                                  length                                */
    double hcap_until;         /* steps capped to hcap until this time  */
    size_t slot_cap;
    long events;               /* slip starts and ends located          */
    long redos;                /* steps redone for a stage's sign change */
    int detect;                /* locate slip events (slipEvents)       */
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
    d->slip_g = a->detect ? a->gst : NULL;
    int rc = dem_forces(d, t, yy, yy + n3, yy + 2 * n3, 0.0, 0, yd + n3,
                        yd + 2 * n3);
    d->spring_in = NULL;
    d->spring_rate = NULL;
    d->slip_mode = NULL;
    d->slip_g = NULL;
    if (a->detect && rc == SIM_OK)
        rc = dem_slip_rates(d, yy, yy + n3, yy + 2 * n3, yd + n3, yy + off,
                            a->mode, a->gst, NULL);
    if (a->detect) {   /* a phase hidden inside a step shows at stages */
        size_t nslot = spring_len(d) / 3;
        for (size_t k = 0; k < nslot; k++) {
            double g = a->gst[k] == HUGE_VAL && a->g0[k] != HUGE_VAL
                       ? -1.0 : a->gst[k];
            a->gmin[k] = g < a->gmin[k] ? g : a->gmin[k];
        }
    }
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
        double room = 0.5 * d->nl.skin - neighbour_half_max_displacement(&d->nl, x);
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
                                rotates springs and rescales slipping
                                ones only */
    d->slip_fn = a->fcache;
    int rc = dem_forces(d, t, yy, yy + n3, yy + 2 * n3, 0.0, 1, s + n3,
                        s + 2 * n3);
    d->spring_in = NULL;
    d->slip_mode = NULL;
    d->slip_g = NULL;
    d->slip_fn = NULL;
    /* a slipping slot also keeps sliding where its spring would leave the
     * cone (A0-24): that needs the accelerations just computed */
    if (rc == SIM_OK)
        rc = dem_slip_rates(d, yy, yy + n3, yy + 2 * n3, s + n3, yy + off,
                            a->mode, a->gcache, a->mode_next);
    if (rc)
        return -1;
    d->stats.fevals--;
    d->stats.hist_evals++;
    memcpy(yy + off, d->hist, 3 * d->nl.npairs * sizeof *yy);
    memcpy(yy + off + 3 * d->nl.npairs, d->whist,
           3 * d->n * (size_t)d->nwalls * sizeof *yy);
    return 0;
}

/* The slip switching functions of every slot (dem.h, slip_g) at (t, y)
 * with the current phases, and F^n: a zero from above of g is the start
 * of a slip phase (stick: the force reaches the cone) or its end (slip:
 * neither the stick force nor the spring would leave it, A0-24); a sign
 * change of F^n a kink of the limit. One force evaluation, counted with
 * the projections. */
static int eval_g(struct ark *a, double t, N_Vector y, double *gout,
                  double *fout)
{
    struct dem *d = a->d;
    size_t n3 = 3 * d->n, off = spring_offset(a);
    double *yy = N_VGetArrayPointer(y), *s = N_VGetArrayPointer(a->scratch);
    d->spring_in = yy + off;
    d->slip_g = gout;
    d->slip_fn = fout;
    d->slip_mode = a->mode;
    int rc = dem_forces(d, t, yy, yy + n3, yy + 2 * n3, 0.0, 0, s + n3,
                        s + 2 * n3);
    d->spring_in = NULL;
    d->slip_g = NULL;
    d->slip_fn = NULL;
    d->slip_mode = NULL;
    d->stats.fevals--;
    d->stats.hist_evals++;
    if (rc == SIM_OK)
        rc = dem_slip_rates(d, yy, yy + n3, yy + 2 * n3, s + n3, yy + off,
                            a->mode, gout, NULL);
    return rc;
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
    if (a->yhi) N_VDestroy(a->yhi);
    a->y = a->atol = a->scratch = a->yprev = a->yhi = NULL;
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
    N_Vector yh = N_VNew_Serial((sunindextype)len, a->sun);
    if (!y || !at || !sc || !yp || !yh) {
        if (y) N_VDestroy(y);
        if (at) N_VDestroy(at);
        if (sc) N_VDestroy(sc);
        if (yp) N_VDestroy(yp);
        if (yh) N_VDestroy(yh);
        return sim_error(SIM_ERR_NOMEM, "ARKode vectors of length %zu", len);
    }
    free_vectors(a);
    a->y = y, a->atol = at, a->scratch = sc, a->yprev = yp, a->yhi = yh;
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

static int init_slots(struct ark *a, struct dem *d);

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
    if (a->detect && eval_g(a, t, a->y, a->g0, a->f0))
        return sim_error(SIM_ERR_NUMERIC, "arkode: force evaluation "
                         "failed at t = %.9g s", t);
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
    TRY(init_slots(a, d));
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
    return init_slots(a, d);
}

/* Per-slot arrays for the current slots; the slot numbering changed, so
 * the slip phases are found again by the committing evaluation that
 * follows every set-up or relayout. */
static int init_slots(struct ark *a, struct dem *d)
{
    size_t nr = spring_len(d) / 3, cap = nr ? nr : 1;
    if (cap > a->slot_cap) {
        unsigned char *m = sim_realloc(a->mode, cap);
        if (!m)
            return SIM_ERR_NOMEM;
        a->mode = m;
        m = sim_realloc(a->mode_next, cap);
        if (!m)
            return SIM_ERR_NOMEM;
        a->mode_next = m;
        m = sim_realloc(a->mode_hi, cap);
        if (!m)
            return SIM_ERR_NOMEM;
        a->mode_hi = m;
        double *g = sim_realloc(a->gcache, cap * sizeof *g);
        if (!g)
            return SIM_ERR_NOMEM;
        a->gcache = g;
        g = sim_realloc(a->g0, cap * sizeof *g);
        if (!g)
            return SIM_ERR_NOMEM;
        a->g0 = g;
        g = sim_realloc(a->glo, cap * sizeof *g);
        if (!g)
            return SIM_ERR_NOMEM;
        a->glo = g;
        g = sim_realloc(a->gst, cap * sizeof *g);
        if (!g)
            return SIM_ERR_NOMEM;
        a->gst = g;
        g = sim_realloc(a->gmin, cap * sizeof *g);
        if (!g)
            return SIM_ERR_NOMEM;
        a->gmin = g;
        g = sim_realloc(a->fcache, cap * sizeof *g);
        if (!g)
            return SIM_ERR_NOMEM;
        a->fcache = g;
        g = sim_realloc(a->f0, cap * sizeof *g);
        if (!g)
            return SIM_ERR_NOMEM;
        a->f0 = g;
        g = sim_realloc(a->treset, cap * sizeof *g);
        if (!g)
            return SIM_ERR_NOMEM;
        a->treset = g;
        a->slot_cap = cap;
    }
    memset(a->mode, 0, nr);
    for (size_t k = 0; k < nr; k++)
        a->treset[k] = -INFINITY;
    int use = a->p.slip_events == 1
              || (a->p.slip_events == 0 && d->n <= DEM_SLIP_EVENTS_MAX);
    a->detect = use && nr > 0 && d->law.tangential->history != 0
                && d->law.c.mu > 0;
    a->need_eval = 1;
    return SIM_OK;
}

/* Switching function g of a slot whose value was g0 at the start of the
 * step: out of contact (HUGE_VAL, dem_forces.c slip_open) after having
 * been in contact counts as -1, so that the end of a contact is located
 * as an event and a slip phase just before it cannot hide in the step. */
static double g_val(double g, double g0)
{
    return g == HUGE_VAL && g0 != HUGE_VAL ? -1.0 : g;
}

static int g_crossed(double g0, double g)
{
    return g0 > 0 && g_val(g, g0) <= 0;
}

/* The step ending at the last projection crossed an event of slot k:
 * 1 its switching function fell through 0, 2 F^n changed sign (both in
 * contact), 3 both. */
static int slot_event(const struct ark *a, size_t k)
{
    return g_crossed(a->g0[k], a->gcache[k])
           | 2 * (a->f0[k] * a->fcache[k] < 0);
}

/* Smallest switching function at the state of the last projection over
 * the slots flagged in glo (slot_event): g, and F^n relative to its
 * value at the step's start, positive until it changes sign. */
static double g_min(const struct ark *a, size_t nslot)
{
    double g = INFINITY;
    for (size_t k = 0; k < nslot; k++) {
        int ev = (int)a->glo[k];
        if (ev & 1)
            g = fmin(g, g_val(a->gcache[k], a->g0[k]));
        if (ev & 2)
            g = fmin(g, a->fcache[k] / a->f0[k]);
    }
    return g;
}

/* Integrate from (t0, yprev) to tm exactly (ARKode's state there, the
 * springs projected by the hook, gcache its switching functions). */
static int redo_to(struct ark *a, double t0, double tm)
{
    ARKCHECK(ERKStepReset(a->mem, t0, a->yprev));
    ARKCHECK(ERKStepSetStopTime(a->mem, tm));
    double t = t0;
    while (t < tm) {
        int flag = ERKStepEvolve(a->mem, tm, a->y, &t, ARK_NORMAL);
        if (flag < 0)
            return sim_error(SIM_ERR_EXTERNAL, "arkode: ERKStepEvolve "
                             "failed at t = %.9g s: %s %s", t,
                             ERKStepGetReturnFlagName(flag), a->msg);
        if (flag == ARK_TSTOP_RETURN)
            break;
    }
    return SIM_OK;
}

/* The step (t0, yprev) -> (t1, y) changed the sign of a switching function
 * from above (g0 > 0 >= gcache): a slip phase started or ended inside it.
 * Locate the earliest such zero of the flagged slots by regula falsi
 * (Illinois) on exact re-integrations from t0 (ARKode's interpolant is
 * not accurate enough there: with the Hermite interpolant of degree 4 a
 * root was placed 2 us early in a 135 us contact), end at the right end
 * of the bracket (the event has happened there), where the projection
 * switches the phases, and restart. *t: t1 in, the event out. */
static int locate_event(struct ark *a, double t0, double *t)
{
    size_t nslot = spring_len(a->d) / 3;
    double tlo = t0, thi = *t, ghi = INFINITY, glo = INFINITY;
    for (size_t k = 0; k < nslot; k++) {
        int ev = slot_event(a, k);
        a->glo[k] = ev;
        if (ev & 1)
            glo = fmin(glo, a->g0[k]);
        if (ev & 2)
            glo = fmin(glo, 1.0);
    }
    ghi = g_min(a, nslot);
    N_VScale(1.0, a->y, a->yhi);
    memcpy(a->mode_hi, a->mode_next, nslot);
    /* a switching function may have a kink at the zero (the larger of
     * two forces, F^n through 0), which stalls regula falsi: bisect
     * until two points lie before the zero, then take secants from that
     * side, landing just past the estimate */
    double ttol = 1e-6 * (thi - tlo), tlo2 = tlo, glo2 = glo;
    int have2 = 0;
    (void)ghi;
    for (int it = 0; it < 100 && thi - tlo > ttol; it++) {
        double tm = 0.5 * (tlo + thi);
        if (have2 && glo2 > glo && glo2 < HUGE_VAL)
            tm = tlo + glo * (tlo - tlo2) / (glo2 - glo) + 0.5 * ttol;
        if (!(tm > tlo && tm < thi))
            tm = 0.5 * (tlo + thi);
        TRY(redo_to(a, t0, tm));
        double gm = g_min(a, nslot);
        if (gm <= 0) {
            thi = tm, ghi = gm;
            N_VScale(1.0, a->y, a->yhi);
            memcpy(a->mode_hi, a->mode_next, nslot);
        } else {
            tlo2 = tlo, glo2 = glo, have2 = 1;
            tlo = tm, glo = gm;
        }
    }
    /* the state there was projected by the hook, which also found the
     * phases (from the state before its projection: a spring just put at
     * the limit no longer shows which way it was going) */
    N_VScale(1.0, a->yhi, a->y);
    memcpy(a->mode_next, a->mode_hi, nslot);
    *t = thi;
    a->events++;
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
        if (a->detect)
            for (size_t k = 0; k < spring_len(d) / 3; k++)
                a->gmin[k] = INFINITY;
        if (a->hcap_until > 0 && t >= a->hcap_until) {
            a->hcap_until = 0;
            ARKCHECK(ERKStepSetMaxStep(a->mem, 0.0));
        }
        int flag = ERKStepEvolve(a->mem, t_end, a->y, &t, ARK_ONE_STEP);
        if (flag < 0)
            return sim_error(SIM_ERR_EXTERNAL,
                             "arkode: ERKStepEvolve failed at t = %.9g s: %s "
                             "%s", t, ERKStepGetReturnFlagName(flag), a->msg);
        size_t nslot = spring_len(d) / 3;
        int event = 0;
        if (a->detect) {
            for (size_t k = 0; k < nslot && !event; k++)
                event = slot_event(a, k);
            int hidden = 0;
            /* a slot that starts the step on the cone (a slip phase
             * just ended there, g0 ~ 1e-12) is left out: it was found
             * moving inward, and the stages' own error takes it across
             * by O(h^2) */
            for (size_t k = 0; k < nslot && !event && !hidden; k++)
                hidden = a->g0[k] > 1e-9 && a->gmin[k] <= 0;
            if (hidden && !event && t - t_prev > 1e-6 * t) {
                /* a stage saw a switching function at or below 0 although
                 * both ends are above: a phase may start and end inside
                 * the step. Redo it in quarters (recursively). */
                double h = 0.25 * (t - t_prev);
                ARKCHECK(ERKStepReset(a->mem, t_prev, a->yprev));
                ARKCHECK(ERKStepSetMaxStep(a->mem, h));
                ARKCHECK(ERKStepSetInitStep(a->mem, h));
                ARKCHECK(ERKStepSetStopTime(a->mem, t_end));
                a->hcap_until = fmax(a->hcap_until, t);
                N_VScale(1.0, a->yprev, a->y);
                t = t_prev;
                a->redos++;
                continue;
            }
            if (event) {
                TRY(locate_event(a, t_prev, &t));
                flag = t < t_end ? ARK_SUCCESS : ARK_TSTOP_RETURN;
            }
        }
        yy = N_VGetArrayPointer(a->y);
        if (nslot && (event || memcmp(a->mode, a->mode_next, nslot))) {
            /* slip phases began or ended at this state: restart with
             * them (without events they take effect at the next stage:
             * a restart at every step of a dense pack would cost an
             * evaluation per step) */
            memcpy(a->mode, a->mode_next, nslot);
            if (a->detect) {
                ARKCHECK(ERKStepReset(a->mem, t, a->y));
                ARKCHECK(ERKStepSetStopTime(a->mem, t_end));
            }
            if (a->detect && eval_g(a, t, a->y, a->g0, a->f0))
                return sim_error(SIM_ERR_NUMERIC, "arkode: force "
                                 "evaluation failed at t = %.9g s", t);
            /* a slip of zero length (A0-24: the dashpot drove the stick
             * force out of the cone against the spring, and the spring
             * put at the limit on its own side is inside again): the
             * projection was its whole effect, stick goes on. These
             * jumps come faster and faster as eta^t |v^t| nears
             * 2 mu |F^n|, where the slip proper starts: one within
             * 1e-9/omega of the slot's last is taken as that point. */
            int zero = 0;
            double tz = d->omega2_max > 0 ? 1e-9 / sqrt(d->omega2_max) : 0;
            for (size_t k = 0; a->detect && k < nslot; k++)
                if (a->mode[k] && a->g0[k] <= 0 && a->g0[k] != HUGE_VAL
                    && !(t - a->treset[k] < tz)) {
                    a->mode[k] = 0, zero = 1;
                    a->treset[k] = t;
                }
            if (zero && eval_g(a, t, a->y, a->g0, a->f0))
                return sim_error(SIM_ERR_NUMERIC, "arkode: force "
                                 "evaluation failed at t = %.9g s", t);
        } else if (a->detect) {
            memcpy(a->g0, a->gcache, nslot * sizeof *a->g0);
            memcpy(a->f0, a->fcache, nslot * sizeof *a->f0);
        }
        if (flag != ARK_TSTOP_RETURN && t < t_end
            && neighbour_half_stale(&d->nl, d->n, yy)) {
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
        /* integrator auto: a contact, or a gap closing to one, ends the
         * ballistic stretch (the commit of this step counted the contacts
         * at its end) */
        if (d->stop_when == DEM_STOP_CONTACT) {
            yy = N_VGetArrayPointer(a->y);   /* relayout replaces a->y */
            if (dem_contact_near(d, yy, yy + n3))
                break;
        }
    }
    long ex1, acc1, rej1;
    ERKStepGetTimestepperStats(a->mem, &ex1, &acc1, &att, &fe, &rej1);
    d->stats.steps += steps + (ex1 + acc1) - (ex0 + acc0);
    d->stats.stab_limited += stab + ex1 - ex0;
    d->stats.rejected += rej + rej1 - rej0;
    yy = N_VGetArrayPointer(a->y);
    for (size_t k = 0; k < n3; k++)
        d->cpl.fd_sum[k] += a->impulse ? yy[3 * n3 + k] : 0.0;
    double t_stop = t < t_end ? t : t_end;
    if (d->cpl.drag)
        d->cpl.sum_time += t_stop - d->t;
    memcpy(d->x, yy, n3 * sizeof *yy);
    memcpy(d->v, yy + n3, n3 * sizeof *yy);
    memcpy(d->w, yy + 2 * n3, n3 * sizeof *yy);
    d->t = t_stop;
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
    free(a->gcache);
    free(a->g0);
    free(a->glo);
    free(a->gst);
    free(a->gmin);
    free(a->fcache);
    free(a->f0);
    free(a->treset);
    free(a->mode);
    free(a->mode_next);
    free(a->mode_hi);
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
