/*
 * collision.h — the particle collision model of Lee et al. (2011) after
 * Koshizuka's original, shared by mpsFluid (`collision lee2011`) and
 * isphSediment (doc/theory.md S0-16): applied to the predicted velocity
 * u* before the pressure equation, so that the equation does not see an
 * approach as a huge divergence. Fluid particles (type 0) closer than rc
 * that approach a neighbour exchange the normal part of their relative
 * velocity as in an inelastic collision of masses m_i, m_j:
 *
 *     du_i = -(1 + e) m_j/(m_i + m_j) ((u_i - u_j).n_ij) n_ij
 *                                     if (u_i - u_j).n_ij > 0,
 *     n_ij = (r_j - r_i)/|r_j - r_i|,
 *
 * summed over all such neighbours (Jacobi form: symmetric, independent of
 * particle order, momentum conserving between fluid particles). Any other
 * type is a wall of infinite mass (du_i = -(1 + e) ...).
 *
 * Reference: B.-H. Lee, J.-C. Park, M.-H. Kim, S.-C. Hwang (2011),
 * Step-by-step improvement of MPS method in simulating violent free-surface
 * motions and impact-loads, Comput. Methods Appl. Mech. Eng. 200,
 * 1113-1125, sect. 3.4.
 */
#ifndef MPSDEM_PARTICLES_COLLISION_H
#define MPSDEM_PARTICLES_COLLISION_H

#include <stdint.h>

struct neighbour_list;

/* u (3 per particle) of the fluid particles changed in place; rho NULL
 * (equal masses) or per particle (m proportional to rho); du: work of 3
 * per particle. 3-D positions x (z = 0 in 2-D). */
void pop_collision(const struct neighbour_list *nl, const double *x,
                   const int32_t *type, const double *rho, double rc,
                   double e, double *u, double *du);

#endif
