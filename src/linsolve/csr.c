/*
 * csr.c — checks and memory-bound kernels on CSR matrices and vectors.
 *
 * Every kernel is one OpenMP loop over rows with a static schedule, so that
 * a row (and the vector entries it writes) stays on the same thread in every
 * kernel of an iteration: first-touch placement and caches then work for us.
 * Reductions fuse into the loop that produces the data (PETSc's
 * VecDotNorm2 idea), so each vector is streamed once per use.
 */
#include "linsolve/csr.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "linsolve/linsolve_impl.h"

int csr_alloc(struct csr_matrix *A, int n, int64_t nnz)
{
    memset(A, 0, sizeof *A);
    A->rowptr = sim_malloc(((size_t)n + 1) * sizeof *A->rowptr);
    A->col = sim_malloc((size_t)(nnz > 0 ? nnz : 1) * sizeof *A->col);
    A->val = sim_malloc((size_t)(nnz > 0 ? nnz : 1) * sizeof *A->val);
    if (!A->rowptr || !A->col || !A->val) {
        csr_free(A);
        return SIM_ERR_NOMEM;
    }
    A->n = n;
    A->nnz = nnz;
    return SIM_OK;
}

int csr_reserve(struct csr_matrix *A, size_t *cap, int64_t nnz)
{
    if ((size_t)nnz <= *cap)
        return SIM_OK;
    size_t c = (size_t)nnz + (size_t)nnz / 4 + 64;
    SIM_GROW(A->col, c);
    SIM_GROW(A->val, c);
    *cap = c;
    return SIM_OK;
}

void csr_free(struct csr_matrix *A)
{
    if (!A)
        return;
    free(A->rowptr);
    free(A->col);
    free(A->val);
    memset(A, 0, sizeof *A);
}

static int check_structure(const struct csr_matrix *A)
{
    if (!A || A->n <= 0)
        return sim_error(SIM_ERR_INPUT, "linear system: empty matrix (n = %d)",
                         A ? A->n : 0);
    if (!A->rowptr || (A->nnz > 0 && (!A->col || !A->val)))
        return sim_error(SIM_ERR_INPUT, "linear system: matrix arrays missing");
    if (A->rowptr[0] != 0 || A->rowptr[A->n] != A->nnz)
        return sim_error(SIM_ERR_INPUT,
                         "linear system: rowptr[0] = %lld and rowptr[n] = %lld,"
                         " expected 0 and nnz = %lld",
                         (long long)A->rowptr[0], (long long)A->rowptr[A->n],
                         (long long)A->nnz);
    for (int i = 0; i < A->n; i++)
        if (A->rowptr[i + 1] < A->rowptr[i])
            return sim_error(SIM_ERR_INPUT,
                             "linear system: rowptr decreases at row %d", i);
    return SIM_OK;
}

/* Returns the first bad row (or -1) and what is wrong with it in *what:
 * 1 column out of range, 2 non-finite value, 3 diagonal missing or <= 0. */
static int scan_rows(const struct csr_matrix *A, double *diag, int *what)
{
    int bad = A->n, kind = 0;
#pragma omp parallel for schedule(static) reduction(min : bad) if (LS_PAR(A->n))
    for (int i = 0; i < A->n; i++) {
        double d = 0.0;
        int k_bad = 0;
        for (int64_t k = A->rowptr[i]; k < A->rowptr[i + 1]; k++) {
            int32_t j = A->col[k];
            if (j < 0 || j >= A->n) {
                k_bad = 1;
                break;
            }
            if (!isfinite(A->val[k])) {
                k_bad = 2;
                break;
            }
            if (j == i)
                d += A->val[k];
        }
        if (!k_bad && !(d > 0.0))
            k_bad = 3;
        if (diag)
            diag[i] = d;
        if (k_bad && i < bad)
            bad = i;
    }
    if (bad == A->n)
        return -1;
    /* Classify the first bad row serially (cheap, once). */
    for (int64_t k = A->rowptr[bad]; k < A->rowptr[bad + 1]; k++) {
        if (A->col[k] < 0 || A->col[k] >= A->n) {
            kind = 1;
            break;
        }
        if (!isfinite(A->val[k])) {
            kind = 2;
            break;
        }
    }
    *what = kind ? kind : 3;
    return bad;
}

