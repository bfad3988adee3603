/* test_porosity_pairs.c — the grain / MPS-particle pair search by cells
 * against the O(ng np) loop (doc/design.md C12: SWIFT test27cells), in 3-D and
 * 2-D, with particles outside the grain box, a non-finite particle, no
 * grains, a radius larger than the cloud, and thinly spread grains (the
 * cell cap); a non-finite grain is an error. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "coupling/pairs.h"
#include "coupling/porosity.h"

static uint64_t rng_state = 99;
static double urand(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (rng_state >> 11) * (1.0 / 9007199254740992.0);
}

struct pw { int32_t j; double w; };

static int cmp_pw(const void *a, const void *b)
{
    const struct pw *x = a, *y = b;
    return (x->j > y->j) - (x->j < y->j);
}

/* Grain rows equal as sets (weights bit for bit); particle rows equal as
 * arrays (grains ascending in both). */
static void assert_same(const struct coupling_pairs *A,
                        const struct coupling_pairs *B)
{
    assert_int_equal(A->ng, B->ng);
    assert_int_equal(A->np, B->np);
    assert_int_equal(A->npair, B->npair);
    struct pw *a = malloc((A->npair + 1) * sizeof *a);
    struct pw *b = malloc((A->npair + 1) * sizeof *b);
    for (int k = 0; k < A->ng; k++) {
        int64_t n = A->gstart[k + 1] - A->gstart[k];
        assert_int_equal(n, B->gstart[k + 1] - B->gstart[k]);
        for (int64_t e = 0; e < n; e++) {
            int64_t ea = A->gstart[k] + e, eb = B->gstart[k] + e;
            a[e] = (struct pw){ A->gj[ea], A->gw[ea] };
            b[e] = (struct pw){ B->gj[eb], B->gw[eb] };
        }
        qsort(a, n, sizeof *a, cmp_pw);
        qsort(b, n, sizeof *b, cmp_pw);
        for (int64_t e = 0; e < n; e++) {
            assert_int_equal(a[e].j, b[e].j);
            assert_memory_equal(&a[e].w, &b[e].w, sizeof(double));
            assert_true(a[e].w > 0 && a[e].w <= 1);
        }
    }
    free(a);
    free(b);
    assert_memory_equal(A->pstart, B->pstart, (A->np + 1) * sizeof(int64_t));
    assert_memory_equal(A->pk, B->pk, A->npair * sizeof(int32_t));
    assert_memory_equal(A->pw, B->pw, A->npair * sizeof(double));
}

static int64_t check_case(int dim, int ng, int np, double box_g, double box_p,
                       double re)
{
    double *xg = calloc(3 * (size_t)ng + 3, sizeof *xg);
    double *xp = calloc(3 * (size_t)np + 3, sizeof *xp);
    for (int k = 0; k < ng; k++)
        for (int c = 0; c < dim; c++)
            xg[3 * k + c] = box_g * urand();
    for (int i = 0; i < np; i++)
        for (int c = 0; c < dim; c++)
            xp[3 * i + c] = box_p * (urand() - 0.25);
    if (np > 3)
        xp[3] = NAN;                     /* an escaped particle */
    if (np > 5 && ng > 0)                /* exactly at a grain: w = 1 */
        memcpy(xp + 15, xg, 3 * sizeof *xp);
    struct coupling_pairs F = { 0 }, B = { 0 };
    assert_int_equal(coupling_pairs_build(&F, dim, re, ng, xg, np, xp), 0);
    assert_int_equal(coupling_pairs_build_brute(&B, dim, re, ng, xg, np, xp),
                     0);
    assert_same(&F, &B);
    if (np > 3)
        assert_true(F.pstart[2] == F.pstart[1]);
    /* the same sizes again: no array is reallocated */
    const void *ptr[] = { F.gstart, F.gj, F.gw, F.pstart, F.pk, F.pw,
                          F.X.grid.start, F.X.grid.order, F.X.xs,
                          F.X.tcount, F.X.tbuf };
    assert_int_equal(coupling_pairs_build(&F, dim, re, ng, xg, np, xp), 0);
    const void *ptr2[] = { F.gstart, F.gj, F.gw, F.pstart, F.pk, F.pw,
                           F.X.grid.start, F.X.grid.order, F.X.xs,
                          F.X.tcount, F.X.tbuf };
    assert_memory_equal(ptr, ptr2, sizeof ptr);
    /* a second build on moved points reuses the storage */
    for (int i = 0; i < 3 * np; i++)
        xp[i] += 0.1 * re * (urand() - 0.5);
    assert_int_equal(coupling_pairs_build(&F, dim, re, ng, xg, np, xp), 0);
    assert_int_equal(coupling_pairs_build_brute(&B, dim, re, ng, xg, np, xp),
                     0);
    assert_same(&F, &B);
    int64_t npair = F.npair;
    coupling_pairs_free(&F);
    coupling_pairs_free(&B);
    free(xg);
    free(xp);
    return npair;
}

