/*
 * walls.h — wall-boundary helpers shared by every solver whose walls are
 * layers of particles (MPS wall + dummy particles, SPH/ISPH dummy walls):
 * the partner of each inner-layer particle (the nearest wall particle,
 * whose pressure it borrows) and the pressure extrapolated from the fluid
 * (Adami, Hu and Adams 2012, J. Comput. Phys. 231, 7057, eq. 27). See
 * walls.c for the equations; src/mps/walls.c decides which particles use
 * which.
 *
 * Particles are told apart by an int32 class per particle (`type`, e.g.
 * MPS_FLUID / MPS_WALL / MPS_DUMMY); the helpers take the class values
 * they need, so that they know nothing of a solver's enumeration.
 */
#ifndef MPSDEM_PARTICLES_OPERATORS_WALLS_H
#define MPSDEM_PARTICLES_OPERATORS_WALLS_H

#include <stdint.h>

#include "particles/operators/weights.h"

struct neighbour_list;

/* May particle i take j (or j's partner) as its partner? NULL: always. */
typedef int pop_partner_filter(const void *ctx, int i, int j);

/* For every particle of class `seeker`, the nearest neighbour of class
 * `target` in its row that `allow` accepts, ties within tol [m] to the
 * smaller id (so that the choice does not depend on the order of the
 * rows); then, in up to four sequential passes, seekers still without
 * one borrow the partner of their nearest seeker neighbour that has one
 * (deep corner layers farther than the radius from every target).
 * partner[i] = -1 for every other particle and for orphans; returns the
 * number of orphans. Once per list build: not parallel (the passes read
 * partners set earlier in the same pass). */
int pop_wall_partners(const struct neighbour_list *nl, int n,
                      const int32_t *type, int32_t seeker, int32_t target,
                      const int64_t *id, double tol,
                      pop_partner_filter *allow, const void *ctx,
                      int32_t *partner);

/* Adami et al. (2012) eq. (27), fixed wall: the pressure at particle i
 * from its neighbours j of class `fluid` with w[k] > 0,
 *   p_i = sum_j (p_j + rho g.(r_i - r_j)) w_ij / sum_j w_ij.
 * Returns 0 (p untouched) when i has no such neighbour. */
int pop_wall_extrapolate(const struct neighbour_list *nl,
                         const struct pop_weights *W, const double *x,
                         const double *p, const int32_t *type, int32_t fluid,
                         double rho, const double g[3], int i, double *out);

#endif
