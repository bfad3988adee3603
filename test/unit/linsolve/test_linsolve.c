/*
 * test_linsolve.c — the PPE solvers of src/linsolve against CHOLMOD and a
 * dense LU, on MPS-like Laplacians of a jittered lattice with a Dirichlet
 * top layer (doc/libraries.md §2), plus warm start, failure and bad input.
 */
#include "linsolve_testutil.h"

#include <nvector/nvector_serial.h>
#include <omp.h>
#include <sundials/sundials_context.h>

#include "linsolve/sunlinsol_ppe.h"

static struct sys s2, s3; /* 2-D 40^2 re 2.1, 3-D 12^3 re 3.1 (SPD) */

static int setup_all(void **state)
{
    (void)state;
    log_set_quiet(1);
    tu_lattice(&s2, 2, 40, 2.1, 0);
    tu_reference(&s2);
    tu_lattice(&s3, 3, 12, 3.1, 0);
    tu_reference(&s3);
    return 0;
}

static int teardown_all(void **state)
{
    (void)state;
    tu_free(&s2);
    tu_free(&s3);
    return 0;
}

static struct linsolve *make(const char *solver, const char *pc, double tol,
                             int maxiter)
{
    struct linsolve *ls = NULL;
    int rc = linsolve_create_named(solver, pc, tol, maxiter, &ls);
    if (rc)
        print_error("%s\n", sim_error_message());
    assert_int_equal(rc, SIM_OK);
    return ls;
}

/* Solve from x = 0, check convergence and the reference; returns iters. */
static int solve_check(const struct sys *s, const char *solver, const char *pc)
{
    struct linsolve *ls = make(solver, pc, 1e-8, 1000);
    struct linsolve_stats st;
    double *x = calloc((size_t)s->A.n, sizeof *x);
    int rc = linsolve_solve(ls, &s->A, s->b, x, &st);
    if (rc)
        print_error("%s\n", sim_error_message());
    assert_int_equal(rc, SIM_OK);
    assert_true(st.converged);
    assert_true(st.res_rel <= 1e-8);
    tu_assert_matches_reference(s, x, 1e-8);
    free(x);
    linsolve_free(ls);
    return st.iters;
}

static void test_pcg_jacobi_matches_cholmod(void **state)
{
    (void)state;
    int i2 = solve_check(&s2, "pcg", "jacobi");
    int i3 = solve_check(&s3, "pcg", "jacobi");
    /* Iteration counts of the same order as doc/libraries.md §2 (40^2 is
     * smaller than its 300^2; 12^3 with re 3.1 is small). */
    assert_in_range(i2, 50, 600);
    assert_in_range(i3, 10, 200);
}

static void test_ic0_fewer_iterations_than_jacobi(void **state)
{
    (void)state;
    int ij = solve_check(&s2, "pcg", "jacobi");
    int ii = solve_check(&s2, "pcg", "ic0");
    int id = solve_check(&s2, "pcg", "dic");
    /* IC(0) cut iterations 3-4x in doc/libraries.md §2; DIC lies between. */
    assert_true(2 * ii < ij);
    assert_true(id < ij);
    assert_true(ii <= id);
}

/* The fused diagonal fast path must follow the generic path iterate for
 * iterate. */
static void test_fused_path_equals_generic(void **state)
{
    (void)state;
    const char *pcs[] = {"jacobi", "none"};
    for (int k = 0; k < 2; k++) {
        struct linsolve *fast = make("pcg", pcs[k], 1e-10, 2000);
        struct linsolve *slow = make("pcg", pcs[k], 1e-10, 2000);
        slow->generic = 1;
        struct linsolve_stats sf, sg;
        int n = s3.A.n;
        double *xf = calloc((size_t)n, sizeof *xf);
        double *xg = calloc((size_t)n, sizeof *xg);
        assert_int_equal(linsolve_solve(fast, &s3.A, s3.b, xf, &sf), SIM_OK);
        assert_int_equal(linsolve_solve(slow, &s3.A, s3.b, xg, &sg), SIM_OK);
        assert_true(abs(sf.iters - sg.iters) <= 1);
        double d = 0.0;
        for (int i = 0; i < n; i++)
            d = fmax(d, fabs(xf[i] - xg[i]));
        assert_true(d <= 1e-8 * tu_norm(n, xg) / sqrt(n) + 1e-300);
        free(xf);
        free(xg);
        linsolve_free(fast);
        linsolve_free(slow);
    }
}

/* The OpenMP paths (systems of >= LINSOLVE_OMP_MIN_ROWS rows) against one
 * thread: PCG takes the same iterations within 2 (reductions round
 * differently; BiCGSTAB's counts moved 88 -> 100, so only its answer is
 * compared), and both answers agree to well within the tolerance. */
