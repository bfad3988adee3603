/*
 * precond_ilu0.c — zero-fill incomplete LU, M = L U on the pattern of A
 * (L unit lower, U upper), by the IKJ variant of Gaussian elimination
 * (Saad, Iterative Methods for Sparse Linear Systems, 2nd ed., Alg. 10.4):
 *
 *   for k < i in row i:  a_ik /= u_kk;  a_ij -= a_ik u_kj  for j > k in row k
 *                                        with (i, j) in the pattern
 *
 * For the non-symmetric PPE of the coupled case (porosity weights 1/eps_j,
 * doc/theory.md §A.4 note [P]) with BiCGSTAB. A zero (tiny) pivot makes us
 * factorise A + alpha diag(A) instead, as in precond_ic0.c.
 */
#include <math.h>

#include "core/error.h"
#include "linsolve/linsolve_impl.h"

static int factor(struct precond *pc, int n, double alpha)
{
    int64_t *fp = pc->fp, *fd = pc->fdiag;
    int32_t *fc = pc->fc, *pos = pc->pos;
    double *fv = pc->fv;
    for (int i = 0; i < n; i++) {
        double a = fv[fd[i]];
        fv[fd[i]] = a * (1.0 + alpha);
        for (int64_t k = fp[i]; k < fp[i + 1]; k++)
            pos[fc[k]] = (int32_t)(k - fp[i]);
        for (int64_t k = fp[i]; k < fd[i]; k++) {
            int kk = fc[k];
            fv[k] /= fv[fd[kk]];
            for (int64_t m = fd[kk] + 1; m < fp[kk + 1]; m++) {
                int32_t p = pos[fc[m]];
                if (p >= 0)
                    fv[fp[i] + p] -= fv[k] * fv[m];
            }
        }
        for (int64_t k = fp[i]; k < fp[i + 1]; k++)
            pos[fc[k]] = -1;
        if (!(fabs(fv[fd[i]]) > 1e-14 * fabs(a)))
            return i;
    }
    return -1;
}

static int attempt(struct precond *pc, const struct csr_matrix *A,
                   const double *diag, double alpha, int *bad_row)
{
    (void)diag;
    TRY(precond_sorted_copy(pc, A, 0));
    *bad_row = factor(pc, A->n, alpha);
    return SIM_OK;
}

static int setup(struct precond *pc, const struct csr_matrix *A,
                 const double *diag)
{
    return precond_factor_shifted(pc, A, diag, "ILU(0)", "zero", "",
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
        y[i] = s;
    }
    for (int i = pc->n - 1; i >= 0; i--) {
        double s = y[i];
        for (int64_t k = fd[i] + 1; k < fp[i + 1]; k++)
            s -= fv[k] * z[fc[k]];
        z[i] = s / fv[fd[i]];
    }
}

const struct precond_ops precond_ilu0 = {
    .name = "ilu0",
    .reference = "Saad 2003, Alg. 10.4, zero-fill incomplete LU",
    .spd = 0, .lower_only = 0, .diagonal = 0, .setup = setup, .apply = apply,
};
