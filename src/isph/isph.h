/*
 * isph.h — the corrected SPH operators of the two-phase ISPH model for
 * suspended sediment (Pan 2022 thesis ch. 5, after Schwaiger 2008;
 * doc/theory.md part S), 2-D: the kernels, the correction matrices and
 * the gradient and Laplacian built on them. The solver (isphSediment) is
 * to come; this part is geometry and linear algebra only, so that the unit
 * tests of E4-01 ... E4-03 call what the solver will call.
 *
 * Conventions (doc S0-02, the thesis's D-07): dx = x_b - x_a, grad W_ab =
 * grad_a W(|x_a - x_b|) = W'(r) (x_a - x_b)/r, F_ab = (dx . grad W_ab)/r^2
 * = -W'(r)/r > 0, V_b the particle volumes (5.34).
 *
 *   L_a^-1  = sum_b V_b grad W_ab (x) dx          (L^-1)_kl = sum V dW/dx_k dx_l
 *   grad f_a = L_a sum_b V_b (f_b - f_a) grad W_ab                   (5.35)
 *   Gamma_a = sum_b V_b F_ab dx (x) dx                                (5.38)
 *   S_a     = sum_b V_b grad W_ab
 *   lap f_a = c_a { sum_b V_b (f_b - f_a) F_ab - grad f_a . S_a }    (5.36)
 *   c_a     = 2 tr(Gamma_a^-1)/n (printed) | 2n/tr(Gamma_a)  (D-08)
 *
 * The gradient is exact for linear fields wherever L_a^-1 is regular; the
 * Laplacian is exact for quadratic fields with an isotropic Hessian where
 * the support is full and symmetric, and with c_a = 2n/tr(Gamma) wherever
 * the gradient of the quadratic is exact.
 */
#ifndef MPSDEM_ISPH_ISPH_H
#define MPSDEM_ISPH_ISPH_H

#include <stdint.h>

struct neighbour_list;

/* A 2-D kernel W(r, h) with support radius `support` h. */
struct isph_kernel {
    const char *name;
    const char *reference;
    double support;                       /* in h                      */
    double (*w)(double r, double h);      /* W [1/m^2]                 */
    double (*dw)(double r, double h);     /* dW/dr [1/m^3]             */
};
extern const struct isph_kernel isph_wendland_c2, isph_cubic_spline;
extern const struct isph_kernel *const isph_kernels[];

/* Laplacian normalisation c_a (D-08). */
enum isph_lap_norm { ISPH_LAP_TRACE_INVERSE, ISPH_LAP_INVERSE_TRACE };

/* What the operators need of the particles, and their corrections. */
struct isph_cloud {
    int n;
    const double *x;          /* 3 per particle [m] (z = 0)              */
    const double *V;          /* per particle [m^2]                      */
    const struct neighbour_list *nl; /* rc >= support h                  */
    const struct isph_kernel *kernel;
    const uint8_t *active;    /* NULL, or 1: corrections made (others    */
                              /* are left alone: dry walls)              */
    double h;                 /* smoothing length [m]                    */
    int norm;                 /* enum isph_lap_norm                      */
    /* per particle, by isph_corrections(): */
    double *L;                /* 4: L_a, row-major                       */
    double *c;                /* c_a                                     */
    double *S;                /* 2: S_a                                  */
    uint8_t *isolated;        /* NULL: a singular L_a is an error; else  */
                              /* 1 where it is (L_a, c_a, S_a zero)      */
    long n_isolated;          /* how many, with `isolated`               */
    double *divr;             /* NULL, or div r = sum_b V_b (x_b - x_a).  */
                              /* grad W_ab (free-surface test, S0-14)    */
    double *theta;            /* NULL, or the kernel sum sum_b V_b W_ab,  */
                              /* a included (volumeRelaxation, S0-19)    */
};

/* L_a, c_a and S_a (and div r, theta with `divr`, `theta`) of every
 * (active) particle.
 * Where L_a^-1 or Gamma_a is singular (fewer than two independent
 * neighbours in the support: a particle thrown off the free surface),
 * SIM_ERR_NUMERIC naming the
 * particle, or with `isolated` the particle is flagged and its operators
 * are zero (no gradient, no Laplacian: it flies on its own). */
int isph_corrections(struct isph_cloud *c);

/* The kernel gradient grad_a W_ab of the pair (a, b) at distance r > 0
 * and dx = x_b - x_a (the uncorrected one of the stress divergence 5.43;
 * the corrections below are built on it). */
void isph_kernel_gradient(const struct isph_cloud *c, int a, int b,
                          double r, double dx[2], double gw[2]);

/* grad f of particle a (5.35), f of particle b at f[stride b]. */
void isph_gradient(const struct isph_cloud *c, const double *f, int stride,
                   int a, double g[2]);

/* The Laplacian of particle a as coefficients over row a of the list:
 * lap f_a = sum_k l[k] (f_{j_k} - f_a), k over the list's row a (the
 * entries outside the support get 0); the PPE's row (5.44). */
void isph_laplacian_row(const struct isph_cloud *c, int a, double *l);

/* lap f_a from the coefficients of isph_laplacian_row. */
double isph_laplacian(const struct isph_cloud *c, const double *f, int a);

#endif
