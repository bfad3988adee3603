/*
 * couple_output.h — per-point coupling fields in the output of a coupled
 * run (issue 6; Xie et al. 2025 eqs. 25, 32-36; doc/theory.md A.7-A.8).
 *
 * demSolid, <time>/dem.vtu, per grain k (couple_dem.h; the state of the
 * coupling interval that ends at the written time):
 *   porosity        eps_k of eq. (32), frozen over the interval
 *   fluidVelocity   u_k of eq. (33) [m/s], frozen over the interval
 *   slipVelocity    u_k - v_k [m/s], v_k the written velocity (0 for a dry
 *                   grain, eps_k = 1: no fluid in reach, no slip defined)
 *   drag            the drag the grain received, averaged over the DEM
 *                   sub-steps [N]: A F^d_k of eq. (25), B F^d_k/eps_k (35)
 *   Model A pressureGradientForce  -V_k gradP_k (34) [N]
 *   Model B buoyancy               -V_k rho_f g  (35) [N]
 * mpsFluid, <time>/fluid.vtu, per MPS particle i (besides porosity eps_i):
 *   reaction        -V_i f_A,i of eq. (36) [N], the averaged drag of the
 *                   last exchange spread over the particles (fluid and
 *                   wall): sum_i reaction_i = -sum_k F_bar_k, F_bar the
 *                   eq. (25) drag the DEM sent (B: eps_k x the grain's
 *                   `drag` field).
 * A standalone run writes none of these.
 *
 * f_A is computed before mps_step(), which renumbers the particles (cell
 * order) and drops escaped ones; couple_output_snapshot() keeps it with
 * the particle ids of that moment and couple_output_reaction() puts it in
 * the order of the written cloud.
 */
#ifndef MPSDEM_COUPLING_COUPLE_OUTPUT_H
#define MPSDEM_COUPLING_COUPLE_OUTPUT_H

#include <stddef.h>
#include <stdint.h>

struct couple_dem;
struct couple_fluid;
struct dem;
struct mps_particles;

/* Slip u_k - v_k of every grain into cd->slip. Returns 1 when cd's arrays
 * describe d's grains (same count: no grain removed since the last
 * exchange), 0 otherwise (then there is nothing consistent to write). */
int couple_dem_output(struct couple_dem *cd, const struct dem *d);

struct couple_output {
    int n, cap;
    int64_t *id;        /* ids at the snapshot                          */
    double *F;          /* 3n reaction at the snapshot                  */
    double *out;        /* 3 cap reaction in the current order          */
    int64_t *key;       /* scratch: (id, index) sorted by id            */
};

/* After couple_fluid_exchange(), before mps_step(): -V_i f_A,i with the
 * ids of P's current order. */
int couple_output_snapshot(struct couple_output *o,
                           const struct couple_fluid *cf,
                           const struct mps_particles *P);

/* The snapshot in P's current order (3 P->n values, in o->out); a
 * particle absent from the snapshot (none expected) gets 0. */
int couple_output_reaction(struct couple_output *o,
                           const struct mps_particles *P, double **out);

void couple_output_free(struct couple_output *o);

#endif
