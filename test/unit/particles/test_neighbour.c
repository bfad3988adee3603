/* test_neighbour.c — cell lists and CSR neighbour lists against the O(n^2)
 * reference on random sets (2-D and 3-D, with particles outside the box and
 * NaN positions; cells of the cut-off and of half of it; a Verlet list with
 * a skin updated after moves; rows split at an inner radius; rows left
 * empty by a mask), and cell-order renumbering. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "particles/cells.h"
#include "particles/neighbour.h"

static unsigned long long rng = 88172645463325252ULL;
static double urand(void)
{
    rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

static int cmp_i32(const void *a, const void *b)
{
    int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    return (x > y) - (x < y);
}

/* Rows equal as sets, distances equal to round-off. */
static void compare(const struct neighbour_list *a,
                    const struct neighbour_list *b, const double *x)
{
    assert_int_equal(a->n, b->n);
    assert_int_equal(a->nnz, b->nnz);
    for (int i = 0; i < a->n; i++) {
        int64_t len = a->start[i + 1] - a->start[i];
        assert_int_equal(len, b->start[i + 1] - b->start[i]);
        int32_t *ra = a->j + a->start[i], *rb = b->j + b->start[i];
        for (int64_t k = 0; k < len; k++) {
            const double *p = x + 3 * i, *q = x + 3 * ra[k];
            double r = sqrt((q[0]-p[0])*(q[0]-p[0]) + (q[1]-p[1])*(q[1]-p[1])
                            + (q[2]-p[2])*(q[2]-p[2]));
            assert_true(fabs(r - a->r[a->start[i] + k]) <= 1e-15 * (1 + r));
        }
        qsort(ra, (size_t)len, sizeof *ra, cmp_i32);
        for (int64_t k = 0; k < len; k++)
            assert_int_equal(ra[k], rb[k]);
    }
}

static void random_case(int dim, int n, double rc, double h, int with_box)
{
    double *x = calloc(3 * (size_t)n, sizeof *x);
    for (int i = 0; i < n; i++)
        for (int k = 0; k < dim; k++)
            x[3 * i + k] = urand();
    /* A few particles out of the box, one NaN: they must get empty rows. */
    x[0] = 7.0;
    x[3 * 5 + 1] = NAN;
    double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
    struct cell_grid g = { 0 };
    struct neighbour_list fast = { 0 }, ref = { 0 };
    assert_int_equal(cells_build(&g, dim, x, n, h, with_box ? lo : NULL,
                                 with_box ? hi : NULL), 0);
    assert_int_equal(g.n_outside, with_box ? 2 : 1);
    assert_int_equal(neighbour_build(&fast, &g, x, rc), 0);
    /* The reference sees the out-of-box particle only without a box. */
    if (with_box)
        x[0] = NAN;
    assert_int_equal(neighbour_build_brute(&ref, dim, x, n, rc), 0);
    compare(&fast, &ref, x);
    assert_true(fast.nnz > 0);
    /* Rebuilding in place after moving gives the same as a fresh build. */
    for (int i = 0; i < n; i++)
        if (isfinite(x[3 * i]))
            x[3 * i] = fmod(x[3 * i] + 0.37, 1.0);
    assert_int_equal(cells_build(&g, dim, x, n, h, lo, hi), 0);
    assert_int_equal(neighbour_build(&fast, &g, x, rc), 0);
    assert_int_equal(neighbour_build_brute(&ref, dim, x, n, rc), 0);
    compare(&fast, &ref, x);
    cells_free(&g);
    neighbour_free(&fast);
    neighbour_free(&ref);
    free(x);
}

/* Split rows (r_inner > 0): [start, mid) holds exactly the pairs within
 * r_inner (as many as the brute-force list of that radius has), the rest
 * of the row the others; the inner view ends each row at mid. */
