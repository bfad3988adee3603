/* mps_impl.h — functions shared between the files of src/mps, not part of
 * the public interface. */
#ifndef MPSDEM_MPS_MPS_IMPL_H
#define MPSDEM_MPS_MPS_IMPL_H

#include "mps/mps.h"

/* Keep n particles, new i <- old perm[i] (every registered field). */
int mps_particles_permute(struct mps_solver *s, const int32_t *perm, int n);
/* Remove the particles outside the box; *lost: the fluid ones among them. */
int mps_particles_drop_outside(struct mps_solver *s, int *lost);

/* Room in the per-particle work arrays for P.cap particles. */
int mps_fit_work(struct mps_solver *s);

/* A distributed run (mps_halo.c; nothing when s->halo is NULL): before a
 * step, migration and fresh ghosts; after a phase, the owners' values of
 * a field at the ghosts. */
int mps_halo_prepare(struct mps_solver *s);
int mps_halo_refresh(struct mps_solver *s, void *field, size_t elem);

/* lost fluid particles have left the box (and were removed): counted,
 * logged; SIM_ERR_INPUT beyond maxEscapeFraction. */
int mps_escaped(struct mps_solver *s, long lost);

/* Free the neighbour list's storage (its settings stay); the next step
 * builds it again. */
void mps_drop_list(struct mps_solver *s);

/* The list still holds every pair within r_e (no particle moved more
 * than half the skin since it was built, no rebuild requested). */
int mps_list_valid(const struct mps_solver *s);

/* Neighbours (with removal of escaped particles and renumbering) and the
 * weights of each operator radius. */
int mps_neighbours(struct mps_solver *s);

/* Trade water content phi between neighbouring fluid particles towards
 * a uniform phi/eps (volume_exchange.c); nothing unless phi_relax_time > 0
 * and the particles hold phi. Uses lap and div as scratch. */
int mps_volume_exchange(struct mps_solver *s, double dt);
/* The largest fluid speed [m/s] (of every rank in a distributed run). */
double mps_max_fluid_speed(const struct mps_solver *s);

/* After every change of the list: room for its rows in the computed
 * weights (mps_w), or the stored weights of every radius (soil). */
int mps_weights(struct mps_solver *s);

/* Assemble and solve the PPE; fills P->p (0 at Dirichlet particles). */
int mps_ppe_solve(struct mps_solver *s, double dt);

/* Dummy pressure from the partner wall particle (or 0). */
int mps_dummy_pressure(struct mps_solver *s);

/* Nearest wall particle of every dummy; where a patch moves or is
 * removed, only within the dummy's own patch (walls.c). */
int mps_find_partners(struct mps_solver *s);

/* Moving and removed walls (walls.c): at the start of a step of size dt
 * from s->time, delete removed patches and set the velocity of moving
 * ones; after the fluid moved, move the walls. */
int mps_walls_begin_step(struct mps_solver *s, double dt);
void mps_walls_move(struct mps_solver *s);

/* Wall particles with too few wall/dummy layers behind them for r_e. */
int mps_thin_walls(const struct mps_solver *s);

#endif
