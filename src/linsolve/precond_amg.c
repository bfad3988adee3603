/*
 * precond_amg.c — aggregation algebraic multigrid: z = M^-1 r is one
 * W-cycle. Plain (unsmoothed) aggregation: Braess (1995), East-West J.
 * Numer. Math. 3:97–127; Notay (2010), ETNA 37:123–146 (the Galerkin
 * coarse operator of piecewise-constant prolongation, and why it needs an
 * over-corrected coarse step).
 *
 *   A_0 = A,  A_{l+1} = P_l^T A_l P_l,  (P_l)_{iI} = 1 when row i lies in
 *   aggregate I (so A_{l+1}[I][J] is the sum of a_ij over i in I, j in J)
 *
 *   cycle on level l, z = M_l^-1 r:
 *     z  = w D^-1 r                 pre-smoothing from zero (damped Jacobi)
 *     rc = P^T (r - A z)            restriction of the residual
 *     zc = M_{l+1}^-1 rc            dense LU on the coarsest level; above
 *     zc += M_{l+1}^-1 (rc - A_{l+1} zc)    it two cycles (a W-cycle)
 *     z += a P zc                   over-corrected prolongation
 *     z += w D^-1 (r - A z)         post-smoothing
 *
 * For PCG (pc->symmetric) the cycle is as above: with a symmetric A the
 * pre- and post-smoothers are adjoint and M is symmetric, positive
 * definite while the smoother and the correction converge (w D^-1 with
 * w < 2/lambda_max(D^-1 A) <= 2 by Gershgorin, a < 2). BiCGSTAB (the
 * non-symmetric PPE of Model B, 1/eps_j weights) needs only a fixed linear
 * operator and gets no pre-smoothing: rc = P^T r, one fine SpMV per cycle
 * instead of two (20 % less time on the porous lattice, doc/libraries.md
 * §2).
 *
 * The W-cycle and the over-correction a were chosen on ppeBench; the
 * iteration counts are in doc/libraries.md §2 ("The aggregation AMG").
 *
 * Why it pays on the PPE: Jacobi needs iterations in proportion to the
 * number of particles across the water (~1/dp); the coarse levels remove
 * the smooth error in a few cycles whatever dp is (doc/theory.md E1-24:
 * time per step in proportion to the particle count).
 *
 * Aggregates are formed greedily in row order — the PPE's rows come
 * sorted by cell, so row order is spatially coherent: an unaggregated row
 * becomes a root and takes its strongest unaggregated neighbours (largest
 * -a_ij: the nearest particles, as the MPS weight falls with distance) up
 * to AGG_SIZE rows, 2 x 2 x 2 lattice sites in 3-D; a row left with no free
 * neighbour joins the aggregate of its strongest neighbour, and a row with
 * no negative coupling (an identity row) has no coarse value. Coarsening
 * stops at COARSE_MAX rows (dense LU, partial pivoting) or when a level
 * shrinks less than 1.5 times. The set-up runs at every solve: the
 * particles move and the matrix changes every step.
 */
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "linsolve/csr.h"
#include "linsolve/linsolve_impl.h"

#define AGG_SIZE 8
#define COARSE_MAX 400
#define MAX_LEVELS 12
#define OMEGA 0.9       /* damped Jacobi                                */
#define OVERCORRECT 1.5 /* a: plain aggregation's coarse step is too short */

struct level {
    struct csr_matrix A; /* level 0: a view of the caller's matrix      */
    double *dinv;        /* n: OMEGA / a_ii                              */
    int32_t *agg;        /* n: aggregate (row of the next level)         */
    int64_t *mstart;     /* nc+1: members of each aggregate, as CSR      */
    int32_t *members;    /* n                                            */
    double *r, *z, *t;   /* n: right-hand side, correction, residual     */
    double *w, *w2;      /* n: the W-cycle's second residual, correction */
    float *fval;         /* A.val rounded to float, for the smoothing     */
    size_t n_cap, nnz_cap, fval_cap;
};

