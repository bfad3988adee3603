/*
 * precond.c — storage shared by the preconditioners, and their registry
 * (the only list to edit when adding one).
 */
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "core/log.h"
#include "linsolve/linsolve_impl.h"

const struct precond_ops *const linsolve_preconditioners[] = {
    &precond_none, &precond_jacobi, &precond_ic0, &precond_dic, &precond_ilu0,
    &precond_amg, NULL};

static int grow(void **p, size_t bytes)
{
    void *q = sim_realloc(*p, bytes ? bytes : 1);
    if (!q)
        return SIM_ERR_NOMEM;
    *p = q;
    return SIM_OK;
}

int precond_reserve(struct precond *pc, int n, int64_t nnz, int factor)
{
    if (n > pc->n_cap) {
        size_t m = (size_t)n;
        TRY(grow((void **)&pc->dinv, m * sizeof(double)));
        TRY(grow((void **)&pc->y, m * sizeof(double)));
        TRY(grow((void **)&pc->fp, (m + 1) * sizeof(int64_t)));
        TRY(grow((void **)&pc->fdiag, m * sizeof(int64_t)));
        TRY(grow((void **)&pc->pos, m * sizeof(int32_t)));
        for (int i = 0; i < n; i++)
            pc->pos[i] = -1;
        pc->n_cap = n;
    }
    if (factor && nnz > pc->nnz_cap) {
        TRY(grow((void **)&pc->fc, (size_t)nnz * sizeof(int32_t)));
        TRY(grow((void **)&pc->fv, (size_t)nnz * sizeof(double)));
        pc->nnz_cap = nnz;
    }
    pc->n = n;
    return SIM_OK;
}

void precond_release(struct precond *pc)
{
    if (pc->ops && pc->ops->release)
        pc->ops->release(pc);
    free(pc->dinv);
    free(pc->y);
    free(pc->fp);
    free(pc->fdiag);
    free(pc->pos);
    free(pc->fc);
    free(pc->fv);
    const struct precond_ops *ops = pc->ops;
    int symmetric = pc->symmetric;
    memset(pc, 0, sizeof *pc);
    pc->ops = ops;
    pc->symmetric = symmetric;
}

/* Insertion sort of one row by column: rows hold tens of entries. */
static void sort_row(int32_t *c, double *v, int64_t len)
{
    for (int64_t a = 1; a < len; a++) {
        int32_t cc = c[a];
        double vv = v[a];
        int64_t b = a - 1;
        while (b >= 0 && c[b] > cc) {
            c[b + 1] = c[b];
            v[b + 1] = v[b];
            b--;
        }
        c[b + 1] = cc;
        v[b + 1] = vv;
    }
}

int precond_sorted_copy(struct precond *pc, const struct csr_matrix *A,
                        int lower_only)
{
    int n = A->n;
    TRY(precond_reserve(pc, n, 0, 0));
    pc->fp[0] = 0;
    for (int i = 0; i < n; i++) {
        int64_t c = 0;
        for (int64_t k = A->rowptr[i]; k < A->rowptr[i + 1]; k++)
            c += !lower_only || A->col[k] <= i;
        pc->fp[i + 1] = pc->fp[i] + c;
    }
    TRY(precond_reserve(pc, n, pc->fp[n], 1));
#pragma omp parallel for schedule(static) if (LS_PAR(n))
    for (int i = 0; i < n; i++) {
        int64_t o = pc->fp[i];
        for (int64_t k = A->rowptr[i]; k < A->rowptr[i + 1]; k++)
            if (!lower_only || A->col[k] <= i) {
                pc->fc[o] = A->col[k];
                pc->fv[o++] = A->val[k];
            }
        sort_row(pc->fc + pc->fp[i], pc->fv + pc->fp[i], o - pc->fp[i]);
    }
    /* Duplicates would break the zero-fill pattern logic; the diagonal must
     * exist (csr_validate checked it is positive). */
    for (int i = 0; i < n; i++) {
        pc->fdiag[i] = -1;
        for (int64_t k = pc->fp[i]; k < pc->fp[i + 1]; k++) {
            if (k > pc->fp[i] && pc->fc[k] == pc->fc[k - 1])
                return sim_error(SIM_ERR_INPUT, "linear system: duplicate "
                                 "entry (%d, %d) in the matrix", i, pc->fc[k]);
            if (pc->fc[k] == i)
                pc->fdiag[i] = k;
        }
    }
    return SIM_OK;
}

int precond_factor_shifted(struct precond *pc, const struct csr_matrix *A,
                           const double *diag, const char *name,
                           const char *pivot, const char *hint,
                           precond_attempt_fn attempt)
{
    double alpha = 0.0;
    int first = -1;
    for (int tries = 0; tries < 30; tries++) {
        int row;
        TRY(attempt(pc, A, diag, alpha, &row));
        if (row < 0) {
            pc->shift = alpha;
            if (alpha > 0.0)
                log_warn("%s: %s pivot at row %d; factorised A + %g diag(A) "
                         "instead", name, pivot, first, alpha);
            return SIM_OK;
        }
        if (first < 0)
            first = row;
        alpha = alpha == 0.0 ? 1e-3 : 4.0 * alpha;
    }
    return sim_error(SIM_ERR_SOLVER, "%s broke down even with a diagonal "
                     "shift of %g diag(A)%s", name, alpha, hint);
}
