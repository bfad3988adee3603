/*
 * shifting_lind2012.c — Fickian particle shifting of Lind, Xu, Stansby and
 * Rogers (2012, J. Comput. Phys. 231, 1499, eqs. 20-24), written with the
 * MPS gradient (Xie et al. 2025 eq. 8 applied to a unit concentration),
 * after the position update:
 *
 *   grad C_i = (d/n0) sum_j r_ij / |r_ij|^2 w_ij / eps_j   (all neighbours)
 *   dr_i     = -A dp^2 grad C_i                             (inner particles)
 *   dr_i     = -A dp^2 (I - n n) grad C_i                   (at the surface)
 *
 * r_ij = r_j - r_i; grad C points to where the particles are denser, so
 * the shift moves a particle towards the gaps. A (`lind2012Coeffs {
 * coefficient }`, default 0.01) is per step: unlike Xu et al. (2009,
 * shifting_xu2009.c) the shift does not scale with u_max dt, so it keeps
 * the distribution regular in still water too, where the first-order
 * consistent gradient (pressureGradient corrected) leaves a zero-energy
 * "checkerboard" mode of the square lattice that grows slowly (measured in
 * the 2-D tank: L2 0.7 % at 1 s, 11 % at 3 s without shifting).
 * Free-surface particles and particles with a surface neighbour move only
 * tangentially (Lind et al. 2012 sect. 3.3): n = -F/|F| from eq. (15), so
 * the surface is not pushed outwards. A shift is capped at 0.1 dp. The
 * velocity and pressure are not re-interpolated to the new position (the
 * shift is a small fraction of dp). Viscoplastic soil is not shifted
 * (doc/theory.md K0-15).
 */
#include <math.h>

#include "core/error.h"
#include "mps/kernel/kernel.h"
#include "mps/mps.h"
#include "mps/soil/soil_step.h"
#include "mps/stabiliser/stabiliser.h"
#include "particles/operators/operators.h"

#define MAX_SHIFT 0.1   /* [dp] */

/* grad C (and F, eq. 15) of particle i at the current positions, on the
 * gradient radius: shifting follows the position update, so the list's
 * distances and weights are those before it. */
static void asymmetry(const struct mps_solver *s, int i, double G[3],
                      double F[3])
{
    const struct mps_particles *P = &s->P;
    pop_concentration_gradient(&s->nl, P->x, P->inv_eps, s->S.kernel->w,
                               s->S.re_grad * s->dp, P->dim / s->Lg.n0, i,
                               G, F);
}

static int near_surface(const struct mps_solver *s,
                        const struct pop_weights *Wg, int i)
{
    const struct mps_particles *P = &s->P;
    const struct neighbour_list *nl = &s->nl;
    if (P->fs[i] == MPS_SURFACE)
        return 1;
    const int64_t k0 = nl->start[i], k1 = nl->start[i + 1];
    const double *w = pop_weights_of(Wg, nl, i, k0, k1);
    for (int64_t k = k0; k < k1; k++) {
        int j = nl->j[k];
        if (w[k - k0] > 0 && P->type[j] == MPS_FLUID
            && P->fs[j] == MPS_SURFACE)
            return 1;
    }
    return 0;
}

static int apply_shifting(struct mps_solver *s, double dt)
{
    (void)dt;
    struct mps_particles *P = &s->P;
    const double D = s->S.shifting_coeff * s->dp * s->dp;
    const double cap = MAX_SHIFT * s->dp;
    double *dr = s->grad;
    const int32_t *fixed = mps_soil_unshifted(s);
    const struct pop_weights Wg = mps_w(s, MPS_W_G);
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++) {
        double G[3], F[3], d[3] = { 0, 0, 0 };
        if (P->type[i] == MPS_FLUID && !(fixed && fixed[i] == 1)) {
            asymmetry(s, i, G, F);
            pop_fickian_shift(G, F, D, near_surface(s, &Wg, i), cap, d);
            if (P->dim == 2)
                d[2] = 0;
        }
        for (int q = 0; q < 3; q++)
            dr[3 * i + q] = d[q];
    }
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++)
        for (int q = 0; q < 3; q++)
            P->x[3 * i + q] += dr[3 * i + q];
    return SIM_OK;
}

const struct mps_stabiliser_ops mps_shifting_lind2012 = {
    .name = "lind2012",
    .reference = "Lind, Xu, Stansby & Rogers 2012 JCP 231 eqs. 20-24",
    .apply = apply_shifting,
};