#define MAX_THREADS 64
/* Two threads pay on a level from ~200,000 entries: LINSOLVE_OMP_MIN_ROWS
 * rows of the ~30 entries it was measured with. Counting entries keeps the
 * first coarse level (1/8 of the rows, 1/20 of the entries of an r_e 3.1
 * PPE) parallel, as the W-cycle visits it twice per cycle. */
#define AMG_PAR(A) ((A)->nnz >= 200000)

struct tbuf {               /* a thread's coarse rows during galerkin()   */
    int32_t *col;
    double *val;
    size_t cap;
};

struct amg {
    int nlev;
    int symmetric;       /* pre-smoothing too (PCG needs M symmetric)     */
    struct level lev[MAX_LEVELS];
    double *lu;          /* coarsest: dense LU factors, row-major        */
    int *piv;
    size_t lu_cap, piv_cap;
    int32_t *mark;       /* scratch of the Galerkin product, per thread   */
    size_t mark_cap;
    struct tbuf buf[MAX_THREADS];
};

static int grow(void **p, size_t *cap, size_t want, size_t elem)
{
    if (want <= *cap && *p)
        return SIM_OK;
    void *q = sim_realloc(*p, (want ? want : 1) * elem);
    if (!q)
        return SIM_ERR_NOMEM;
    *p = q;
    *cap = want;
    return SIM_OK;
}

static int resize(void **p, size_t bytes)
{
    void *q = sim_realloc(*p, bytes ? bytes : 1);
    if (!q)
        return SIM_ERR_NOMEM;
    *p = q;
    return SIM_OK;
}

/* Room for n rows on level L and, for a coarse level (own), its matrix of
 * nnz entries. */
static int level_reserve(struct level *L, int n, int64_t nnz, int own)
{
    if ((size_t)n > L->n_cap || !L->r) {
        size_t m = (size_t)n;
        double **v[] = {&L->dinv, &L->r, &L->z, &L->t, &L->w, &L->w2};
        for (size_t k = 0; k < sizeof v / sizeof v[0]; k++)
            TRY(resize((void **)v[k], m * sizeof(double)));
        TRY(resize((void **)&L->agg, m * sizeof(int32_t)));
        TRY(resize((void **)&L->members, m * sizeof(int32_t)));
        TRY(resize((void **)&L->mstart, (m + 1) * sizeof(int64_t)));
        if (own)
            TRY(resize((void **)&L->A.rowptr, (m + 1) * sizeof(int64_t)));
        L->n_cap = m;
    }
    if (own && ((size_t)nnz > L->nnz_cap || !L->A.col)) {
        TRY(resize((void **)&L->A.col, (size_t)nnz * sizeof(int32_t)));
        TRY(resize((void **)&L->A.val, (size_t)nnz * sizeof(double)));
        L->nnz_cap = (size_t)nnz;
    }
    return SIM_OK;
}

/* The cycle's own products use A rounded to float: 8 instead of 12 bytes
 * per entry in the memory-bound SpMV, and M changes by a relative 6e-8,
 * far below what a preconditioner needs. The Krylov method keeps the
 * double A, so the answer and its tolerance are unchanged. */
static int to_float(struct level *L)
{
    const struct csr_matrix *A = &L->A;
    TRY(grow((void **)&L->fval, &L->fval_cap, (size_t)A->nnz, sizeof(float)));
#pragma omp parallel for schedule(static) if (AMG_PAR(A))
    for (int i = 0; i < A->n; i++)
        for (int64_t k = A->rowptr[i]; k < A->rowptr[i + 1]; k++)
            L->fval[k] = (float)A->val[k];
    return SIM_OK;
}

/* ---- set-up ------------------------------------------------------------ */