static void check_split(const struct neighbour_list *nl, const double *x,
                        int dim, int n, double ri)
{
    struct neighbour_list in = { 0 };
    assert_int_equal(neighbour_build_brute(&in, dim, x, n, ri), 0);
    struct neighbour_list v = neighbour_inner(nl);
    for (int i = 0; i < nl->n; i++) {
        assert_true(nl->mid[i] >= nl->start[i] && nl->mid[i] <= nl->start[i + 1]);
        assert_int_equal(neighbour_row_end(&v, i), nl->mid[i]);
        assert_int_equal(nl->mid[i] - nl->start[i], in.start[i + 1] - in.start[i]);
        for (int64_t k = nl->start[i]; k < nl->start[i + 1]; k++)
            assert_true((k < nl->mid[i]) == (nl->r[k] < ri));
    }
    neighbour_free(&in);
}

/* Verlet list: candidates within rc + skin on cells of (rc + skin) / 2,
 * then rows re-selected after every particle moved by less than skin/2
 * equal the brute-force list at the new positions, twice in a row; with
 * ri > 0 the rows are split at ri (check_split). */
static void skin_case(int dim, int n, double rc, double skin, double h,
                      double ri)
{
    double *x = calloc(3 * (size_t)n, sizeof *x);
    for (int i = 0; i < n; i++)
        for (int k = 0; k < dim; k++)
            x[3 * i + k] = urand();
    x[0] = 7.0;
    double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
    struct cell_grid g = { 0 };
    struct neighbour_list fast = { 0 }, ref = { 0 };
    assert_int_equal(cells_build(&g, dim, x, n, h, lo, hi), 0);
    fast.r_inner = ri;
    assert_int_equal(neighbour_build_skin(&fast, &g, x, rc, skin), 0);
    x[0] = NAN;
    assert_int_equal(neighbour_build_brute(&ref, dim, x, n, rc), 0);
    if (ri > 0)
        check_split(&fast, x, dim, n, ri);
    compare(&fast, &ref, x);
    assert_true(fast.nnz_cand > fast.nnz);
    const double a = 0.499 * skin / sqrt(dim) / 2; /* two moves < skin/2 */
    for (int move = 0; move < 2; move++) {
        for (int i = 0; i < n; i++)
            for (int k = 0; k < dim; k++)
                x[3 * i + k] += a * (2 * urand() - 1);
        neighbour_update(&fast, x);
        assert_int_equal(neighbour_build_brute(&ref, dim, x, n, rc), 0);
        if (ri > 0)
            check_split(&fast, x, dim, n, ri);
        compare(&fast, &ref, x);
    }
    cells_free(&g);
    neighbour_free(&fast);
    neighbour_free(&ref);
    free(x);
}

/* Row mask: masked rows are empty, before and after an update; the other
 * rows are those of the unmasked list, masked particles included in them. */
static void test_row_mask(void **st)
{
    (void)st;
    const int n = 2000;
    const double rc = 0.08, skin = 0.02;
    double *x = calloc(3 * (size_t)n, sizeof *x);
    uint8_t *rows = malloc((size_t)n);
    for (int i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++)
            x[3 * i + k] = urand();
        rows[i] = (uint8_t)(i % 3 != 0);
    }
    double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
    struct cell_grid g = { 0 };
    struct neighbour_list all = { 0 }, some = { 0 };
    assert_int_equal(cells_build(&g, 3, x, n, rc + skin, lo, hi), 0);
    assert_int_equal(neighbour_build_skin(&all, &g, x, rc, skin), 0);
    some.rows = rows;
    assert_int_equal(neighbour_build_skin(&some, &g, x, rc, skin), 0);
    for (int pass = 0; pass < 2; pass++) {
        int64_t seen_masked = 0;
        for (int i = 0; i < n; i++) {
            int64_t len = some.start[i + 1] - some.start[i];
            if (!rows[i]) {
                assert_int_equal(len, 0);
                continue;
            }
            assert_int_equal(len, all.start[i + 1] - all.start[i]);
            for (int64_t k = 0; k < len; k++) {
                assert_int_equal(some.j[some.start[i] + k],
                                 all.j[all.start[i] + k]);
                seen_masked += !rows[some.j[some.start[i] + k]];
            }
        }
        assert_true(seen_masked > 0);
        for (int i = 0; i < n; i++)   /* move by < skin/2, then update */
            for (int k = 0; k < 3; k++)
                x[3 * i + k] += 0.004 * (2 * urand() - 1);
        neighbour_update(&all, x);
        neighbour_update(&some, x);
    }
    cells_free(&g);
    neighbour_free(&all);
    neighbour_free(&some);
    free(rows);
    free(x);
}

