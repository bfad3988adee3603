/*
 * solver_pcg.c — preconditioned conjugate gradients for the symmetric
 * positive definite PPE (single phase, doc/theory.md §A.4 with Dirichlet
 * free-surface rows). Hestenes & Stiefel (1952); Saad (2003), Alg. 9.1:
 *
 *   r = b - A x, z = M^-1 r, p = z
 *   loop: q = A p, alpha = (r,z)/(p,q), x += alpha p, r -= alpha q,
 *         z = M^-1 r, beta = (r,z)_new/(r,z), p = z + beta p
 *
 * Converged when ||r||_2 <= tol ||b||_2 on the recursive residual; the true
 * residual b - A x is then recomputed, and if it does not meet the tolerance
 * (rounding drift) CG restarts from x, at most a few times within maxIter.
 *
 * Fast path for a diagonal M (jacobi, none), memory-bound, so organised to
 * stream as little as possible: z is never stored; the r update accumulates
 * (r,r) and (r, M^-1 r) in the same loop; the x update is deferred to the
 * direction loop (x += alpha p just before p is overwritten), which reads p
 * anyway. Bytes per iteration (STREAM counting): 12 nnz + 8 n x 13 streams
 * (SpMV: rowptr, p, q; residual: r r/w, q, dinv; direction: x r/w, p r/w,
 * r, dinv). The generic path (any M, and the reference for the fast one in
 * the tests) follows Alg. 9.1 literally.
 */
#include <math.h>

#include "core/error.h"
#include "linsolve/linsolve_impl.h"

enum { W_R, W_P, W_Q, W_Z };
#define MAX_RESTARTS 3

static int breakdown(int iters, double pq, double rz)
{
    return sim_error(SIM_ERR_SOLVER, "PCG breakdown at iteration %d: p'Ap = "
                     "%g, r'M^-1r = %g (matrix or preconditioner not positive "
                     "definite; use bicgstab for a non-symmetric PPE)",
                     iters, pq, rz);
}

/* r -= alpha q; returns (r,r), and (r, dinv r) in *rz. */
static double residual_diag(int n, double alpha, const double *q,
                            const double *dinv, double *r, double *rz)
{
    double rr = 0.0, s = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : rr, s) if (LS_PAR(n))
    for (int i = 0; i < n; i++) {
        double ri = r[i] - alpha * q[i];
        r[i] = ri;
        rr += ri * ri;
        s += ri * ri * dinv[i];
    }
    *rz = s;
    return rr;
}

/* x += alpha p; p = dinv r + beta p. */
static void direction_diag(int n, double alpha, double beta, const double *r,
                           const double *dinv, double *x, double *p)
{
#pragma omp parallel for schedule(static) if (LS_PAR(n))
    for (int i = 0; i < n; i++) {
        x[i] += alpha * p[i];
        p[i] = dinv[i] * r[i] + beta * p[i];
    }
}

static void axpy(int n, double alpha, const double *p, double *x)
{
#pragma omp parallel for schedule(static) if (LS_PAR(n))
    for (int i = 0; i < n; i++)
        x[i] += alpha * p[i];
}

static int cycle_diag(struct linsolve *s, const struct csr_matrix *A,
                      double *x, double tolabs, int *iters)
{
    int n = A->n;
    double *r = s->work[W_R], *p = s->work[W_P], *q = s->work[W_Q];
    const double *dinv = s->pc.dinv;
    double rz = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : rz) if (LS_PAR(n))
    for (int i = 0; i < n; i++) {
        p[i] = dinv[i] * r[i];
        rz += r[i] * p[i];
    }
    while (*iters < s->maxiter) {
        double pq = csr_spmv_dot(A, p, q);
        if (!(pq > 0.0) || !(rz > 0.0))
            return breakdown(*iters, pq, rz);
        double alpha = rz / pq, rz_new;
        double rr = residual_diag(n, alpha, q, dinv, r, &rz_new);
        ++*iters;
        if (sqrt(rr) <= tolabs || *iters >= s->maxiter) {
            axpy(n, alpha, p, x);
            return SIM_OK;
        }
        double beta = rz_new / rz;
        rz = rz_new;
        direction_diag(n, alpha, beta, r, dinv, x, p);
    }
    return SIM_OK;
}

static int cycle_generic(struct linsolve *s, const struct csr_matrix *A,
                         double *x, double tolabs, int *iters)
{
    int n = A->n;
    double *r = s->work[W_R], *p = s->work[W_P], *q = s->work[W_Q];
    double *z = s->work[W_Z];
    const struct precond *pc = &s->pc;
    pc->ops->apply(pc, r, z);
    double rz = vec_dot(n, r, z);
    vec_copy(n, z, p);
    while (*iters < s->maxiter) {
        double pq = csr_spmv_dot(A, p, q);
        if (!(pq > 0.0) || !(rz > 0.0))
            return breakdown(*iters, pq, rz);
        double alpha = rz / pq, rr = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : rr) if (LS_PAR(n))
        for (int i = 0; i < n; i++) {
            x[i] += alpha * p[i];
            r[i] -= alpha * q[i];
            rr += r[i] * r[i];
        }
        ++*iters;
        if (sqrt(rr) <= tolabs)
            return SIM_OK;
        pc->ops->apply(pc, r, z);
        double rz_new = vec_dot(n, r, z), beta = rz_new / rz;
        rz = rz_new;
#pragma omp parallel for schedule(static) if (LS_PAR(n))
        for (int i = 0; i < n; i++)
            p[i] = z[i] + beta * p[i];
    }
    return SIM_OK;
}

static int solve(struct linsolve *s, const struct csr_matrix *A,
                 const double *b, double *x, double tolabs,
                 struct linsolve_stats *st)
{
    double *r = s->work[W_R];
    int iters = 0, fast = s->pc.ops->diagonal && !s->generic;
    for (int restart = 0;; restart++) {
        double rnorm = sqrt(csr_residual(A, b, x, r));
        if (!isfinite(rnorm))
            return sim_error(SIM_ERR_NUMERIC, "PCG: residual is not finite "
                             "after %d iterations", iters);
        if (rnorm <= tolabs || iters >= s->maxiter || restart > MAX_RESTARTS)
            break;
        int rc = fast ? cycle_diag(s, A, x, tolabs, &iters)
                      : cycle_generic(s, A, x, tolabs, &iters);
        st->iters = iters;
        if (rc)
            return rc;
    }
    st->iters = iters;
    return SIM_OK;
}

const struct solver_ops solver_pcg = {
    .name = "pcg",
    .reference = "Hestenes & Stiefel 1952; Saad 2003, Alg. 9.1",
    .iterative = 1, .needs_symmetric = 0, .needs_spd_pc = 1,
    .solve = solve,
};