/* Greedy aggregation of A's rows into L->agg; returns the aggregate count. */
static int aggregate(const struct csr_matrix *A, int32_t *agg)
{
    const int n = A->n;
    int nagg = 0;
    for (int i = 0; i < n; i++)
        agg[i] = -1;
    for (int i = 0; i < n; i++) {
        if (agg[i] >= 0)
            continue;
        /* the AGG_SIZE - 1 strongest free neighbours, by selection */
        int32_t pick[AGG_SIZE];
        double best[AGG_SIZE];
        int np = 0;
        for (int64_t k = A->rowptr[i]; k < A->rowptr[i + 1]; k++) {
            int j = A->col[k];
            double s = -A->val[k];
            if (j == i || s <= 0.0 || agg[j] >= 0)
                continue;
            if (np < AGG_SIZE - 1) {
                pick[np] = j;
                best[np++] = s;
            } else {
                int w = 0;
                for (int m = 1; m < np; m++)
                    if (best[m] < best[w])
                        w = m;
                if (s > best[w]) {
                    pick[w] = j;
                    best[w] = s;
                }
            }
        }
        if (np == 0)
            continue; /* second pass */
        agg[i] = nagg;
        for (int m = 0; m < np; m++)
            agg[pick[m]] = nagg;
        nagg++;
    }
    for (int i = 0; i < n; i++) {
        if (agg[i] >= 0)
            continue;
        double sbest = 0.0;
        int to = -1, coupled = 0;
        for (int64_t k = A->rowptr[i]; k < A->rowptr[i + 1]; k++) {
            int j = A->col[k];
            double s = -A->val[k];
            coupled |= j != i && s > 0.0;
            if (j != i && agg[j] >= 0 && s > sbest) {
                sbest = s;
                to = agg[j];
            }
        }
        /* a row with no negative coupling (a Dirichlet identity row) needs
         * no coarse value: the smoother solves it exactly */
        agg[i] = to >= 0 ? to : coupled ? nagg++ : -1;
    }
    return nagg;
}

/* Members of each aggregate as CSR (counting sort, rows in order). */
static void members(struct level *L, int nc)
{
    int n = L->A.n;
    memset(L->mstart, 0, (size_t)(nc + 1) * sizeof(int64_t));
    for (int i = 0; i < n; i++)
        if (L->agg[i] >= 0)
            L->mstart[L->agg[i] + 1]++;
    for (int I = 0; I < nc; I++)
        L->mstart[I + 1] += L->mstart[I];
    for (int i = 0; i < n; i++)
        if (L->agg[i] >= 0)
            L->members[L->mstart[L->agg[i]]++] = i;
    for (int I = nc; I > 0; I--)
        L->mstart[I] = L->mstart[I - 1];
    L->mstart[0] = 0;
}

/* Coarse row I of P^T A P appended to col/val (room for nc entries is
 * guaranteed by the caller); mark (nc, all -1 on entry and exit) maps a
 * column to its slot. Returns the row's length; *diag gets A_c[I][I]. */
static int64_t galerkin_row(const struct level *F, int I, int32_t *mark,
                            int32_t *col, double *val, double *diag)
{
    int64_t len = 0;
    for (int64_t m = F->mstart[I]; m < F->mstart[I + 1]; m++) {
        int i = F->members[m];
        for (int64_t k = F->A.rowptr[i]; k < F->A.rowptr[i + 1]; k++) {
            int J = F->agg[F->A.col[k]];
            if (J < 0)
                continue;
            if (mark[J] < 0) {
                mark[J] = (int32_t)len;
                col[len] = J;
                val[len++] = 0.0;
            }
            val[mark[J]] += F->A.val[k];
        }
    }
    *diag = mark[I] >= 0 ? val[mark[I]] : 0.0;
    for (int64_t k = 0; k < len; k++)
        mark[col[k]] = -1;
    return len;
}

