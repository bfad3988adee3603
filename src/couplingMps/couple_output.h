/*
 * couple_output.h — the per-particle coupling field of a coupled mpsFluid
 * run's output (Xie et al. 2025 eq. 36; doc/theory.md A.8; the grains'
 * fields are in couple_dem.h).
 *
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
#ifndef MPSDEM_COUPLINGMPS_COUPLE_OUTPUT_H
#define MPSDEM_COUPLINGMPS_COUPLE_OUTPUT_H

#include <stddef.h>
#include <stdint.h>

struct couple_fluid;
struct mps_particles;

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