static void test_threads_match_one_thread(void **state)
{
    (void)state;
    struct sys big;
    tu_lattice(&big, 3, 22, 2.1, 0); /* 10,648 rows */
    assert_true(big.A.n >= LINSOLVE_OMP_MIN_ROWS);
    int n = big.A.n, nt = omp_get_max_threads();
    const char *combos[][2] = {{"pcg", "jacobi"}, {"bicgstab", "jacobi"}};
    for (int k = 0; k < 2; k++) {
        struct linsolve *ls = make(combos[k][0], combos[k][1], 1e-10, 1000);
        struct linsolve_stats s1, sn;
        double *x1 = calloc((size_t)n, sizeof *x1);
        double *xn = calloc((size_t)n, sizeof *xn);
        omp_set_num_threads(1);
        assert_int_equal(linsolve_solve(ls, &big.A, big.b, x1, &s1), SIM_OK);
        omp_set_num_threads(nt > 1 ? nt : 2);
        assert_int_equal(linsolve_solve(ls, &big.A, big.b, xn, &sn), SIM_OK);
        omp_set_num_threads(nt);
        print_message("  %s/%s: %d iterations on 1 thread, %d on %d\n",
                      combos[k][0], combos[k][1], s1.iters, sn.iters,
                      nt > 1 ? nt : 2);
        if (k == 0) /* BiCGSTAB's erratic convergence amplifies rounding */
            assert_true(abs(s1.iters - sn.iters) <= 2);
        double e = 0.0;
        for (int i = 0; i < n; i++)
            e += (x1[i] - xn[i]) * (x1[i] - xn[i]);
        assert_true(sqrt(e) <= 1e-6 * tu_norm(n, x1));
        free(x1);
        free(xn);
        linsolve_free(ls);
    }
    tu_free(&big);
}

static void test_warm_start_from_exact_solution(void **state)
{
    (void)state;
    const char *combos[][2] = {{"pcg", "jacobi"}, {"pcg", "ic0"},
                               {"pcg", "dic"}, {"bicgstab", "ilu0"}};
    for (int k = 0; k < 4; k++) {
        struct linsolve *ls = make(combos[k][0], combos[k][1], 1e-8, 1000);
        struct linsolve_stats st;
        double *x = malloc((size_t)s3.A.n * sizeof *x);
        memcpy(x, s3.xref, (size_t)s3.A.n * sizeof *x);
        assert_int_equal(linsolve_solve(ls, &s3.A, s3.b, x, &st), SIM_OK);
        assert_in_range(st.iters, 0, 1);
        /* And a perturbed start converges in fewer iterations than 0. */
        for (int i = 0; i < s3.A.n; i++)
            x[i] = s3.xref[i] * (1.0 + 1e-4 * sin(i));
        struct linsolve_stats sw;
        assert_int_equal(linsolve_solve(ls, &s3.A, s3.b, x, &sw), SIM_OK);
        memset(x, 0, (size_t)s3.A.n * sizeof *x);
        struct linsolve_stats s0;
        assert_int_equal(linsolve_solve(ls, &s3.A, s3.b, x, &s0), SIM_OK);
        assert_true(sw.iters < s0.iters);
        free(x);
        linsolve_free(ls);
    }
}

static void test_warm_start_off_ignores_guess(void **state)
{
    (void)state;
    struct linsolve *ls = make("pcg", "jacobi", 1e-8, 1000);
    ls->warm_start = 0;
    int n = s2.A.n;
    double *x = malloc((size_t)n * sizeof *x);
    for (int i = 0; i < n; i++)
        x[i] = NAN;
    struct linsolve_stats st;
    assert_int_equal(linsolve_solve(ls, &s2.A, s2.b, x, &st), SIM_OK);
    tu_assert_matches_reference(&s2, x, 1e-8);
    /* With warm start on, the same NaN guess is an error, not a hang. */
    ls->warm_start = 1;
    for (int i = 0; i < n; i++)
        x[i] = NAN;
    assert_int_equal(linsolve_solve(ls, &s2.A, s2.b, x, &st),
                     SIM_ERR_NUMERIC);
    free(x);
    linsolve_free(ls);
}

static void test_nonconvergence_is_an_error(void **state)
{
    (void)state;
    const char *combos[][2] = {{"pcg", "jacobi"}, {"pcg", "ic0"},
                               {"bicgstab", "jacobi"}};
    for (int k = 0; k < 3; k++) {
        struct linsolve *ls = make(combos[k][0], combos[k][1], 1e-8, 5);
        struct linsolve_stats st;
        int n = s2.A.n;
        double *x = calloc((size_t)n, sizeof *x);
        assert_int_equal(linsolve_solve(ls, &s2.A, s2.b, x, &st),
                         SIM_ERR_SOLVER);
        assert_int_equal(st.iters, 5);
        assert_false(st.converged);
        assert_true(st.res_rel > 1e-8 && isfinite(st.res_rel));
        assert_non_null(strstr(sim_error_message(), "5 iterations"));
        assert_non_null(strstr(sim_error_message(), "relative residual"));
        /* x is the last iterate: its residual is the one reported. */
        double r = tu_resnorm(&s2.A, s2.b, x) / tu_norm(n, s2.b);
        assert_float_equal(r, st.res_rel, 1e-12);
        free(x);
        linsolve_free(ls);
    }
}