/* A_c = P^T A P in one pass: each thread builds its block of coarse rows in
 * its own buffer, then the blocks are copied into place. C->dinv receives
 * the diagonal (smoother() scales it). */
static int galerkin(struct amg *g, struct level *F, struct level *C, int nc)
{
    int nth = AMG_PAR(&F->A) ? omp_get_max_threads() : 1;
    if (nth > MAX_THREADS)
        nth = MAX_THREADS;
    TRY(grow((void **)&g->mark, &g->mark_cap, (size_t)nth * (size_t)nc,
             sizeof(int32_t)));
    for (size_t k = 0; k < (size_t)nth * (size_t)nc; k++)
        g->mark[k] = -1;
    TRY(level_reserve(C, nc, 0, 1));
    C->A.n = nc;
    int64_t used[MAX_THREADS] = {0};
    int rc = SIM_OK, nblk = 1;
#pragma omp parallel num_threads(nth) reduction(| : rc)
    {
        int t = omp_get_thread_num(), nt = omp_get_num_threads();
        if (t == 0)
            nblk = nt;
        int a = (int)((int64_t)nc * t / nt);
        int b = (int)((int64_t)nc * (t + 1) / nt);
        struct tbuf *B = &g->buf[t];
        int32_t *mark = g->mark + (size_t)t * nc;
        int64_t pos = 0;
        for (int I = a; I < b && rc == SIM_OK; I++) {
            if (pos + nc > (int64_t)B->cap) { /* a row has <= nc entries */
                size_t want = (size_t)(2 * (pos + nc));
                size_t c1 = B->cap;
                rc = grow((void **)&B->col, &c1, want, sizeof(int32_t));
                if (rc == SIM_OK)
                    rc = grow((void **)&B->val, &B->cap, want, sizeof(double));
                if (rc)
                    break;
            }
            int64_t len = galerkin_row(F, I, mark, B->col + pos, B->val + pos,
                                       &C->dinv[I]);
            C->A.rowptr[I + 1] = len;
            pos += len;
        }
        used[t] = pos;
    }
    TRY(rc);
    C->A.rowptr[0] = 0;
    for (int I = 0; I < nc; I++)
        C->A.rowptr[I + 1] += C->A.rowptr[I];
    C->A.nnz = C->A.rowptr[nc];
    TRY(level_reserve(C, nc, C->A.nnz, 1));
#pragma omp parallel for num_threads(nblk) schedule(static, 1)
    for (int t = 0; t < nblk; t++) {
        int64_t o = C->A.rowptr[(int)((int64_t)nc * t / nblk)];
        memcpy(C->A.col + o, g->buf[t].col, (size_t)used[t] * sizeof(int32_t));
        memcpy(C->A.val + o, g->buf[t].val, (size_t)used[t] * sizeof(double));
    }
    return SIM_OK;
}

/* dinv = OMEGA / diagonal, from the diagonal in d (may alias dinv); a row
 * whose diagonal is not positive (a coarse row can lose it only in a
 * degenerate matrix) uses its absolute row sum. */
static void smoother(struct level *L, const double *d)
{
    const struct csr_matrix *A = &L->A;
#pragma omp parallel for schedule(static) if (AMG_PAR(A))
    for (int i = 0; i < A->n; i++) {
        double di = d[i];
        if (!(di > 0.0)) {
            di = 0.0;
            for (int64_t k = A->rowptr[i]; k < A->rowptr[i + 1]; k++)
                di += fabs(A->val[k]);
            if (!(di > 0.0))
                di = 1.0;
        }
        L->dinv[i] = OMEGA / di;
    }
}

/* Dense LU with partial pivoting of the coarsest matrix; a pivot below
 * 1e-13 of the largest entry (a singular coarsest matrix: no Dirichlet
 * row reaches it) is replaced by that floor, which leaves the V-cycle a
 * valid, slightly weaker preconditioner. */