static void test_against_brute(void **state)
{
    (void)state;
    for (int dim = 2; dim <= 3; dim++) {
        assert_true(check_case(dim, 200, 5000, 0.05, 0.1, 0.011) > 1000);
        check_case(dim, 1, 500, 0.05, 0.1, 0.011);      /* one grain    */
        check_case(dim, 0, 500, 0.05, 0.1, 0.011);      /* no grains    */
        check_case(dim, 50, 0, 0.05, 0.1, 0.011);       /* no particles */
        check_case(dim, 30, 400, 0.01, 0.02, 0.5);      /* re >> cloud  */
        assert_true(check_case(dim, 300, 3000, 50.0, 60.0, 0.3) > 0);
    }
}

static void test_bad_grain(void **state)
{
    (void)state;
    double xg[6] = { 0, 0, 0, 0, INFINITY, 0 }, xp[3] = { 0, 0, 0 };
    struct coupling_pairs P = { 0 };
    assert_int_equal(coupling_pairs_build(&P, 3, 0.01, 2, xg, 1, xp),
                     SIM_ERR_NUMERIC);
    assert_int_equal(coupling_pairs_build(&P, 4, 0.01, 1, xg, 1, xp),
                     SIM_ERR_INPUT);
    assert_int_equal(coupling_pairs_build(&P, 3, -1.0, 1, xg, 1, xp),
                     SIM_ERR_INPUT);
    coupling_pairs_free(&P);
}

/* The build and the sums over it do not depend on the thread count. */
static void test_threads(void **state)
{
    (void)state;
    enum { NG = 400, NP = 20000 };
    static double xg[3 * NG], xp[3 * NP], V[NG], e1[NP], e2[NP];
    for (int k = 0; k < 3 * NG; k++)
        xg[k] = 0.05 * urand();
    for (int k = 0; k < NG; k++)
        V[k] = 1e-8;
    for (int i = 0; i < 3 * NP; i++)
        xp[i] = 0.06 * urand();
    struct coupling_pairs A = { 0 }, B = { 0 };
    int nt = omp_get_max_threads();
    omp_set_num_threads(1);
    assert_int_equal(coupling_pairs_build(&A, 3, 0.011, NG, xg, NP, xp), 0);
    assert_int_equal(coupling_porosity(&A, V, 0.3, e1, NULL, NULL), 0);
    omp_set_num_threads(3);   /* more chunks than cores is fine */
    assert_int_equal(coupling_pairs_build(&B, 3, 0.011, NG, xg, NP, xp), 0);
    assert_int_equal(coupling_porosity(&B, V, 0.3, e2, NULL, NULL), 0);
    omp_set_num_threads(nt);
    assert_int_equal(A.npair, B.npair);
    assert_memory_equal(A.gstart, B.gstart, (NG + 1) * sizeof(int64_t));
    assert_memory_equal(A.gj, B.gj, A.npair * sizeof(int32_t));
    assert_memory_equal(A.gw, B.gw, A.npair * sizeof(double));
    assert_memory_equal(A.pstart, B.pstart, (NP + 1) * sizeof(int64_t));
    assert_memory_equal(A.pk, B.pk, A.npair * sizeof(int32_t));
    assert_memory_equal(A.pw, B.pw, A.npair * sizeof(double));
    assert_memory_equal(e1, e2, sizeof e1);
    coupling_pairs_free(&A);
    coupling_pairs_free(&B);
}

/* Non-zero entries of A equal to B's pairs (grain rows as sets, particle
 * rows in order), weights bit for bit. */
