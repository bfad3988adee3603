/*
 * sunlinsol_ppe.c — see sunlinsol_ppe.h. Modelled on SUNDIALS'
 * sunlinsol_pcg.c: a content struct, an ops table filled by the
 * constructor, numiters/resnorm/lastflag reporting.
 */
#include "linsolve/sunlinsol_ppe.h"

#include <math.h>
#include <stdlib.h>

#include <nvector/nvector_serial.h>

#include "core/error.h"
#include "linsolve/linsolve_impl.h"

struct ppe_content {
    struct linsolve *ls;
    const struct csr_matrix *A;
    int zero_guess;
    long last_flag;
    double resnorm;
    struct linsolve_stats st;
};

#define CONTENT(S) ((struct ppe_content *)(S)->content)

static SUNLinearSolver_Type get_type(SUNLinearSolver S)
{
    (void)S;
    return SUNLINEARSOLVER_MATRIX_EMBEDDED;
}

static SUNLinearSolver_ID get_id(SUNLinearSolver S)
{
    (void)S;
    return SUNLINEARSOLVER_CUSTOM;
}

static int set_zero_guess(SUNLinearSolver S, booleantype onoff)
{
    CONTENT(S)->zero_guess = onoff ? 1 : 0;
    return SUNLS_SUCCESS;
}

static int initialize(SUNLinearSolver S)
{
    CONTENT(S)->last_flag = SIM_OK;
    return SUNLS_SUCCESS;
}

static int setup(SUNLinearSolver S, SUNMatrix A)
{
    if (A != NULL || !CONTENT(S)->A) {
        CONTENT(S)->last_flag = SIM_ERR_INPUT;
        return SUNLS_ILL_INPUT;
    }
    return SUNLS_SUCCESS;
}

static int solve(SUNLinearSolver S, SUNMatrix A, N_Vector x, N_Vector b,
                 realtype tol)
{
    struct ppe_content *c = CONTENT(S);
    if (A != NULL || !c->A || N_VGetLength(x) != c->A->n ||
        N_VGetLength(b) != c->A->n) {
        c->last_flag = sim_error(SIM_ERR_INPUT, "SUNLinSol_PPE: no matrix "
                                 "attached, a SUNMatrix given, or vector "
                                 "lengths differ from the matrix");
        return SUNLS_ILL_INPUT;
    }
    double *xd = N_VGetArrayPointer(x), *bd = N_VGetArrayPointer(b);
    if (c->zero_guess)
        vec_zero(c->A->n, xd);
    c->zero_guess = 0; /* SUNDIALS semantics: reset after every solve */
    int rc = linsolve_solve_abs(c->ls, c->A, bd, xd, tol > 0.0 ? tol : 0.0,
                                &c->st);
    c->last_flag = rc;
    c->resnorm = c->st.res_rel * sqrt(vec_dot(c->A->n, bd, bd));
    if (rc == SIM_OK)
        return SUNLS_SUCCESS;
    if (rc == SIM_ERR_SOLVER)
        return SUNLS_CONV_FAIL;
    if (rc == SIM_ERR_INPUT || rc == SIM_ERR_NUMERIC)
        return SUNLS_ILL_INPUT;
    return SUNLS_PACKAGE_FAIL_UNREC;
}

static int num_iters(SUNLinearSolver S)
{
    return CONTENT(S)->st.iters;
}

static realtype res_norm(SUNLinearSolver S)
{
    return CONTENT(S)->resnorm;
}

static sunindextype last_flag(SUNLinearSolver S)
{
    return CONTENT(S)->last_flag;
}

static int space(SUNLinearSolver S, long *lrw, long *liw)
{
    const struct linsolve *ls = CONTENT(S)->ls;
    *lrw = (long)ls->n_cap * (LINSOLVE_NWORK + 1) + (long)ls->pc.nnz_cap +
           2L * ls->pc.n_cap;
    *liw = (long)ls->pc.nnz_cap / 2 + 3L * ls->pc.n_cap;
    return SUNLS_SUCCESS;
}

static int free_solver(SUNLinearSolver S)
{
    if (!S)
        return SUNLS_SUCCESS;
    free(S->content);
    S->content = NULL;
    SUNLinSolFreeEmpty(S);
    return SUNLS_SUCCESS;
}

SUNLinearSolver SUNLinSol_PPE(struct linsolve *ls, SUNContext ctx)
{
    if (!ls)
        return NULL;
    SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
    if (!S)
        return NULL;
    S->content = calloc(1, sizeof(struct ppe_content));
    if (!S->content) {
        SUNLinSolFreeEmpty(S);
        return NULL;
    }
    CONTENT(S)->ls = ls;
    S->ops->gettype = get_type;
    S->ops->getid = get_id;
    S->ops->setzeroguess = set_zero_guess;
    S->ops->initialize = initialize;
    S->ops->setup = setup;
    S->ops->solve = solve;
    S->ops->numiters = num_iters;
    S->ops->resnorm = res_norm;
    S->ops->lastflag = last_flag;
    S->ops->space = space;
    S->ops->free = free_solver;
    return S;
}

int SUNLinSol_PPESetMatrix(SUNLinearSolver S, const struct csr_matrix *A)
{
    if (!S || !S->content)
        return SUNLS_MEM_NULL;
    CONTENT(S)->A = A;
    return SUNLS_SUCCESS;
}

const struct linsolve_stats *SUNLinSol_PPEStats(SUNLinearSolver S)
{
    return &CONTENT(S)->st;
}