static int coarse_factor(struct amg *g, const struct csr_matrix *A)
{
    int n = A->n;
    TRY(grow((void **)&g->lu, &g->lu_cap, (size_t)n * n, sizeof(double)));
    TRY(grow((void **)&g->piv, &g->piv_cap, (size_t)n, sizeof(int)));
    double *a = g->lu, amax = 0.0;
    memset(a, 0, (size_t)n * n * sizeof *a);
    for (int i = 0; i < n; i++)
        for (int64_t k = A->rowptr[i]; k < A->rowptr[i + 1]; k++) {
            a[(size_t)i * n + A->col[k]] += A->val[k];
            amax = fmax(amax, fabs(A->val[k]));
        }
    double floor = 1e-13 * (amax > 0.0 ? amax : 1.0);
    for (int c = 0; c < n; c++) {
        int p = c;
        for (int i = c + 1; i < n; i++)
            if (fabs(a[(size_t)i * n + c]) > fabs(a[(size_t)p * n + c]))
                p = i;
        g->piv[c] = p;
        if (p != c)
            for (int k = 0; k < n; k++) {
                double t = a[(size_t)c * n + k];
                a[(size_t)c * n + k] = a[(size_t)p * n + k];
                a[(size_t)p * n + k] = t;
            }
        double d = a[(size_t)c * n + c];
        if (fabs(d) < floor)
            a[(size_t)c * n + c] = d = d < 0.0 ? -floor : floor;
        for (int i = c + 1; i < n; i++) {
            double f = a[(size_t)i * n + c] /= d;
            if (f != 0.0)
                for (int k = c + 1; k < n; k++)
                    a[(size_t)i * n + k] -= f * a[(size_t)c * n + k];
        }
    }
    return SIM_OK;
}

static void coarse_solve(const struct amg *g, int n, const double *r,
                         double *z)
{
    const double *a = g->lu;
    for (int i = 0; i < n; i++)
        z[i] = r[i];
    for (int c = 0; c < n; c++) {
        int p = g->piv[c];
        double t = z[c];
        z[c] = z[p];
        z[p] = t;
        for (int i = c + 1; i < n; i++)
            z[i] -= a[(size_t)i * n + c] * z[c];
    }
    for (int i = n - 1; i >= 0; i--) {
        double s = z[i];
        for (int k = i + 1; k < n; k++)
            s -= a[(size_t)i * n + k] * z[k];
        z[i] = s / a[(size_t)i * n + i];
    }
}

static int setup(struct precond *pc, const struct csr_matrix *A,
                 const double *diag)
{
    if (!pc->state) {
        pc->state = sim_calloc(1, sizeof(struct amg));
        if (!pc->state)
            return SIM_ERR_NOMEM;
    }
    struct amg *g = pc->state;
    pc->n = A->n;
    g->symmetric = pc->symmetric;
    struct level *L0 = &g->lev[0];
    TRY(level_reserve(L0, A->n, 0, 0));
    L0->A = *A;
    int l = 0;
    while (g->lev[l].A.n > COARSE_MAX && l + 1 < MAX_LEVELS) {
        struct level *F = &g->lev[l];
        int nc = aggregate(&F->A, F->agg);
        if (nc * 3 > F->A.n * 2) /* shrinks less than 1.5 times */
            break;
        members(F, nc);
        smoother(F, l == 0 ? diag : F->dinv); /* galerkin() left a_ii there */
        TRY(to_float(F));
        TRY(galerkin(g, F, &g->lev[l + 1], nc));
        l++;
    }
    g->nlev = l + 1;
    struct level *C = &g->lev[l];
    if (C->A.n > COARSE_MAX * 4)
        return sim_error(SIM_ERR_SOLVER, "amg: the coarsening stalled at %d "
                         "rows on level %d (no strong negative couplings?): "
                         "use preconditioner jacobi", C->A.n, l);
    TRY(coarse_factor(g, &C->A));
    return SIM_OK;
}

