/* test_isph_operators.c — the kernels and the corrected SPH operators of
 * ISPH (src/isph, doc/theory.md S.2), 2-D, h = 1.3 dl (S0-01):
 *   kernels            both integrate to 1 (quadrature on rings, 1e-6)
 *                      and dw is the derivative of w (central differences)
 *   e4_01_gradient     the corrected gradient of a linear field is exact
 *                      (1e-10) at every particle of a jittered cloud in a
 *                      box, whose edges truncate the supports as a wall or
 *                      a free surface does
 *   e4_02_laplacian    lap (x^2 + y^2) = 4: interior particles of the
 *                      regular lattice within 1 % with both
 *                      normalisations (D-08; measured 3e-14), of the
 *                      cloud jittered by 0.3 dl within 5 % (2.2e-2); the
 *                      errors at truncated supports are printed (the
 *                      report E4-02 asks for: 0.6-2 % at 1-2 dl from an
 *                      edge, 100 % on it, where the gradient of the
 *                      quadratic is not exact and the bracket of (5.36)
 *                      does not cancel it; such particles are wall or
 *                      surface rows in the PPE)
 *   singular           a particle with one neighbour: SIM_ERR_NUMERIC
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "isph/isph.h"
#include "particles/lattice.h"
#include "particles/neighbour.h"

#define NX 21
#define DL 0.05

struct cloud {
    struct isph_cloud c;
    struct neighbour_list nl;
    double *x, *V, *L, *cc, *S;
    int n;
};

static void make_cloud(struct cloud *cl, double k, int norm,
                       const struct isph_kernel *kern)
{
    memset(cl, 0, sizeof *cl);
    int n = NX * NX;
    cl->n = n;
    cl->x = calloc(3 * (size_t)n, sizeof(double));
    cl->V = calloc((size_t)n, sizeof(double));
    cl->L = calloc(4 * (size_t)n, sizeof(double));
    cl->cc = calloc((size_t)n, sizeof(double));
    cl->S = calloc(2 * (size_t)n, sizeof(double));
    double *jit = calloc(3 * (size_t)n, sizeof(double));
    assert_non_null(cl->x && cl->V && cl->L && cl->cc && cl->S && jit);
    lattice_jitter(jit, (size_t)n, 2, k * DL / 2, 7);
    for (int j = 0; j < NX; j++)
        for (int i = 0; i < NX; i++) {
            int a = j * NX + i;
            cl->x[3 * a] = i * DL + jit[3 * a];
            cl->x[3 * a + 1] = j * DL + jit[3 * a + 1];
            cl->V[a] = DL * DL;
        }
    free(jit);
    double h = 1.3 * DL;
    assert_int_equal(neighbour_build_brute(&cl->nl, 2, cl->x, n,
                                           kern->support * h), SIM_OK);
    cl->c = (struct isph_cloud){ .n = n, .x = cl->x, .V = cl->V,
                                 .nl = &cl->nl, .kernel = kern, .h = h,
                                 .norm = norm, .L = cl->L, .c = cl->cc,
                                 .S = cl->S };
    assert_int_equal(isph_corrections(&cl->c), SIM_OK);
}

static void free_cloud(struct cloud *cl)
{
    neighbour_free(&cl->nl);
    free(cl->x), free(cl->V), free(cl->L), free(cl->cc), free(cl->S);
}

/* Distance of particle a's lattice site from the box's edges [dl]. */
static int depth(int a)
{
    int i = a % NX, j = a / NX, d = i;
    if (j < d) d = j;
    if (NX - 1 - i < d) d = NX - 1 - i;
    if (NX - 1 - j < d) d = NX - 1 - j;
    return d;
}

static void test_kernels(void **state)
{
    (void)state;
    for (int q = 0; isph_kernels[q]; q++) {
        const struct isph_kernel *k = isph_kernels[q];
        double h = 0.7, s = 0, R = k->support * h;
        int m = 200000;
        for (int i = 0; i < m; i++) { /* midpoint rule on rings */
            double r = (i + 0.5) * R / m;
            s += k->w(r, h) * 2 * M_PI * r * R / m;
        }
        if (fabs(s - 1) > 1e-6) {
            print_error("%s: integral %.9f\n", k->name, s);
            fail();
        }
        for (double r = 0.05; r < R; r += 0.1) {
            double e = 1e-6, fd = (k->w(r + e, h) - k->w(r - e, h)) / (2 * e);
            assert_true(fabs(fd - k->dw(r, h)) < 1e-6 * (1 + fabs(fd)));
        }
        assert_true(k->w(R, h) == 0 && k->dw(R, h) == 0);
    }
}