/* A tolerance below rounding level: an error after bounded work, no hang. */
static void test_unreachable_tolerance_is_an_error(void **state)
{
    (void)state;
    const char *combos[][2] = {{"pcg", "jacobi"}, {"bicgstab", "ilu0"}};
    for (int k = 0; k < 2; k++) {
        struct linsolve *ls = make(combos[k][0], combos[k][1], 1e-19, 400);
        struct linsolve_stats st;
        double *x = calloc((size_t)s2.A.n, sizeof *x);
        assert_int_equal(linsolve_solve(ls, &s2.A, s2.b, x, &st),
                         SIM_ERR_SOLVER);
        assert_true(st.iters <= 400);
        assert_false(st.converged);
        /* The last iterate is still a good answer. */
        assert_true(st.res_rel < 1e-12);
        free(x);
        linsolve_free(ls);
    }
}

/* Dense LU with partial pivoting: the oracle for the non-symmetric case
 * (independent of every sparse code; its own residual is checked). */
static void dense_lu_solve(const struct csr_matrix *A, const double *b,
                           double *x)
{
    int n = A->n;
    double *M = calloc((size_t)n * n, sizeof *M);
    for (int i = 0; i < n; i++)
        for (int64_t k = A->rowptr[i]; k < A->rowptr[i + 1]; k++)
            M[(size_t)i * n + A->col[k]] += A->val[k];
    memcpy(x, b, (size_t)n * sizeof *x);
    for (int c = 0; c < n; c++) {
        int p = c;
        for (int i = c + 1; i < n; i++)
            if (fabs(M[(size_t)i * n + c]) > fabs(M[(size_t)p * n + c]))
                p = i;
        if (p != c) {
            for (int j = 0; j < n; j++) {
                double t = M[(size_t)c * n + j];
                M[(size_t)c * n + j] = M[(size_t)p * n + j];
                M[(size_t)p * n + j] = t;
            }
            double t = x[c];
            x[c] = x[p];
            x[p] = t;
        }
        double piv = M[(size_t)c * n + c];
        for (int i = c + 1; i < n; i++) {
            double f = M[(size_t)i * n + c] / piv;
            if (f == 0.0)
                continue;
            for (int j = c + 1; j < n; j++)
                M[(size_t)i * n + j] -= f * M[(size_t)c * n + j];
            x[i] -= f * x[c];
        }
    }
    for (int i = n - 1; i >= 0; i--) {
        double s = x[i];
        for (int j = i + 1; j < n; j++)
            s -= M[(size_t)i * n + j] * x[j];
        x[i] = s / M[(size_t)i * n + i];
    }
    free(M);
}

/* BiCGSTAB and GMRES(20) on the non-symmetric porous lattice against a
 * dense LU. Without a preconditioner GMRES needs several restarts of its
 * 20-vector basis (900 rows of a 2-D Laplacian), so the restart is
 * exercised too. */
