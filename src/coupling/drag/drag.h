/*
 * drag.h — fluid-grain drag laws, selected by name (`dragModel ergunWenYu;`
 * in system/couplingDict; doc/design.md C3).
 *
 * Every law is written as a momentum-transfer coefficient per unit grain
 * volume,
 *
 *   F^d_k = K_k V_k (u_k - v_k),       K_k = beta_k / (1 - eps_k)   (25)
 *
 * K [kg m^-3 s^-1] stays finite as eps -> 1 (where beta -> 0) and as
 * |u - v| -> 0 (each law evaluates C_d |u - v| in a form that does not
 * divide by Re, doc/theory.md A.7), so F^d is finite, odd in (u - v) and zero
 * at u = v for every law: test/models/coupling checks this over the table.
 *
 * Re_k = eps_k rho_f d_k |u_k - v_k| / mu_f (28) in every law.
 *
 * Ops, field by field:
 *   name, reference  dictionary word; source printed at selection
 *   validity         one line: the regime where the correlation holds
 *   coeff(f, eps, slip, d)  K for porosity eps (0 < eps <= 1), slip speed
 *                    |u - v| >= 0 [m/s] and diameter d [m]
 *   force_all(f, n, eps, d, V, u, v, F)  F[3k..] = K V (u - v) for n grains
 *                    (array-level entry, doc/design.md C4: one indirect
 *                    call per batch); u, v, F interleaved 3 per grain
 *                    [m/s], [N]; V [m^3]; may run OpenMP threads.
 *   jump_eps         porosity of a documented discontinuity (the Ergun /
 *                    Wen-Yu switch), or 0 when the law is continuous in eps
 */
#ifndef MPSDEM_COUPLING_DRAG_H
#define MPSDEM_COUPLING_DRAG_H

#include <math.h>

struct dict;

/* Fluid properties every law needs. */
struct drag_fluid {
    double rho;   /* density rho_f [kg/m^3]        */
    double mu;    /* dynamic viscosity mu_f [Pa s] */
};

struct drag_ops {
    const char *name;
    const char *reference;
    const char *validity;
    double (*coeff)(const struct drag_fluid *f, double eps, double slip,
                    double d);
    void (*force_all)(const struct drag_fluid *f, int n, const double *eps,
                      const double *d, const double *V, const double *u,
                      const double *v, double *F);
    double jump_eps;
};

extern const struct drag_ops drag_none;
extern const struct drag_ops drag_ergun_wen_yu;
extern const struct drag_ops drag_gidaspow_blend;
extern const struct drag_ops drag_di_felice;

/* Every drag law; NULL-terminated (drag_register.c is the only list). */
extern const struct drag_ops *const drag_table[];

/* Select `dragModel` of couplingDict d (default ergunWenYu). */
int drag_select(const struct dict *d, const struct drag_ops **out);

/* Schiller-Naumann (27) written as C_d |u - v|, finite as Re -> 0:
 *   C_d |du| = 24 mu (1 + 0.15 Re^0.687) / (eps rho d)   Re <= 1000
 *            = 0.44 |du|                                 Re >  1000 */
static inline double drag_cd_slip_schiller_naumann(const struct drag_fluid *f,
                                                   double eps, double slip,
                                                   double d)
{
    double re = eps * f->rho * d * slip / f->mu;
    if (re > 1000.0)
        return 0.44 * slip;
    return 24.0 * f->mu * (1.0 + 0.15 * pow(re, 0.687)) / (eps * f->rho * d);
}

/* K of Ergun (26, eps <= 0.8 branch) divided by (1 - eps). */
static inline double drag_k_ergun(const struct drag_fluid *f, double eps,
                                  double slip, double d)
{
    return 150.0 * (1.0 - eps) / eps * f->mu / (d * d) +
           1.75 * f->rho * slip / d;
}

/* K of Wen-Yu (26, eps > 0.8 branch) divided by (1 - eps). */
static inline double drag_k_wen_yu(const struct drag_fluid *f, double eps,
                                   double slip, double d)
{
    return 0.75 * drag_cd_slip_schiller_naumann(f, eps, slip, d) * f->rho *
           pow(eps, -1.65) / d;
}

/* The body of force_all for a law whose coefficient is the static inline
 * function `coeff`: the indirect call is paid once per batch and the
 * coefficient is inlined into the loop. */
#define DRAG_DEFINE_FORCE_ALL(fname, coeff)                                  \
    static void fname(const struct drag_fluid *f, int n, const double *eps,  \
                      const double *d, const double *V, const double *u,     \
                      const double *v, double *F)                            \
    {                                                                        \
        _Pragma("omp parallel for schedule(static) if (n > 512)")            \
        for (int k = 0; k < n; k++) {                                        \
            double du[3], s2 = 0;                                            \
            for (int c = 0; c < 3; c++) {                                    \
                du[c] = u[3 * k + c] - v[3 * k + c];                         \
                s2 += du[c] * du[c];                                         \
            }                                                                \
            double kv = coeff(f, eps[k], sqrt(s2), d[k]) * V[k];             \
            for (int c = 0; c < 3; c++)                                      \
                F[3 * k + c] = kv * du[c];                                   \
        }                                                                    \
    }

#endif
