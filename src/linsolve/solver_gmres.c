/*
 * solver_gmres.c — restarted GMRES(m) with right preconditioning, for the
 * non-symmetric PPE of the coupled case (porosity weights 1/eps_j,
 * doc/theory.md §A.4 note [P]). Saad and Schultz (1986), SIAM J. Sci. Stat.
 * Comput. 7:856–869; Saad (2003), Iterative Methods for Sparse Linear
 * Systems, 2nd ed., Alg. 9.5 (right-preconditioned GMRES):
 *
 *   r = b - A x, beta = ||r||, v_1 = r / beta, g = beta e_1
 *   for j = 1..m:  w = A M^-1 v_j
 *                  h_ij = (w, v_i), w -= h_ij v_i   (i = 1..j, modified
 *                                                   Gram-Schmidt)
 *                  h_{j+1,j} = ||w||, v_{j+1} = w / h_{j+1,j}
 *                  Givens rotations bring H to upper triangular form and
 *                  rotate g; |g_{j+1}| = ||b - A x_j|| (the residual of the
 *                  unpreconditioned system: right preconditioning)
 *   H y = g (the j x j triangle), x += M^-1 (V y); restart from the new x
 *
 * Why beside BiCGSTAB: an iteration costs one SpMV and one preconditioner
 * application, BiCGSTAB's two of each, and the residual falls
 * monotonically. With the aggregation AMG a 3-D porous PPE takes 14-17
 * GMRES iterations where BiCGSTAB takes 8-11 (16-22 products; ppeBench,
 * doc/libraries.md §2), so the solve costs less while the matrix stays
 * the neighbour-weighted one of eq. (10).
 *
 * The basis is kept (V, (m+1) vectors of n), not the preconditioned one:
 * M^-1 is applied once more at the end of a cycle instead of storing m
 * more vectors (memory per particle is a target, issue 21). GMRES_RESTART
 * m = 20: the warm-started PPE converges in 13-17 iterations, so a restart
 * is rare; one cycle costs (m+1) n doubles.
 */
#include <math.h>
#include <stdlib.h>

#include "core/error.h"
#include "linsolve/csr.h"
#include "linsolve/linsolve_impl.h"

#define GMRES_RESTART 20

enum { W_Z, W_U };

struct gmres {
    int n_cap;
    double *v[GMRES_RESTART + 1];           /* the Krylov basis        */
    double h[GMRES_RESTART + 1][GMRES_RESTART]; /* Hessenberg, rotated  */
    double cs[GMRES_RESTART], sn[GMRES_RESTART], g[GMRES_RESTART + 1];
};

static int init(struct linsolve *s)
{
    s->ext = sim_calloc(1, sizeof(struct gmres));
    return s->ext ? SIM_OK : SIM_ERR_NOMEM;
}

static void fini(struct linsolve *s)
{
    struct gmres *G = s->ext;
    if (!G)
        return;
    for (int k = 0; k <= GMRES_RESTART; k++)
        free(G->v[k]);
    free(G);
    s->ext = NULL;
}

static int reserve(struct gmres *G, int n)
{
    if (n <= G->n_cap)
        return SIM_OK;
    for (int k = 0; k <= GMRES_RESTART; k++) {
        double *p = sim_realloc(G->v[k], (size_t)n * sizeof *p);
        if (!p)
            return SIM_ERR_NOMEM;
        G->v[k] = p;
    }
    G->n_cap = n;
    return SIM_OK;
}

/* w -= h v; returns (w, a) after the update (a = the next basis vector
 * or w itself): one pass where MGS would take two. */
static double axpy_dot(int n, double h, const double *v, double *w,
                       const double *a)
{
    double d = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : d) if (LS_PAR(n))
    for (int i = 0; i < n; i++) {
        w[i] -= h * v[i];
        d += w[i] * (a ? a[i] : w[i]);
    }
    return d;
}

static void scale(int n, double a, const double *x, double *y)
{
#pragma omp parallel for schedule(static) if (LS_PAR(n))
    for (int i = 0; i < n; i++)
        y[i] = a * x[i];
}

/* u = V y over the first k basis vectors */
static void combine(int n, int k, double *const *v, const double *y,
                    double *u)
{
#pragma omp parallel for schedule(static) if (LS_PAR(n))
    for (int i = 0; i < n; i++) {
        double s = 0.0;
        for (int c = 0; c < k; c++)
            s += y[c] * v[c][i];
        u[i] = s;
    }
}

