/*
 * linsolve_dict.c — linsolve_create(): the solver from a dictionary such as
 * the PPE sub-dictionary of system/mpsSolution,
 *
 *   PPE
 *   {
 *       solver          pcg;      // pcg | bicgstab | gmres | cholmod | hypre
 *       preconditioner  jacobi;   // none | jacobi | ic0 | dic | ilu0 | amg
 *       tolerance       1e-8;     // on ||b - A x||_2 / ||b||_2
 *       maxIter         1000;
 *       warmStart       yes;      // start from the previous pressure
 *   }
 *
 * Kept apart from linsolve.c so that programs and tests that only use
 * linsolve_create_named() do not link the dictionary code.
 */
#include "linsolve/linsolve.h"

#include <stdio.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/select.h"
#include "linsolve/linsolve_impl.h"

const struct model_choice linsolve_choices[] = {
    { "", "solver", (const void *const *)linsolve_solvers },
    { "", "preconditioner", (const void *const *)linsolve_preconditioners },
    { NULL, NULL, NULL }
};

int linsolve_create(const struct dict *d, struct linsolve **out)
{
    const void *so, *po;
    double tol;
    long maxiter;
    int warm;
    *out = NULL;
    TRY(model_select(d, "solver", "linear solver",
                     (const void *const *)linsolve_solvers, "pcg", &so));
    const struct solver_ops *sops = so;
    po = &precond_none; /* direct solvers and hypre read no preconditioner */
    int ours = sops->iterative && !sops->own_pc;
    if (ours)
        TRY(model_select(d, "preconditioner", "preconditioner",
                         (const void *const *)linsolve_preconditioners,
                         "jacobi", &po));
    TRY(dict_get_scalar_or(d, "tolerance", 1e-8, &tol));
    if (!(tol > 0.0 && tol < 1.0))
        return dict_error(d, "tolerance", SIM_ERR_DICT, "tolerance %g is not "
                          "in (0, 1)", tol);
    TRY(dict_get_label_or(d, "maxIter", 1000, &maxiter));
    if (maxiter < 1 || maxiter > 1000000000L)
        return dict_error(d, "maxIter", SIM_ERR_DICT, "maxIter %ld is not in "
                          "[1, 1e9]", maxiter);
    TRY(dict_get_bool_or(d, "warmStart", 1, &warm));
    char msg[512];
    if (ours && linsolve_check_combination(sops, po) != SIM_OK) {
        snprintf(msg, sizeof msg, "%s", sim_error_message());
        return dict_error(d, "preconditioner", SIM_ERR_DICT, "%s", msg);
    }
    int rc = linsolve_create_ops(sops, po, tol, (int)maxiter, out);
    if (rc != SIM_OK) {
        snprintf(msg, sizeof msg, "%s", sim_error_message());
        return dict_error(d, "solver",
                          rc == SIM_ERR_INPUT ? SIM_ERR_DICT : rc, "%s", msg);
    }
    (*out)->warm_start = warm;
    return SIM_OK;
}
