/*
 * checks.h — time-step limits and the NaN guard of an explicit or
 * semi-implicit particle method, shared by every solver (see checks.c for
 * the limits).
 */
#ifndef MPSDEM_PARTICLES_OPERATORS_CHECKS_H
#define MPSDEM_PARTICLES_OPERATORS_CHECKS_H

#include <stdint.h>

/* max |v_i| over the particles with type[i] == only (type NULL: all);
 * v holds 3 values per particle. */
double pop_max_norm3(int n, const double *v, const int32_t *type,
                     int32_t only);

/* The largest stable step for spacing dp [m], viscosity nu [m^2/s],
 * speed umax [m/s] and gravity |g| [m/s^2] at Courant number max_co. */
double pop_stable_dt(double dp, double nu, double umax, double gnorm,
                     double max_co);

/* The first particle with a non-finite p (may be NULL), u or x, in that
 * order of checking, and the name of the field ("pressure", "velocity",
 * "position") in *field; -1 when every value is finite. */
int pop_first_nonfinite(int n, const double *p, const double *u,
                        const double *x, const char **field);

#endif
