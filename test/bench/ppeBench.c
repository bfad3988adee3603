/*
 * ppeBench.c — the PPE benchmark of doc/libraries.md §2 on our own solvers:
 * jittered-lattice MPS Laplacians (csr_lattice_ppe), step 1 from zero, then
 * "step 2": particles moved by U(+-0.02), new matrix and right-hand side,
 * warm start from the step-1 pressure (the time-loop situation).
 *
 * Prints, per case and solver: iterations (step 1 / step 2), set-up and
 * solve wall time (minimum over --reps repetitions of step 1), the process
 * CPU time of set-up + solve divided by the thread count (cpu_s: robust
 * against other jobs with 1 thread; with more threads it includes
 * OpenMP spin-waiting), time per
 * iteration per row, and for Jacobi/none-PCG the achieved memory bandwidth
 * against a STREAM triad measured in the same run. Bytes per PCG iteration
 * (STREAM counting, no write-allocate): 12 nnz + 8 n x 13 streams (rowptr;
 * SpMV p, q; residual r r/w, q, dinv; direction x r/w, p r/w, r, dinv).
 *
 *   ppeBench [--quick] [--cholmod] [--reps N] [--only SOLVER:PRECOND]
 *            [--case DIM:NSIDE:RE[:porous] ...]
 */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/app.h"
#include "core/error.h"
#include "core/log.h"
#include "linsolve/csr.h"
#include "linsolve/linsolve.h"
#include "linsolve/linsolve_impl.h"

#define VEC_STREAMS 13

struct bcase { int dim, nside; double re; int porous; };

/* Best-of-5 STREAM triad a = b + s c, bytes counted as 24 per element. */
static double stream_triad_gbs(void)
{
    size_t n = (size_t)1 << 24; /* 3 x 128 MiB: far beyond any cache */
    double *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b),
           *c = malloc(n * sizeof *c);
    if (!a || !b || !c)
        return 0.0;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; i++) {
        a[i] = 0.0;
        b[i] = 1.0;
        c[i] = 2.0;
    }
    double best = 1e30;
    for (int rep = 0; rep < 5; rep++) {
        double t = app_wall_time();
#pragma omp parallel for schedule(static)
        for (size_t i = 0; i < n; i++)
            a[i] = b[i] + 3.0 * c[i];
        t = app_wall_time() - t;
        if (t < best)
            best = t;
    }
    double check = a[n / 2];
    free(a);
    free(b);
    free(c);
    return check == 7.0 ? 24.0 * (double)n / best * 1e-9 : 0.0;
}

static double cpu_time(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int build(const struct bcase *c, double move, struct csr_matrix *A,
                 double **b, double *secs)
{
    struct csr_lattice L = {.dim = c->dim, .nside = c->nside, .re = c->re,
                            .jitter = 0.1, .move = move, .seed = 2024,
                            .move_seed = 99, .rhs_seed = move > 0 ? 2 : 1,
                            .porous = c->porous};
    double t = app_wall_time();
    int rc = csr_lattice_ppe(&L, A, b);
    *secs = app_wall_time() - t;
    return rc;
}

static void run_solver(const char *solver, const char *pc,
                       const struct csr_matrix *A1, const double *b1,
                       const struct csr_matrix *A2, const double *b2,
                       int reps, double stream)
{
    struct linsolve *ls;
    if (linsolve_create_named(solver, pc, 1e-8, 100000, &ls)) {
        printf("  %-9s %-7s  %s\n", solver, pc, sim_error_message());
        return;
    }
    int n = A1->n;
    double *x = calloc((size_t)n, sizeof *x);
    struct linsolve_stats st, best = {0}, s2 = {0};
    best.solve_s = 1e30;
    int rc = 0;
    double cpu = 1e30; /* process CPU s per thread of the best solve */
    for (int r = 0; r < reps && !rc; r++) {
        memset(x, 0, (size_t)n * sizeof *x);
        double c0 = cpu_time();
        rc = linsolve_solve(ls, A1, b1, x, &st);
        double c = (cpu_time() - c0) / omp_get_max_threads();
        if (c < cpu)
            cpu = c;
        if (st.solve_s + st.setup_s < best.solve_s + best.setup_s)
            best = st;
    }
    if (!rc)
        rc = linsolve_solve(ls, A2, b2, x, &s2); /* warm from step 1 */
    if (rc) {
        printf("  %-9s %-7s  FAILED: %s\n", solver, pc, sim_error_message());
    } else {
        double per = best.iters ? best.solve_s / best.iters : 0.0;
        printf("  %-9s %-7s %6d %6d %9.4f %9.4f %9.4f %9.4f %8.2f", solver,
               pc, best.iters, s2.iters, best.setup_s, best.solve_s,
               best.setup_s + best.solve_s, cpu, per / n * 1e9);
        int bw = !strcmp(solver, "pcg") &&
                 (!strcmp(pc, "jacobi") || !strcmp(pc, "none"));
        if (bw && per > 0.0) {
            double bytes = 12.0 * (double)A1->nnz + 8.0 * n * VEC_STREAMS;
            double gbs = bytes / per * 1e-9;
            printf(" %7.1f %6.0f%%", gbs, 100.0 * gbs / stream);
        }
        printf("   res %.1e / %.1e\n", best.res_rel, s2.res_rel);
    }
    fflush(stdout);
    free(x);
    linsolve_free(ls);
}

static const char *only; /* --only SOLVER:PRECOND, or NULL for all */

static int wanted(const char *solver, const char *pc)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%s:%s", solver, pc);
    return !only || !strcmp(only, buf);
}