static void test_nonsymmetric_vs_dense_lu(void **state)
{
    (void)state;
    struct sys p;
    tu_lattice(&p, 2, 30, 2.1, 1);
    int n = p.A.n;
    assert_false(csr_is_symmetric(&p.A, 1e-12, NULL));
    double *xd = malloc((size_t)n * sizeof *xd);
    dense_lu_solve(&p.A, p.b, xd);
    double bn = tu_norm(n, p.b);
    assert_true(tu_resnorm(&p.A, p.b, xd) <= 1e-12 * bn);
    /* A^-1 bound for the forward error: diagonal dominance gives
     * ||A^-1||_inf <= 1/min_i(a_ii - sum_j |a_ij|) only for strict rows, so
     * use the dense solution itself: e <= cond * r, with cond measured by
     * ||x_d|| / ||b|| * ||A||_1 as a practical scale. */
    const char *solvers[] = {"bicgstab", "gmres"};
    const char *pcs[] = {"none", "jacobi", "ilu0"};
    for (int v = 0; v < 2; v++) {
        int it[3];
        for (int k = 0; k < 3; k++) {
            struct linsolve *ls = make(solvers[v], pcs[k], 1e-10, 2000);
            struct linsolve_stats st;
            double *x = calloc((size_t)n, sizeof *x);
            int rc = linsolve_solve(ls, &p.A, p.b, x, &st);
            if (rc)
                print_error("%s\n", sim_error_message());
            assert_int_equal(rc, SIM_OK);
            assert_true(tu_resnorm(&p.A, p.b, x) <= 1e-10 * bn);
            double e = 0.0;
            for (int i = 0; i < n; i++)
                e = fmax(e, fabs(x[i] - xd[i]));
            double xs = 0.0;
            for (int i = 0; i < n; i++)
                xs = fmax(xs, fabs(xd[i]));
            /* tol 1e-10 times a condition number of the order of n (a 2-D
             * Laplacian, 900 rows): the error must be below 1e-6
             * relative. */
            assert_true(e <= 1e-6 * xs);
            it[k] = st.iters;
            print_message("%s-%s: %d iterations\n", solvers[v], pcs[k],
                          st.iters);
            free(x);
            linsolve_free(ls);
        }
        assert_true(it[2] < it[1]); /* ILU(0) does better than Jacobi */
        if (v == 1)
            assert_true(it[0] > 20); /* restarted */
    }
    /* running out of iterations is an error that says so */
    struct linsolve *ls = make("gmres", "none", 1e-10, 5);
    double *x = calloc((size_t)n, sizeof *x);
    assert_int_equal(linsolve_solve(ls, &p.A, p.b, x, NULL), SIM_ERR_SOLVER);
    assert_non_null(strstr(sim_error_message(), "gmres (none) did not "
                                                "converge: 5 iterations"));
    free(x);
    linsolve_free(ls);
    free(xd);
    tu_free(&p);
}

/* Aggregation AMG (precond_amg.c). On a 3-D lattice of 8000 rows at r_e
 * 3.1 (three levels: 8000 -> ~1000 -> ~125 rows, dense LU) PCG-AMG meets
 * CHOLMOD's answer within the forward-error bound in at most a quarter of
 * Jacobi-PCG's iterations (11 against 59 here; 12 against 114 at 64,000
 * rows in ppeBench). */
static void test_amg_pcg_matches_cholmod(void **state)
{
    (void)state;
    struct sys m;
    tu_lattice(&m, 3, 20, 3.1, 0);
    tu_reference(&m);
    int ij = solve_check(&m, "pcg", "jacobi");
    int ia = solve_check(&m, "pcg", "amg");
    print_message("pcg: jacobi %d, amg %d iterations\n", ij, ia);
    assert_true(4 * ia <= ij);
    /* 2-D as well (one level: 1600 rows -> ~200, dense LU) */
    int ij2 = solve_check(&s2, "pcg", "jacobi");
    int ia2 = solve_check(&s2, "pcg", "amg");
    print_message("pcg 2-D: jacobi %d, amg %d iterations\n", ij2, ia2);
    assert_true(4 * ia2 <= ij2);
    tu_free(&m);
}

/* BiCGSTAB-AMG and GMRES-AMG (no pre-smoothing) on the non-symmetric porous
 * lattice (1/eps_j weights): the same answer as BiCGSTAB-Jacobi to the
 * tolerance's error scale, BiCGSTAB in at most a quarter of its
 * iterations, GMRES in no more products than BiCGSTAB-AMG. */
static void test_amg_bicgstab_nonsymmetric(void **state)
{
    (void)state;
    struct sys p;
    tu_lattice(&p, 3, 20, 3.1, 1);
    int n = p.A.n;
    assert_false(csr_is_symmetric(&p.A, 1e-12, NULL));
    double bn = tu_norm(n, p.b);
    double *x[3];
    int it[3];
    const char *sv[] = {"bicgstab", "bicgstab", "gmres"};
    const char *pcs[] = {"jacobi", "amg", "amg"};
    for (int k = 0; k < 3; k++) {
        struct linsolve *ls = make(sv[k], pcs[k], 1e-10, 2000);
        struct linsolve_stats st;
        x[k] = calloc((size_t)n, sizeof *x[k]);
        assert_int_equal(linsolve_solve(ls, &p.A, p.b, x[k], &st), SIM_OK);
        assert_true(tu_resnorm(&p.A, p.b, x[k]) <= 1e-10 * bn);
        it[k] = st.iters;
        linsolve_free(ls);
    }
    double e = 0.0, xs = 0.0;
    for (int i = 0; i < n; i++) {
        e = fmax(e, fmax(fabs(x[0][i] - x[1][i]), fabs(x[0][i] - x[2][i])));
        xs = fmax(xs, fabs(x[0][i]));
    }
    assert_true(e <= 1e-6 * xs); /* as test_nonsymmetric_vs_dense_lu */
    print_message("bicgstab: jacobi %d, amg %d; gmres-amg %d iterations\n",
                  it[0], it[1], it[2]);
    assert_true(4 * it[1] <= it[0]);
    /* a GMRES iteration is one product, a BiCGSTAB iteration two */
    assert_true(it[2] <= 2 * it[1]);
    for (int k = 0; k < 3; k++)
        free(x[k]);
    tu_free(&p);
}

