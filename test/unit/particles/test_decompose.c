/*
 * test_decompose.c — recursive coordinate bisection and halo counts
 * (particles/decompose.h):
 *   - unit weights: every one of k = 1 ... 13 subdomains owns n/k
 *     particles within the rounding of its cuts (one particle per level);
 *   - weights: the weight, not the count, is balanced;
 *   - a box long in x is first cut across x (all of one side below the
 *     other), and the same input gives the same partition;
 *   - halo and neighbour counts equal an O(n^2) count, 2-D and 3-D;
 *   - the recorded cuts give every particle the subdomain the bisection
 *     gave it (decompose_owner), 2-D and 3-D, k = 1 ... 13, also with
 *     fewer particles than subdomains;
 *   - bad input (no subdomain, a NaN position, rc <= 0) is refused.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "core/error.h"
#include "core/log.h"
#include "particles/decompose.h"

static unsigned long long rng = 0x9E3779B97F4A7C15ULL;
static double urand(void)
{
    rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

static double *cloud(int n, int dim, double lx)
{
    double *x = calloc(3 * (size_t)n, sizeof *x);
    for (int i = 0; i < n; i++) {
        x[3 * i] = lx * urand();
        for (int a = 1; a < dim; a++)
            x[3 * i + a] = urand();
    }
    return x;
}

static void test_balance(void **st)
{
    (void)st;
    const int n = 5000;
    double *x = cloud(n, 3, 1.0);
    int32_t *part = malloc(n * sizeof *part);
    for (int k = 1; k <= 13; k++) {
        assert_int_equal(decompose_rcb(3, x, NULL, n, k, part), SIM_OK);
        long cnt[13] = { 0 };
        for (int i = 0; i < n; i++) {
            assert_true(part[i] >= 0 && part[i] < k);
            cnt[part[i]]++;
        }
        int depth = 0;
        while ((1 << depth) < k)
            depth++;
        for (int p = 0; p < k; p++)
            assert_true(fabs(cnt[p] - (double)n / k) <= depth + 1);
    }
    free(part);
    free(x);
}

static void test_weights(void **st)
{
    (void)st;
    const int n = 4000, k = 6;
    double *x = cloud(n, 3, 2.0);
    double *w = malloc(n * sizeof *w);
    double total = 0;
    for (int i = 0; i < n; i++)
        total += w[i] = x[3 * i] < 1.0 ? 1.0 : 0.0;   /* the left half works */
    int32_t *part = malloc(n * sizeof *part);
    assert_int_equal(decompose_rcb(3, x, w, n, k, part), SIM_OK);
    double wp[6] = { 0 };
    for (int i = 0; i < n; i++)
        wp[part[i]] += w[i];
    for (int p = 0; p < k; p++)
        assert_true(fabs(wp[p] - total / k) <= 4);
    free(part);
    free(w);
    free(x);
}

static void test_first_cut_and_repeat(void **st)
{
    (void)st;
    const int n = 3000;
    double *x = cloud(n, 3, 5.0);
    int32_t *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
    assert_int_equal(decompose_rcb(3, x, NULL, n, 2, a), SIM_OK);
    double max0 = -INFINITY, min1 = INFINITY;
    for (int i = 0; i < n; i++) {
        if (a[i] == 0)
            max0 = fmax(max0, x[3 * i]);
        else
            min1 = fmin(min1, x[3 * i]);
    }
    assert_true(max0 <= min1);
    assert_int_equal(decompose_rcb(3, x, NULL, n, 7, a), SIM_OK);
    assert_int_equal(decompose_rcb(3, x, NULL, n, 7, b), SIM_OK);
    assert_memory_equal(a, b, n * sizeof *a);
    free(a);
    free(b);
    free(x);
}

static void halo_case(int dim, int n, int k, double rc)
{
    double *x = cloud(n, dim, 1.5);
    int32_t *part = malloc(n * sizeof *part);
    assert_int_equal(decompose_rcb(dim, x, NULL, n, k, part), SIM_OK);
    struct decompose_part *out = calloc(k, sizeof *out);
    assert_int_equal(decompose_halo(dim, x, NULL, n, part, k, rc, out),
                     SIM_OK);
    unsigned char *in = calloc((size_t)n * k, 1);
    unsigned char *nb = calloc((size_t)k * k, 1);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            if (part[i] == part[j])
                continue;
            double d2 = 0;
            for (int a = 0; a < 3; a++)
                d2 += (x[3 * i + a] - x[3 * j + a])
                    * (x[3 * i + a] - x[3 * j + a]);
            if (d2 < rc * rc) {
                in[(size_t)part[i] * n + j] = 1;
                nb[part[i] * k + part[j]] = 1;
            }
        }
    long total = 0;
    for (int p = 0; p < k; p++) {
        long h = 0, m = 0;
        int c = 0;
        for (int j = 0; j < n; j++)
            h += in[(size_t)p * n + j];
        for (int i = 0; i < n; i++)
            m += part[i] == p;
        for (int q = 0; q < k; q++)
            c += nb[p * k + q];
        assert_int_equal(out[p].owned, m);
        assert_int_equal(out[p].halo, h);
        assert_int_equal(out[p].neighbours, c);
        total += h;
    }
    assert_true(k == 1 ? total == 0 : total > 0);
    free(in);
    free(nb);
    free(out);
    free(part);
    free(x);
}

static void test_halo_brute(void **st)
{
    (void)st;
    halo_case(3, 1500, 5, 0.12);
    halo_case(2, 1200, 8, 0.05);
    halo_case(3, 800, 1, 0.2);
}

static void test_cuts_owner(void **st)
{
    (void)st;
    for (int dim = 2; dim <= 3; dim++)
        for (int n = 3; n <= 3000; n += 2997) {
            double *x = cloud(n, dim, 2.0);
            int32_t *part = malloc(n * sizeof *part);
            struct decompose_cut cuts[12];
            for (int k = 1; k <= 13; k++) {
                assert_int_equal(decompose_rcb_cuts(dim, x, NULL, n, k, part,
                                                    cuts), SIM_OK);
                for (int i = 0; i < n; i++)
                    assert_int_equal(decompose_owner(cuts, k, x + 3 * i),
                                     part[i]);
            }
            free(part);
            free(x);
        }
}

static void test_bad_input(void **st)
{
    (void)st;
    log_set_quiet(1);
    double x[6] = { 0, 0, 0, 1, NAN, 0 };
    int32_t part[2];
    assert_int_equal(decompose_rcb(3, x, NULL, 2, 0, part), SIM_ERR_INPUT);
    assert_int_equal(decompose_rcb(3, x, NULL, 2, 2, part), SIM_ERR_INPUT);
    x[4] = 0;
    assert_int_equal(decompose_rcb(3, x, NULL, 2, 2, part), SIM_OK);
    struct decompose_part out[2];
    assert_int_equal(decompose_halo(3, x, NULL, 2, part, 2, 0.0, out),
                     SIM_ERR_INPUT);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_balance),
        cmocka_unit_test(test_weights),
        cmocka_unit_test(test_first_cut_and_repeat),
        cmocka_unit_test(test_halo_brute),
        cmocka_unit_test(test_cuts_owner),
        cmocka_unit_test(test_bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
