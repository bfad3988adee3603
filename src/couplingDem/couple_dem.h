/*
 * couple_dem.h — the DEM side of a coupled MPS-DEM run: what demSolid does
 * around each advance to the next coupling time (doc/theory.md A.8, A.10 step
 * 4; doc/design.md §4).
 *
 * One coupling interval t^m -> t^{m+1}:
 *   couple_dem_recv()   the fluid state at t^m (u_k, eps_k, Model A gradP_k)
 *                       -> external force (A: -V gradP_k, B: -V rho_f g)
 *                       and the drag law (A: F^d, B: F^d/eps_k) handed to
 *                       dem_coupling_set(): the drag is evaluated with the
 *                       grain's current velocity at every sub-step
 *   integrator->advance(d, t^{m+1})
 *   couple_dem_send()   positions, velocities, radii and the drag of eq.
 *                       (25) averaged over the interval (dem_mean_drag)
 * couple_dem_send() once before the loop sends the initial state (zero
 * drag). Dry grains (wet_k = 0: no fluid particle in reach) feel neither
 * drag nor buoyancy.
 *
 * Without a channel (tests): couple_dem_apply() and couple_dem_state().
 */
#ifndef MPSDEM_COUPLINGDEM_COUPLE_DEM_H
#define MPSDEM_COUPLINGDEM_COUPLE_DEM_H

#include <stddef.h>
#include <stdint.h>

#include "coupling/drag/drag.h"
#include "coupling/models.h"

struct dict;
struct channel;
struct dem;
struct proto_fluid_state;
struct proto_dem_state;

struct couple_dem {
    struct coupling_settings cs;
    struct channel *ch;
    struct drag_fluid fl;       /* rho_f, mu_f = rho_f nu                */
    double g[3];
    size_t n, cap;
    double *uf, *eps, *gradp;   /* fluid state at the grains (frozen)    */
    uint8_t *wet;
    double *fext;               /* 3n external force [N]                 */
    double *V, *d;              /* sphere volume, diameter               */
    double *Fapplied;           /* 3n mean drag the grains received      */
    double *Fsend;              /* 3n mean drag of eq. (25)              */
    double *work;               /* 3n                                    */
    double *slip;               /* 3n u_k - v_k (couple_dem_output)      */
    double fluid_time;          /* time of the last fluid state          */
    long exchanges;
    double wait;                /* seconds waiting for the fluid side    */
    int concurrent;             /* scheme concurrent: no send at endTime */
};

/* Settings from system/couplingDict; fluid density and viscosity from
 * constant/transportProperties (rho, nu); gravity g [m/s^2]. */
int couple_dem_init(struct couple_dem *cd, const struct dict *coupling,
                    const struct dict *transport, const double g[3]);

/* Take a fluid state for the n grains of d (n must be d->n): external
 * forces and drag law set on d. The arrays stay owned by cd. */
int couple_dem_apply(struct couple_dem *cd, struct dem *d,
                     const struct proto_fluid_state *fs);

/* After an advance: the averaged drag into cd->Fsend (eq. 25, what the
 * fluid's reaction needs) and cd->Fapplied (what the grains received). */
int couple_dem_after(struct couple_dem *cd, struct dem *d);

/* The DEM state to send: views of d and cd->Fsend. */
void couple_dem_state(const struct couple_dem *cd, const struct dem *d,
                      struct proto_dem_state *st);

/* Channel: open (couplingDict channel keys; the dimension and endTime of
 * the case, which the handshake compares with the fluid's). */
int couple_dem_open(struct couple_dem *cd, const struct dict *coupling,
                    const char *case_dir, const char *program, int dim,
                    double end_time);
/* Send the state at time t (after couple_dem_after, or the initial state
 * with zero drag when no advance happened yet). With `scheme concurrent`
 * the state at endTime is not sent: the fluid takes the DEM state at t^m
 * before its last step, nobody reads that one, and the fluid may have
 * closed the channel already (a send to a closed peer is an error). */
int couple_dem_send(struct couple_dem *cd, struct dem *d, long step,
                    double t);
/* Receive the fluid state; its time must be d->t. */
int couple_dem_recv(struct couple_dem *cd, struct dem *d);
void couple_dem_close(struct couple_dem *cd, int rc);

/* Totals of the last interval: drag sum_k F_bar^d_k (eq. 25) and the
 * pressure-gradient / buoyancy force sum_k F_ext,k [N]; largest slip
 * |u_k - v_k| [m/s], smallest eps_k, number of wet grains. */
void couple_dem_totals(const struct couple_dem *cd, const struct dem *d,
                       double drag[3], double press[3], double *slip_max,
                       double *eps_min, double *wet);

/* The same as function-object values (couple_fo.c: type couplingForces;
 * demSolid adds couple_fo_table to its tables and these to its scene). */
#define COUPLE_DEM_NVALUES 5
struct fo_value;
struct fo_ops;
void couple_dem_values(const struct couple_dem *cd, const struct dem *d,
                       struct fo_value *v);   /* COUPLE_DEM_NVALUES */
extern const struct fo_ops *const couple_fo_table[];

/* Per-grain fields of a coupled run's <time>/dem.vtu (the state of the
 * coupling interval that ends at the written time):
 *   porosity        eps_k of eq. (32), frozen over the interval
 *   fluidVelocity   u_k of eq. (33) [m/s], frozen over the interval
 *   slipVelocity    u_k - v_k [m/s], v_k the written velocity (0 for a dry
 *                   grain, eps_k = 1: no fluid in reach, no slip defined)
 *   drag            the drag the grain received, averaged over the DEM
 *                   sub-steps [N]: A F^d_k of eq. (25), B F^d_k/eps_k (35)
 *   Model A pressureGradientForce  -V_k gradP_k (34) [N]
 *   Model B buoyancy               -V_k rho_f g  (35) [N]
 * Slip u_k - v_k of every grain into cd->slip. Returns 1 when cd's arrays
 * describe d's grains (same count: no grain removed since the last
 * exchange), 0 otherwise (then there is nothing consistent to write). */
int couple_dem_output(struct couple_dem *cd, const struct dem *d);

void couple_dem_free(struct couple_dem *cd);

#endif
