/*
 * shifting_xu2009.c — particle shifting of Xu, Stansby and Laurence (2009),
 * eqs. (16)-(17) there, applied to inner fluid particles after the position
 * update:
 *
 *     dr_i = C alpha R_i,    R_i = sum_j (r0/|r_ij|)^2 (r_i - r_j)/|r_ij|,
 *     alpha = u_max dt,
 *
 * over neighbours within the gradient radius, r0 = dp. Free-surface
 * particles are not shifted (they would be pushed out of the fluid), nor is
 * viscoplastic soil (doc/theory.md K0-15). Key in
 * system/mpsSchemes: shiftingCoeff (C, default 0.01 [-]).
 *
 * Reference: R. Xu, P. Stansby, D. Laurence (2009), Accuracy and stability
 * in incompressible SPH (ISPH) based on the projection method and a new
 * approach, J. Comput. Phys. 228, 6703-6725, eqs. 16-17.
 */
#include <math.h>

#include "core/error.h"
#include "mps/mps.h"
#include "mps/mps_impl.h"
#include "mps/soil/soil_step.h"
#include "mps/stabiliser/stabiliser.h"

static int apply_shifting(struct mps_solver *s, double dt)
{
    struct mps_particles *P = &s->P;
    const struct neighbour_list *nl = &s->nl;
    const double re = s->S.re_grad * s->dp, r0 = s->dp;
    const double ca = s->S.shifting_coeff * mps_max_fluid_speed(s) * dt;
    double *dr = s->grad;
    const int32_t *fixed = mps_soil_unshifted(s);
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++) {
        double R[3] = { 0, 0, 0 };
        if (P->type[i] == MPS_FLUID && P->fs[i] == MPS_INNER
            && !(fixed && fixed[i] == 1)) {
            const int64_t k0 = nl->start[i], k1 = nl->start[i + 1];
            const double *rr = neighbour_row_r(nl, i, k0, k1);
            for (int64_t k = k0; k < k1; k++) {
                double r = rr[k - k0];
                if (r >= re || r == 0)
                    continue;
                int j = nl->j[k];
                double f = r0 * r0 / (r * r * r);
                for (int q = 0; q < 3; q++)
                    R[q] += f * (P->x[3 * i + q] - P->x[3 * j + q]);
            }
        }
        for (int q = 0; q < 3; q++)
            dr[3 * i + q] = ca * R[q];
    }
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++)
        for (int q = 0; q < 3; q++)
            P->x[3 * i + q] += dr[3 * i + q];
    return SIM_OK;
}

const struct mps_stabiliser_ops mps_shifting_xu2009 = {
    .name = "xu2009",
    .reference = "Xu, Stansby & Laurence 2009 JCP 228 eqs. 16-17",
    .apply = apply_shifting,
};
