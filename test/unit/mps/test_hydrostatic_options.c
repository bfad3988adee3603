/* test_hydrostatic_options.c — the still-water options of mpsSchemes:
 * the corrective-matrix gradient (pressureGradient corrected) is exact for
 * linear fields on jittered and truncated clouds and falls back where its
 * matrix is singular; a 2-D still tank with corrected gradient, wall and
 * dummy pressure extrapolated from the fluid, surface pressure extrapolated
 * to dp/2 and Lind shifting stays hydrostatic (doc/theory.md E1-07/E1-08 in
 * 2-D: L2 < 1 %, max |u| < 1 % sqrt(g h) over 0.25 s; measured 0.45 % and
 * 0.39 %). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/log.h"
#include "linsolve/linsolve.h"
#include "mps/kernel/kernel.h"
#include "mps/mps.h"
#include "mps/operators.h"
#include "mps/stabiliser/stabiliser.h"
#include "particles/neighbour.h"
#include "mps_test_tank.h"

/* deterministic jitter in [-a, a] */
static double jit(unsigned *seed, double a)
{
    *seed = *seed * 1103515245u + 12345u;
    return a * (2.0 * ((*seed >> 8) & 0xffff) / 65535.0 - 1.0);
}

/* Cloud of side^dim particles of spacing 1, jittered by 0.2; with half,
 * only the lower half (a free surface on top). GC gradient of
 * phi = 3 + b.x compared with b on every particle with a regular moment
 * matrix; returns how many used the fallback. */
static int check_linear(int dim, int half)
{
    enum { SIDE = 9 };
    double x[3 * SIDE * SIDE * SIDE], phi[SIDE * SIDE * SIDE];
    double b[3] = { 1.5, -9810.0, dim == 3 ? 0.25 : 0 };
    unsigned seed = 7;
    int n = 0, zs = dim == 3 ? SIDE : 1;
    for (int i = 0; i < SIDE; i++)
        for (int j = 0; j < (half ? SIDE / 2 + 1 : SIDE); j++)
            for (int k = 0; k < zs; k++) {
                x[3 * n] = i + jit(&seed, 0.2);
                x[3 * n + 1] = j + jit(&seed, 0.2);
                x[3 * n + 2] = dim == 3 ? k + jit(&seed, 0.2) : 0;
                phi[n] = 3 + b[0] * x[3 * n] + b[1] * x[3 * n + 1]
                       + b[2] * x[3 * n + 2];
                n++;
            }
    struct neighbour_list nl;
    memset(&nl, 0, sizeof nl);
    const double re = 2.1;
    assert_int_equal(neighbour_build_brute(&nl, dim, x, n, re), 0);
    double *w = malloc(sizeof *w * (size_t)nl.nnz);
    double *g = malloc(sizeof *g * 3 * (size_t)n);
    mps_kernel_zhang2014.weights(nl.r, nl.nnz, re, w);
    struct pop_lattice L;
    assert_int_equal(mps_lattice_constants(&mps_kernel_zhang2014, dim, 1.0, re,
                                           &L), 0);
    mps_gradient_corrected(&nl, POP_STORED(w), dim, L.n0, x, phi, NULL, NULL, g);
    int fallback = 0;
    for (int i = 0; i < n; i++) {
        double e = 0;
        for (int q = 0; q < dim; q++)
            e = fmax(e, fabs(g[3 * i + q] - b[q]));
        if (e > 1e-9 * 9810.0)
            fallback++;
    }
    free(w);
    free(g);
    neighbour_free(&nl);
    return fallback;
}

static void test_gc_linear(void **st)
{
    (void)st;
    /* every particle, corners and the surface included, has a regular
     * moment matrix at r_e = 2.1: the gradient is exact */
    assert_int_equal(check_linear(2, 0), 0);
    assert_int_equal(check_linear(2, 1), 0);
    assert_int_equal(check_linear(3, 0), 0);
    assert_int_equal(check_linear(3, 1), 0);
}

/* Three particles on a line (2-D): the moment matrix is singular; the
 * gradient along the line is the uncorrected (d/n0) form, finite. */
