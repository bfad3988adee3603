/*
 * precond_ic0.c — zero-fill incomplete Cholesky, M = L L^T with L on the
 * sparsity pattern of the lower triangle of A:
 *
 *   l_ij = (a_ij - sum_{k<j} l_ik l_jk) / l_jj      (j < i, a_ij != 0)
 *   l_ii = sqrt(a_ii - sum_{k<i} l_ik^2)
 *
 * Meijerink & van der Vorst (1977), Math. Comp. 31:148–162: the pivots are
 * positive for an M-matrix, which the single-phase PPE is. For other SPD
 * matrices a pivot may be <= 0; we then factorise A + alpha diag(A) with
 * alpha = 1e-3, 4e-3, ... (Manteuffel 1980, Math. Comp. 34:473–497) and say
 * so in a warning.
 *
 * Set-up is row by row with a scatter map of row i (cost ~ nnz_row^2 per
 * row) and the triangular solves are sequential: on 2 cores this pays off in
 * 2-D (3-4x fewer iterations) and little in 3-D (doc/libraries.md §2).
 */
#include <math.h>

#include "core/error.h"
#include "linsolve/linsolve_impl.h"

/* One attempt; returns the first row with a non-positive pivot, or -1. */
static int factor(struct precond *pc, const struct csr_matrix *A, double alpha)
{
    int n = A->n;
    int64_t *fp = pc->fp, *fd = pc->fdiag;
    int32_t *fc = pc->fc, *pos = pc->pos;
    double *fv = pc->fv;
    for (int i = 0; i < n; i++) {
        for (int64_t k = fp[i]; k < fd[i]; k++)
            pos[fc[k]] = (int32_t)(k - fp[i]);
        for (int64_t k = fp[i]; k < fd[i]; k++) {
            int j = fc[k];
            double v = fv[k];
            for (int64_t m = fp[j]; m < fd[j]; m++) {
                int32_t p = pos[fc[m]];
                if (p >= 0 && fp[i] + p < k)
                    v -= fv[fp[i] + p] * fv[m];
            }
            fv[k] = v / fv[fd[j]];
        }
        double d = fv[fd[i]] * (1.0 + alpha), a = d;
        for (int64_t k = fp[i]; k < fd[i]; k++) {
            d -= fv[k] * fv[k];
            pos[fc[k]] = -1;
        }
        if (!(d > 1e-14 * a))
            return i;
        fv[fd[i]] = sqrt(d);
    }
    return -1;
}

static int attempt(struct precond *pc, const struct csr_matrix *A,
                   const double *diag, double alpha, int *bad_row)
{
    (void)diag;
    TRY(precond_sorted_copy(pc, A, 1));
    for (int i = 0; i < A->n; i++)
        if (pc->fdiag[i] != pc->fp[i + 1] - 1)
            return sim_error(SIM_ERR_INTERNAL, "ic0: diagonal of row %d "
                             "is not last after sorting", i);
    *bad_row = factor(pc, A, alpha);
    return SIM_OK;
}

static int setup(struct precond *pc, const struct csr_matrix *A,
                 const double *diag)
{
    return precond_factor_shifted(pc, A, diag, "IC(0)", "non-positive",
                                  "; the matrix is probably not SPD",
                                  attempt);
}

static void apply(const struct precond *pc, const double *r, double *z)
{
    const int64_t *fp = pc->fp, *fd = pc->fdiag;
    const int32_t *fc = pc->fc;
    const double *fv = pc->fv;
    double *y = pc->y;
    for (int i = 0; i < pc->n; i++) {
        double s = r[i];
        for (int64_t k = fp[i]; k < fd[i]; k++)
            s -= fv[k] * y[fc[k]];
        y[i] = s / fv[fd[i]];
    }
    /* L^T z = y by columns of L^T, i.e. rows of L, in reverse order. */
    for (int i = pc->n - 1; i >= 0; i--) {
        double zi = y[i] / fv[fd[i]];
        z[i] = zi;
        for (int64_t k = fp[i]; k < fd[i]; k++)
            y[fc[k]] -= fv[k] * zi;
    }
}

const struct precond_ops precond_ic0 = {
    .name = "ic0",
    .reference = "Meijerink & van der Vorst 1977, zero-fill incomplete "
                 "Cholesky",
    .spd = 1, .lower_only = 1, .diagonal = 0, .setup = setup, .apply = apply,
};
