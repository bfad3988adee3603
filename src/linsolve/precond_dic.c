/*
 * precond_dic.c — diagonal incomplete Cholesky (DIC), the cheap variant of
 * IC(0): only the diagonal is modified,
 *
 *   M = (D + L) D^-1 (D + L^T),   d_i = a_ii - sum_{j<i} a_ij^2 / d_j,
 *
 * with L the strictly lower triangle of A itself, so that diag(M) = diag(A).
 * Pommerell (1992) / OpenFOAM's DIC preconditioner; Meijerink & van der Vorst
 * (1977) for existence on M-matrices. Set-up copies the strictly lower
 * triangle (unsorted: DIC does not need sorted columns) and computes d in one
 * pass; the backward solve runs over the same rows as columns of L^T, so A
 * is never read again. On a non-positive d_i we shift the diagonal as in
 * precond_ic0.c.
 */
#include "core/error.h"
#include "linsolve/linsolve_impl.h"

/* Strictly lower triangle of A into pc->fp/fc/fv, in A's column order. */
static int copy_lower(struct precond *pc, const struct csr_matrix *A)
{
    int n = A->n;
    TRY(precond_reserve(pc, n, 0, 0));
    pc->fp[0] = 0;
    for (int i = 0; i < n; i++) {
        int64_t c = 0;
        for (int64_t k = A->rowptr[i]; k < A->rowptr[i + 1]; k++)
            c += A->col[k] < i;
        pc->fp[i + 1] = pc->fp[i] + c;
    }
    TRY(precond_reserve(pc, n, pc->fp[n], 1));
#pragma omp parallel for schedule(static) if (LS_PAR(n))
    for (int i = 0; i < n; i++) {
        int64_t o = pc->fp[i];
        for (int64_t k = A->rowptr[i]; k < A->rowptr[i + 1]; k++)
            if (A->col[k] < i) {
                pc->fc[o] = A->col[k];
                pc->fv[o++] = A->val[k];
            }
    }
    return SIM_OK;
}

static int factor(struct precond *pc, const double *diag, double alpha)
{
    for (int i = 0; i < pc->n; i++) {
        double s = diag[i] * (1.0 + alpha);
        for (int64_t k = pc->fp[i]; k < pc->fp[i + 1]; k++)
            s -= pc->fv[k] * pc->fv[k] * pc->dinv[pc->fc[k]];
        if (!(s > 1e-14 * diag[i]))
            return i;
        pc->dinv[i] = 1.0 / s;
    }
    return -1;
}

static int attempt(struct precond *pc, const struct csr_matrix *A,
                   const double *diag, double alpha, int *bad_row)
{
    (void)A;  /* copied once by setup: the attempts only rewrite dinv */
    *bad_row = factor(pc, diag, alpha);
    return SIM_OK;
}

static int setup(struct precond *pc, const struct csr_matrix *A,
                 const double *diag)
{
    TRY(copy_lower(pc, A));
    return precond_factor_shifted(pc, A, diag, "DIC", "non-positive",
                                  "; the matrix is probably not SPD",
                                  attempt);
}

static void apply(const struct precond *pc, const double *r, double *z)
{
    const int64_t *fp = pc->fp;
    const int32_t *fc = pc->fc;
    const double *fv = pc->fv, *dinv = pc->dinv;
    double *y = pc->y;
    for (int i = 0; i < pc->n; i++) {
        double s = r[i];
        for (int64_t k = fp[i]; k < fp[i + 1]; k++)
            s -= fv[k] * y[fc[k]];
        y[i] = s * dinv[i];
    }
    /* (D + L^T) z = D y, i.e. z_i = y_i - sum_{j>i} a_ji z_j / d_i, by
     * columns of L^T (= rows of L), last first: once z_i is known it is
     * removed from the equations c < i it appears in. */
    for (int i = pc->n - 1; i >= 0; i--) {
        double zi = y[i];
        z[i] = zi;
        for (int64_t k = fp[i]; k < fp[i + 1]; k++)
            y[fc[k]] -= fv[k] * zi * dinv[fc[k]];
    }
}

const struct precond_ops precond_dic = {
    .name = "dic",
    .reference = "diagonal incomplete Cholesky, Meijerink & van der Vorst "
                 "1977",
    .spd = 1, .lower_only = 1, .diagonal = 0, .setup = setup, .apply = apply,
};
