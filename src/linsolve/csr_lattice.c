/*
 * csr_lattice.c — the MPS-like pressure Laplacian on a jittered lattice
 * (doc/libraries.md §2 "Benchmark set-up"), for the linsolve tests and
 * ppeBench.
 *
 *   a_ij = -w(r_ij),  a_ii = sum_j w(r_ij),  w(r) = re/r - 1  (r < re)
 *
 * is the matrix of -<lap P>_i up to the constant 2d/(lambda n0) of
 * Koshizuka & Oka (1996), Eq. (10) in doc/theory.md. Free-surface (top layer)
 * rows are identity rows with P = 0; their couplings are dropped from the
 * other rows but their weights stay in a_ii, which makes the matrix SPD.
 * With porosity (Model B, doc/theory.md §A.4 note [P]) the weights are
 * w_ij/eps_j and the matrix is no longer symmetric.
 */
#include "linsolve/csr.h"

#include <math.h>
#include <stdlib.h>

#include "core/error.h"
#include "linsolve/linsolve_impl.h"

/* splitmix64: a deterministic, seedable stream independent of libc. */
static double urand(unsigned long *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1.0p-53;
}

struct lat {
    const struct csr_lattice *L;
    int n, K;
    double *x;   /* dim per particle */
    double *eps; /* porosity or NULL */
};

static int is_surface(const struct lat *g, int i)
{
    int top = g->L->dim == 2 ? i / g->L->nside
                             : i / (g->L->nside * g->L->nside);
    return top == g->L->nside - 1;
}

/* Neighbours j of particle i with r < re: *wsum gets the sum of all their
 * weights; those not on the surface are stored from k0 on (when col is
 * given) and counted. */
static int row_visit(const struct lat *g, int i, int64_t k0, int32_t *col,
                     double *val, double *wsum)
{
    const struct csr_lattice *L = g->L;
    int m = L->nside, d = L->dim, K = g->K, cnt = 0;
    int ci[3] = {0, 0, 0};
    ci[0] = i % m;
    ci[1] = (i / m) % m;
    if (d == 3)
        ci[2] = i / (m * m);
    int lo2 = d == 3 ? -K : 0, hi2 = d == 3 ? K : 0;
    double sum = 0.0;
    for (int o2 = lo2; o2 <= hi2; o2++)
        for (int o1 = -K; o1 <= K; o1++)
            for (int o0 = -K; o0 <= K; o0++) {
                int c0 = ci[0] + o0, c1 = ci[1] + o1, c2 = ci[2] + o2;
                if (c0 < 0 || c0 >= m || c1 < 0 || c1 >= m || c2 < 0 ||
                    (d == 3 && c2 >= m) || (o0 == 0 && o1 == 0 && o2 == 0))
                    continue;
                int j = c0 + m * (c1 + m * c2);
                double r2 = 0.0;
                for (int a = 0; a < d; a++) {
                    double dx = g->x[(size_t)d * j + a] - g->x[(size_t)d * i + a];
                    r2 += dx * dx;
                }
                double r = sqrt(r2);
                if (r >= L->re || r <= 0.0)
                    continue;
                double w = L->re / r - 1.0;
                if (g->eps)
                    w /= g->eps[j];
                sum += w;
                if (is_surface(g, j))
                    continue;
                if (col) {
                    col[k0 + cnt] = j;
                    val[k0 + cnt] = -w;
                }
                cnt++;
            }
    *wsum = sum;
    return cnt;
}

static int build(struct lat *g, struct csr_matrix *A)
{
    int n = g->n;
    int64_t *cnt = sim_malloc(((size_t)n + 1) * sizeof *cnt);
    if (!cnt)
        return SIM_ERR_NOMEM;
#pragma omp parallel for schedule(static) if (LS_PAR(n))
    for (int i = 0; i < n; i++) {
        double s;
        cnt[i + 1] = is_surface(g, i) ? 1 : 1 + row_visit(g, i, 0, NULL, NULL, &s);
    }
    cnt[0] = 0;
    for (int i = 0; i < n; i++)
        cnt[i + 1] += cnt[i];
    int rc = csr_alloc(A, n, cnt[n]);
    if (rc) {
        free(cnt);
        return rc;
    }
    for (int i = 0; i <= n; i++)
        A->rowptr[i] = cnt[i];
    free(cnt);
#pragma omp parallel for schedule(static) if (LS_PAR(n))
    for (int i = 0; i < n; i++) {
        int64_t k = A->rowptr[i];
        double s = 1.0;
        if (!is_surface(g, i))
            row_visit(g, i, k + 1, A->col, A->val, &s);
        A->col[k] = i; /* diagonal first: rows are not sorted on purpose */
        A->val[k] = s;
    }
    return SIM_OK;
}

int csr_lattice_ppe(const struct csr_lattice *L, struct csr_matrix *A,
                    double **b)
{
    if ((L->dim != 2 && L->dim != 3) || L->nside < 2 || !(L->re > 0.0))
        return sim_error(SIM_ERR_INPUT, "csr_lattice_ppe: bad dim %d, nside %d"
                         " or re %g", L->dim, L->nside, L->re);
    struct lat g = {.L = L};
    g.n = L->dim == 2 ? L->nside * L->nside : L->nside * L->nside * L->nside;
    g.K = (int)ceil(L->re + 2.0 * (L->jitter + L->move));
    g.x = sim_malloc((size_t)g.n * (size_t)L->dim * sizeof *g.x);
    double *rhs = sim_malloc((size_t)g.n * sizeof *rhs);
    if (L->porous)
        g.eps = sim_malloc((size_t)g.n * sizeof *g.eps);
    int rc = SIM_ERR_NOMEM;
    if (!g.x || !rhs || (L->porous && !g.eps))
        goto out;
    unsigned long s1 = L->seed, s2 = L->move_seed, s3 = L->rhs_seed;
    for (int i = 0; i < g.n; i++) {
        int c[3] = {i % L->nside, (i / L->nside) % L->nside,
                    i / (L->nside * L->nside)};
        for (int a = 0; a < L->dim; a++)
            g.x[(size_t)L->dim * i + a] = c[a] +
                L->jitter * (2.0 * urand(&s1) - 1.0) +
                L->move * (2.0 * urand(&s2) - 1.0);
        if (g.eps)
            g.eps[i] = 0.4 + 0.6 * urand(&s1);
        rhs[i] = is_surface(&g, i) ? 0.0 : 1.0 + 0.1 * (2.0 * urand(&s3) - 1.0);
    }
    rc = build(&g, A);
out:
    free(g.x);
    free(g.eps);
    if (rc == SIM_OK && b)
        *b = rhs;
    else
        free(rhs);
    return rc;
}
