/*
 * integrator.h — DEM time integrators, selected by name in
 * system/demSolution (`integrator arkode;`, `verlet;` or `auto;`).
 *
 * An integrator advances a struct dem from d->t to a given time exactly
 * (every coupling and output time is a stop time), leaves the tangential
 * histories of the state it ends at in d->hist, d->whist, rebuilds the
 * neighbour list when due, adds the applied drag to the coupling
 * accumulator, and counts steps, rejected steps and force evaluations in
 * d->stats. It may keep forces from one advance to the next (Verlet does):
 * whoever changes the grains, their histories or the coupling inputs from
 * outside calls dem_invalidate_forces (dem_setup, dem_check_domain,
 * dem_coupling_set and dem_read_contacts do).
 */
#ifndef MPSDEM_DEM_INTEGRATOR_H
#define MPSDEM_DEM_INTEGRATOR_H

struct dem;

#define DEM_SLIP_EVENTS_MAX 10

struct dem_integrator_params {
    /* verlet */
    double dt;              /* fixed step [s]; 0: dt_fraction * Rayleigh     */
    double dt_fraction;     /* of the Rayleigh step (eq. 38)                 */
    /* arkode */
    double rtol;            /* relative tolerance                            */
    double atol_x;          /* absolute tolerance, positions [m]             */
    double atol_v;          /* velocities [m/s]                              */
    double atol_w;          /* spins [rad/s]                                 */
    double safety;          /* fraction of the contact stability bound       */
    const char *table;      /* ERK table name, e.g. "DORMAND_PRINCE_7_4_5"   */
    long max_steps;         /* per advance                                   */
    int slip_events;        /* locate slip starts/ends as events: 0 auto (on
                               for at most DEM_SLIP_EVENTS_MAX grains: each
                               event restarts the integration), 1 on, 2 off */
};

struct dem_integrator_ops {
    const char *name;
    const char *reference;
    /* Check p against d (e.g. a fixed step above the stability bound is
     * SIM_ERR_INPUT with the bound in the message) and create the state. */
    int (*create)(struct dem *d, const struct dem_integrator_params *p,
                  void **ctx);
    /* Advance to t_end (> d->t). Call after any outside change of the
     * grains (count, positions) too: the integrator notices (a change of
     * positions or velocities alone only after dem_invalidate_forces). */
    int (*advance)(void *ctx, struct dem *d, double t_end);
    /* At a write time: make the integrator's future independent of its
     * past (an adaptive one restarts from d->h_next, which it sets), so
     * that a run restarted from this time repeats the continuous run to
     * round-off. May be NULL (nothing to do). */
    int (*checkpoint)(void *ctx, struct dem *d);
    void (*destroy)(void *ctx);
};

extern const struct dem_integrator_ops dem_integrator_verlet;
extern const struct dem_integrator_ops dem_integrator_arkode;
extern const struct dem_integrator_ops dem_integrator_auto;
extern const struct dem_integrator_ops *const dem_integrator_table[];

#endif
