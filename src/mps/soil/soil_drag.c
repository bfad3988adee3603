/*
 * soil_drag.c — the drag of the fluid on a soil particle, in the form with
 * consistent units that replaces Kim's eq. (15) (doc/theory.md K.4, K0-06):
 *
 *   F_d,i = (1/n0) sum_{j fluid} w_ij (1/2) C_D rho_f |v_ji| v_ji / l0,     (K.1)
 *   v_ji = v_j - v_i
 *
 * the drag of a cube of side l0 in the relative flow, averaged over the
 * fluid neighbours with the kernel. Reaction [P]: soil particle i (volume
 * V = l0^d) gives each fluid neighbour j the force -F_d,i V w_ij/S_i,
 * S_i = sum_{k fluid} w_ik, i.e. the acceleration -F_d,i w_ij/(S_i rho_f)
 * (a fluid particle's mass is rho_f V). Summed over j this is -F_d,i V:
 * the drag moves momentum between the phases and creates none (E5-06).
 * The reaction is gathered per fluid particle over its soil neighbours (the
 * list is symmetric), so no two threads write one particle.
 */
#include <math.h>

#include "mps/soil/soil.h"
#include "particles/neighbour.h"

void soil_drag(const struct soil_drag_params *p,
               const struct neighbour_list *nl, const double *w,
               const double *v, const uint8_t *role, double *F,
               double *a_fluid, double *S)
{
    const double c = 0.5 * p->cd * p->rho_f / (p->l0 * p->n0);
#pragma omp parallel for schedule(static)
    for (int i = 0; i < nl->n; i++) {
        double f[3] = { 0, 0, 0 }, sw = 0.0;
        if (role[i] == SOIL_SOIL)
            for (int64_t k = nl->start[i]; k < neighbour_row_end(nl, i); k++) {
                const int j = nl->j[k];
                if (role[j] != SOIL_FLUID || !(w[k] > 0))
                    continue;
                double u[3], um;
                for (int q = 0; q < 3; q++)
                    u[q] = v[3 * j + q] - v[3 * i + q];
                um = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
                for (int q = 0; q < 3; q++)
                    f[q] += w[k] * um * u[q];
                sw += w[k];
            }
        for (int q = 0; q < 3; q++)
            F[3 * i + q] = c * f[q];
        S[i] = sw;
    }
    if (!a_fluid)
        return;
#pragma omp parallel for schedule(static)
    for (int j = 0; j < nl->n; j++) {
        if (role[j] != SOIL_FLUID)
            continue;
        double r[3] = { 0, 0, 0 };
        for (int64_t k = nl->start[j]; k < neighbour_row_end(nl, j); k++) {
            const int i = nl->j[k];
            if (role[i] != SOIL_SOIL || !(w[k] > 0) || !(S[i] > 0))
                continue;
            for (int q = 0; q < 3; q++)
                r[q] += F[3 * i + q] * w[k] / S[i];
        }
        for (int q = 0; q < 3; q++)
            a_fluid[3 * j + q] -= r[q] / p->rho_f;
    }
}