static void test_e4_01_gradient(void **state)
{
    (void)state;
    for (int q = 0; isph_kernels[q]; q++) {
        struct cloud cl;
        make_cloud(&cl, 0.5, ISPH_LAP_TRACE_INVERSE, isph_kernels[q]);
        double *f = malloc(sizeof(double) * cl.n), worst = 0;
        for (int a = 0; a < cl.n; a++)
            f[a] = 2 + 3 * cl.x[3 * a] - 1.5 * cl.x[3 * a + 1];
        for (int a = 0; a < cl.n; a++) {
            double g[2];
            isph_gradient(&cl.c, f, 1, a, g);
            worst = fmax(worst, fmax(fabs(g[0] - 3), fabs(g[1] + 1.5)));
        }
        printf("E4-01 %s: largest gradient error %.2e (corners and edges "
               "included)\n", isph_kernels[q]->name, worst);
        assert_true(worst < 1e-10 * 3);
        free(f);
        free_cloud(&cl);
    }
}

/* Largest |lap f - 4| over the particles whose depth is in [d0, d1]. */
static double lap_error(const struct cloud *cl, const double *f, int d0,
                        int d1)
{
    double e = 0;
    for (int a = 0; a < cl->n; a++)
        if (depth(a) >= d0 && depth(a) <= d1)
            e = fmax(e, fabs(isph_laplacian(&cl->c, f, a) - 4));
    return e / 4;
}

static void test_e4_02_laplacian(void **state)
{
    (void)state;
    static const char *const names[] = { "2 tr(Gamma^-1)/n", "2n/tr(Gamma)" };
    for (int q = 0; isph_kernels[q]; q++)
        for (int norm = 0; norm < 2; norm++) {
            double e[2][3];
            for (int jit = 0; jit < 2; jit++) {
                struct cloud cl;
                make_cloud(&cl, jit ? 0.3 : 0, norm, isph_kernels[q]);
                double *f = malloc(sizeof(double) * cl.n);
                for (int a = 0; a < cl.n; a++)
                    f[a] = cl.x[3 * a] * cl.x[3 * a]
                         + cl.x[3 * a + 1] * cl.x[3 * a + 1];
                e[jit][0] = lap_error(&cl, f, 3, NX);  /* full support  */
                e[jit][1] = lap_error(&cl, f, 1, 2);   /* truncated     */
                e[jit][2] = lap_error(&cl, f, 0, 0);   /* on the edge   */
                free(f);
                free_cloud(&cl);
            }
            printf("E4-02 %s, c = %s: relative error of lap (x^2 + y^2), "
                   "lattice / jittered 0.3 dl: interior %.1e / %.1e, 1-2 dl "
                   "from the edge %.1e / %.1e, on the edge %.1e / %.1e\n",
                   isph_kernels[q]->name, names[norm], e[0][0], e[1][0],
                   e[0][1], e[1][1], e[0][2], e[1][2]);
            assert_true(e[0][0] < 0.01);  /* E4-02: interior 1 %        */
            assert_true(e[1][0] < 0.05);  /* jittered interior (ours)   */
        }
}

static void test_singular(void **state)
{
    (void)state;
    double x[6] = { 0, 0, 0, 0.05, 0, 0 }, V[2] = { 1, 1 }, L[8], c[2],
           S[4];
    struct neighbour_list nl = { 0 };
    assert_int_equal(neighbour_build_brute(&nl, 2, x, 2, 0.2), SIM_OK);
    struct isph_cloud cl = { .n = 2, .x = x, .V = V, .nl = &nl,
                             .kernel = &isph_wendland_c2, .h = 0.065,
                             .L = L, .c = c, .S = S };
    assert_int_equal(isph_corrections(&cl), SIM_ERR_NUMERIC);
    assert_non_null(strstr(sim_error_message(), "do not span"));
    sim_error_clear();
    /* with `isolated`: both flagged, their operators zero, no error */
    uint8_t iso[2] = { 7, 7 };
    cl.isolated = iso;
    assert_int_equal(isph_corrections(&cl), SIM_OK);
    assert_int_equal(cl.n_isolated, 2);
    assert_int_equal(iso[0], 1);
    assert_int_equal(iso[1], 1);
    double f[2] = { 1, 3 }, g[2];
    isph_gradient(&cl, f, 1, 0, g);
    assert_true(g[0] == 0 && g[1] == 0);
    assert_true(c[0] == 0 && S[0] == 0 && S[1] == 0);
    neighbour_free(&nl);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_kernels),
        cmocka_unit_test(test_e4_01_gradient),
        cmocka_unit_test(test_e4_02_laplacian),
        cmocka_unit_test(test_singular),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
