/*
 * precond_jacobi.c — Jacobi (diagonal) preconditioning, M = diag(A).
 * The default for the PPE (doc/libraries.md §2): in 3-D it is the fastest or
 * within 1.25x of the fastest, needs no set-up and threads with the SpMV.
 * PCG fuses z = M^-1 r into its vector updates (ops->diagonal).
 */
#include "core/error.h"
#include "linsolve/linsolve_impl.h"

static int setup(struct precond *pc, const struct csr_matrix *A,
                 const double *diag)
{
    TRY(precond_reserve(pc, A->n, 0, 0));
#pragma omp parallel for schedule(static) if (LS_PAR(A->n))
    for (int i = 0; i < A->n; i++)
        pc->dinv[i] = 1.0 / diag[i];
    return SIM_OK;
}

static void apply(const struct precond *pc, const double *r, double *z)
{
#pragma omp parallel for schedule(static) if (LS_PAR(pc->n))
    for (int i = 0; i < pc->n; i++)
        z[i] = pc->dinv[i] * r[i];
}

const struct precond_ops precond_jacobi = {
    .name = "jacobi", .reference = "diagonal scaling", .spd = 1,
    .lower_only = 0, .diagonal = 1, .setup = setup, .apply = apply,
};
