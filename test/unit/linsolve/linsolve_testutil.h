/*
 * linsolve_testutil.h — helpers shared by the linsolve unit and model tests
 * (a header, so that the build does not make an executable of it).
 *
 * The oracle for SPD systems is CHOLMOD. An iterative answer x is accepted
 * when ||x - x_c||_2 <= 2 (||b - A x||_2 + ||b - A x_c||_2) / lambda_min(A),
 * the sound forward-error bound ||x - x*|| <= ||r|| / lambda_min for SPD A,
 * applied to both x and CHOLMOD's x_c (factor 2 covers the estimate of
 * lambda_min, an upper bound from inverse iteration + Rayleigh quotient).
 */
#ifndef LINSOLVE_TESTUTIL_H
#define LINSOLVE_TESTUTIL_H

#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "core/error.h"
#include "core/log.h"
#include "linsolve/csr.h"
#include "linsolve/linsolve.h"
#include "linsolve/linsolve_impl.h"

struct sys {
    struct csr_matrix A;
    double *b, *xref; /* CHOLMOD solution (SPD systems)      */
    double lmin;      /* estimate of the smallest eigenvalue */
};

static inline double tu_norm(int n, const double *v)
{
    double s = 0.0;
    for (int i = 0; i < n; i++)
        s += v[i] * v[i];
    return sqrt(s);
}

static inline double tu_resnorm(const struct csr_matrix *A, const double *b,
                                const double *x)
{
    double *r = malloc((size_t)A->n * sizeof *r);
    double s = sqrt(csr_residual(A, b, x, r));
    free(r);
    return s;
}

static inline void tu_lattice(struct sys *s, int dim, int nside, double re,
                              int porous)
{
    struct csr_lattice L = {.dim = dim, .nside = nside, .re = re,
                            .jitter = 0.1, .seed = 12345, .rhs_seed = 777,
                            .porous = porous};
    memset(s, 0, sizeof *s);
    assert_int_equal(csr_lattice_ppe(&L, &s->A, &s->b), SIM_OK);
}

/* x = A^-1 b by CHOLMOD. */
static inline void tu_cholmod(const struct csr_matrix *A, const double *b,
                              double *x)
{
    struct linsolve *ls;
    struct linsolve_stats st;
    assert_int_equal(linsolve_create_named("cholmod", "none", 1e-8, 1, &ls),
                     SIM_OK);
    int rc = linsolve_solve(ls, A, b, x, &st);
    if (rc)
        print_error("cholmod: %s\n", sim_error_message());
    assert_int_equal(rc, SIM_OK);
    linsolve_free(ls);
}

/* Reference solution (CHOLMOD) and lambda_min of an SPD system. The inner
 * solves of the inverse iteration use IC(0)-PCG to 1e-12: lambda_min only
 * scales the bound (with a factor 2 of margin) and need not come from the
 * oracle. */
static inline void tu_reference(struct sys *s)
{
    int n = s->A.n;
    s->xref = malloc((size_t)n * sizeof *s->xref);
    tu_cholmod(&s->A, s->b, s->xref);
    double *v = malloc((size_t)n * sizeof *v), *w = malloc((size_t)n * sizeof *w);
    struct linsolve *ls;
    assert_int_equal(linsolve_create_named("pcg", "ic0", 1e-12, 5000, &ls),
                     SIM_OK);
    for (int i = 0; i < n; i++)
        v[i] = 1.0 + 0.5 * sin(0.37 * i);
    for (int it = 0; it < 25; it++) {
        double nv = tu_norm(n, v);
        for (int i = 0; i < n; i++)
            v[i] /= nv;
        memcpy(w, v, (size_t)n * sizeof *v); /* warm start */
        assert_int_equal(linsolve_solve(ls, &s->A, v, w, NULL), SIM_OK);
        memcpy(v, w, (size_t)n * sizeof *v);
    }
    linsolve_free(ls);
    csr_spmv(&s->A, v, w);
    double vv = 0.0, vav = 0.0;
    for (int i = 0; i < n; i++) {
        vv += v[i] * v[i];
        vav += v[i] * w[i];
    }
    s->lmin = vav / vv;
    free(v);
    free(w);
}

static inline void tu_free(struct sys *s)
{
    csr_free(&s->A);
    free(s->b);
    free(s->xref);
    memset(s, 0, sizeof *s);
}

/* Assert that x solves the SPD system s as well as its residual allows. */
static inline void tu_assert_matches_reference(const struct sys *s,
                                               const double *x, double tol)
{
    int n = s->A.n;
    double bn = tu_norm(n, s->b);
    double r = tu_resnorm(&s->A, s->b, x);
    double rc = tu_resnorm(&s->A, s->b, s->xref);
    double e = 0.0;
    for (int i = 0; i < n; i++)
        e += (x[i] - s->xref[i]) * (x[i] - s->xref[i]);
    e = sqrt(e);
    double bound = 2.0 * (r + rc) / s->lmin;
    if (!(r <= tol * bn) || !(e <= bound))
        print_error("residual %.3e (tol %.1e), error %.3e, bound %.3e "
                    "(lambda_min %.3e)\n", r / bn, tol, e, bound, s->lmin);
    assert_true(r <= tol * bn);
    assert_true(e <= bound);
    /* The bound is not vacuous: it is far below the size of the answer. */
    assert_true(bound < 1e-3 * tu_norm(n, s->xref));
}

#endif
