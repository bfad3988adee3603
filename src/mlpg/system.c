/*
 * system.c — assembly of the MLPG_R pressure equation A p = b (Pan 2022
 * thesis eqs. 4.22-4.24; doc/theory.md M.5) and the wall-scheme table.
 *
 * Row i holds node i first, then the nodes of row i of the neighbour list
 * (whose radius covers every MLS support reached from i's sub-domain);
 * the coefficients of nodes outside every support are exact zeros and
 * stay in the pattern, so that the pattern is the list's. A Dirichlet
 * node (free surface, a pinned reference) gets an identity row.
 */
#include <stdlib.h>

#include "core/error.h"
#include "linsolve/csr.h"
#include "mlpg/mlpg.h"
#include "particles/neighbour.h"

#ifdef _OPENMP
#include <omp.h>
#endif

const struct mlpg_wall_ops *const mlpg_wall_schemes[] = {
    &mlpg_wall_improved, &mlpg_wall_consistent, &mlpg_wall_original, NULL
};

static int node_row(const struct mlpg_cloud *c, const struct mlpg_system *S,
                    const struct mlpg_wall_ops *ops, int i,
                    const int32_t *cand, int m, double *coef, double *work,
                    double *D)
{
    if (ops) /* NULL: the right-hand side only */
        TRY(ops->row(c, i, cand, m, coef, work));
    *D = 0;
    if (S->ustar && S->rho_dt != 0 && S->dw)
        *D = mlpg_domain_sum(c, i, cand, m, S->dw + S->dw_start[i], S->ustar);
    else if (S->ustar && S->rho_dt != 0)
        TRY(mlpg_domain_integral(c, i, cand, m, S->ustar, work, D));
    return SIM_OK;
}

/* Rows (matrix != 0: coefficients and right-hand side; else the
 * right-hand side only, into b, of a pattern assembled before). */
static int build(const struct mlpg_cloud *c, const struct mlpg_system *S,
                 struct csr_matrix *A, size_t *cap, double *b, int matrix)
{
    const int n = c->n;
    int maxlen = 1;
    if (!matrix) {
        for (int i = 0; i < n; i++) {
            int len = (int)(A->rowptr[i + 1] - A->rowptr[i]);
            if (len > maxlen)
                maxlen = len;
        }
    } else if (!A->rowptr || A->n < n) {
        free(A->rowptr);
        A->rowptr = sim_malloc((size_t)(n + 1) * sizeof *A->rowptr);
        if (!A->rowptr)
            return SIM_ERR_NOMEM;
    }
    if (matrix) {
        A->n = n;
        A->rowptr[0] = 0;
        for (int i = 0; i < n; i++) {
            int len = c->dirichlet && c->dirichlet[i]
                    ? 1 : mlpg_candidates(c, i, NULL);
            A->rowptr[i + 1] = A->rowptr[i] + len;
            if (len > maxlen)
                maxlen = len;
        }
        TRY(csr_reserve(A, cap, A->rowptr[n]));
        A->nnz = A->rowptr[n];
    }

    int nthr = 1;
#ifdef _OPENMP
    nthr = omp_get_max_threads();
#endif
    /* per thread: candidates, coefficients, 5 maxlen of work */
    size_t per = (size_t)maxlen * (sizeof(int32_t) + 6 * sizeof(double));
    per = (per + 63) / 64 * 64; /* every thread's doubles aligned */
    char *buf = sim_malloc((size_t)nthr * per);
    if (!buf)
        return SIM_ERR_NOMEM;
    int bad = -1; /* smallest failing node: redone below for its message */
#pragma omp parallel
    {
        int t = 0;
#ifdef _OPENMP
        t = omp_get_thread_num();
#endif
        double *coef = (double *)(buf + (size_t)t * per);
        double *work = coef + maxlen;
        int32_t *cand = (int32_t *)(work + 5 * maxlen);
#pragma omp for schedule(dynamic, 64)
        for (int i = 0; i < n; i++) {
            int64_t e = A->rowptr[i];
            if (c->dirichlet && c->dirichlet[i]) {
                if (matrix) {
                    A->col[e] = i;
                    A->val[e] = 1;
                }
                b[i] = S->p_given ? S->p_given[i] : 0;
                continue;
            }
            int m = mlpg_candidates(c, i, cand);
            const int wall = c->type[i] == MLPG_WALL;
            const struct mlpg_wall_ops *ops = wall ? S->wall
                                                   : &mlpg_wall_improved;
            double D = 0;
            if (node_row(c, S, matrix ? ops : NULL, i, cand, m, coef, work,
                         &D) != SIM_OK) {
#pragma omp critical(mlpg_assemble_err)
                if (bad < 0 || i < bad)
                    bad = i;
                continue;
            }
            double t0, angle, ns[2][2], g[2] = { 0, 0 };
            int nseg;
            mlpg_sector(c, i, &t0, &angle, &nseg, ns);
            if (nseg && S->neumann)
                S->neumann(S->ctx, i, nseg, ns, g);
            static const double zero[3] = { 0, 0, 0 };
            b[i] = ops->rhs(c, i, S->rho_dt, D,
                            S->ustar ? S->ustar + 3 * i : zero, nseg, ns, g);
            if (matrix)
                for (int k = 0; k < m; k++) {
                    A->col[e + k] = cand[k];
                    A->val[e + k] = coef[k];
                }
        }
    }
    int rc = SIM_OK;
    if (bad >= 0) { /* messages are thread-local: make it again here */
        double *coef = (double *)buf, *work = coef + maxlen, D;
        int32_t *cand = (int32_t *)(work + 5 * maxlen);
        int m = mlpg_candidates(c, bad, cand);
        rc = node_row(c, S, !matrix ? NULL
                            : c->type[bad] == MLPG_WALL ? S->wall
                            : &mlpg_wall_improved,
                      bad, cand, m, coef, work, &D);
        if (rc == SIM_OK)
            rc = sim_error(SIM_ERR_INTERNAL, "node %d failed once only", bad);
    }
    free(buf);
    return rc;
}

int mlpg_assemble(const struct mlpg_cloud *c, const struct mlpg_system *S,
                  struct csr_matrix *A, size_t *cap, double *b)
{
    return build(c, S, A, cap, b, 1);
}

int mlpg_rhs(const struct mlpg_cloud *c, const struct mlpg_system *S,
             const struct csr_matrix *A, double *b)
{
    return build(c, S, (struct csr_matrix *)A, NULL, b, 0);
}
