/*
 * linsolve_dist.c — the pressure equation of a distributed run (issue 22,
 * doc/design.md §8): each rank holds the rows of its own unknowns with
 * global column numbers; hypre's IJ interface (Falgout and Yang 2002,
 * "hypre: a library of high performance preconditioners", ICCS 2002,
 * LNCS 2331:632-641) builds the ParCSR matrix and solves it.
 *
 * The case's PPE dictionary keeps its meaning: solver pcg, bicgstab or
 * gmres run hypre's PCG, BiCGSTAB or GMRES(20); preconditioner none and
 * jacobi are hypre's none and diagonal scaling; amg, and the serial
 * factorisations ic0, dic and ilu0, which have no distributed form here,
 * are BoomerAMG with the settings of solver_hypre.c; solver hypre is PCG
 * with BoomerAMG, and cholmod (one process only) becomes the same. The
 * tolerance is relative to the global ||b||_2, and the true residual of
 * the answer is checked as in one process (linsolve.c).
 *
 * Only in MPI builds (`make MPI=1`).
 */
#ifdef MPSDEM_HAVE_MPI

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
#include <mpi.h>

#include "core/app.h"
#include "core/error.h"
#include "core/log.h"
#include "linsolve/linsolve_impl.h"

enum { K_PCG, K_BICGSTAB, K_GMRES };
enum { P_NONE, P_JACOBI, P_AMG };

static void choose(const struct linsolve *s, int *krylov, int *pc)
{
    const char *sv = s->solver->name, *p = s->pc.ops->name;
    *krylov = !strcmp(sv, "bicgstab") ? K_BICGSTAB
            : !strcmp(sv, "gmres") ? K_GMRES : K_PCG;
    *pc = !strcmp(sv, "hypre") || !strcmp(sv, "cholmod") ? P_AMG
        : !strcmp(p, "none") ? P_NONE : !strcmp(p, "jacobi") ? P_JACOBI
        : P_AMG;
    static int said;
    if (!said) {
        said = 1;
        log_info("Distributed PPE: hypre %s with %s (the case's %s with %s)",
                 *krylov == K_PCG ? "PCG" : *krylov == K_BICGSTAB
                 ? "BiCGSTAB" : "GMRES(20)", *pc == P_NONE ? "no "
                 "preconditioner" : *pc == P_JACOBI ? "diagonal scaling"
                 : "BoomerAMG", sv, s->solver->iterative ? p : "its own");
    }
}

/* Krylov solver k with preconditioner p on (a, b, x); iterations in *its. */
static int krylov_solve(MPI_Comm comm, int k, int p, const struct linsolve *s,
                        double tol, HYPRE_ParCSRMatrix a, HYPRE_ParVector b,
                        HYPRE_ParVector x, int *its)
{
    HYPRE_Solver ks = NULL, amg = NULL;
    HYPRE_PtrToSolverFcn ps = NULL, pset = NULL;
    if (p == P_AMG) {
        HYPRE_BoomerAMGCreate(&amg);
        hypre_amg_settings(amg);
        ps = (HYPRE_PtrToSolverFcn)HYPRE_BoomerAMGSolve;
        pset = (HYPRE_PtrToSolverFcn)HYPRE_BoomerAMGSetup;
    } else if (p == P_JACOBI) {
        ps = (HYPRE_PtrToSolverFcn)HYPRE_ParCSRDiagScale;
        pset = (HYPRE_PtrToSolverFcn)HYPRE_ParCSRDiagScaleSetup;
    }
    HYPRE_Int err = 0, n = 0;
    if (k == K_PCG) {
        HYPRE_ParCSRPCGCreate(comm, &ks);
        HYPRE_PCGSetTol(ks, tol);
        HYPRE_PCGSetTwoNorm(ks, 1);
        HYPRE_PCGSetMaxIter(ks, s->maxiter);
        if (ps)
            HYPRE_PCGSetPrecond(ks, ps, pset, amg);
        err = HYPRE_ParCSRPCGSetup(ks, a, b, x);
        if (!err)
            err = HYPRE_ParCSRPCGSolve(ks, a, b, x);
        HYPRE_PCGGetNumIterations(ks, &n);
        HYPRE_ParCSRPCGDestroy(ks);
    } else if (k == K_BICGSTAB) {
        HYPRE_ParCSRBiCGSTABCreate(comm, &ks);
        HYPRE_BiCGSTABSetTol(ks, tol);
        HYPRE_BiCGSTABSetMaxIter(ks, s->maxiter);
        if (ps)
            HYPRE_BiCGSTABSetPrecond(ks, ps, pset, amg);
        err = HYPRE_ParCSRBiCGSTABSetup(ks, a, b, x);
        if (!err)
            err = HYPRE_ParCSRBiCGSTABSolve(ks, a, b, x);
        HYPRE_BiCGSTABGetNumIterations(ks, &n);
        HYPRE_ParCSRBiCGSTABDestroy(ks);
    } else {
        HYPRE_ParCSRGMRESCreate(comm, &ks);
        HYPRE_GMRESSetKDim(ks, 20);
        HYPRE_GMRESSetTol(ks, tol);
        HYPRE_GMRESSetMaxIter(ks, s->maxiter);
        if (ps)
            HYPRE_GMRESSetPrecond(ks, ps, pset, amg);
        err = HYPRE_ParCSRGMRESSetup(ks, a, b, x);
        if (!err)
            err = HYPRE_ParCSRGMRESSolve(ks, a, b, x);
        HYPRE_GMRESGetNumIterations(ks, &n);
        HYPRE_ParCSRGMRESDestroy(ks);
    }
    if (amg)
        HYPRE_BoomerAMGDestroy(amg);
    *its = (int)n;
    if (err && !HYPRE_CheckError(err, HYPRE_ERROR_CONV))
        return hypre_check(err, "Krylov solve");
    HYPRE_ClearAllErrors();    /* not converged: the residual check says */
    return SIM_OK;
}

