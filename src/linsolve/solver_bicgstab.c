/*
 * solver_bicgstab.c — BiCGSTAB with right preconditioning, for the
 * non-symmetric PPE of the coupled case (porosity weights 1/eps_j,
 * doc/theory.md §A.4 note [P]). van der Vorst (1992), SIAM J. Sci. Stat.
 * Comput. 13:631–644, Alg. "preconditioned Bi-CGSTAB"; Saad (2003) Alg. 7.7:
 *
 *   r = b - A x, rh = r, rho = alpha = omega = 1, v = p = 0
 *   loop: rho' = (rh, r); beta = (rho'/rho)(alpha/omega)
 *         p = r + beta (p - omega v); y = M^-1 p; v = A y
 *         alpha = rho' / (rh, v); s = r - alpha v
 *         z = M^-1 s; t = A z; omega = (t, s)/(t, t)
 *         x += alpha y + omega z; r = s - omega t
 *
 * With right preconditioning r is the residual of the unpreconditioned
 * system, so the stopping test is the one the facade checks. One iteration
 * costs two SpMVs and two preconditioner applications. On breakdown
 * (rho' = 0, (rh, v) = 0 or omega = 0) we restart with rh = r, a few times.
 */
#include <math.h>

#include "core/error.h"
#include "linsolve/csr.h"
#include "linsolve/linsolve_impl.h"

enum { W_R, W_RH, W_P, W_V, W_Y, W_S, W_Z, W_T };
#define MAX_RESTARTS 5

static void direction(int n, double beta, double omega, const double *r,
                      const double *v, double *p)
{
#pragma omp parallel for schedule(static) if (LS_PAR(n))
    for (int i = 0; i < n; i++)
        p[i] = r[i] + beta * (p[i] - omega * v[i]);
}

/* s = r - alpha v; returns (s, s). */
static double axpy_norm(int n, double alpha, const double *r, const double *v,
                        double *s)
{
    double d = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : d) if (LS_PAR(n))
    for (int i = 0; i < n; i++) {
        s[i] = r[i] - alpha * v[i];
        d += s[i] * s[i];
    }
    return d;
}

/* (t, s) and (t, t) in one pass. */
static void dot2(int n, const double *t, const double *s, double *ts,
                 double *tt)
{
    double a = 0.0, b = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : a, b) if (LS_PAR(n))
    for (int i = 0; i < n; i++) {
        a += t[i] * s[i];
        b += t[i] * t[i];
    }
    *ts = a;
    *tt = b;
}

/* x += alpha y + omega z; r = s - omega t; returns (r, r). */
static double update(int n, double alpha, double omega, const double *y,
                     const double *z, const double *s, const double *t,
                     double *x, double *r)
{
    double d = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : d) if (LS_PAR(n))
    for (int i = 0; i < n; i++) {
        x[i] += alpha * y[i] + omega * z[i];
        r[i] = s[i] - omega * t[i];
        d += r[i] * r[i];
    }
    return d;
}

/* One cycle from r = b - A x; returns SIM_OK with *broke set on breakdown. */
static int cycle(struct linsolve *s, const struct csr_matrix *A, double *x,
                 double tolabs, int *iters, int *broke)
{
    int n = A->n;
    double **w = s->work;
    const struct precond *pc = &s->pc;
    double rho = 1.0, alpha = 1.0, omega = 1.0;
    vec_copy(n, w[W_R], w[W_RH]);
    vec_zero(n, w[W_P]);
    vec_zero(n, w[W_V]);
    *broke = 0;
    while (*iters < s->maxiter) {
        double rho1 = vec_dot(n, w[W_RH], w[W_R]);
        if (rho1 == 0.0 || omega == 0.0)
            return *broke = 1, SIM_OK;
        double beta = (rho1 / rho) * (alpha / omega);
        rho = rho1;
        direction(n, beta, omega, w[W_R], w[W_V], w[W_P]);
        pc->ops->apply(pc, w[W_P], w[W_Y]);
        csr_spmv(A, w[W_Y], w[W_V]);
        double rhv = vec_dot(n, w[W_RH], w[W_V]);
        if (rhv == 0.0 || !isfinite(rhv))
            return *broke = 1, SIM_OK;
        alpha = rho / rhv;
        double ss = axpy_norm(n, alpha, w[W_R], w[W_V], w[W_S]);
        ++*iters;
        if (sqrt(ss) <= tolabs) {
            /* x += alpha y, r = s: the half step already converged. */
            update(n, alpha, 0.0, w[W_Y], w[W_Y], w[W_S], w[W_S], x, w[W_R]);
            return SIM_OK;
        }
        pc->ops->apply(pc, w[W_S], w[W_Z]);
        csr_spmv(A, w[W_Z], w[W_T]);
        double ts, tt;
        dot2(n, w[W_T], w[W_S], &ts, &tt);
        if (!(tt > 0.0))
            return *broke = 1, SIM_OK;
        omega = ts / tt;
        double rr = update(n, alpha, omega, w[W_Y], w[W_Z], w[W_S], w[W_T], x,
                           w[W_R]);
        if (sqrt(rr) <= tolabs)
            return SIM_OK;
    }
    return SIM_OK;
}

static int solve(struct linsolve *s, const struct csr_matrix *A,
                 const double *b, double *x, double tolabs,
                 struct linsolve_stats *st)
{
    int iters = 0, broke = 0;
    for (int restart = 0;; restart++) {
        double rnorm = sqrt(csr_residual(A, b, x, s->work[W_R]));
        if (!isfinite(rnorm))
            return sim_error(SIM_ERR_NUMERIC, "BiCGSTAB: residual is not "
                             "finite after %d iterations", iters);
        if (rnorm <= tolabs || iters >= s->maxiter || restart > MAX_RESTARTS)
            break;
        int before = iters;
        TRY(cycle(s, A, x, tolabs, &iters, &broke));
        if (broke && iters == before)
            return sim_error(SIM_ERR_SOLVER, "BiCGSTAB breakdown at iteration "
                             "%d with no progress (rho or omega = 0)", iters);
    }
    st->iters = iters;
    return SIM_OK;
}

const struct solver_ops solver_bicgstab = {
    .name = "bicgstab",
    .reference = "van der Vorst 1992, right-preconditioned",
    .iterative = 1, .needs_symmetric = 0, .needs_spd_pc = 0,
    .solve = solve,
};