/* z = M^-1 r of a linsolve's preconditioner, set up for A. */
static void pc_apply(struct linsolve *ls, const struct csr_matrix *A,
                     const double *r, double *z)
{
    double *d = malloc((size_t)A->n * sizeof *d);
    assert_int_equal(csr_validate(A, d), SIM_OK);
    assert_int_equal(ls->pc.ops->setup(&ls->pc, A, d), SIM_OK);
    ls->pc.ops->apply(&ls->pc, r, z);
    free(d);
}

/* What PCG needs of M: for PCG the cycle smooths before and after,
 * symmetric and positive definite ((M^-1 u, v) = (u, M^-1 v) to
 * round-off, (M^-1 u, u) > 0); BiCGSTAB's cycle without pre-smoothing is a
 * different, non-symmetric operator. A system
 * below the coarsest size is solved exactly by the dense LU: PCG converges
 * in one iteration. */
static void test_amg_operator(void **state)
{
    (void)state;
    struct sys m;
    tu_lattice(&m, 3, 20, 3.1, 0);
    int n = m.A.n;
    double *u = malloc((size_t)n * sizeof *u), *v = malloc((size_t)n * sizeof *v);
    double *mu = malloc((size_t)n * sizeof *mu), *mv = malloc((size_t)n * sizeof *mv);
    for (int i = 0; i < n; i++) {
        u[i] = sin(0.91 * i) + 0.3;
        v[i] = cos(1.37 * i);
    }
    struct linsolve *sym = make("pcg", "amg", 1e-8, 100);
    struct linsolve *non = make("bicgstab", "amg", 1e-8, 100);
    pc_apply(sym, &m.A, u, mu);
    pc_apply(sym, &m.A, v, mv);
    double a = vec_dot(n, mu, v), b = vec_dot(n, u, mv);
    assert_true(fabs(a - b) <= 1e-12 * (fabs(a) + fabs(b)));
    assert_true(vec_dot(n, mu, u) > 0.0 && vec_dot(n, mv, v) > 0.0);
    pc_apply(non, &m.A, u, mu);
    pc_apply(non, &m.A, v, mv);
    a = vec_dot(n, mu, v);
    b = vec_dot(n, u, mv);
    assert_true(fabs(a - b) > 1e-6 * (fabs(a) + fabs(b)));
    linsolve_free(sym);
    linsolve_free(non);
    free(u);
    free(v);
    free(mu);
    free(mv);
    tu_free(&m);

    tu_lattice(&m, 2, 15, 2.1, 0); /* 225 rows: coarsest level at once */
    tu_reference(&m);
    assert_int_equal(solve_check(&m, "pcg", "amg"), 1);
    tu_free(&m);
}

/* Kershaw (1978, J. Comput. Phys. 26:43) SPD matrix on which IC(0) breaks
 * down (l_44^2 = 3 - 4/3 - 4/0.6 < 0). */
static void kershaw(struct csr_matrix *A)
{
    static const double K[4][4] = {
        {3, -2, 0, 2}, {-2, 3, -2, 0}, {0, -2, 3, -2}, {2, 0, -2, 3}};
    assert_int_equal(csr_alloc(A, 4, 12), SIM_OK);
    int64_t k = 0;
    for (int i = 0; i < 4; i++) {
        A->rowptr[i] = k;
        for (int j = 3; j >= 0; j--) /* unsorted on purpose */
            if (K[i][j] != 0.0) {
                A->col[k] = j;
                A->val[k++] = K[i][j];
            }
    }
    A->rowptr[4] = k;
}

static void test_ic0_breakdown_falls_back_to_shift(void **state)
{
    (void)state;
    struct csr_matrix A;
    kershaw(&A);
    double b[4] = {1, 2, 3, 4}, xc[4], x[4] = {0};
    tu_cholmod(&A, b, xc); /* succeeds: the matrix is SPD */
    const char *pcs[] = {"ic0", "dic"};
    for (int k = 0; k < 2; k++) {
        struct linsolve *ls = make("pcg", pcs[k], 1e-12, 100);
        struct linsolve_stats st;
        memset(x, 0, sizeof x);
        long w0 = log_warning_count();
        int rc = linsolve_solve(ls, &A, b, x, &st);
        if (rc)
            print_error("%s\n", sim_error_message());
        assert_int_equal(rc, SIM_OK);
        if (k == 0) { /* IC(0) must have broken down and said so */
            assert_true(ls->pc.shift > 0.0);
            assert_true(log_warning_count() > w0);
        }
        for (int i = 0; i < 4; i++)
            assert_float_equal(x[i], xc[i], 1e-9 * fabs(xc[i]) + 1e-10);
        linsolve_free(ls);
    }
    csr_free(&A);
}

