/*
 * volume_exchange.c — water content that follows the grains (coupled runs
 * whose fluid particles hold phi_i dp^d of water, genParticles
 * `grainVolume scale`; couplingDict `volumeFractionRelaxation`).
 *
 * Every neighbour sum of a coupled run weighs particle j by a_j =
 * phi_j/eps_j (eq. 7 of Xie et al. 2025 with the volume fraction), so a
 * particle sits at spacing dp where a = 1. phi is set to the porosity of
 * the starting bed (a = 1 everywhere); when the bed then settles and
 * compacts, eps moves under particles whose phi does not: particles that
 * held pore water end in clear water holding half a particle's water, and
 * particles left in the compacted bed hold more than its pores do. a then
 * ranges over 0.6-1.4 (dp = 2.7 mm sedimentation), the number density of
 * the PPE wanders with it, and so do the operators' weights.
 *
 * Water is not bound to a particle, so neighbours trade it towards a
 * uniform a, conserving the water volume and its momentum:
 *
 *   F_ij = c (w_ij/n0) min(eps_i, eps_j) (a_j - a_i) = -F_ji,
 *   phi_i' = phi_i + sum_j F_ij,
 *   phi_i' u_i' = phi_i u_i + sum_j (F_ij > 0 ? F_ij u_j : F_ij u_i),
 *
 * over fluid pairs within the number-density radius (w of eq. 6),
 * c = dt / tau (tau = volumeFractionRelaxation [s]) capped at 1/4: then
 * each a_i' is a convex combination of its neighbours' a (the weights
 * sum to c (sum_j w_ij)/n0 <= 1/2 up to twice the lattice count), so phi
 * stays positive and a within its neighbours' range. Water moves with the
 * velocity of the particle it leaves. sum phi and sum phi u change by
 * round-off only; the exchange is a redistribution of the discretisation,
 * like particle shifting, not a flux of the physics: tau must be long
 * against dt and short against the bed's settling (10-100 steps).
 */
#include <math.h>

#include "core/error.h"
#include "mps/mps.h"
#include "mps/mps_impl.h"

int mps_volume_exchange(struct mps_solver *s, double dt)
{
    struct mps_particles *P = &s->P;
    const double tau = s->S.phi_relax_time;
    if (!(tau > 0) || !P->phi || !P->inv_eps)
        return SIM_OK;
    const double c = fmin(dt / tau, 0.25) / s->Ln.n0;
    const struct neighbour_list in = neighbour_inner(&s->nl);
    const struct neighbour_list *nl = &in;
    const struct pop_weights W = mps_w(s, MPS_W_N);
    const double *a = P->inv_eps, *phi = P->phi, *u = P->u;
    /* The step has not used lap and div yet: new phi in div, new u in lap. */
    double *phi_new = s->div, *u_new = s->lap;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++) {
        if (P->type[i] != MPS_FLUID)
            continue;
        const double eps_i = phi[i] / a[i];
        double dphi = 0, mom[3] = { 0, 0, 0 };
        const int64_t k0 = nl->start[i], k1 = neighbour_row_end(nl, i);
        const double *w = pop_weights_of(&W, nl, i, k0, k1);
        for (int64_t k = k0; k < k1; k++) {
            int j = nl->j[k];
            if (w[k - k0] == 0 || P->type[j] != MPS_FLUID)
                continue;
            double f = c * w[k - k0] * fmin(eps_i, phi[j] / a[j])
                     * (a[j] - a[i]);
            const double *uf = u + 3 * (f > 0 ? j : i);
            dphi += f;
            for (int q = 0; q < 3; q++)
                mom[q] += f * uf[q];
        }
        double p = phi[i] + dphi;
        phi_new[i] = p;
        for (int q = 0; q < 3; q++)
            u_new[3 * i + q] = (phi[i] * u[3 * i + q] + mom[q]) / p;
    }
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++) {
        if (P->type[i] != MPS_FLUID)
            continue;
        P->inv_eps[i] *= phi_new[i] / P->phi[i];
        P->phi[i] = phi_new[i];
        for (int q = 0; q < 3; q++)
            P->u[3 * i + q] = u_new[3 * i + q];
    }
    /* a ghost's row misses neighbours beyond the halo: its owner's
     * values */
    TRY(mps_halo_refresh(s, P->phi, sizeof *P->phi));
    TRY(mps_halo_refresh(s, P->inv_eps, sizeof *P->inv_eps));
    return mps_halo_refresh(s, P->u, 3 * sizeof *P->u);
}
