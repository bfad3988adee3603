/*
 * collision_lee2011.c — the MPS collision model of Lee et al. (2011), after
 * Koshizuka's original, applied to the predicted velocity u* before the
 * pressure equation (as in the reference code of Koshizuka et al. 2018,
 * so that the PPE does not see the approach as a huge divergence): fluid
 * particles closer than alpha_c dp that approach each other exchange the
 * normal part of their relative velocity as in an inelastic collision of
 * masses m = rho dp^d (equal but for the soil of doc/theory.md K),
 *
 *     du_i = -(1 + e) m_j/(m_i + m_j) ((u_i - u_j).n_ij) n_ij
 *                                         if (u_i - u_j).n_ij > 0,
 *     n_ij = (r_j - r_i)/|r_j - r_i|,
 *
 * summed over all such neighbours (Jacobi form: symmetric, independent of
 * particle order, momentum conserving between fluid particles). A wall or
 * dummy partner has infinite mass (du_i = -(1 + e) ... ). Keys in
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

static int apply_collision(struct mps_solver *s, double dt)
{
    (void)dt;
    struct mps_particles *P = &s->P;
    const double rc = s->S.collision_ratio * s->dp;
    const struct neighbour_list in = neighbour_inner(&s->nl);
    const struct neighbour_list *nl = rc <= s->nl.r_inner ? &in : &s->nl;
    const double e = s->S.collision_restitution;
    double *du = s->grad; /* free before the correction */
    double *u = s->ustar;
    const double *rho = s->soil ? s->soil->rho : NULL; /* NULL: one density */
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++) {
        double d[3] = { 0, 0, 0 };
        if (P->type[i] == MPS_FLUID) {
            const int64_t k1 = neighbour_row_end(nl, i);
            for (int64_t k = nl->start[i]; k < k1; k++) {
                double r = nl->r[k];
                if (r >= rc || r == 0)
                    continue;
                int j = nl->j[k];
                double n[3], vn = 0;
                for (int q = 0; q < 3; q++) {
                    n[q] = (P->x[3 * j + q] - P->x[3 * i + q]) / r;
                    vn += (u[3 * i + q] - u[3 * j + q]) * n[q];
                }
                if (vn <= 0)
                    continue;
                double f = P->type[j] != MPS_FLUID ? 1 + e
                         : rho ? (1 + e) * rho[j] / (rho[i] + rho[j])
                         : 0.5 * (1 + e);
                for (int q = 0; q < 3; q++)
                    d[q] -= f * vn * n[q];
            }
        }
        for (int q = 0; q < 3; q++)
            du[3 * i + q] = d[q];
    }
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++)
        if (P->type[i] == MPS_FLUID)
            for (int q = 0; q < 3; q++)
                u[3 * i + q] += du[3 * i + q];
    return SIM_OK;
}

const struct mps_stabiliser_ops mps_collision_lee2011 = {
    .name = "lee2011",
    .reference = "Lee et al. 2011 CMAME 200 sect. 3.4",
    .apply = apply_collision,
};