static void test_unsorted_columns_same_answer(void **state)
{
    (void)state;
    struct csr_matrix B;
    assert_int_equal(csr_alloc(&B, s2.A.n, s2.A.nnz), SIM_OK);
    memcpy(B.rowptr, s2.A.rowptr, ((size_t)B.n + 1) * sizeof *B.rowptr);
    for (int i = 0; i < B.n; i++) { /* reverse each row */
        int64_t a = s2.A.rowptr[i], e = s2.A.rowptr[i + 1];
        for (int64_t k = a; k < e; k++) {
            B.col[k] = s2.A.col[a + e - 1 - k];
            B.val[k] = s2.A.val[a + e - 1 - k];
        }
    }
    const char *pcs[] = {"ic0", "dic"};
    for (int k = 0; k < 2; k++) {
        struct linsolve *ls = make("pcg", pcs[k], 1e-8, 1000);
        struct linsolve_stats sa, sb;
        double *xa = calloc((size_t)B.n, sizeof *xa);
        double *xb = calloc((size_t)B.n, sizeof *xb);
        assert_int_equal(linsolve_solve(ls, &s2.A, s2.b, xa, &sa), SIM_OK);
        assert_int_equal(linsolve_solve(ls, &B, s2.b, xb, &sb), SIM_OK);
        assert_true(abs(sa.iters - sb.iters) <= 1);
        tu_assert_matches_reference(&s2, xb, 1e-8);
        free(xa);
        free(xb);
        linsolve_free(ls);
    }
    csr_free(&B);
}

static void test_zero_rhs_gives_zero(void **state)
{
    (void)state;
    struct linsolve *ls = make("pcg", "jacobi", 1e-8, 10);
    int n = s2.A.n;
    double *b = calloc((size_t)n, sizeof *b), *x = malloc((size_t)n * sizeof *x);
    for (int i = 0; i < n; i++)
        x[i] = 1.0;
    struct linsolve_stats st;
    assert_int_equal(linsolve_solve(ls, &s2.A, b, x, &st), SIM_OK);
    assert_int_equal(st.iters, 0);
    assert_true(st.converged);
    for (int i = 0; i < n; i++)
        assert_true(x[i] == 0.0);
    free(b);
    free(x);
    linsolve_free(ls);
}

static void test_storage_reused_across_solves(void **state)
{
    (void)state;
    struct linsolve *ls = make("pcg", "ic0", 1e-8, 1000);
    int n = s2.A.n;
    double *x = calloc((size_t)n, sizeof *x);
    struct linsolve_stats st;
    assert_int_equal(linsolve_solve(ls, &s2.A, s2.b, x, &st), SIM_OK);
    void *w0 = ls->work[0], *f0 = ls->pc.fv, *d0 = ls->diag;
    memset(x, 0, (size_t)n * sizeof *x);
    assert_int_equal(linsolve_solve(ls, &s2.A, s2.b, x, &st), SIM_OK);
    assert_ptr_equal(ls->work[0], w0);
    assert_ptr_equal(ls->pc.fv, f0);
    assert_ptr_equal(ls->diag, d0);
    free(x);
    linsolve_free(ls);
}

/* One bad system: build a copy of a 3x3 SPD matrix, spoil it, expect code. */
static void expect_bad(const char *what, int code, struct csr_matrix *A,
                       const double *b)
{
    const char *solvers[][2] = {{"pcg", "jacobi"}, {"pcg", "ic0"},
                                {"bicgstab", "ilu0"}, {"cholmod", "none"}};
    for (int k = 0; k < 4; k++) {
        struct linsolve *ls = make(solvers[k][0], solvers[k][1], 1e-8, 100);
        double x[3] = {0, 0, 0};
        struct linsolve_stats st;
        int rc = linsolve_solve(ls, A, b, x, &st);
        if (rc != code)
            print_error("%s with %s: got %d (%s)\n", what, solvers[k][0], rc,
                        sim_error_message());
        assert_int_equal(rc, code);
        assert_true(strlen(sim_error_message()) > 10);
        linsolve_free(ls);
    }
}

