/* test_drag_models.c — property tests over every registered drag law
 * (doc/design.md C12 level 1): named and referenced; finite; odd in (u - v)
 * bit for bit; zero at u = v; monotone non-decreasing in |u - v| along any
 * direction; continuous in eps except at the law's documented jump_eps;
 * and the array entry equal to the scalar coefficient. A law added to
 * drag_register.c is tested here the day it is added. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>

#include "coupling/drag/drag.h"

static uint64_t rng_state = 2024;
static double urand(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (rng_state >> 11) * (1.0 / 9007199254740992.0);
}

static const struct drag_fluid fluids[] = {
    { 1000.0, 1.0e-3 },     /* water          */
    { 1.2, 1.8e-5 },        /* air            */
    { 1260.0, 1.4 },        /* glycerol       */
};

enum { N = 512 };
static double eps[N], d[N], V[N], u[3 * N], v[3 * N], F1[3 * N], F2[3 * N];

static void random_batch(double slip_max)
{
    for (int k = 0; k < N; k++) {
        eps[k] = 0.3 + 0.7 * urand();
        if (k % 17 == 0)
            eps[k] = 1.0;
        d[k] = 1e-4 * pow(300.0, urand());     /* 0.1 mm .. 3 cm */
        V[k] = M_PI * pow(d[k], 3) / 6;
        double s = slip_max * pow(urand(), 3);
        if (k % 13 == 0)
            s = 0;
        for (int c = 0; c < 3; c++) {
            u[3 * k + c] = 2 * urand() - 1;
            v[3 * k + c] = u[3 * k + c] + s * (2 * urand() - 1);
        }
    }
}

static void test_registry(void **state)
{
    (void)state;
    int n = 0, has_none = 0;
    for (int m = 0; drag_table[m]; m++, n++) {
        const struct drag_ops *L = drag_table[m];
        assert_non_null(L->name);
        assert_non_null(L->reference);
        assert_non_null(L->validity);
        assert_non_null(L->coeff);
        assert_non_null(L->force_all);
        has_none |= strcmp(L->name, "none") == 0;
        for (int q = 0; q < m; q++)
            assert_string_not_equal(L->name, drag_table[q]->name);
    }
    assert_true(n >= 4 && has_none);
}

/* Finite, odd, zero at u = v; array entry = scalar coefficient. */
static void test_finite_odd_zero(void **state)
{
    (void)state;
    for (size_t f = 0; f < sizeof fluids / sizeof fluids[0]; f++)
        for (int m = 0; drag_table[m]; m++) {
            const struct drag_ops *L = drag_table[m];
            random_batch(20.0);
            L->force_all(&fluids[f], N, eps, d, V, u, v, F1);
            L->force_all(&fluids[f], N, eps, d, V, v, u, F2);
            for (int k = 0; k < N; k++) {
                double s2 = 0;
                for (int c = 0; c < 3; c++)
                    s2 += pow(u[3 * k + c] - v[3 * k + c], 2);
                double K = L->coeff(&fluids[f], eps[k], sqrt(s2), d[k]);
                assert_true(isfinite(K) && K >= 0);
                for (int c = 0; c < 3; c++) {
                    double a = F1[3 * k + c], b = F2[3 * k + c];
                    assert_true(isfinite(a));
                    assert_true(a == -b);
                    double du = u[3 * k + c] - v[3 * k + c];
                    /* the force points along u - v (drag, never thrust) */
                    assert_true(a * du >= 0);
                    if (s2 == 0)
                        assert_true(a == 0);
                }
            }
        }
}

/* Monotone in |u - v| at fixed eps and d, over 8 decades of slip. */
static void test_monotone(void **state)
{
    (void)state;
    for (size_t f = 0; f < sizeof fluids / sizeof fluids[0]; f++)
        for (int m = 0; drag_table[m]; m++) {
            const struct drag_ops *L = drag_table[m];
            for (double e = 0.3; e <= 1.0 + 1e-12; e += 0.035)
                for (double dd = 1e-4; dd < 0.05; dd *= 4.3) {
                    double prev = 0;
                    for (double s = 1e-6; s < 100; s *= 1.05) {
                        double Fm = L->coeff(&fluids[f], fmin(e, 1.0), s, dd) *
                                    s;
                        assert_true(Fm >= prev);
                        prev = Fm;
                    }
                }
        }
}

/* Continuous in eps except at jump_eps: scanning eps with a fine step,
 * every relative change between neighbours is small, except across the
 * documented switch. */
static void test_continuity_in_eps(void **state)
{
    (void)state;
    const struct drag_fluid *w = &fluids[0];
    for (int m = 0; drag_table[m]; m++) {
        const struct drag_ops *L = drag_table[m];
        const double h = 1e-6;
        for (double s = 1e-4; s < 10; s *= 3.1)
            for (double e = 0.3; e + h <= 1.0; e += h * 997) {
                double a = L->coeff(w, e, s, 2.7e-3);
                double b = L->coeff(w, e + h, s, 2.7e-3);
                int across = L->jump_eps > 0 && e <= L->jump_eps &&
                             e + h > L->jump_eps;
                if (!across)
                    assert_true(fabs(a - b) <= 1e-3 * fmax(a, b) ||
                                (a == 0 && b == 0));
            }
        if (L->jump_eps > 0) {
            double a = L->coeff(w, L->jump_eps, 0.1, 2.7e-3);
            double b = L->coeff(w, nextafter(L->jump_eps, 2), 0.1, 2.7e-3);
            print_message("%s: documented jump at eps = %g, K ratio %.4f "
                          "(d = 2.7 mm, |u-v| = 0.1 m/s, water)\n", L->name,
                          L->jump_eps, a / b);
            assert_true(a != b);
        } else {
            /* a continuous law has no jump at the classic switch either */
            for (double s = 1e-4; s < 10; s *= 3.1) {
                double a = L->coeff(w, 0.8, s, 2.7e-3);
                double b = L->coeff(w, nextafter(0.8, 2), s, 2.7e-3);
                assert_true(fabs(a - b) <= 1e-9 * fmax(a, b));
            }
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_registry),
        cmocka_unit_test(test_finite_odd_zero),
        cmocka_unit_test(test_monotone),
        cmocka_unit_test(test_continuity_in_eps),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
