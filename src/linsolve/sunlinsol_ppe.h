/*
 * sunlinsol_ppe.h — our PPE solvers as a SUNDIALS SUNLinearSolver
 * (doc/design.md C13): a SUNLINEARSOLVER_CUSTOM object of type MATRIX_EMBEDDED
 * (the CSR matrix is attached with SUNLinSol_PPESetMatrix, the SUNMatrix
 * argument of Setup/Solve must be NULL) whose content is a struct linsolve.
 *
 * The hot loop stays in linsolve.c's own code rather than in SUNDIALS'
 * PCG: SUNDIALS' serial N_Vector operations are unthreaded and unfused and
 * its PCG was 1.1-2.3x slower than our CG (doc/libraries.md §1-2), so the
 * adapter only translates calls: Solve(S, NULL, x, b, tol) solves A x = b
 * to ||b - A x||_2 <= tol when tol > 0 (SUNDIALS' absolute convention) or to
 * the configured relative tolerance when tol <= 0; x is the initial guess
 * unless SUNLinSolSetZeroGuess(S, SUNTRUE) was called before this solve.
 * NumIters and ResNorm (= ||b - A x||_2) report the last solve; LastFlag is
 * our error code. Return values: SUNLS_SUCCESS, SUNLS_CONV_FAIL (not
 * converged within maxIter: recoverable), SUNLS_ILL_INPUT (bad matrix or
 * right-hand side, message in sim_error_message()), SUNLS_PACKAGE_FAIL_UNREC
 * otherwise.
 */
#ifndef MPSDEM_LINSOLVE_SUNLINSOL_PPE_H
#define MPSDEM_LINSOLVE_SUNLINSOL_PPE_H

#include <sundials/sundials_linearsolver.h>

#include "linsolve/linsolve.h"

/* ls stays owned by the caller and must outlive S. NULL on failure. */
SUNLinearSolver SUNLinSol_PPE(struct linsolve *ls, SUNContext ctx);
int SUNLinSol_PPESetMatrix(SUNLinearSolver S, const struct csr_matrix *A);
/* Statistics of the last solve (times included). */
const struct linsolve_stats *SUNLinSol_PPEStats(SUNLinearSolver S);

#endif