static void run_case(const struct bcase *c, int reps, int cholmod,
                     double stream)
{
    struct csr_matrix A1, A2;
    double *b1, *b2, t1, t2;
    if (build(c, 0.0, &A1, &b1, &t1) || build(c, 0.02, &A2, &b2, &t2)) {
        fprintf(stderr, "ppeBench: %s\n", sim_error_message());
        exit(1);
    }
    printf("\n%dD %d^%d = %d rows, re %.1f%s: %.1f nnz/row, build %.3f s\n",
           c->dim, c->nside, c->dim, A1.n, c->re,
           c->porous ? ", porous (1/eps_j weights)" : "",
           (double)A1.nnz / A1.n, t1);
    printf("  %-9s %-7s %6s %6s %9s %9s %9s %9s %8s %7s %7s\n", "solver",
           "precond", "it1", "it2", "setup_s", "solve_s", "total_s", "cpu_s",
           "ns/row/it", "GB/s", "%STREAM");
    static const char *combos[][2] = {{"pcg", "jacobi"}, {"pcg", "dic"},
                                      {"pcg", "ic0"}, {"bicgstab", "jacobi"},
                                      {"pcg", "amg"}, {"bicgstab", "ilu0"},
                                      {"bicgstab", "amg"}, {"gmres", "ilu0"},
                                      {"gmres", "amg"}, {"hypre", "none"}};
    for (size_t k = 0; k < sizeof combos / sizeof combos[0]; k++)
        if (wanted(combos[k][0], combos[k][1]))
            run_solver(combos[k][0], combos[k][1], &A1, b1, &A2, b2, reps,
                       stream);
    if (cholmod)
        run_solver("cholmod", "none", &A1, b1, &A2, b2, 1, stream);
    csr_free(&A1);
    csr_free(&A2);
    free(b1);
    free(b2);
}

int main(int argc, char **argv)
{
    struct bcase cases[16];
    int nc = 0, reps = 3, cholmod = 0, quick = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--quick"))
            quick = 1;
        else if (!strcmp(argv[i], "--cholmod"))
            cholmod = 1;
        else if (!strcmp(argv[i], "--only") && i + 1 < argc)
            only = argv[++i];
        else if (!strcmp(argv[i], "--reps") && i + 1 < argc)
            reps = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--case") && i + 1 < argc && nc < 16) {
            struct bcase *c = &cases[nc];
            char tail[16] = "";
            int k = sscanf(argv[++i], "%d:%d:%lf:%15s", &c->dim, &c->nside,
                           &c->re, tail);
            c->porous = k == 4 && !strcmp(tail, "porous");
            if (k < 3 || (k == 4 && !c->porous)) {
                fprintf(stderr, "ppeBench: --case DIM:NSIDE:RE[:porous], e.g. "
                                "3:40:2.1 or 3:40:3.1:porous\n");
                return 2;
            }
            nc++;
        } else {
            fprintf(stderr, "usage: ppeBench [--quick] [--cholmod] [--reps N] "
                            "[--only SOLVER:PRECOND] "
                            "[--case DIM:NSIDE:RE[:porous] ...]\n");
            return 2;
        }
    }
    if (nc == 0) {
        const struct bcase all[] = {{2, 300, 2.1, 0}, {2, 300, 3.1, 0},
                                    {3, 40, 2.1, 0},  {3, 40, 3.1, 0},
                                    {3, 60, 2.1, 0},  {3, 60, 3.1, 0}};
        const struct bcase small[] = {{2, 100, 2.1, 0}, {3, 20, 2.1, 0}};
        const struct bcase *src = quick ? small : all;
        nc = quick ? 2 : 6;
        memcpy(cases, src, (size_t)nc * sizeof *cases);
    }
    log_set_quiet(1);
    double stream = stream_triad_gbs();
    printf("ppeBench: %d OpenMP threads; STREAM triad %.1f GB/s (best of 5, "
           "3 x 128 MiB); tolerance 1e-8 on ||b-Ax||/||b||; times are wall "
           "clock, min of %d step-1 solves; it2 = step 2 (moved particles, "
           "warm start)\n", omp_get_max_threads(), stream, reps);
    for (int i = 0; i < nc; i++)
        run_case(&cases[i], reps, cholmod, stream);
    return 0;
}
