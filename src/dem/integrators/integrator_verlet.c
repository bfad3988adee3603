/*
 * integrator_verlet.c — fixed-step velocity Verlet (doc/theory.md A.6 [P]),
 * the reference integrator:
 *
 *   v^{n+1/2} = v^n + dt/2 a^n,            w^{n+1/2} = w^n + dt/2 alpha^n
 *   x^{n+1}   = x^n + dt v^{n+1/2}
 *   a^{n+1}   = a(x^{n+1}, v^{n+1/2}, w^{n+1/2})   (velocity-dependent
 *               forces use the half-step velocity: first order in them,
 *               the usual DEM practice; doc/libraries.md §1)
 *   v^{n+1}   = v^{n+1/2} + dt/2 a^{n+1},  w likewise
 *
 * The step is dt = dt_fraction * dt_R (eq. 38) unless given; a given step
 * above dt_R is refused with the bound. Each advance ends exactly at t_end
 * by shortening all its steps equally (never by one small last step), or
 * for integrator auto at the first step that ends with no contact near.
 *
 * a^{n+1} is kept for the first half kick of the next advance: N steps
 * cost N force evaluations however many advances they are split into
 * (+1 at the start). The forces are evaluated afresh (at v^n, histories
 * committed with tau = 0) only when they are stale (d->forces_valid
 * cleared: new grains, grains removed, a new coupling state, histories
 * read) and at write times (checkpoint), so that a run restarted there,
 * which must start that way, repeats the continuous run.
 */
#include <math.h>
#include <stdlib.h>

#include "core/error.h"
#include "dem/dem.h"
#include "dem/integrators/integrator.h"

struct verlet {
    double dt;
    size_t n;     /* grains the kept forces belong to */
};

static int verlet_create(struct dem *d, const struct dem_integrator_params *p,
                         void **ctx)
{
    double dtr = d->dt_stable;
    double dt = p->dt > 0 ? p->dt : p->dt_fraction * dtr;
    if (!(dt > 0))
        return sim_error(SIM_ERR_INPUT, "verlet: time step %g must be > 0",
                         dt);
    if (dtr > 0 && dt > dtr)
        return sim_error(SIM_ERR_INPUT,
                         "verlet: time step %g s is above the stability "
                         "bound %g s (Rayleigh step, eq. 38, R_min = %g m%s)",
                         dt, dtr, d->rmin,
                         dtr < d->dt_rayleigh ? "; linear law: 2/omega" : "");
    struct verlet *v = sim_calloc(1, sizeof *v);
    if (!v)
        return SIM_ERR_NOMEM;
    v->dt = dt;
    /* neighbours are checked after every drift, and a step moves a grain
     * far less than the skin: the wall list is safe */
    d->use_wlist = 1;
    *ctx = v;
    return SIM_OK;
}

/* First half kick and drift in one pass (memory traffic is most of their
 * cost); returns the largest squared displacement since the neighbour
 * list was built, so that staleness needs no extra pass. */
static double kick_drift(struct dem *d, double h)
{
    const double *x0 = d->nl.x0;
    size_t n = d->n < d->nl.n ? d->n : d->nl.n;
    double m2 = 0;
    #pragma omp parallel for schedule(static) reduction(max : m2) \
        if (d->n > DEM_OMP_MIN)
    for (size_t i = 0; i < d->n; i++) {
        double d2 = 0;
        for (int a = 0; a < 3; a++) {
            size_t k = 3 * i + a;
            d->v[k] += 0.5 * h * d->acc[k];
            d->w[k] += 0.5 * h * d->alpha[k];
            d->x[k] += h * d->v[k];
            double dx = i < n ? d->x[k] - x0[k] : 0.0;
            d2 += dx * dx;
        }
        m2 = d2 > m2 ? d2 : m2;
    }
    return m2;
}

/* Half of the trapezoid rule for the applied drag impulse: Verlet applies
 * dt/2 (F_n + F_{n+1}), so summing both halves makes the averaged drag
 * balance the momentum exactly (what eq. 36 needs). */
static void accumulate_drag(struct dem *d, double h, double time_part)
{
    if (!d->cpl.drag)
        return;
    for (size_t k = 0; k < 3 * d->n; k++)
        d->cpl.fd_sum[k] += 0.5 * h * d->cpl.fd[k];
    d->cpl.sum_time += time_part;
}

static int verlet_advance(void *ctx, struct dem *d, double t_end)
{
    struct verlet *vl = ctx;
    double span = t_end - d->t;
    if (!(span > 0))
        return SIM_OK;
    long nsteps = (long)ceil(span / vl->dt * (1 - 1e-12));
    double h = span / (double)(nsteps > 0 ? nsteps : 1);
    TRY(dem_update_neighbours(d, d->x));
    if (!d->forces_valid || vl->n != d->n)
        TRY(dem_forces(d, d->t, d->x, d->v, d->w, 0.0, 1, d->acc, d->alpha));
    d->forces_valid = 0;   /* until the loop has completed */
    for (long s = 0; s < nsteps; s++) {
        double tn = s + 1 == nsteps ? t_end : d->t + h;
        accumulate_drag(d, h, 0.0);
        double m2 = kick_drift(d, h);
        if (d->n != d->nl.n || m2 > 0.25 * d->nl.skin * d->nl.skin)
            TRY(dem_rebuild_neighbours(d));
        d->kick = 0.5 * h;   /* the closing half kick, inside the force pass */
        int rc = dem_forces(d, tn, d->x, d->v, d->w, h, 1, d->acc, d->alpha);
        d->kick = 0;
        if (rc)
            return rc;
        accumulate_drag(d, h, h);
        d->t = tn;
        d->stats.steps++;
        if (d->stop_when == DEM_STOP_FREE && !dem_contact_near(d, d->x, d->v))
            break;   /* the forces are those of this state: kept */
    }
    d->forces_valid = 1;
    vl->n = d->n;
    return SIM_OK;
}

static int verlet_checkpoint(void *ctx, struct dem *d)
{
    (void)ctx;
    dem_invalidate_forces(d);
    return SIM_OK;
}

static void verlet_destroy(void *ctx)
{
    free(ctx);
}

const struct dem_integrator_ops dem_integrator_verlet = {
    .name = "verlet",
    .reference = "velocity Verlet, fixed step (Swope et al. 1982)",
    .create = verlet_create,
    .advance = verlet_advance,
    .checkpoint = verlet_checkpoint,
    .destroy = verlet_destroy,
};