int csr_validate(const struct csr_matrix *A, double *diag)
{
    TRY(check_structure(A));
    int what = 0;
    int row = scan_rows(A, diag, &what);
    if (row < 0)
        return SIM_OK;
    if (what == 1)
        return sim_error(SIM_ERR_INPUT,
                         "linear system: column index out of range [0, %d) in "
                         "row %d", A->n, row);
    if (what == 2)
        return sim_error(SIM_ERR_NUMERIC,
                         "linear system: non-finite matrix entry in row %d", row);
    double d = 0.0;
    for (int64_t k = A->rowptr[row]; k < A->rowptr[row + 1]; k++)
        if (A->col[k] == row)
            d += A->val[k];
    return sim_error(SIM_ERR_INPUT,
                     "linear system: diagonal entry of row %d is %g (missing or "
                     "not positive); the PPE matrix must have a positive "
                     "diagonal", row, d);
}

void csr_spmv(const struct csr_matrix *A, const double *x, double *y)
{
    const int64_t *rp = A->rowptr;
    const int32_t *col = A->col;
    const double *val = A->val;
#pragma omp parallel for schedule(static) if (LS_PAR(A->n))
    for (int i = 0; i < A->n; i++)
        y[i] = csr_row_dot(rp, col, val, x, i);
}

double csr_spmv_dot(const struct csr_matrix *A, const double *p, double *q)
{
    const int64_t *rp = A->rowptr;
    const int32_t *col = A->col;
    const double *val = A->val;
    double d = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : d) if (LS_PAR(A->n))
    for (int i = 0; i < A->n; i++) {
        double s = csr_row_dot(rp, col, val, p, i);
        q[i] = s;
        d += p[i] * s;
    }
    return d;
}

double csr_residual(const struct csr_matrix *A, const double *b,
                    const double *x, double *r)
{
    const int64_t *rp = A->rowptr;
    const int32_t *col = A->col;
    const double *val = A->val;
    double d = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : d) if (LS_PAR(A->n))
    for (int i = 0; i < A->n; i++) {
        double s = b[i] - csr_row_dot(rp, col, val, x, i);
        r[i] = s;
        d += s * s;
    }
    return d;
}

double vec_dot(int n, const double *a, const double *b)
{
    double d = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : d) if (LS_PAR(n))
    for (int i = 0; i < n; i++)
        d += a[i] * b[i];
    return d;
}

void vec_copy(int n, const double *a, double *b)
{
#pragma omp parallel for schedule(static) if (LS_PAR(n))
    for (int i = 0; i < n; i++)
        b[i] = a[i];
}

void vec_zero(int n, double *a)
{
#pragma omp parallel for schedule(static) if (LS_PAR(n))
    for (int i = 0; i < n; i++)
        a[i] = 0.0;
}

/* Value of a_ji, found by a linear search of row j (rows are short). */
static double entry(const struct csr_matrix *A, int j, int i)
{
    double v = 0.0;
    for (int64_t k = A->rowptr[j]; k < A->rowptr[j + 1]; k++)
        if (A->col[k] == i)
            v += A->val[k];
    return v;
}

int csr_is_symmetric(const struct csr_matrix *A, double rtol, int *row)
{
    int bad = A->n;
#pragma omp parallel for schedule(static) reduction(min : bad) if (LS_PAR(A->n))
    for (int i = 0; i < A->n; i++) {
        for (int64_t k = A->rowptr[i]; k < A->rowptr[i + 1]; k++) {
            int j = A->col[k];
            if (j == i)
                continue;
            double aij = entry(A, i, j), aji = entry(A, j, i);
            if (fabs(aij - aji) > rtol * (fabs(aij) + fabs(aji))) {
                if (i < bad)
                    bad = i;
                break;
            }
        }
    }
    if (row)
        *row = bad < A->n ? bad : -1;
    return bad == A->n;
}
