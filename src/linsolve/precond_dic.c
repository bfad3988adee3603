/*
 * precond_dic.c — diagonal incomplete Cholesky (DIC), the cheap variant of
 * IC(0): only the diagonal is modified,
 *
 *   M = (D + L) D^-1 (D + L^T),   d_i = a_ii - sum_{j<i} a_ij^2 / d_j,
 *
 * with L the strictly lower triangle of A itself, so that diag(M) = diag(A).
 * Pommerell (1992) / OpenFOAM's DIC preconditioner; Meijerink & van der Vorst
 * (1977) for existence on M-matrices. Set-up costs one pass over A and no
 * factor storage; the solves read A's own rows, so its columns need not be
 * sorted. On a non-positive d_i we shift the diagonal as in precond_ic0.c.
 */
#include "core/error.h"
#include "core/log.h"
#include "linsolve/linsolve_impl.h"

static int factor(struct precond *pc, const struct csr_matrix *A,
                  const double *diag, double alpha)
{
    for (int i = 0; i < A->n; i++) {
        double s = diag[i] * (1.0 + alpha);
        for (int64_t k = A->rowptr[i]; k < A->rowptr[i + 1]; k++) {
            int j = A->col[k];
            if (j < i)
                s -= A->val[k] * A->val[k] * pc->dinv[j];
        }
        if (!(s > 1e-14 * diag[i]))
            return i;
        pc->dinv[i] = 1.0 / s;
    }
    return -1;
}

static int setup(struct precond *pc, const struct csr_matrix *A,
                 const double *diag)
{
    TRY(precond_reserve(pc, A->n, 0, 0));
    pc->A = A;
    double alpha = 0.0;
    int first = -1;
    for (int attempt = 0; attempt < 30; attempt++) {
        int row = factor(pc, A, diag, alpha);
        if (row < 0) {
            pc->shift = alpha;
            if (alpha > 0.0)
                log_warn("DIC: non-positive pivot at row %d; factorised "
                         "A + %g diag(A) instead", first, alpha);
            return SIM_OK;
        }
        if (first < 0)
            first = row;
        alpha = alpha == 0.0 ? 1e-3 : 4.0 * alpha;
    }
    return sim_error(SIM_ERR_SOLVER, "DIC broke down even with a diagonal "
                     "shift of %g diag(A); the matrix is probably not SPD",
                     alpha);
}

static void apply(const struct precond *pc, const double *r, double *z)
{
    const struct csr_matrix *A = pc->A;
    double *y = pc->y;
    for (int i = 0; i < A->n; i++) {
        double s = r[i];
        for (int64_t k = A->rowptr[i]; k < A->rowptr[i + 1]; k++)
            if (A->col[k] < i)
                s -= A->val[k] * y[A->col[k]];
        y[i] = s * pc->dinv[i];
    }
    /* (D + L^T) z = D y, with L^T's row i = the upper part of A's row i. */
    for (int i = A->n - 1; i >= 0; i--) {
        double s = 0.0;
        for (int64_t k = A->rowptr[i]; k < A->rowptr[i + 1]; k++)
            if (A->col[k] > i)
                s += A->val[k] * z[A->col[k]];
        z[i] = y[i] - s * pc->dinv[i];
    }
}

const struct precond_ops precond_dic = {
    .name = "dic",
    .reference = "diagonal incomplete Cholesky, Meijerink & van der Vorst "
                 "1977",
    .spd = 1, .lower_only = 1, .diagonal = 0, .setup = setup, .apply = apply,
};