static void test_bad_systems_are_rejected(void **state)
{
    (void)state;
    int64_t rp[4] = {0, 2, 5, 7};
    int32_t col[7] = {0, 1, 0, 1, 2, 1, 2};
    double val[7] = {2, -1, -1, 2, -1, -1, 2};
    double b[3] = {1, 1, 1};
    struct csr_matrix A = {3, 7, rp, col, val};
    struct csr_matrix E = {0, 0, rp, col, val};
    expect_bad("n = 0", SIM_ERR_INPUT, &E, b);
    val[3] = 0.0;
    expect_bad("zero diagonal", SIM_ERR_INPUT, &A, b);
    val[3] = -2.0;
    expect_bad("negative diagonal", SIM_ERR_INPUT, &A, b);
    val[3] = NAN;
    expect_bad("NaN diagonal", SIM_ERR_NUMERIC, &A, b);
    val[3] = 2.0;
    val[1] = INFINITY;
    expect_bad("infinite entry", SIM_ERR_NUMERIC, &A, b);
    val[1] = -1.0;
    b[2] = NAN;
    expect_bad("NaN in b", SIM_ERR_NUMERIC, &A, b);
    b[2] = 1.0;
    col[4] = 3;
    expect_bad("column out of range", SIM_ERR_INPUT, &A, b);
    col[4] = 0; /* row 1 now has no diagonal: (1,0) twice */
    col[3] = 2;
    expect_bad("missing diagonal", SIM_ERR_INPUT, &A, b);
    col[3] = 1;
    col[4] = 2;
    rp[2] = 1;
    expect_bad("decreasing rowptr", SIM_ERR_INPUT, &A, b);
    rp[2] = 5;
    rp[3] = 6;
    expect_bad("rowptr[n] != nnz", SIM_ERR_INPUT, &A, b);
    rp[3] = 7;
    /* The repaired matrix is fine again: the checks are not over-eager. */
    double x[3] = {0};
    struct linsolve *ls = make("pcg", "ic0", 1e-12, 10);
    assert_int_equal(linsolve_solve(ls, &A, b, x, NULL), SIM_OK);
    assert_float_equal(x[0], 1.5, 1e-10);
    assert_float_equal(x[1], 2.0, 1e-10);
    linsolve_free(ls);
}

static void test_cholmod_refuses_bad_matrices(void **state)
{
    (void)state;
    struct sys p;
    tu_lattice(&p, 2, 12, 2.1, 1);
    struct linsolve *ls = make("cholmod", "none", 1e-8, 1);
    double *x = calloc((size_t)p.A.n, sizeof *x);
    assert_int_equal(linsolve_solve(ls, &p.A, p.b, x, NULL), SIM_ERR_INPUT);
    assert_non_null(strstr(sim_error_message(), "not symmetric"));
    free(x);
    tu_free(&p);
    /* Symmetric, positive diagonal, indefinite: [[1 2][2 1]]. */
    int64_t rp[3] = {0, 2, 4};
    int32_t col[4] = {0, 1, 0, 1};
    double val[4] = {1, 2, 2, 1}, b[2] = {1, 0}, y[2] = {0, 0};
    struct csr_matrix A = {2, 4, rp, col, val};
    assert_int_equal(linsolve_solve(ls, &A, b, y, NULL), SIM_ERR_SOLVER);
    assert_non_null(strstr(sim_error_message(), "positive definite"));
    linsolve_free(ls);
    /* PCG detects the indefinite matrix instead of returning garbage. */
    ls = make("pcg", "none", 1e-8, 100);
    y[0] = y[1] = 0.0;
    b[1] = 0.3;
    int rc = linsolve_solve(ls, &A, b, y, NULL);
    assert_true(rc == SIM_ERR_SOLVER);
    linsolve_free(ls);
}

static void test_bad_names_and_combinations(void **state)
{
    (void)state;
    struct linsolve *ls = NULL;
    assert_int_equal(linsolve_create_named("gmre", "jacobi", 1e-8, 10, &ls),
                     SIM_ERR_INPUT);
    assert_non_null(strstr(sim_error_message(), "pcg bicgstab gmres cholmod"));
    assert_non_null(strstr(sim_error_message(), "did you mean 'gmres'"));
    assert_int_equal(linsolve_create_named("gmres", "dic", 1e-8, 10, &ls),
                     SIM_ERR_INPUT);
    assert_int_equal(linsolve_create_named("pcg", "ilu", 1e-8, 10, &ls),
                     SIM_ERR_INPUT);
    assert_non_null(strstr(sim_error_message(), "ic0 dic"));
    assert_int_equal(linsolve_create_named("pcg", "ilu0", 1e-8, 10, &ls),
                     SIM_ERR_INPUT);
    assert_int_equal(linsolve_create_named("bicgstab", "ic0", 1e-8, 10, &ls),
                     SIM_ERR_INPUT);
    assert_int_equal(linsolve_create_named("pcg", "jacobi", 0.0, 10, &ls),
                     SIM_ERR_INPUT);
    assert_int_equal(linsolve_create_named("pcg", "jacobi", 1e-8, 0, &ls),
                     SIM_ERR_INPUT);
#ifndef MPSDEM_HAVE_HYPRE
    assert_int_equal(linsolve_create_named("hypre", "none", 1e-8, 10, &ls),
                     SIM_ERR_INPUT);
    assert_non_null(strstr(sim_error_message(), "make HYPRE=1"));
#endif
    assert_null(ls);
}

