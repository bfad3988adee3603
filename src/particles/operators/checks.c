/*
 * checks.c — time-step limits and the NaN guard (doc/theory.md A.8):
 *
 *   Courant (A.8 eq. 37):   dt <= C dp / |u|_max
 *   acceleration:           dt <= C sqrt(dp / |g|)   (the first steps, when
 *                                                     u is still ~0)
 *   viscous diffusion [P]:  dt <= 0.2 dp^2 / nu      (explicit Laplacian)
 *
 * The acceleration limit keeps the first steps of a case that starts at
 * rest from taking the viscous limit alone, which can be seconds.
 */
#include "particles/operators/checks.h"

#include <math.h>
#include <stddef.h>

double pop_max_norm3(int n, const double *v, const int32_t *type,
                     int32_t only)
{
    double m = 0;
#pragma omp parallel for reduction(max : m)
    for (int i = 0; i < n; i++)
        if (!type || type[i] == only) {
            const double *u = v + 3 * i;
            m = fmax(m, u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        }
    return sqrt(m);
}

double pop_stable_dt(double dp, double nu, double umax, double gnorm,
                     double max_co)
{
    double dt = 0.2 * dp * dp / fmax(nu, 1e-300);
    if (umax > 0)
        dt = fmin(dt, max_co * dp / umax);
    if (gnorm > 0)
        dt = fmin(dt, max_co * sqrt(dp / gnorm));
    return dt;
}

int pop_first_nonfinite(int n, const double *p, const double *u,
                        const double *x, const char **field)
{
    *field = NULL;
    for (int i = 0; i < n; i++) {
        if (p && !isfinite(p[i]))
            *field = "pressure";
        else if (!isfinite(u[3 * i]) || !isfinite(u[3 * i + 1])
                 || !isfinite(u[3 * i + 2]))
            *field = "velocity";
        else if (!isfinite(x[3 * i]) || !isfinite(x[3 * i + 1])
                 || !isfinite(x[3 * i + 2]))
            *field = "position";
        if (*field)
            return i;
    }
    return -1;
}