static void test_gc_fallback(void **st)
{
    (void)st;
    double x[9] = { 0, 0, 0, 1, 0, 0, 2, 0, 0 }, phi[3] = { 0, 1, 2 }, g[9];
    struct neighbour_list nl;
    memset(&nl, 0, sizeof nl);
    assert_int_equal(neighbour_build_brute(&nl, 2, x, 3, 2.1), 0);
    double w[16];
    assert_true(nl.nnz <= 16);
    mps_kernel_zhang2014.weights(nl.r, nl.nnz, 2.1, w);
    mps_gradient_corrected(&nl, POP_STORED(w), 2, 4.0, x, phi, NULL, NULL, g);
    /* middle particle: (2/4) (w(1) + w(1)) * 1 / 1 */
    double w1 = mps_kernel_zhang2014.w(1.0, 2.1);
    assert_true(fabs(g[3] - 0.5 * 2 * w1) < 1e-12);
    assert_true(g[4] == 0 && isfinite(g[0]) && isfinite(g[6]));
    neighbour_free(&nl);
}

enum { NX = 20, NY = 20, LAYERS = 4 };
static const double DP = 0.005, RHO = 1000, G = 9.81;

/* The tank of test_step.c, fluid started from p = rho g (h - y). */
static void build_tank(struct mps_particles *P)
{
    mps_test_tank2d(P, NX, NY, LAYERS, 6, DP);
    for (int n = 0; n < P->n; n++)
        if (P->type[n] == MPS_FLUID)
            P->p[n] = RHO * G * (NY * DP - P->x[3 * n + 1]);
}

static void test_still_tank(void **st)
{
    (void)st;
    struct mps_particles P;
    struct mps_settings S;
    struct linsolve *ls;
    struct mps_solver s;
    log_set_quiet(1);
    build_tank(&P);
    mps_settings_default(&S);     /* the paper's method, plus: */
    S.gradient = MPS_GRAD_CORRECTED;
    S.dummy_pressure = MPS_DUMMY_P_EXTRAPOLATED;
    S.fs_pressure = MPS_FS_P_EXTRAPOLATED;
    S.shifting = &mps_shifting_lind2012;
    S.gamma = 0.003;
    S.g[1] = -G;
    S.g[2] = 0;
    assert_int_equal(linsolve_create_named("pcg", "ic0", 1e-10, 2000, &ls), 0);
    assert_int_equal(mps_solver_init(&s, &P, &S, DP, ls), 0);
    const double h = NY * DP, umax_ok = 0.01 * sqrt(G * h);
    double umax = 0, e2 = 0, r2 = 0, pw_err = 0, ps_err = 0;
    for (int k = 0; k < 500; k++) {
        assert_int_equal(mps_step(&s, 5e-4), 0);
        for (int i = 0; i < s.P.n; i++) {
            const double *x = s.P.x + 3 * i, pe = RHO * G * (h - x[1]);
            if (s.P.type[i] == MPS_FLUID) {
                umax = fmax(umax, hypot(s.P.u[3 * i], s.P.u[3 * i + 1]));
                if (k == 499) {
                    e2 += (s.P.p[i] - pe) * (s.P.p[i] - pe);
                    r2 += pe * pe;
                }
                /* surface particles carry rho g dp/2 (24.5 Pa), not 0 */
                if (k == 499 && s.P.fs[i] == MPS_SURFACE)
                    ps_err = fmax(ps_err, fabs(s.P.p[i] - RHO * G * DP / 2));
            } else if (k == 499 && s.P.type[i] == MPS_WALL && x[1] < h) {
                /* wall pressure continues the hydrostatic field */
                pw_err = fmax(pw_err, fabs(s.P.p[i] - pe));
            }
        }
        if (k == 0) {            /* E1-07 at the first step */
            int wrong = 0;
            for (int i = 0; i < s.P.n; i++)
                if (s.P.type[i] == MPS_FLUID)
                    wrong += (s.P.fs[i] == MPS_SURFACE)
                           != (s.P.x[3 * i + 1] > (NY - 1) * DP);
            assert_int_equal(wrong, 0);
        }
    }
    double l2 = sqrt(e2 / r2);
    print_message("still tank 0.25 s: L2 %.4f, max |u| %.5f m/s (%.4f "
                  "sqrt(gh)), surface p error %.2f Pa, wall p error %.2f "
                  "Pa\n", l2, umax, umax / sqrt(G * h), ps_err, pw_err);
    assert_true(l2 < 0.01);
    assert_true(umax < umax_ok);
    assert_true(ps_err < 0.2 * RHO * G * DP / 2);
    assert_true(pw_err < 0.02 * RHO * G * h);
    mps_solver_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_gc_linear),
        cmocka_unit_test(test_gc_fallback),
        cmocka_unit_test(test_still_tank),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
