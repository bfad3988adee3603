/*
 * integrator_auto.c — `integrator auto;`: ARKode's adaptive step while no
 * grain touches another grain or a wall, velocity Verlet's fixed step
 * while any does (doc/theory.md A0-26).
 *
 * Why the switch is on "any contact": ARKode takes one step for every
 * grain, and a contact bounds it by the contact's stability limit
 * (safety x 2/omega, integrator_arkode.c), where each step costs the six
 * evaluations of the Dormand-Prince pair against Verlet's one per
 * rayleighFraction x dt_R; its steps into a contact, resolved by error
 * control, cost more still. Out of contact (flights, settling under drag
 * and gravity) ARKode's step grows with the smoothness of the motion and
 * Verlet's stays at the contact time scale (test/bench/README.dem.md).
 *
 * Each advance runs the integrator of the current state until its
 * stretch ends: ARKode returns at the end of the first step that ends
 * near a contact, Verlet at the end of the first step that ends near
 * none (dem->stop_when, dem_contact_near); the other one takes over from
 * that state. The first decision of a run (no force evaluation yet, e.g.
 * after a restart) is geometric alone; later ones also read the contact
 * counts of the last committing evaluation, which was at the current
 * state. A switch clears the kept forces (Verlet evaluates
 * afresh) and ARKode, seeing a state it did not leave, sets itself up
 * from the grains and their springs.
 * Both sub-integrators read their own coefficients (arkodeCoeffs,
 * verletCoeffs).
 */
#include <stdlib.h>

#include "core/error.h"
#include "dem/dem.h"
#include "dem/integrators/integrator.h"

/* A contact within HORIZON Verlet steps at the grains' speeds counts as
 * one: ARKode's steps into a contact cost more than Verlet's (the Hertz
 * onset is resolved by error control: 45 steps and 400 evaluations for a
 * bead closing 20 um at 0.87 m/s, against 3 Verlet steps), and handing
 * over a few Verlet steps before the touch avoids them. */
#define HORIZON 4.0

struct auto_int {
    void *ark, *verlet;
    int ark_wlist, verlet_wlist;   /* use_wlist each one asks for */
    double dt_verlet;              /* Verlet's step (its create's rule) */
    const struct dem_integrator_ops *last;
};

static int auto_create(struct dem *d, const struct dem_integrator_params *p,
                       void **ctx)
{
    struct auto_int *a = sim_calloc(1, sizeof *a);
    if (!a)
        return SIM_ERR_NOMEM;
    a->dt_verlet = p->dt > 0 ? p->dt : p->dt_fraction * d->dt_stable;
    int rc = dem_integrator_verlet.create(d, p, &a->verlet);
    a->verlet_wlist = d->use_wlist;
    if (rc == SIM_OK)
        rc = dem_integrator_arkode.create(d, p, &a->ark);
    a->ark_wlist = d->use_wlist;
    if (rc) {
        if (a->verlet)
            dem_integrator_verlet.destroy(a->verlet);
        if (a->ark)
            dem_integrator_arkode.destroy(a->ark);
        free(a);
        return rc;
    }
    *ctx = a;
    return SIM_OK;
}

/* With nothing evaluated yet the contact counts are empty, and the
 * geometric test of dem_contact_near (an overlap is within any horizon)
 * decides alone, on a list valid for the start state. */
static int in_contact(struct dem *d, int *contact)
{
    if (d->stats.fevals == 0)
        TRY(dem_update_neighbours(d, d->x));
    *contact = dem_contact_near(d, d->x, d->v);
    return SIM_OK;
}

static int auto_advance(void *ctx, struct dem *d, double t_end)
{
    struct auto_int *a = ctx;
    d->stop_horizon = HORIZON * a->dt_verlet;
    while (d->t < t_end) {
        int contact;
        TRY(in_contact(d, &contact));
        const struct dem_integrator_ops *op = contact ? &dem_integrator_verlet
                                                      : &dem_integrator_arkode;
        if (op != a->last) {
            dem_invalidate_forces(d);
            d->use_wlist = contact ? a->verlet_wlist : a->ark_wlist;
            a->last = op;
        }
        double t0 = d->t;
        d->stop_when = contact ? DEM_STOP_FREE : DEM_STOP_CONTACT;
        int rc = op->advance(contact ? a->verlet : a->ark, d, t_end);
        d->stop_when = 0;
        if (rc)
            return rc;
        if (!(d->t > t0))
            return sim_error(SIM_ERR_NUMERIC, "integrator auto: %s made no "
                             "progress at t = %.9g s", op->name, t0);
    }
    return SIM_OK;
}

static int auto_checkpoint(void *ctx, struct dem *d)
{
    struct auto_int *a = ctx;
    TRY(dem_integrator_verlet.checkpoint(a->verlet, d));
    TRY(dem_integrator_arkode.checkpoint(a->ark, d));
    /* a restart decides afresh from the written state: so does this run */
    a->last = NULL;
    return SIM_OK;
}

static void auto_destroy(void *ctx)
{
    struct auto_int *a = ctx;
    if (!a)
        return;
    dem_integrator_verlet.destroy(a->verlet);
    dem_integrator_arkode.destroy(a->ark);
    free(a);
}

const struct dem_integrator_ops dem_integrator_auto = {
    .name = "auto",
    .reference = "arkode out of contact, verlet in contact (doc/theory.md "
                 "A0-26)",
    .create = auto_create,
    .advance = auto_advance,
    .checkpoint = auto_checkpoint,
    .destroy = auto_destroy,
};