static void test_sunlinearsolver_adapter(void **state)
{
    (void)state;
    SUNContext ctx;
    assert_int_equal(SUNContext_Create(NULL, &ctx), 0);
    struct linsolve *ls = make("pcg", "jacobi", 1e-8, 1000);
    SUNLinearSolver S = SUNLinSol_PPE(ls, ctx);
    assert_non_null(S);
    assert_int_equal(SUNLinSolGetID(S), SUNLINEARSOLVER_CUSTOM);
    assert_int_equal(SUNLinSolGetType(S), SUNLINEARSOLVER_MATRIX_EMBEDDED);
    int n = s3.A.n;
    N_Vector x = N_VNew_Serial(n, ctx), b = N_VNew_Serial(n, ctx);
    memcpy(N_VGetArrayPointer(b), s3.b, (size_t)n * sizeof(double));
    N_VConst(1e6, x); /* garbage guess, then zero guess requested */
    assert_int_equal(SUNLinSol_PPESetMatrix(S, &s3.A), SUNLS_SUCCESS);
    assert_int_equal(SUNLinSolInitialize(S), SUNLS_SUCCESS);
    assert_int_equal(SUNLinSolSetup(S, NULL), SUNLS_SUCCESS);
    assert_int_equal(SUNLinSolSetZeroGuess(S, SUNTRUE), SUNLS_SUCCESS);
    double bn = tu_norm(n, s3.b);
    assert_int_equal(SUNLinSolSolve(S, NULL, x, b, 1e-9 * bn), SUNLS_SUCCESS);
    tu_assert_matches_reference(&s3, N_VGetArrayPointer(x), 1e-9);
    /* Same iterations as the facade from zero with the same tolerance. */
    struct linsolve *l2 = make("pcg", "jacobi", 1e-9, 1000);
    struct linsolve_stats st;
    double *y = calloc((size_t)n, sizeof *y);
    assert_int_equal(linsolve_solve(l2, &s3.A, s3.b, y, &st), SIM_OK);
    assert_int_equal(SUNLinSolNumIters(S), st.iters);
    double rn = SUNLinSolResNorm(S);
    assert_true(rn > 0.0 && rn <= 1e-9 * bn);
    assert_int_equal(SUNLinSolLastFlag(S), SIM_OK);
    /* Warm start (no zero guess): from the answer, at most one iteration. */
    assert_int_equal(SUNLinSolSolve(S, NULL, x, b, 1e-9 * bn), SUNLS_SUCCESS);
    assert_in_range(SUNLinSolNumIters(S), 0, 1);
    /* Not converging is recoverable, as in SUNDIALS' own solvers. */
    ls->maxiter = 2;
    N_VConst(0.0, x);
    assert_int_equal(SUNLinSolSolve(S, NULL, x, b, 1e-9 * bn), SUNLS_CONV_FAIL);
    assert_int_equal(SUNLinSolLastFlag(S), SIM_ERR_SOLVER);
    free(y);
    linsolve_free(l2);
    N_VDestroy(x);
    N_VDestroy(b);
    SUNLinSolFree(S);
    linsolve_free(ls);
    SUNContext_Free(&ctx);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pcg_jacobi_matches_cholmod),
        cmocka_unit_test(test_ic0_fewer_iterations_than_jacobi),
        cmocka_unit_test(test_fused_path_equals_generic),
        cmocka_unit_test(test_threads_match_one_thread),
        cmocka_unit_test(test_warm_start_from_exact_solution),
        cmocka_unit_test(test_warm_start_off_ignores_guess),
        cmocka_unit_test(test_nonconvergence_is_an_error),
        cmocka_unit_test(test_unreachable_tolerance_is_an_error),
        cmocka_unit_test(test_nonsymmetric_vs_dense_lu),
        cmocka_unit_test(test_amg_pcg_matches_cholmod),
        cmocka_unit_test(test_amg_bicgstab_nonsymmetric),
        cmocka_unit_test(test_amg_operator),
        cmocka_unit_test(test_ic0_breakdown_falls_back_to_shift),
        cmocka_unit_test(test_unsorted_columns_same_answer),
        cmocka_unit_test(test_zero_rhs_gives_zero),
        cmocka_unit_test(test_storage_reused_across_solves),
        cmocka_unit_test(test_bad_systems_are_rejected),
        cmocka_unit_test(test_cholmod_refuses_bad_matrices),
        cmocka_unit_test(test_bad_names_and_combinations),
        cmocka_unit_test(test_sunlinearsolver_adapter),
    };
    return cmocka_run_group_tests(tests, setup_all, teardown_all);
}
