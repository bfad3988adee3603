/*
 * test_lattice.c — site lattices (src/particles/lattice.c): exact counts
 * for boxes, neighbour distances and coordination of the hexagonal
 * lattices, the fill against a brute-force loop over all sites, order
 * independent of the number of threads, and jitter bounds/determinism.
 */
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
#include "particles/lattice.h"

static void test_cubic_counts(void **state)
{
    /* Staggered fluid lattice: sites at dp/2 + i dp fill [0, L] with
     * floor(L / dp) per axis. */
    struct lattice l = { LATTICE_CUBIC, 3, { 0.05, 0.05, 0.05 }, 0.1 };
    double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 0.5, 0.3 }, *x;
    size_t n;
    (void)state;
    assert_int_equal(lattice_fill(&l, lo, hi, NULL, NULL, &x, &n), SIM_OK);
    assert_int_equal(n, 10 * 5 * 3);
    for (size_t i = 0; i < n; i++)
        for (int d = 0; d < 3; d++)
            assert_true(x[3 * i + d] > lo[d] && x[3 * i + d] < hi[d]);
    free(x);
    l.dim = 2;
    assert_int_equal(lattice_fill(&l, lo, hi, NULL, NULL, &x, &n), SIM_OK);
    assert_int_equal(n, 10 * 5);
    for (size_t i = 0; i < n; i++)
        assert_true(x[3 * i + 2] == 0.0);
    free(x);
    /* Sites exactly on the box faces are kept (tolerance 1e-9 spacing). */
    l.origin[0] = l.origin[1] = l.origin[2] = 0;
    l.dim = 3;
    assert_int_equal(lattice_fill(&l, lo, hi, NULL, NULL, &x, &n), SIM_OK);
    assert_int_equal(n, 11 * 6 * 4);
    free(x);
}

/* Minimum distance to another site and number of sites at that distance
 * (within 1e-9), for site i. */
static void neighbours(const double *x, size_t n, size_t i, double *dmin,
                       int *count)
{
    *dmin = HUGE_VAL;
    *count = 0;
    for (size_t j = 0; j < n; j++) {
        if (j == i)
            continue;
        double r = hypot(hypot(x[3 * i] - x[3 * j], x[3 * i + 1] - x[3 * j + 1]),
                         x[3 * i + 2] - x[3 * j + 2]);
        if (r < *dmin - 1e-9) {
            *dmin = r;
            *count = 1;
        } else if (fabs(r - *dmin) <= 1e-9) {
            (*count)++;
        }
    }
}

static void check_hex(int dim, int coordination, double density)
{
    struct lattice l = { LATTICE_HEXAGONAL, dim, { 0, 0, 0 }, 0.01 };
    double lo[3] = { 0, 0, 0 }, hi[3] = { 0.1, 0.1, 0.1 }, *x;
    double centre[3] = { 0.05, 0.05, dim == 3 ? 0.05 : 0 };
    size_t n, interior = 0;
    assert_int_equal(lattice_fill(&l, lo, hi, NULL, NULL, &x, &n), SIM_OK);
    for (size_t i = 0; i < n; i++) {
        double dmin;
        int count;
        neighbours(x, n, i, &dmin, &count);
        assert_true(fabs(dmin - 0.01) < 1e-12);
        /* Sites at least one spacing from the faces see a full shell. */
        int inner = 1;
        for (int d = 0; d < dim; d++)
            inner &= x[3 * i + d] > 0.011 && x[3 * i + d] < 0.089;
        if (inner) {
            assert_int_equal(count, coordination);
            interior++;
        }
    }
    assert_true(interior > 20);
    /* Sites per unit volume (area) within 20 % in a box this small. */
    assert_true(fabs(n / pow(0.1, dim) / density - 1) < 0.2);
    (void)centre;
    free(x);
}

static void test_hexagonal(void **state)
{
    (void)state;
    check_hex(2, 6, 2 / (sqrt(3.0) * 1e-4));         /* 2/(sqrt3 s^2) */
    check_hex(3, 12, sqrt(2.0) / 1e-6);              /* sqrt2 / s^3   */
}

struct ball { double c[3], r; };