int linsolve_solve_dist(struct linsolve *s, MPI_Comm comm,
                        const struct csr_matrix *A, int64_t row0,
                        int64_t nglobal, const double *b, double *x,
                        struct linsolve_stats *st)
{
    const int n = A->n;
    double t0 = app_wall_time();
    memset(st, 0, sizeof *st);
    if (sizeof(HYPRE_BigInt) < sizeof(int64_t) && nglobal > INT32_MAX)
        return sim_error(SIM_ERR_INPUT, "hypre: %lld unknowns exceed its "
                         "32-bit indices", (long long)nglobal);
    double bb = 0;
    for (int i = 0; i < n; i++)
        bb += b[i] * b[i];
    double bg = 0;
    MPI_Allreduce(&bb, &bg, 1, MPI_DOUBLE, MPI_SUM, comm);
    const double bnorm = sqrt(bg);
    if (!isfinite(bnorm))
        return sim_error(SIM_ERR_NUMERIC, "linear system: the right-hand "
                         "side holds NaN or infinite values");
    if (!s->warm_start)
        memset(x, 0, sizeof *x * (size_t)n);
    if (bnorm == 0 || nglobal == 0) {
        memset(x, 0, sizeof *x * (size_t)n);
        st->converged = 1;
        return SIM_OK;
    }
    static int hypre_ready;
    if (!hypre_ready) {
        TRY(hypre_check(HYPRE_Init(), "HYPRE_Init"));
        hypre_ready = 1;
    }
    int krylov, pc;
    choose(s, &krylov, &pc);
    HYPRE_BigInt *rows = sim_malloc(((size_t)n + 1) * sizeof *rows);
    HYPRE_Int *ncols = sim_malloc(((size_t)n + 1) * sizeof *ncols);
    HYPRE_BigInt *cols = sim_malloc(((size_t)A->nnz + 1) * sizeof *cols);
    int rc = rows && ncols && cols ? SIM_OK : SIM_ERR_NOMEM;
    HYPRE_IJMatrix ij = NULL;
    HYPRE_IJVector bij = NULL, xij = NULL, rij = NULL;
    HYPRE_ParCSRMatrix pa = NULL;
    HYPRE_ParVector pb = NULL, px = NULL, pr = NULL;
    const HYPRE_BigInt lo = (HYPRE_BigInt)row0;
    if (rc)
        goto out;
    for (int i = 0; i < n; i++) {
        rows[i] = lo + i;
        ncols[i] = (HYPRE_Int)(A->rowptr[i + 1] - A->rowptr[i]);
    }
    for (int64_t k = 0; k < A->nnz; k++)
        cols[k] = A->col[k];
    TRY_GOTO(rc, hypre_check(HYPRE_IJMatrixCreate(comm, lo, lo + n - 1, lo,
                                            lo + n - 1, &ij), "matrix"), out);
    HYPRE_IJMatrixSetObjectType(ij, HYPRE_PARCSR);
    HYPRE_IJMatrixSetRowSizes(ij, ncols);
    HYPRE_IJMatrixInitialize(ij);
    if (n > 0)
        TRY_GOTO(rc, hypre_check(HYPRE_IJMatrixSetValues(ij, n, ncols, rows,
                                                         cols, A->val),
                                 "matrix values"), out);
    TRY_GOTO(rc, hypre_check(HYPRE_IJMatrixAssemble(ij), "matrix assemble"),
             out);
    void *obj;
    HYPRE_IJMatrixGetObject(ij, &obj);
    pa = obj;
    TRY_GOTO(rc, hypre_vector(comm, lo, n, rows, b, &bij, &pb), out);
    TRY_GOTO(rc, hypre_vector(comm, lo, n, rows, x, &xij, &px), out);
    TRY_GOTO(rc, hypre_vector(comm, lo, n, rows, b, &rij, &pr), out);
    double t1 = app_wall_time();
    st->setup_s = t1 - t0;
    int its = 0;
    TRY_GOTO(rc, krylov_solve(comm, krylov, pc, s, s->tol, pa, pb, px, &its),
             out);
    st->iters = its;
    /* the true residual r = b - A x, as linsolve.c checks it */
    HYPRE_ParCSRMatrixMatvec(-1.0, pa, px, 1.0, pr);
    double rr = 0;
    HYPRE_ParVectorInnerProd(pr, pr, &rr);
    if (n > 0)
        HYPRE_IJVectorGetValues(xij, n, rows, x);
    st->solve_s = app_wall_time() - t1;
    st->res_rel = sqrt(rr) / bnorm;
    if (!(st->res_rel <= s->tol))
        rc = sim_error(SIM_ERR_SOLVER, "hypre (distributed %s) did not "
                       "converge: %d iterations (maxIter %d), relative "
                       "residual %.3e > tolerance %.3e", s->solver->name,
                       its, s->maxiter, st->res_rel, s->tol);
    else
        st->converged = 1;
out:
    if (rij)
        HYPRE_IJVectorDestroy(rij);
    if (xij)
        HYPRE_IJVectorDestroy(xij);
    if (bij)
        HYPRE_IJVectorDestroy(bij);
    if (ij)
        HYPRE_IJMatrixDestroy(ij);
    free(rows);
    free(ncols);
    free(cols);
    return rc;
}

#endif
