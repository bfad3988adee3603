/*
 * integrator.h — DEM time integrators, selected by name in
 * system/demSolution (`integrator arkode;` or `verlet;`).
 *
 * An integrator advances a struct dem from d->t to a given time exactly
 * (every coupling and output time is a stop time), updates the tangential
 * histories at accepted steps, rebuilds the neighbour list when due, adds
 * the applied drag to the coupling accumulator, and counts steps, rejected
 * steps and force evaluations in d->stats.
 */
#ifndef MPSDEM_DEM_INTEGRATOR_H
#define MPSDEM_DEM_INTEGRATOR_H

struct dem;

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
};

struct dem_integrator_ops {
    const char *name;
    const char *reference;
    /* Check p against d (e.g. a fixed step above the stability bound is
     * SIM_ERR_INPUT with the bound in the message) and create the state. */
    int (*create)(struct dem *d, const struct dem_integrator_params *p,
                  void **ctx);
    /* Advance to t_end (> d->t). Call after any outside change of the
     * grains (count, positions) too: the integrator notices. */
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
extern const struct dem_integrator_ops *const dem_integrator_table[];

#endif
