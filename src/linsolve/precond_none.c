/*
 * precond_none.c — no preconditioning, M = I (plain CG / BiCGSTAB); kept as
 * the baseline the others are measured against.
 */
#include "core/error.h"
#include "linsolve/linsolve_impl.h"

static int setup(struct precond *pc, const struct csr_matrix *A,
                 const double *diag)
{
    (void)diag;
    TRY(precond_reserve(pc, A->n, 0, 0));
    for (int i = 0; i < A->n; i++)
        pc->dinv[i] = 1.0;
    return SIM_OK;
}

static void apply(const struct precond *pc, const double *r, double *z)
{
    vec_copy(pc->n, r, z);
}

const struct precond_ops precond_none = {
    .name = "none", .reference = "", .spd = 1, .lower_only = 0,
    .diagonal = 1, .setup = setup, .apply = apply,
};
