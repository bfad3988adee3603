/*
 * linsolve_impl.h — internals shared by the solver and preconditioner files
 * of src/linsolve (not for use outside this library and its tests).
 *
 * A solver and a preconditioner are each a model (doc/design.md C3): a
 * const ops table selected by name from a NULL-terminated registry. The
 * facade (linsolve.c) validates the matrix and the right-hand side, owns
 * the work storage, times set-up and solve, and checks the true residual
 * of every answer, so a solver only has to produce x.
 */
#ifndef MPSDEM_LINSOLVE_IMPL_H
#define MPSDEM_LINSOLVE_IMPL_H

#include <stddef.h>
#include <stdint.h>

#include "linsolve/linsolve.h"

struct linsolve;
struct precond;

/* ---- preconditioners ------------------------------------------------------ */

struct precond_ops {
    const char *name;
    const char *reference;
    /* z = M^-1 r is symmetric positive definite whenever A is SPD, so PCG
     * may use it. */
    int spd;
    /* Built from the lower triangle only: meaningless for a non-symmetric
     * A, so BiCGSTAB refuses it. */
    int lower_only;
    /* M is diagonal and pc->dinv holds M^-1: PCG fuses it into its vector
     * updates (the fast path). */
    int diagonal;
    /* Build M for A (validated; diag = its diagonal, all > 0). */
    int (*setup)(struct precond *pc, const struct csr_matrix *A,
                 const double *diag);
    /* z = M^-1 r (r and z distinct). */
    void (*apply)(const struct precond *pc, const double *r, double *z);
    /* Frees pc->state (NULL when the preconditioner keeps none). */
    void (*release)(struct precond *pc);
};

/* Storage of every preconditioner, grown on demand and kept across solves. */
struct precond {
    const struct precond_ops *ops;
    int n;
    double *dinv;            /* n: inverse of a diagonal (jacobi, dic)     */
    int64_t *fp;             /* n+1: factor rows (ic0: L, ilu0: L\U, dic:
                                strict lower triangle of A)                */
    int32_t *fc;             /* factor columns, sorted within a row         */
    double *fv;              /* factor values                               */
    int64_t *fdiag;          /* n: position of the diagonal in each row     */
    int32_t *pos;            /* n: scatter map, -1 outside the current row  */
    double *y;               /* n: intermediate of the triangular solves    */
    int n_cap;
    int64_t nnz_cap;
    double shift;            /* diagonal shift used after a breakdown, or 0 */
    void *state;             /* a preconditioner's own storage (amg levels) */
    int symmetric;           /* the solver needs M symmetric (PCG)          */
};

extern const struct precond_ops precond_none, precond_jacobi, precond_ic0,
    precond_dic, precond_ilu0, precond_amg;
extern const struct precond_ops *const linsolve_preconditioners[];

/* Make room for n rows and nnz factor entries in pc (keeps old storage when
 * it is large enough). */
int precond_reserve(struct precond *pc, int n, int64_t nnz, int factor);
void precond_release(struct precond *pc);

/* Copy the rows of A into pc's factor arrays with columns sorted, keeping
 * only j <= i when lower_only; fdiag[i] gives the diagonal entry. */
int precond_sorted_copy(struct precond *pc, const struct csr_matrix *A,
                        int lower_only);

/* One factorisation attempt of A + alpha diag(A): *bad_row is the first
 * row with an unusable pivot, or -1 when the factor is complete; the
 * return value is an error code (allocation, inconsistent storage). */
typedef int (*precond_attempt_fn)(struct precond *pc,
                                  const struct csr_matrix *A,
                                  const double *diag, double alpha,
                                  int *bad_row);
/* Factorise with no shift, then with alpha = 1e-3, 4e-3, ... (at most 30
 * tries) until an attempt succeeds; warn once, naming the first bad row
 * ("<name>: <pivot> pivot at row ..."). Never succeeding is SIM_ERR_SOLVER
 * ("<name> broke down ...<hint>"). */
int precond_factor_shifted(struct precond *pc, const struct csr_matrix *A,
                           const double *diag, const char *name,
                           const char *pivot, const char *hint,
                           precond_attempt_fn attempt);

/* ---- solvers -------------------------------------------------------------- */

struct solver_ops {
    const char *name;
    const char *reference;
    int iterative;       /* uses the preconditioner, maxIter and warm start */
    int needs_symmetric; /* refuses a non-symmetric matrix                  */
    int needs_spd_pc;    /* needs a preconditioner with ops->spd            */
    int own_pc;          /* brings its own preconditioner (hypre's AMG):
                            ours is not read and stays none                */
    /* Called once at creation; may refuse (e.g. not compiled in). */
    int (*init)(struct linsolve *s);
    /* x: initial guess on entry (iterative solvers), solution on exit.
     * Iterate until ||b - A x||_2 <= tolabs (> 0) or maxiter; set st->iters.
     * The facade checks the final true residual, so running out of
     * iterations is not an error here. */
    int (*solve)(struct linsolve *s, const struct csr_matrix *A,
                 const double *b, double *x, double tolabs,
                 struct linsolve_stats *st);
    void (*fini)(struct linsolve *s);
};

