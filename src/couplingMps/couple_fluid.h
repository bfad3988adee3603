/*
 * couple_fluid.h — the fluid side of a coupled MPS-DEM run: what mpsFluid
 * does around each mps_step() (doc/theory.md A.10, sequential MSS, A0-15;
 * doc/design.md §4). It connects the channel (channel.h, protocol.h), the
 * coupling physics (pairs, porosity, interp, reaction, models) and the MPS
 * solver's hooks inv_eps and f_ext (mps.h).
 *
 * One fluid step m -> m+1, in the order of models.h:
 *   couple_fluid_exchange()  Shepard eps_k, u_k (Model A: gradP_k) at the
 *                            grains at t^m -> send; receive the DEM state at
 *                            t^{m+1} (positions, velocities, radii, drag
 *                            averaged over the sub-steps); porosity eps^{m+1}
 *                            of every MPS particle -> P.inv_eps; reaction
 *                            f_A (36) -> P.f_ext (coupling_mps_accel)
 *   mps_step()
 * The first exchange first receives the DEM's initial state (at t^0).
 *
 * `scheme concurrent;` (one-step lag): the exchange before the step
 * t^m -> t^{m+1} receives the DEM state at t^m (positions and the drag of
 * the interval before), computes eps^m and f_A from it, then sends the
 * fluid state at t^m; the DEM advances to t^{m+1} while the fluid steps,
 * so both programs compute at once. The DEM side is the same in both
 * schemes.
 *
 * The same work without a channel (tests, a single program that owns both
 * phases): couple_fluid_set_grains() + couple_fluid_update() replace the
 * receive, couple_fluid_grain_fields() the send.
 *
 * 2-D: grains stay spheres (their drag and buoyancy are those of a sphere)
 * and the 2-D fluid is read as a slab one dp deep: a grain occupies the
 * area V_k/dp of the plane in eq. (31), and its reaction is spread over
 * MPS particles of volume dp^3, so that momentum balances in the slab.
 *
 * Model B's PPE source factor s_i = eps_i (13) and correction factor
 * c_i = 1/eps_i (the 1/eps of eq. 5 on the intrinsic velocity) go into
 * the solver's ppe_scale and corr_scale hooks, allocated for Model B only;
 * with `ppeDivergence superficial;` the solver's scaled_divergence is set
 * (the PPE takes the divergence of eps u*, models.c).
 */
#ifndef MPSDEM_COUPLINGMPS_COUPLE_FLUID_H
#define MPSDEM_COUPLINGMPS_COUPLE_FLUID_H

#include <stdint.h>

#include "coupling/interp.h"
#include "coupling/models.h"
#include "coupling/pairs.h"

struct dict;
struct channel;
struct mps_solver;
struct proto_dem_state;

struct couple_fluid {
    struct coupling_settings cs;
    const struct dict *dict;    /* system/couplingDict (the caller's)    */
    struct channel *ch;         /* NULL until couple_fluid_open          */
    int dim;
    double dp, re, Vp;          /* spacing, r_e,s [m], MPS volume dp^3   */
    double rho, g[3];
    struct coupling_pairs pairs;
    /* grains of the last DEM state */
    int ng, cap_g;
    double *xg, *vg, *rg, *Vg;  /* 3ng, 3ng, ng, ng (area in 2-D)       */
    double *Fbar, *Fin;         /* 3ng averaged drag; what (36) spreads  */
    double *Vs;                 /* ng sphere volumes (guards)            */
    double dem_time;            /* time of the last DEM state            */
    /* fields at the grains, sent to the DEM side */
    double *eps_k, *u_k, *gradp_k;
    uint8_t *wet;
    double *gsum;               /* COUPLING_SUMS ng: a distributed run's
                                   per-grain sums before the reduction  */
    /* per MPS particle (capacity cap_p) */
    int cap_p;
    double *eps, *fA, *gradp_p;
    uint8_t *mask;              /* fluid and wall: interpolation, (36)   */
    int64_t *id_seen;           /* ids at the last pair search           */
    int n_seen;
    /* book-keeping */
    long n_clamped;             /* porosity clamps at the last update    */
    int n_orphan;               /* grains whose reaction found no fluid  */
    int concurrent;             /* scheme concurrent (one-step lag)      */
    long exchanges;
    long searches;              /* grain-particle pair searches          */
    double wall;                /* seconds spent here (not in the wait)  */
    double wait;                /* seconds waiting for the DEM side      */
};

/* Settings from system/couplingDict, then own the hooks of s: allocate
 * s->P.inv_eps (= 1) and s->P.f_ext (= 0) for the solver's capacity.
 * rho and g are those of the MPS settings. */
int couple_fluid_init(struct couple_fluid *cf, const struct dict *coupling,
                      struct mps_solver *s);

/* Copy a DEM state (positions, velocities, radii, drag) in; time t. */
int couple_fluid_set_grains(struct couple_fluid *cf,
                            const struct proto_dem_state *st, double t);

/* Pairs and porosity (31) of every MPS particle at the current grain
 * positions -> cf->eps, s->P.inv_eps; then the reaction (36) of the
 * averaged drag -> cf->fA and s->P.f_ext (models.h step 6-7), using the
 * eps_k of the last couple_fluid_grain_fields (the values the DEM used). */
int couple_fluid_update(struct couple_fluid *cf, struct mps_solver *s);

/* eps_k, u_k (and Model A gradP_k) at the grain centres from the current
 * MPS state (eqs. 32-33, A0-14). */
int couple_fluid_grain_fields(struct couple_fluid *cf, struct mps_solver *s);

/* sum_i V_i f_A,i of the last update [N] (E1-13 diagnostics). */
void couple_fluid_reaction_total(const struct couple_fluid *cf,
                                 const struct mps_solver *s, double F[3]);

/* -V_i f_A,i of the last update for every particle of P (3 P->n) [N]:
 * the reaction written with the output, kept as a field of P's store so
 * that it follows the particles through mps_step()'s renumbering (and a
 * distributed run's migration). */
struct mps_particles;
void couple_fluid_reaction_field(const struct couple_fluid *cf,
                                 const struct mps_particles *P, double *F);

/* Channel: open (couplingDict channel keys; the dimension and endTime of
 * the case, which the handshake compares with the DEM's). In a
 * distributed run (s->halo) rank 0 alone holds the channel: the exchange
 * shares the grains it receives with every rank (each holds every grain),
 * and the grains' sums of eqs. (32)-(33) and (36) are summed over the
 * ranks' own particles. */
int couple_fluid_open(struct couple_fluid *cf, const struct mps_solver *s,
                      const struct dict *coupling, const char *case_dir,
                      const char *program, double end_time);
/* One exchange before the step t -> t + dt (see the top of this file).
 * The DEM state must arrive at t + dt (same coupling interval on both
 * sides), else SIM_ERR_INPUT naming both controlDicts. */
int couple_fluid_exchange(struct couple_fluid *cf, struct mps_solver *s,
                          long step, double t, double dt);
/* Close the channel with status rc (SIM_OK: normal end). */
void couple_fluid_close(struct couple_fluid *cf, int rc);
/* Close if open, free everything (the hooks in s stay owned by s). */
void couple_fluid_free(struct couple_fluid *cf);

#endif
