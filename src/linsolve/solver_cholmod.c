/*
 * solver_cholmod.c — sparse direct solve A = L L^T by CHOLMOD's supernodal
 * factorisation (Chen, Davis, Hager & Rajamanickam 2008, ACM TOMS 35(3):22)
 * with a fresh AMD ordering per solve: the pattern of a particle method
 * changes every step, and reusing an old ordering doubled the fill
 * (doc/libraries.md §2). 15-60x slower than PCG in 3-D: meant as the oracle of
 * the tests and for small 2-D cases, not for the time loop.
 *
 * Refuses a non-symmetric matrix (CHOLMOD would silently use one triangle).
 * Every CHOLMOD call goes through check(), which turns cholmod_common.status
 * into our code and message. CHOLMOD allocates its factor on every solve.
 */
#include <limits.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include <suitesparse/cholmod.h>

#include "core/error.h"
#include "linsolve/csr.h"
#include "linsolve/linsolve_impl.h"

static const char *status_text(int status)
{
    switch (status) {
    case CHOLMOD_NOT_INSTALLED: return "method not installed";
    case CHOLMOD_OUT_OF_MEMORY: return "out of memory";
    case CHOLMOD_TOO_LARGE:     return "integer overflow";
    case CHOLMOD_INVALID:       return "invalid input";
    case CHOLMOD_GPU_PROBLEM:   return "GPU problem";
    case CHOLMOD_NOT_POSDEF:    return "matrix not positive definite";
    case CHOLMOD_DSMALL:        return "tiny diagonal in the factor";
    default:                    return "unknown status";
    }
}

static int check(const cholmod_common *c, const void *result, const char *what)
{
    if (c->status == CHOLMOD_OK && result)
        return SIM_OK;
    if (c->status == CHOLMOD_OUT_OF_MEMORY)
        return sim_error(SIM_ERR_NOMEM, "CHOLMOD %s: out of memory", what);
    return sim_error(SIM_ERR_EXTERNAL, "CHOLMOD %s failed: %s (status %d)",
                     what, status_text(c->status), c->status);
}

static void quiet_handler(int status, const char *file, int line,
                          const char *msg)
{
    (void)status, (void)file, (void)line, (void)msg; /* check() reports */
}

static int init(struct linsolve *s)
{
    cholmod_common *c = sim_calloc(1, sizeof *c);
    if (!c)
        return SIM_ERR_NOMEM;
    if (!cholmod_start(c)) {
        free(c);
        return sim_error(SIM_ERR_EXTERNAL, "CHOLMOD: cholmod_start failed");
    }
    c->error_handler = quiet_handler;
    c->print = 0;
    c->supernodal = CHOLMOD_SUPERNODAL;
    c->nmethods = 1;
    c->method[0].ordering = CHOLMOD_AMD;
    c->final_ll = 1;
    s->ext = c;
    return SIM_OK;
}

static void fini(struct linsolve *s)
{
    if (s->ext) {
        cholmod_finish(s->ext);
        free(s->ext);
        s->ext = NULL;
    }
}

/* Our CSR read as CSC is A^T = A; with stype = -1 CHOLMOD uses only the
 * entries with row index >= column index (our j >= i), hence the symmetry
 * check before. */
static int to_cholmod(const struct csr_matrix *A, cholmod_common *c,
                      cholmod_sparse **out)
{
    cholmod_sparse *S = cholmod_allocate_sparse(A->n, A->n, A->nnz, 0, 1, -1,
                                                CHOLMOD_REAL, c);
    TRY(check(c, S, "allocate_sparse"));
    int *p = S->p, *i = S->i;
    for (int r = 0; r <= A->n; r++)
        p[r] = (int)A->rowptr[r];
    for (int64_t k = 0; k < A->nnz; k++)
        i[k] = A->col[k];
    memcpy(S->x, A->val, (size_t)A->nnz * sizeof(double));
    cholmod_sort(S, c);
    int rc = check(c, S, "sort");
    if (rc)
        cholmod_free_sparse(&S, c);
    *out = S;
    return rc;
}

static int factor_solve(struct linsolve *s, const struct csr_matrix *A,
                        const double *b, double *x);

/* Small systems on one thread: CHOLMOD and its OpenMP BLAS spin up a thread
 * team per call, which on a busy 2-core machine made the unit tests 20x
 * slower than serial. */
static int solve(struct linsolve *s, const struct csr_matrix *A,
                 const double *b, double *x, double tolabs,
                 struct linsolve_stats *st)
{
    (void)tolabs;
    int nt = omp_get_max_threads();
    if (!LS_PAR(A->n))
        omp_set_num_threads(1);
    int rc = factor_solve(s, A, b, x);
    omp_set_num_threads(nt);
    st->iters = 0;
    return rc;
}

static int factor_solve(struct linsolve *s, const struct csr_matrix *A,
                        const double *b, double *x)
{
    cholmod_common *c = s->ext;
    int row;
    if (A->nnz > INT_MAX)
        return sim_error(SIM_ERR_INPUT, "cholmod: %lld non-zeros exceed the "
                         "32-bit interface; use pcg", (long long)A->nnz);
    if (!csr_is_symmetric(A, 1e-12, &row))
        return sim_error(SIM_ERR_INPUT, "cholmod: the matrix is not symmetric "
                         "(first at row %d); use bicgstab", row);
    cholmod_sparse *S = NULL;
    cholmod_factor *L = NULL;
    cholmod_dense *B = NULL, *X = NULL;
    int rc;
    TRY(to_cholmod(A, c, &S));
    L = cholmod_analyze(S, c);
    TRY_GOTO(rc, check(c, L, "analyze"), out);
    cholmod_factorize(S, L, c);
    if (c->status == CHOLMOD_NOT_POSDEF) {
        rc = sim_error(SIM_ERR_SOLVER, "cholmod: the matrix is not positive "
                       "definite (failed at column %d of the factor)",
                       (int)L->minor);
        goto out;
    }
    TRY_GOTO(rc, check(c, L, "factorize"), out);
    B = cholmod_allocate_dense(A->n, 1, A->n, CHOLMOD_REAL, c);
    TRY_GOTO(rc, check(c, B, "allocate_dense"), out);
    memcpy(B->x, b, (size_t)A->n * sizeof(double));
    X = cholmod_solve(CHOLMOD_A, L, B, c);
    TRY_GOTO(rc, check(c, X, "solve"), out);
    memcpy(x, X->x, (size_t)A->n * sizeof(double));
out:
    cholmod_free_dense(&X, c);
    cholmod_free_dense(&B, c);
    cholmod_free_factor(&L, c);
    cholmod_free_sparse(&S, c);
    return rc;
}

const struct solver_ops solver_cholmod = {
    .name = "cholmod",
    .reference = "CHOLMOD supernodal Cholesky, Chen et al. 2008",
    .iterative = 0, .needs_symmetric = 1, .needs_spd_pc = 0,
    .init = init, .solve = solve, .fini = fini,
};
