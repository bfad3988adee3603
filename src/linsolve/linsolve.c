/*
 * linsolve.c — the facade of linsolve.h: selection of a solver and a
 * preconditioner by name, validation of every system, work storage reused
 * across solves, timing, and the final true-residual check that every
 * answer has to pass (doc/design.md C12: no silent wrong answer).
 */
#include "core/app.h"
#include "linsolve/linsolve.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "core/select.h"
#include "linsolve/csr.h"
#include "linsolve/linsolve_impl.h"

const struct solver_ops *const linsolve_solvers[] = {
    &solver_pcg, &solver_bicgstab, &solver_gmres, &solver_cholmod,
    &solver_hypre, NULL};

int linsolve_check_combination(const struct solver_ops *so,
                               const struct precond_ops *po)
{
    if (so->needs_spd_pc && !po->spd)
        return sim_error(SIM_ERR_INPUT, "preconditioner '%s' is not symmetric;"
                         " solver '%s' needs one of: none jacobi ic0 dic amg",
                         po->name, so->name);
    if (so->iterative && !so->needs_spd_pc && po->lower_only)
        return sim_error(SIM_ERR_INPUT, "preconditioner '%s' uses only the "
                         "lower triangle of a symmetric matrix; solver '%s' is "
                         "for non-symmetric ones: use none, jacobi, ilu0 or "
                         "amg",
                         po->name, so->name);
    return SIM_OK;
}

int linsolve_create_named(const char *solver, const char *precond, double tol,
                          int maxiter, struct linsolve **out)
{
    char msg[1400];
    *out = NULL;
    const void *const *st = (const void *const *)linsolve_solvers;
    const void *const *pt = (const void *const *)linsolve_preconditioners;
    const struct solver_ops *so = model_find(st, solver ? solver : "");
    if (!so)
        return sim_error(SIM_ERR_INPUT, "%s",
                         model_unknown(st, "linear solver",
                                       solver ? solver : "(null)", msg,
                                       sizeof msg));
    const struct precond_ops *po = model_find(pt, precond ? precond : "");
    if (!po)
        return sim_error(SIM_ERR_INPUT, "%s",
                         model_unknown(pt, "preconditioner",
                                       precond ? precond : "(null)", msg,
                                       sizeof msg));
    return linsolve_create_ops(so, po, tol, maxiter, out);
}

int linsolve_create_ops(const struct solver_ops *so,
                        const struct precond_ops *po, double tol, int maxiter,
                        struct linsolve **out)
{
    *out = NULL;
    if (!(tol > 0.0 && tol < 1.0))
        return sim_error(SIM_ERR_INPUT, "linear solver tolerance %g is not in "
                         "(0, 1)", tol);
    if (maxiter < 1)
        return sim_error(SIM_ERR_INPUT, "linear solver maxIter %d is not "
                         "positive", maxiter);
    int ours = so->iterative && !so->own_pc; /* uses our preconditioner */
    if (ours)
        TRY(linsolve_check_combination(so, po));
    struct linsolve *s = sim_calloc(1, sizeof *s);
    if (!s)
        return SIM_ERR_NOMEM;
    s->solver = so;
    s->pc.ops = ours ? po : &precond_none;
    s->pc.symmetric = so->needs_spd_pc;
    s->tol = tol;
    s->maxiter = maxiter;
    s->warm_start = 1;
    if (so->init) {
        int rc = so->init(s);
        if (rc) {
            free(s);
            return rc;
        }
    }
    *out = s;
    return SIM_OK;
}

void linsolve_free(struct linsolve *s)
{
    if (!s)
        return;
    if (s->solver->fini)
        s->solver->fini(s);
    precond_release(&s->pc);
    free(s->diag);
    for (int k = 0; k < LINSOLVE_NWORK; k++)
        free(s->work[k]);
    free(s);
}