static void test_skin_3d(void **s) { (void)s; skin_case(3, 3000, 0.07, 0.03, 0.05, 0); }
static void test_skin_2d(void **s) { (void)s; skin_case(2, 3000, 0.05, 0.02, 0.07, 0); }
static void test_split_3d(void **s) { (void)s; skin_case(3, 3000, 0.07, 0.03, 0.05, 0.047); }
static void test_random_3d(void **s) { (void)s; random_case(3, 3000, 0.07, 0.07, 1); }
static void test_half_cells(void **s) { (void)s; random_case(3, 3000, 0.08, 0.04, 1); }
static void test_random_2d(void **s) { (void)s; random_case(2, 3000, 0.05, 0.06, 1); }
static void test_random_bbox(void **s) { (void)s; random_case(3, 1500, 0.1, 0.1, 0); }

/* Cut-off larger than the cell is refused, not silently truncated. */
static void test_bad_cutoff(void **s)
{
    (void)s;
    double x[6] = { 0, 0, 0, 0.1, 0, 0 };
    struct cell_grid g = { 0 };
    struct neighbour_list nl = { 0 };
    assert_int_equal(cells_build(&g, 3, x, 2, 0.05, NULL, NULL), 0);
    assert_int_not_equal(neighbour_build(&nl, &g, x, 0.2), 0);
    assert_int_not_equal(neighbour_build_skin(&nl, &g, x, 0.08, 0.03), 0);
    assert_int_not_equal(cells_build(&g, 3, x, 2, 0.0, NULL, NULL), 0);
    cells_free(&g);
    neighbour_free(&nl);
}

/* Renumbering by cell order: a permutation, cell ids non-decreasing after,
 * and applying it twice changes nothing more (stable sort). */
static void test_renumber(void **s)
{
    (void)s;
    const int n = 2000;
    double *x = malloc(3 * sizeof *x * n), *scr = malloc(3 * sizeof *x * n);
    int32_t *perm = malloc(sizeof *perm * n), *id = malloc(sizeof *id * n);
    for (int i = 0; i < n; i++) {
        x[3*i] = urand(); x[3*i+1] = urand(); x[3*i+2] = urand();
        id[i] = i;
    }
    struct cell_grid g = { 0 };
    assert_int_equal(cells_build(&g, 3, x, n, 0.1, NULL, NULL), 0);
    memcpy(perm, g.order, sizeof *perm * n);
    cells_permute(x, 3 * sizeof *x, perm, n, scr);
    cells_permute(id, sizeof *id, perm, n, scr);
    char *seen = calloc(n, 1);
    for (int i = 0; i < n; i++) {
        assert_false(seen[id[i]]);
        seen[id[i]] = 1;
    }
    assert_int_equal(cells_build(&g, 3, x, n, 0.1, NULL, NULL), 0);
    for (int i = 0; i < n; i++) {
        assert_int_equal(g.order[i], i);
        if (i)
            assert_true(g.cell_of[i] >= g.cell_of[i - 1]);
    }
    cells_free(&g);
    free(seen); free(x); free(scr); free(perm); free(id);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_3d),
        cmocka_unit_test(test_half_cells),
        cmocka_unit_test(test_skin_3d),
        cmocka_unit_test(test_skin_2d),
        cmocka_unit_test(test_split_3d),
        cmocka_unit_test(test_random_2d),
        cmocka_unit_test(test_random_bbox),
        cmocka_unit_test(test_bad_cutoff),
        cmocka_unit_test(test_renumber),
        cmocka_unit_test(test_row_mask),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