/* ---- the cycle ---------------------------------------------------------- */

static void cycle(const struct amg *g, int l, const double *r, double *z)
{
    const struct level *L = &g->lev[l];
    const struct csr_matrix *A = &L->A;
    const int n = A->n;
    if (l == g->nlev - 1) {
        coarse_solve(g, n, r, z);
        return;
    }
    const struct level *C = &g->lev[l + 1];
    double *t = L->t;
    const double *t0 = r; /* the residual restricted */
    if (g->symmetric) {
#pragma omp parallel for schedule(static) if (AMG_PAR(A))
        for (int i = 0; i < n; i++)
            z[i] = L->dinv[i] * r[i];
#pragma omp parallel for schedule(static) if (AMG_PAR(A))
        for (int i = 0; i < n; i++)
            t[i] = r[i] - csr_row_dot_f(A->rowptr, A->col, L->fval, z, i);
        t0 = t;
    }
    const int nc = C->A.n;
#pragma omp parallel for schedule(static) if (AMG_PAR(A))
    for (int I = 0; I < nc; I++) {
        double s = 0.0;
        for (int64_t m = L->mstart[I]; m < L->mstart[I + 1]; m++)
            s += t0[L->members[m]];
        C->r[I] = s;
    }
    cycle(g, l + 1, C->r, C->z);
    if (l + 1 < g->nlev - 1) {
        /* W-cycle: a second coarse cycle on the remaining coarse residual */
        const struct csr_matrix *Ac = &C->A;
#pragma omp parallel for schedule(static) if (AMG_PAR(Ac))
        for (int I = 0; I < nc; I++)
            C->w[I] = C->r[I]
                    - csr_row_dot_f(Ac->rowptr, Ac->col, C->fval, C->z, I);
        cycle(g, l + 1, C->w, C->w2);
#pragma omp parallel for schedule(static) if (AMG_PAR(Ac))
        for (int I = 0; I < nc; I++)
            C->z[I] += C->w2[I];
    }
#pragma omp parallel for schedule(static) if (AMG_PAR(A))
    for (int i = 0; i < n; i++) {
        double zc = L->agg[i] >= 0 ? OVERCORRECT * C->z[L->agg[i]] : 0.0;
        z[i] = g->symmetric ? z[i] + zc : zc;
    }
#pragma omp parallel for schedule(static) if (AMG_PAR(A))
    for (int i = 0; i < n; i++)
        t[i] = r[i] - csr_row_dot_f(A->rowptr, A->col, L->fval, z, i);
#pragma omp parallel for schedule(static) if (AMG_PAR(A))
    for (int i = 0; i < n; i++)
        z[i] += L->dinv[i] * t[i];
}

static void apply(const struct precond *pc, const double *r, double *z)
{
    cycle(pc->state, 0, r, z);
}

static void release(struct precond *pc)
{
    struct amg *g = pc->state;
    if (!g)
        return;
    for (int l = 0; l < MAX_LEVELS; l++) {
        struct level *L = &g->lev[l];
        free(L->dinv);
        free(L->agg);
        free(L->mstart);
        free(L->members);
        free(L->r);
        free(L->z);
        free(L->t);
        free(L->w);
        free(L->w2);
        free(L->fval);
        if (l > 0) {
            free(L->A.rowptr);
            free(L->A.col);
            free(L->A.val);
        }
    }
    free(g->lu);
    free(g->piv);
    free(g->mark);
    for (int t = 0; t < MAX_THREADS; t++) {
        free(g->buf[t].col);
        free(g->buf[t].val);
    }
    free(g);
    pc->state = NULL;
}

const struct precond_ops precond_amg = {
    .name = "amg",
    .reference = "plain-aggregation AMG W-cycle, Braess 1995 / Notay 2010",
    .spd = 1, .lower_only = 0, .diagonal = 0,
    .setup = setup, .apply = apply, .release = release,
};
