/*
 * matrix.c — row pointers of an implicit operator's matrix from the
 * neighbour list (CSR, doc/design.md C13): row lengths in parallel, then
 * a sequential prefix sum so that the numbering does not depend on the
 * thread count.
 */
#include "particles/operators/matrix.h"

#include "particles/neighbour.h"

int64_t pop_matrix_rowptr(const struct neighbour_list *nl, int n,
                          const struct pop_weights *W, const int32_t *unk,
                          int m,
                          int64_t *rowptr)
{
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; i++) {
        if (unk[i] < 0)
            continue;
        int64_t len = 1;
        const int64_t k0 = nl->start[i], k1 = nl->start[i + 1];
        const double *w = pop_weights_of(W, nl, i, k0, k1);
        for (int64_t k = k0; k < k1; k++)
            len += w[k - k0] > 0 && unk[nl->j[k]] >= 0;
        rowptr[unk[i] + 1] = len;
    }
    rowptr[0] = 0;
    for (int r = 0; r < m; r++)
        rowptr[r + 1] += rowptr[r];
    return rowptr[m];
}
