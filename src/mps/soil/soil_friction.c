/*
 * soil_friction.c — the friction force of Kim's solid-soil model
 * (doc/theory.md K.3), per unit volume:
 *
 *   F_f,i = sum_j (1/2)(mu_i + mu_j) [ |rho_j a_n,j - rho_i a_n,i|        (10)
 *                                      + p_s,ij sin(theta_ij) ] t_ij       (11), (14)
 *   p_s,ij = (p_h,i + p_h,j)/2                                             (12)
 *
 *   e_ij = r_ij/|r_ij|, a_n = a . e_ij (acceleration of the previous step),
 *   t_ij = -v^t_ij/|v^t_ij|, v^t_ij the part of v_i - v_j normal to e_ij,
 *   sin(theta_ij) = |e_ij x v_i|/|v_i|
 *
 * over the soil and wall neighbours j of a soil particle i (one soil
 * material: (mu_i + mu_j)/2 = mu). A wall neighbour has a = 0, the soil's
 * density and p_s = p_h,i: it carries the column standing on it. A pair
 * with |v^t_ij| < 1e-12 m/s adds nothing. Options: K0-04 (the pair terms
 * times d w_ij/n0) and K0-05 (the impulse |F| dt/rho_i of a step capped at
 * the largest sliding speed |v^t_ij| it opposes).
 */
#include <math.h>

#include "mps/soil/soil.h"
#include "particles/neighbour.h"

#define VT_MIN 1e-12   /* [m/s] below this a pair is not sliding */

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void soil_friction(const struct soil_friction_params *p, int dim,
                   const struct neighbour_list *nl, const double *w,
                   const double *x, const double *v, const double *a,
                   const double *rho, const double *p_h,
                   const uint8_t *role, double *F)
{
    const double kw = p->kernel_weight ? dim / p->n0 : 0.0;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < nl->n; i++) {
        double f[3] = { 0, 0, 0 }, vt_max = 0.0;
        if (role[i] == SOIL_SOIL) {
            const double *vi = v + 3 * i, *ai = a + 3 * i;
            const double speed = sqrt(dot3(vi, vi));
            const int64_t k0 = nl->start[i], k1 = neighbour_row_end(nl, i);
            const double *rr = neighbour_row_r(nl, i, k0, k1);
            for (int64_t k = k0; k < k1; k++) {
                const int j = nl->j[k];
                if (!(w[k] > 0) || (role[j] != SOIL_SOIL && role[j] != SOIL_WALL))
                    continue;
                const int wall = role[j] == SOIL_WALL;
                double e[3], vr[3];
                for (int q = 0; q < 3; q++) {
                    e[q] = (x[3 * j + q] - x[3 * i + q]) / rr[k - k0];
                    vr[q] = vi[q] - v[3 * j + q];
                }
                const double vn = dot3(vr, e);
                double vt[3];
                for (int q = 0; q < 3; q++)
                    vt[q] = vr[q] - vn * e[q];
                const double vtm = sqrt(dot3(vt, vt));
                if (vtm < VT_MIN)
                    continue;
                const double rho_j = wall ? rho[i] : rho[j];
                const double an_j = wall ? 0.0 : dot3(a + 3 * j, e);
                const double load = fabs(rho_j * an_j - rho[i] * dot3(ai, e));
                const double ps = wall ? p_h[i] : 0.5 * (p_h[i] + p_h[j]);
                double s = 0.0;
                if (speed > 0) {
                    double c[3] = { e[1] * vi[2] - e[2] * vi[1],
                                    e[2] * vi[0] - e[0] * vi[2],
                                    e[0] * vi[1] - e[1] * vi[0] };
                    s = sqrt(dot3(c, c)) / speed;
                }
                double mag = p->mu * (load + ps * s);
                if (p->kernel_weight)
                    mag *= kw * w[k];
                for (int q = 0; q < 3; q++)
                    f[q] -= mag * vt[q] / vtm;
                if (vtm > vt_max)
                    vt_max = vtm;
            }
            if (p->cap) {
                const double fm = sqrt(dot3(f, f));
                if (fm * p->dt > vt_max * rho[i])
                    for (int q = 0; q < 3; q++)
                        f[q] *= vt_max * rho[i] / (fm * p->dt);
            }
        }
        for (int q = 0; q < 3; q++)
            F[3 * i + q] = f[q];
    }
}
