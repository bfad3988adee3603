/*
 * solver_pcg.c — preconditioned conjugate gradients for the symmetric
 * positive definite PPE (single phase, METHODS.md §A.4 with Dirichlet
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
 * Fast path for a diagonal M (jacobi, none): z is never stored; one loop
 * updates x and r and accumulates (r,r) and (r, M^-1 r), and the direction
 * update recomputes M^-1 r on the fly. Bytes per iteration (STREAM
 * counting): 12 nnz + 8 n (rowptr) + 8 n x 13 vector streams (SpMV: p, q;
 * update: x r/w, r r/w, p, q, dinv; direction: r, dinv, p r/w).
 */
#include <math.h>

#include "core/error.h"
#include "linsolve/linsolve_impl.h"

enum { W_R, W_P, W_Q, W_Z };
#define MAX_RESTARTS 3

/* x += alpha p; r -= alpha q; returns (r,r) and (r, dinv r) in *rz. */
static double update_diag(int n, double alpha, const double *p,
                          const double *q, const double *dinv, double *x,
                          double *r, double *rz)
{
    double rr = 0.0, s = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : rr, s)
    for (int i = 0; i < n; i++) {
        x[i] += alpha * p[i];
        double ri = r[i] - alpha * q[i];
        r[i] = ri;
        rr += ri * ri;
        s += ri * ri * dinv[i];
    }
    *rz = s;
    return rr;
}

/* p = M^-1 r + beta p; beta = 0 starts afresh (p may hold garbage). */
static void direction_diag(int n, double beta, const double *r,
                           const double *dinv, double *p)
{
    if (beta == 0.0) {
#pragma omp parallel for schedule(static)
        for (int i = 0; i < n; i++)
            p[i] = dinv[i] * r[i];
        return;
    }
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; i++)
        p[i] = dinv[i] * r[i] + beta * p[i];
}

static double update_generic(int n, double alpha, const double *p,
                             const double *q, double *x, double *r)
{
    double rr = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : rr)
    for (int i = 0; i < n; i++) {
        x[i] += alpha * p[i];
        r[i] -= alpha * q[i];
        rr += r[i] * r[i];
    }
    return rr;
}

static void direction_generic(int n, double beta, const double *z, double *p)
{
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; i++)
        p[i] = z[i] + beta * p[i];
}

/* z = M^-1 r, returns (r, z); for a diagonal M without storing z. */
static double precondition(const struct linsolve *s, int fast, const double *r,
                           double *z)
{
    const struct precond *pc = &s->pc;
    int n = pc->n;
    if (!fast) {
        pc->ops->apply(pc, r, z);
        return vec_dot(n, r, z);
    }
    double d = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : d)
    for (int i = 0; i < n; i++)
        d += r[i] * r[i] * pc->dinv[i];
    return d;
}

/* CG iterations from the residual r = b - A x until the recursive residual
 * meets tolabs or maxiter is reached. */
static int cg_cycle(struct linsolve *s, const struct csr_matrix *A, double *x,
                    double tolabs, int *iters)
{
    int n = A->n, fast = s->pc.ops->diagonal && !s->generic;
    double *r = s->work[W_R], *p = s->work[W_P], *q = s->work[W_Q];
    double *z = s->work[W_Z];
    const double *dinv = s->pc.dinv;
    double rz = precondition(s, fast, r, z);
    if (fast)
        direction_diag(n, 0.0, r, dinv, p);
    else
        vec_copy(n, z, p);
    while (*iters < s->maxiter) {
        double pq = csr_spmv_dot(A, p, q);
        if (!(pq > 0.0) || !(rz > 0.0))
            return sim_error(SIM_ERR_SOLVER, "PCG breakdown at iteration %d: "
                             "p'Ap = %g, r'M^-1r = %g (matrix or "
                             "preconditioner not positive definite; use "
                             "bicgstab for a non-symmetric PPE)",
                             *iters, pq, rz);
        double alpha = rz / pq, rz_new, rr;
        if (fast) {
            rr = update_diag(n, alpha, p, q, dinv, x, r, &rz_new);
        } else {
            rr = update_generic(n, alpha, p, q, x, r);
        }
        ++*iters;
        if (sqrt(rr) <= tolabs)
            return SIM_OK;
        if (!fast)
            rz_new = precondition(s, 0, r, z);
        double beta = rz_new / rz;
        rz = rz_new;
        if (fast)
            direction_diag(n, beta, r, dinv, p);
        else
            direction_generic(n, beta, z, p);
    }
    return SIM_OK;
}

static int solve(struct linsolve *s, const struct csr_matrix *A,
                 const double *b, double *x, double tolabs,
                 struct linsolve_stats *st)
{
    double *r = s->work[W_R];
    int iters = 0;
    for (int restart = 0;; restart++) {
        double rnorm = sqrt(csr_residual(A, b, x, r));
        if (!isfinite(rnorm))
            return sim_error(SIM_ERR_NUMERIC, "PCG: residual is not finite "
                             "after %d iterations", iters);
        if (rnorm <= tolabs || iters >= s->maxiter || restart > MAX_RESTARTS)
            break;
        int rc = cg_cycle(s, A, x, tolabs, &iters);
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