static int reserve(struct linsolve *s, int n)
{
    if (n <= s->n_cap)
        return SIM_OK;
    size_t bytes = (size_t)n * sizeof(double);
    double *p = sim_realloc(s->diag, bytes);
    if (!p)
        return SIM_ERR_NOMEM;
    s->diag = p;
    for (int k = 0; k < LINSOLVE_NWORK; k++) {
        p = sim_realloc(s->work[k], bytes);
        if (!p)
            return SIM_ERR_NOMEM;
        s->work[k] = p;
    }
    s->n_cap = n;
    return SIM_OK;
}

/* ||v||_2, or -1 when v holds a NaN or an infinity. */
static double checked_norm(int n, const double *v)
{
    double d = 0.0;
    int bad = 0;
#pragma omp parallel for schedule(static) reduction(+ : d) reduction(| : bad) \
    if (LS_PAR(n))
    for (int i = 0; i < n; i++) {
        bad |= !isfinite(v[i]);
        d += v[i] * v[i];
    }
    return bad || !isfinite(d) ? -1.0 : sqrt(d);
}

static int prepare(struct linsolve *s, const struct csr_matrix *A,
                   const double *b, double *x, double *bnorm)
{
    if (!A || !b || !x)
        return sim_error(SIM_ERR_INPUT, "linsolve_solve: NULL argument");
    if (A->n <= 0)
        return csr_validate(A, NULL); /* the message for an empty matrix */
    TRY(reserve(s, A->n));
    TRY(csr_validate(A, s->diag));
    *bnorm = checked_norm(A->n, b);
    if (*bnorm < 0.0)
        return sim_error(SIM_ERR_NUMERIC, "linear system: the right-hand side "
                         "holds NaN or infinite values");
    if (!s->warm_start || !s->solver->iterative)
        vec_zero(A->n, x);
    else if (checked_norm(A->n, x) < 0.0)
        return sim_error(SIM_ERR_NUMERIC, "linear system: the initial guess "
                         "holds NaN or infinite values");
    return SIM_OK;
}

int linsolve_solve_abs(struct linsolve *s, const struct csr_matrix *A,
                       const double *b, double *x, double abstol,
                       struct linsolve_stats *st)
{
    struct linsolve_stats dummy;
    double bnorm = 0.0, t0 = app_wall_time();
    if (!st)
        st = &dummy;
    memset(st, 0, sizeof *st);
    TRY(prepare(s, A, b, x, &bnorm));
    if (bnorm == 0.0) {
        vec_zero(A->n, x);
        st->converged = 1;
        st->setup_s = app_wall_time() - t0;
        return SIM_OK;
    }
    double tolabs = abstol > 0.0 ? abstol : s->tol * bnorm;
    if (s->solver->iterative)
        TRY(s->pc.ops->setup(&s->pc, A, s->diag));
    double t1 = app_wall_time();
    st->setup_s = t1 - t0;
    int rc = s->solver->solve(s, A, b, x, tolabs, st);
    double rnorm = sqrt(csr_residual(A, b, x, s->work[0]));
    st->solve_s = app_wall_time() - t1;
    st->res_rel = rnorm / bnorm;
    if (rc)
        return rc;
    if (!(rnorm <= tolabs))
        return sim_error(SIM_ERR_SOLVER, "%s (%s) did not converge: %d "
                         "iterations (maxIter %d), relative residual %.3e > "
                         "tolerance %.3e%s", s->solver->name, s->pc.ops->name,
                         st->iters, s->maxiter, st->res_rel, tolabs / bnorm,
                         st->iters < s->maxiter && s->solver->iterative
                             ? " (stagnated: the true residual stays above "
                               "the tolerance; is it below rounding level?)"
                             : "");
    st->converged = 1;
    return SIM_OK;
}

int linsolve_solve(struct linsolve *s, const struct csr_matrix *A,
                   const double *b, double *x, struct linsolve_stats *st)
{
    return linsolve_solve_abs(s, A, b, x, 0.0, st);
}