extern const struct solver_ops solver_pcg, solver_bicgstab, solver_gmres,
    solver_cholmod,
    solver_hypre;
extern const struct solver_ops *const linsolve_solvers[];

#define LINSOLVE_NWORK 8

/* Loops over fewer rows run on one thread: below this, fork/join costs more
 * than the loop, and on an oversubscribed machine a spinning OpenMP team
 * made a 2,000-row test 15x slower (29 s instead of 2 s). */
#define LINSOLVE_OMP_MIN_ROWS 8192
#define LS_PAR(n) ((n) >= LINSOLVE_OMP_MIN_ROWS)

struct linsolve {
    const struct solver_ops *solver;
    struct precond pc;
    double tol;          /* relative, on ||b - A x||_2 / ||b||_2           */
    int maxiter;
    int warm_start;
    int generic;         /* tests: bypass the fused Jacobi fast path       */
    int n_cap;
    double *diag;        /* n: diagonal of the current matrix               */
    double *work[LINSOLVE_NWORK]; /* n each: solver vectors                 */
    void *ext;           /* solver-private state (CHOLMOD common, ...)     */
};

/* Row i of A times x. Four partial sums: with one, every multiply-add
 * waits for the previous one (4 cycles of add latency per entry), which
 * made the SpMV latency-bound rather than memory-bound on PPE rows of
 * 13-120 entries. Values in double (csr_row_dot) or float
 * (csr_row_dot_f: precond_amg.c's copy of its level matrices), sums in
 * double. */
#define CSR_ROW_DOT(name, vtype)                                          \
    static inline double name(const int64_t *restrict rp,                 \
                              const int32_t *restrict col,                \
                              const vtype *restrict val,                  \
                              const double *restrict x, int i)            \
    {                                                                     \
        double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;                    \
        int64_t k = rp[i], e = rp[i + 1];                                 \
        for (; k + 3 < e; k += 4) {                                       \
            s0 += (double)val[k] * x[col[k]];                             \
            s1 += (double)val[k + 1] * x[col[k + 1]];                     \
            s2 += (double)val[k + 2] * x[col[k + 2]];                     \
            s3 += (double)val[k + 3] * x[col[k + 3]];                     \
        }                                                                 \
        for (; k < e; k++)                                                \
            s0 += (double)val[k] * x[col[k]];                             \
        return (s0 + s1) + (s2 + s3);                                     \
    }
CSR_ROW_DOT(csr_row_dot, double)
CSR_ROW_DOT(csr_row_dot_f, float)

/* Check the preconditioner and solver combination (messages name both). */
/* linsolve_create_named() with the tables' entries (the dictionary
 * front end has selected them already). */
int linsolve_create_ops(const struct solver_ops *so,
                        const struct precond_ops *po, double tol, int maxiter,
                        struct linsolve **out);

int linsolve_check_combination(const struct solver_ops *so,
                               const struct precond_ops *po);

/* Internal solve with an absolute tolerance override (> 0) on ||b-Ax||_2,
 * used by the SUNLinearSolver adapter. */
int linsolve_solve_abs(struct linsolve *s, const struct csr_matrix *A,
                       const double *b, double *x, double abstol,
                       struct linsolve_stats *st);

/* ---- vector kernels (OpenMP) ---------------------------------------------- */

/* q = A p; returns p.q */
double csr_spmv_dot(const struct csr_matrix *A, const double *p, double *q);
/* r = b - A x; returns r.r */
double csr_residual(const struct csr_matrix *A, const double *b,
                    const double *x, double *r);
double vec_dot(int n, const double *a, const double *b);
void vec_copy(int n, const double *a, double *b);
void vec_zero(int n, double *a);

#ifdef MPSDEM_HAVE_HYPRE
#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
/* solver_hypre.c, shared with the distributed solve (linsolve_dist.c): a
 * hypre error as our SIM_ERR_EXTERNAL naming `what`, BoomerAMG as one
 * preconditioning V-cycle with the settings of the benchmark, vectors. */
#include <mpi.h>
int hypre_check(HYPRE_Int err, const char *what);
void hypre_amg_settings(HYPRE_Solver amg);
/* The IJ vector of rows [lo, lo + n) of comm holding v. */
int hypre_vector(MPI_Comm comm, HYPRE_BigInt lo, int n,
                 const HYPRE_BigInt *rows, const double *v,
                 HYPRE_IJVector *out, HYPRE_ParVector *par);
#endif

#endif