static int in_ball(const double x[3], void *ctx)
{
    const struct ball *b = ctx;
    double d = hypot(hypot(x[0] - b->c[0], x[1] - b->c[1]), x[2] - b->c[2]);
    return d <= b->r;
}

static void test_fill_vs_brute(void **state)
{
    struct ball b = { { 0.31, 0.27, 0.4 }, 0.23 };
    double lo[3] = { 0, 0, 0 }, hi[3] = { 0.6, 0.6, 0.8 }, *x, *y;
    size_t n, m, brute = 0;
    (void)state;
    for (int kind = 0; kind < 2; kind++) {
        struct lattice l = { (enum lattice_kind)kind, 3, { 0.013, 0.02, 0.0 },
                             0.021 };
        long first[3], count[3];
        double ns;
        brute = 0;
        assert_int_equal(lattice_range(&l, lo, hi, first, count, &ns), SIM_OK);
        for (long k = first[2]; k < first[2] + count[2]; k++)
            for (long j = first[1]; j < first[1] + count[1]; j++)
                for (long i = first[0]; i < first[0] + count[0]; i++) {
                    double p[3];
                    lattice_site(&l, i, j, k, p);
                    brute += in_ball(p, &b);
                }
        omp_set_num_threads(1);
        assert_int_equal(lattice_fill(&l, lo, hi, in_ball, &b, &x, &n), SIM_OK);
        omp_set_num_threads(4);
        assert_int_equal(lattice_fill(&l, lo, hi, in_ball, &b, &y, &m), SIM_OK);
        assert_int_equal(n, brute);
        assert_int_equal(m, n);
        assert_memory_equal(x, y, 3 * n * sizeof *x);
        /* Roughly the ball's volume over the volume per site. */
        double per_site = kind ? pow(0.021, 3) / sqrt(2.0) : pow(0.021, 3);
        assert_true(fabs(n * per_site / (4.0 / 3 * M_PI * pow(0.23, 3)) - 1)
                    < 0.05);
        free(x);
        free(y);
    }
}

static void test_jitter(void **state)
{
    double x[3 * 500], y[3 * 500];
    (void)state;
    memset(x, 0, sizeof x);
    memset(y, 0, sizeof y);
    lattice_jitter(x, 500, 2, 0.1, 7);
    lattice_jitter(y, 500, 2, 0.1, 7);
    assert_memory_equal(x, y, sizeof x);
    double mean = 0, maxabs = 0;
    for (int i = 0; i < 500; i++) {
        assert_true(x[3 * i + 2] == 0.0); /* z untouched in 2-D */
        for (int d = 0; d < 2; d++) {
            mean += x[3 * i + d] / 1000;
            maxabs = fmax(maxabs, fabs(x[3 * i + d]));
        }
    }
    assert_true(maxabs <= 0.1 && maxabs > 0.09);
    assert_true(fabs(mean) < 0.01); /* sd of the mean ~ 0.0018 */
    memset(y, 0, sizeof y);
    lattice_jitter(y, 500, 2, 0.1, 8);
    assert_true(memcmp(x, y, sizeof x) != 0);
}

static void test_errors(void **state)
{
    struct lattice l = { LATTICE_CUBIC, 3, { 0, 0, 0 }, 0 };
    double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 }, *x;
    size_t n;
    (void)state;
    assert_int_equal(lattice_fill(&l, lo, hi, NULL, NULL, &x, &n),
                     SIM_ERR_INPUT);
    l.spacing = 1e-5;
    assert_int_equal(lattice_fill(&l, lo, hi, NULL, NULL, &x, &n),
                     SIM_ERR_INPUT); /* 1e15 sites */
    assert_non_null(strstr(sim_error_message(), "too many sites"));
    l.spacing = 0.1;
    hi[1] = HUGE_VAL;
    assert_int_equal(lattice_fill(&l, lo, hi, NULL, NULL, &x, &n),
                     SIM_ERR_INPUT);
    assert_null(x);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cubic_counts),
        cmocka_unit_test(test_hexagonal),
        cmocka_unit_test(test_fill_vs_brute),
        cmocka_unit_test(test_jitter),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