static void assert_same_nonzero(const struct coupling_pairs *A,
                                const struct coupling_pairs *B)
{
    int64_t nz = 0;
    for (int i = 0; i < A->np; i++) {
        int64_t eb = B->pstart[i];
        for (int64_t e = A->pstart[i]; e < A->pstart[i + 1]; e++) {
            if (A->pw[e] == 0)
                continue;
            assert_true(eb < B->pstart[i + 1]);
            assert_int_equal(A->pk[e], B->pk[eb]);
            assert_memory_equal(&A->pw[e], &B->pw[eb], sizeof(double));
            eb++;
            nz++;
        }
        assert_true(eb == B->pstart[i + 1]);
    }
    assert_int_equal(nz, B->npair);
    for (int k = 0; k < A->ng; k++) {
        int64_t n = 0;
        for (int64_t e = A->gstart[k]; e < A->gstart[k + 1]; e++)
            n += A->gw[e] != 0;
        assert_int_equal(n, B->gstart[k + 1] - B->gstart[k]);
    }
}

/* The Verlet-skin update: refreshed lists carry exactly the pairs and
 * weights of a fresh build (plus zero-weight candidates), the porosity is
 * bit for bit the same, and a search runs when the displacements reach
 * the skin or a particle goes non-finite. */
static void test_update(void **state)
{
    (void)state;
    enum { NG = 150, NP = 4000 };
    static double xg[3 * NG], xp[3 * NP], V[NG], e1[NP], e2[NP];
    const double re = 0.011, skin = 0.002;
    for (int dim = 2; dim <= 3; dim++) {
        memset(xg, 0, sizeof xg);
        memset(xp, 0, sizeof xp);
        for (int k = 0; k < NG; k++) {
            V[k] = 1e-8;
            for (int c = 0; c < dim; c++)
                xg[3 * k + c] = 0.05 * urand();
        }
        for (int i = 0; i < NP; i++)
            for (int c = 0; c < dim; c++)
                xp[3 * i + c] = 0.06 * urand() - 0.005;
        struct coupling_pairs U = { 0 }, B = { 0 };
        int searches = 0, refreshes = 0, searched;
        for (int step = 0; step < 14; step++) {
            double amp = step == 9 ? 10 * skin : 0.15 * skin;
            for (int c = 0; c < dim; c++) {
                xg[3 * (step % NG) + c] += amp * (urand() - 0.5);
                xp[3 * (step % NP) + c] += amp * (urand() - 0.5);
                xp[3 * ((7 * step) % NP) + c] += amp * (urand() - 0.5);
            }
            if (step == 12)
                xp[3 * 5] = NAN;
            assert_int_equal(coupling_pairs_update(&U, dim, re, skin, NG, xg,
                                                   NP, xp, &searched), 0);
            searches += searched;
            refreshes += !searched;
            if (step == 0 || step == 9 || step == 12)
                assert_int_equal(searched, 1);
            if (step == 13)   /* still non-finite: no change */
                assert_int_equal(searched, 0);
            assert_int_equal(coupling_pairs_build_brute(&B, dim, re, NG, xg,
                                                        NP, xp), 0);
            assert_same_nonzero(&U, &B);
            assert_int_equal(coupling_porosity(&U, V, 0.3, e1, NULL, NULL),
                             0);
            assert_int_equal(coupling_porosity(&B, V, 0.3, e2, NULL, NULL),
                             0);
            assert_memory_equal(e1, e2, sizeof e1);
        }
        assert_true(refreshes >= 8 && searches >= 3);
        /* a plain build after updates, then an update: searches again */
        assert_int_equal(coupling_pairs_build(&U, dim, re, NG, xg, NP, xp),
                         0);
        assert_int_equal(coupling_pairs_update(&U, dim, re, skin, NG, xg, NP,
                                               xp, &searched), 0);
        assert_int_equal(searched, 1);
        assert_int_equal(coupling_pairs_update(&U, dim, re, skin, NG, xg, NP,
                                               xp, &searched), 0);
        assert_int_equal(searched, 0);
        coupling_pairs_invalidate(&U);
        assert_int_equal(coupling_pairs_update(&U, dim, re, skin, NG, xg, NP,
                                               xp, &searched), 0);
        assert_int_equal(searched, 1);
        assert_int_equal(coupling_pairs_update(&U, dim, re, -1, NG, xg, NP,
                                               xp, &searched), SIM_ERR_INPUT);
        coupling_pairs_free(&U);
        coupling_pairs_free(&B);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_against_brute),
        cmocka_unit_test(test_bad_grain),
        cmocka_unit_test(test_threads),
        cmocka_unit_test(test_update),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
