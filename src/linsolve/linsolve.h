/*
 * linsolve.h — linear solvers for the MPS pressure Poisson equation (PPE).
 *
 * The MPS library assembles the PPE matrix in CSR and calls this facade; the
 * solver, its preconditioner and its tolerances come from a dictionary (the
 * PPE sub-dictionary of system/mpsSolution) or from plain values.
 *
 *   solver          pcg | bicgstab | gmres | cholmod | hypre     (default pcg)
 *   preconditioner  none | jacobi | ic0 | dic | ilu0 | amg (default jacobi)
 *   tolerance       relative, on ||b - A x||_2 / ||b||_2  (default 1e-8)
 *   maxIter         (default 1000)
 *   warmStart       yes | no                              (default yes)
 *
 * pcg takes none, jacobi, ic0, dic or amg (symmetric positive definite
 * matrix); bicgstab and gmres (GMRES(20), one product and one
 * preconditioner application per iteration where BiCGSTAB takes two:
 * solver_gmres.c) are for the non-symmetric PPE of the coupled case,
 * porosity weights, and take none, jacobi, ilu0 or amg (aggregation
 * multigrid, one W-cycle per application: iterations nearly independent
 * of the resolution, precond_amg.c); cholmod (direct; SPD only, small systems
 * and tests) and hypre (BoomerAMG-PCG, only in a `make HYPRE=1` build) read no
 * preconditioner. Other pairs are refused with a message.
 *
 * Every system is validated (n > 0, structure, finite values, positive
 * diagonal, finite b) and every answer passes a true-residual check, so a
 * solve either meets its tolerance or returns an error: SIM_ERR_INPUT or
 * SIM_ERR_NUMERIC for a bad system, SIM_ERR_SOLVER for no convergence or a
 * matrix that is not positive definite where it must be.
 *
 * The same solvers as a SUNDIALS SUNLinearSolver: sunlinsol_ppe.h.
 * Helpers (SpMV, checks, the benchmark matrix): csr.h.
 * See doc/libraries.md §2 for the benchmark that chose these defaults.
 */
#ifndef MPSDEM_LINSOLVE_LINSOLVE_H
#define MPSDEM_LINSOLVE_LINSOLVE_H

#include <stdint.h>

#include "core/select.h"

struct dict;

struct csr_matrix {           /* square, rows in any order of columns (not necessarily sorted) */
    int n;                    /* rows                                    */
    int64_t nnz;
    int64_t *rowptr;          /* n+1                                     */
    int32_t *col;             /* nnz                                     */
    double  *val;             /* nnz                                     */
};
struct linsolve_stats { int iters; double res_rel; double setup_s, solve_s; int converged; };
struct linsolve;              /* opaque: a selected, configured solver with its work storage */
/* Read `solver` (pcg | bicgstab | gmres | cholmod | hypre, default pcg), `preconditioner` (none | jacobi | ic0 | dic | ilu0 | amg, default jacobi),
 * `tolerance` (relative on ||b - Ax||_2/||b||_2, default 1e-8), `maxIter` (default 1000), `warmStart` (yes) from d
 * (e.g. the PPE sub-dictionary of system/mpsSolution); logs "Selecting ...". */
int  linsolve_create(const struct dict *d, struct linsolve **out);
/* The choices linsolve_create reads (keys relative to its dictionary). */
extern const struct model_choice linsolve_choices[];
/* Same from plain values, for tests and tools. */
int  linsolve_create_named(const char *solver, const char *precond, double tol, int maxiter, struct linsolve **out);
/* Solve A x = b. x holds the initial guess on entry (warm start) — ignored (zeroed) when warmStart is off.
 * Not converged within maxIter -> SIM_ERR_SOLVER with iterations and residual in the message, x left at the last iterate.
 * Storage is reused across calls; no allocation once sizes stop growing. */
int  linsolve_solve(struct linsolve *s, const struct csr_matrix *A, const double *b, double *x, struct linsolve_stats *st);
void linsolve_free(struct linsolve *s);

#ifdef MPSDEM_HAVE_MPI
#include <mpi.h>
/* A distributed system (MPI builds, linsolve_dist.c): this rank's rows
 * [row0, row0 + A->n) of nglobal, columns global; the solver and
 * preconditioner of s map onto hypre's. Collective over comm. */
int linsolve_solve_dist(struct linsolve *s, MPI_Comm comm,
                        const struct csr_matrix *A, int64_t row0,
                        int64_t nglobal, const double *b, double *x,
                        struct linsolve_stats *st);
#endif

#endif