/* x += M^-1 V y with H y = g over the first k columns */
static void finish(struct linsolve *s, struct gmres *G, int n, int k,
                   double *x)
{
    double y[GMRES_RESTART];
    for (int i = k - 1; i >= 0; i--) {
        double t = G->g[i];
        for (int c = i + 1; c < k; c++)
            t -= G->h[i][c] * y[c];
        y[i] = t / G->h[i][i];
    }
    combine(n, k, G->v, y, s->work[W_U]);
    s->pc.ops->apply(&s->pc, s->work[W_U], s->work[W_Z]);
#pragma omp parallel for schedule(static) if (LS_PAR(n))
    for (int i = 0; i < n; i++)
        x[i] += s->work[W_Z][i];
}

/* One cycle of at most GMRES_RESTART steps from r = b - A x (in v[0],
 * norm beta), ending early where the residual estimate meets tolabs. */
static int cycle(struct linsolve *s, const struct csr_matrix *A, double *x,
                 double beta, double tolabs, int *iters)
{
    struct gmres *G = s->ext;
    const int n = A->n;
    double *const *v = G->v;
    scale(n, 1.0 / beta, v[0], v[0]);
    G->g[0] = beta;
    int k = 0;
    while (k < GMRES_RESTART && *iters < s->maxiter) {
        double *w = v[k + 1];
        s->pc.ops->apply(&s->pc, v[k], s->work[W_Z]);
        csr_spmv(A, s->work[W_Z], w);
        double d = vec_dot(n, w, v[0]);
        for (int i = 0; i <= k; i++) {
            G->h[i][k] = d;
            d = axpy_dot(n, d, v[i], w, i < k ? v[i + 1] : NULL);
        }
        double hn = sqrt(d);   /* the last pass returned (w, w) */
        ++*iters;
        if (!isfinite(hn))
            return sim_error(SIM_ERR_NUMERIC, "GMRES: the Krylov vector is "
                             "not finite after %d iterations", *iters);
        for (int i = 0; i < k; i++) { /* earlier rotations on column k */
            double a = G->h[i][k], b = G->h[i + 1][k];
            G->h[i][k] = G->cs[i] * a + G->sn[i] * b;
            G->h[i + 1][k] = -G->sn[i] * a + G->cs[i] * b;
        }
        double a = G->h[k][k], r = hypot(a, hn);
        if (r == 0.0) /* A M^-1 v_k = 0: singular system */
            return sim_error(SIM_ERR_SOLVER, "GMRES breakdown at iteration "
                             "%d (zero column: singular matrix?)", *iters);
        G->cs[k] = a / r;
        G->sn[k] = hn / r;
        G->h[k][k] = r;
        G->g[k + 1] = -G->sn[k] * G->g[k];
        G->g[k] *= G->cs[k];
        k++;
        /* hn = 0: the solution lies in the space built (lucky breakdown) */
        if (fabs(G->g[k]) <= tolabs || hn == 0.0)
            break;
        scale(n, 1.0 / hn, w, w);
    }
    finish(s, G, n, k, x);
    return SIM_OK;
}

static int solve(struct linsolve *s, const struct csr_matrix *A,
                 const double *b, double *x, double tolabs,
                 struct linsolve_stats *st)
{
    struct gmres *G = s->ext;
    TRY(reserve(G, A->n));
    int iters = 0;
    for (;;) {
        double rnorm = sqrt(csr_residual(A, b, x, G->v[0]));
        if (!isfinite(rnorm))
            return sim_error(SIM_ERR_NUMERIC, "GMRES: residual is not finite "
                             "after %d iterations", iters);
        if (rnorm <= tolabs || iters >= s->maxiter)
            break;
        /* the true residual above decides, not the cycle's estimate */
        TRY(cycle(s, A, x, rnorm, tolabs, &iters));
    }
    st->iters = iters;
    return SIM_OK;
}

const struct solver_ops solver_gmres = {
    .name = "gmres",
    .reference = "Saad & Schultz 1986, right-preconditioned GMRES(20)",
    .iterative = 1, .needs_symmetric = 0, .needs_spd_pc = 0,
    .init = init, .solve = solve, .fini = fini,
};
