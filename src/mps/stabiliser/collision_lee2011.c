/*
 * collision_lee2011.c — the MPS collision model of Lee et al. (2011), after
 * Koshizuka's original (the shared src/particles/operators/collision.h),
 * applied to the predicted velocity u* before the pressure equation (as in
 * the reference code of Koshizuka et al. 2018, so that the PPE does not
 * see the approach as a huge divergence): fluid particles closer than
 * alpha_c dp that approach each other exchange the normal part of their
 * relative velocity as in an inelastic collision of masses m = rho dp^d
 * (equal but for the soil of doc/theory.md K); a wall or dummy partner
 * has infinite mass. Keys in
 * system/mpsSchemes: collisionDistance (alpha_c, default 0.5 [-]),
 * collisionRestitution (e, default 0.2 [-]).
 *
 * Reference: B.-H. Lee, J.-C. Park, M.-H. Kim, S.-C. Hwang (2011),
 * Step-by-step improvement of MPS method in simulating violent free-surface
 * motions and impact-loads, Comput. Methods Appl. Mech. Eng. 200,
 * 1113-1125, sect. 3.4.
 */
#include "core/error.h"
#include "mps/mps.h"
#include "mps/soil/soil_step.h"
#include "mps/stabiliser/stabiliser.h"
#include "particles/operators/collision.h"

static int apply_collision(struct mps_solver *s, double dt)
{
    (void)dt;
    struct mps_particles *P = &s->P;
    const double rc = s->S.collision_ratio * s->dp;
    const struct neighbour_list in = neighbour_inner(&s->nl);
    const struct neighbour_list *nl = rc <= s->nl.r_inner ? &in : &s->nl;
    /* du: s->grad, free before the correction; NULL rho: one density */
    pop_collision(nl, P->x, P->type, s->soil ? s->soil->rho : NULL, rc,
                  s->S.collision_restitution, s->ustar, s->grad);
    return SIM_OK;
}

const struct mps_stabiliser_ops mps_collision_lee2011 = {
    .name = "lee2011",
    .reference = "Lee et al. 2011 CMAME 200 sect. 3.4",
    .apply = apply_collision,
};
