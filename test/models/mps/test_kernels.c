/* test_kernels.c — property tests over every registered MPS kernel
 * (doc/design.md C12 level 1): compact support, non-negative, non-increasing,
 * the array entry equal to the scalar one bit for bit, and n0 > 0 with
 * lambda between dp^2 and r_e^2 on the lattice. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>

#include "mps/kernel/kernel.h"
#include "mps/operators.h"

static void test_properties(void **s)
{
    (void)s;
    const double re = 0.021;
    enum { N = 1001 };
    double r[N], w[N];
    for (int k = 0; k < N; k++)
        r[k] = 1.2 * re * k / (N - 1);
    for (int m = 0; mps_kernel_table[m]; m++) {
        const struct mps_kernel_ops *K = mps_kernel_table[m];
        assert_non_null(K->name);
        assert_non_null(K->reference);
        K->weights(r, N, re, w);
        for (int k = 0; k < N; k++) {
            double wk = K->w(r[k], re);
            assert_memory_equal(&wk, &w[k], sizeof wk);
            assert_true(wk >= 0);
            assert_true(isfinite(wk));
            if (r[k] >= re)
                assert_true(wk == 0);
            if (k)
                assert_true(w[k] <= w[k - 1]);
        }
        /* continuity at r_e */
        assert_true(K->w(re * (1 - 1e-9), re) < 1e-6);
        struct pop_lattice L;
        assert_int_equal(mps_lattice_constants(K, 3, re / 2.1, re, &L), 0);
        assert_true(L.n0 > 0);
        assert_true(L.lambda > pow(re / 2.1, 2) && L.lambda < re * re);
        assert_int_equal(L.nnb, 32);
    }
}

/* E5-01 (doc/theory.md): the soil model's kernel (8) on the 2-D square
 * lattice, r_e = 2.1 dp: n0 = 2.505337, lambda = 1.264422 dp^2 (12
 * neighbours), to 1e-6. */
static void test_poly6_lattice(void **s)
{
    (void)s;
    const double dp = 0.002;
    struct pop_lattice L;
    assert_int_equal(mps_lattice_constants(&mps_kernel_poly6, 2, dp, 2.1 * dp, &L), 0);
    assert_int_equal(L.nnb, 12);
    assert_float_equal(L.n0, 2.505337, 1e-6);
    assert_float_equal(L.lambda / (dp * dp), 1.264422, 1e-6);
    assert_float_equal(mps_kernel_poly6.w(0, 2.1 * dp), 1.0, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = { cmocka_unit_test(test_properties),
                                        cmocka_unit_test(test_poly6_lattice) };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
