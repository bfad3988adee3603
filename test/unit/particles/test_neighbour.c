/* test_neighbour.c — the neighbour service of the particle layer against
 * O(n^2) references on random sets:
 * - full CSR self lists (2-D and 3-D, with particles outside the box and
 *   NaN positions; cells of the cut-off and of half of it; a Verlet list
 *   with a skin updated after moves; rows split at an inner radius; rows
 *   left empty by a mask), and cell-order renumbering;
 * - half self lists with radii (polydisperse, a far point that makes the
 *   grid coarsen), per-pair history carried over a rebuild after moves,
 *   staleness, a non-finite position refused;
 * - cross lists between two clouds (2-D and 3-D, NaN and far points in B,
 *   empty clouds), both layouts, independence of the thread count, the
 *   Verlet-skin update. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <omp.h>

#include "core/error.h"
#include "particles/cells.h"
#include "particles/neighbour.h"
#include "particles/neighbour_cross.h"
#include "particles/neighbour_half.h"

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
    /* every candidate selected: the entries outgrow their room (they hold
     * the pairs within rc, not the candidates) and the update grows them */
    size_t room = fast.cap_nnz;
    fast.rc = rc + skin;
    assert_int_equal(neighbour_update(&fast, x), 0);
    assert_true(fast.nnz == fast.nnz_cand && (size_t)fast.nnz > room);
    assert_int_equal(neighbour_build_brute(&ref, dim, x, n, rc + skin), 0);
    compare(&fast, &ref, x);
    fast.rc = rc;
    const double a = 0.499 * skin / sqrt(dim) / 2; /* two moves < skin/2 */
    const int threads = omp_get_max_threads();
    for (int move = 0; move < 2; move++) {
        for (int i = 0; i < n; i++)
            for (int k = 0; k < dim; k++)
                x[3 * i + k] += a * (2 * urand() - 1);
        /* the candidates stay in the build's blocks: an update with
         * another thread count reads them there */
        omp_set_num_threads(move ? threads + 1 : 1);
        int rc_update = neighbour_update(&fast, x);
        omp_set_num_threads(threads);
        assert_int_equal(rc_update, 0);
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
        assert_int_equal(neighbour_update(&all, x), 0);
        assert_int_equal(neighbour_update(&some, x), 0);
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
    /* the solver renumbers through its field registry (store_permute):
     * new i <- old perm[i] */
    for (int i = 0; i < n; i++)
        memcpy(scr + 3 * i, x + 3 * perm[i], 3 * sizeof *x);
    memcpy(x, scr, 3 * sizeof *x * n);
    int32_t *idn = malloc(sizeof *idn * n);
    for (int i = 0; i < n; i++)
        idn[i] = id[perm[i]];
    memcpy(id, idn, sizeof *id * n);
    free(idn);
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

/* ---- half self lists ------------------------------------------------ */

/* n points with radii in [R, 2R] at random in the unit cube (z = 0 when
 * flat), one far away: the grid of cells 2 R_max + skin would need 10^9
 * cells and must coarsen instead. */
static void half_cloud(int n, int flat, double R, double *x, double *r)
{
    for (int i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++)
            x[3 * i + k] = k == 2 && flat ? 0.0 : urand();
        r[i] = R * (1 + urand());
    }
    x[3 * (n - 1)] = 1e3;
}

/* The cell build gives the brute-force list exactly (rows sorted, j > i),
 * before and after the points move. */
static void half_case(int n, int flat)
{
    double *x = malloc(3 * sizeof *x * n), *r = malloc(sizeof *r * n);
    half_cloud(n, flat, 0.02, x, r);
    struct neighbour_half fast, ref;
    neighbour_half_init(&fast, 0.004);
    neighbour_half_init(&ref, 0.004);
    for (int pass = 0; pass < 2; pass++) {
        assert_int_equal(neighbour_half_build(&fast, n, x, r), SIM_OK);
        assert_int_equal(neighbour_half_build_brute(&ref, n, x, r), SIM_OK);
        assert_int_equal(fast.n, n);
        assert_int_equal(fast.npairs, ref.npairs);
        assert_true(fast.npairs > (size_t)n);
        assert_memory_equal(fast.start, ref.start, (n + 1) * sizeof(size_t));
        assert_memory_equal(fast.j, ref.j, fast.npairs * sizeof(uint32_t));
        for (int i = 0; i < n; i++)
            for (size_t p = fast.start[i]; p < fast.start[i + 1]; p++)
                assert_true(fast.j[p] > (uint32_t)i
                            && (p == fast.start[i]
                                || fast.j[p] > fast.j[p - 1]));
        for (int i = 0; i < 3 * (n - 1); i++)
            x[i] = fmod(x[i] + 0.3 + 0.01 * urand(), 1.0);
    }
    neighbour_half_free(&fast);
    neighbour_half_free(&ref);
    free(x);
    free(r);
}

static void test_half_3d(void **s) { (void)s; half_case(3000, 0); }
static void test_half_flat(void **s) { (void)s; half_case(2000, 1); }

/* History: every pair of the old list holds (i, j); after moves and a
 * rebuild, pairs present before keep their (i, j), new pairs hold zeros;
 * staleness follows half the skin. */
static void test_half_carry(void **st)
{
    (void)st;
    const int n = 2000;
    double *x = malloc(3 * sizeof *x * n), *r = malloc(sizeof *r * n);
    half_cloud(n, 0, 0.02, x, r);
    struct neighbour_half nl;
    neighbour_half_init(&nl, 0.004);
    assert_int_equal(neighbour_half_build(&nl, n, x, r), SIM_OK);
    size_t on = nl.n, onp = nl.npairs;
    size_t *ostart = malloc((on + 1) * sizeof *ostart);
    uint32_t *oj = malloc((onp + 1) * sizeof *oj);
    double *oval = malloc(2 * (onp + 1) * sizeof *oval);
    memcpy(ostart, nl.start, (on + 1) * sizeof *ostart);
    memcpy(oj, nl.j, onp * sizeof *oj);
    for (size_t i = 0; i < on; i++)
        for (size_t p = ostart[i]; p < ostart[i + 1]; p++) {
            oval[2 * p] = (double)i;
            oval[2 * p + 1] = (double)oj[p];
        }
    assert_false(neighbour_half_stale(&nl, n, x));
    for (int i = 0; i < 3 * (n - 1); i++)
        x[i] += 0.006 * (2 * urand() - 1);   /* up to 2.6 skins */
    assert_true(neighbour_half_stale(&nl, n, x));
    assert_true(neighbour_half_stale(&nl, n - 1, x));
    assert_int_equal(neighbour_half_build(&nl, n, x, r), SIM_OK);
    double *val = malloc(2 * (nl.npairs + 1) * sizeof *val);
    neighbour_half_carry(&nl, ostart, oj, on, oval, 2, val);
    size_t kept = 0, fresh = 0;
    for (size_t i = 0; i < nl.n; i++)
        for (size_t p = nl.start[i]; p < nl.start[i + 1]; p++) {
            int was = 0;
            for (size_t q = ostart[i]; q < ostart[i + 1]; q++)
                was |= oj[q] == nl.j[p];
            if (was) {
                assert_true(val[2 * p] == (double)i
                            && val[2 * p + 1] == (double)nl.j[p]);
                kept++;
            } else {
                assert_true(val[2 * p] == 0 && val[2 * p + 1] == 0);
                fresh++;
            }
        }
    assert_true(kept > 100 && fresh > 100);
    /* a non-finite position is an error, not a silently lost point */
    x[7] = NAN;
    assert_int_equal(neighbour_half_build(&nl, n, x, r), SIM_ERR_NUMERIC);
    neighbour_half_free(&nl);
    free(ostart); free(oj); free(oval); free(val); free(x); free(r);
}

/* ---- cross lists ------------------------------------------------------ */

struct jr { int32_t j; double r; };
static int cmp_jr(const void *a, const void *b)
{
    const struct jr *x = a, *y = b;
    return (x->j > y->j) - (x->j < y->j);
}

/* Same pairs as the brute-force list: A-major rows equal as sets with
 * distances equal to the bit (the same arithmetic), B-major rows equal,
 * and bmap pointing at the A-major entry of each pair. */
static void cross_compare(const struct neighbour_cross *F,
                          const struct neighbour_cross *B)
{
    assert_int_equal(F->npair, B->npair);
    assert_memory_equal(F->astart, B->astart, (F->na + 1) * sizeof(int64_t));
    struct jr *a = malloc((F->npair + 1) * sizeof *a);
    for (int k = 0; k < F->na; k++) {
        int64_t e0 = F->astart[k], m = F->astart[k + 1] - e0;
        for (int64_t e = 0; e < m; e++)
            a[e] = (struct jr){ F->aj[e0 + e], F->ar[e0 + e] };
        qsort(a, (size_t)m, sizeof *a, cmp_jr);
        for (int64_t e = 0; e < m; e++) {
            assert_int_equal(a[e].j, B->aj[e0 + e]);
            assert_true(a[e].r == B->ar[e0 + e]);
        }
    }
    free(a);
    assert_memory_equal(F->bstart, B->bstart, (F->nb + 1) * sizeof(int64_t));
    if (F->npair)
        assert_memory_equal(F->bk, B->bk, F->npair * sizeof(int32_t));
    for (int i = 0; i < F->nb; i++)
        for (int64_t e = F->bstart[i]; e < F->bstart[i + 1]; e++) {
            int64_t g = F->bmap[e];
            assert_true(F->aj[g] == i && g >= F->astart[F->bk[e]]
                        && g < F->astart[F->bk[e] + 1]);
        }
}

static int64_t cross_case(int dim, int na, int nb, double box_a, double box_b,
                          double rc)
{
    double *xa = calloc(3 * (size_t)na + 3, sizeof *xa);
    double *xb = calloc(3 * (size_t)nb + 3, sizeof *xb);
    for (int k = 0; k < na; k++)
        for (int c = 0; c < dim; c++)
            xa[3 * k + c] = box_a * urand();
    for (int i = 0; i < nb; i++)
        for (int c = 0; c < dim; c++)
            xb[3 * i + c] = box_b * (urand() - 0.25);
    if (nb > 3)
        xb[3] = NAN;                       /* escaped: no pairs */
    if (nb > 4)
        xb[12] = 1e6;                      /* far outside the box of A */
    if (nb > 5 && na > 0)                  /* exactly at a point of A */
        memcpy(xb + 15, xa, 3 * sizeof *xb);
    struct neighbour_cross F = { 0 }, B = { 0 }, T = { 0 };
    assert_int_equal(neighbour_cross_build(&F, dim, rc, na, xa, nb, xb), 0);
    assert_int_equal(neighbour_cross_build_brute(&B, dim, rc, na, xa, nb,
                                                 xb), 0);
    cross_compare(&F, &B);
    if (nb > 4)
        assert_true(F.bstart[2] == F.bstart[1] && F.bstart[5] == F.bstart[4]);
    /* one thread gives the same lists, entry for entry */
    int nt = omp_get_max_threads();
    omp_set_num_threads(1);
    assert_int_equal(neighbour_cross_build(&T, dim, rc, na, xa, nb, xb), 0);
    omp_set_num_threads(nt);
    assert_int_equal(T.npair, F.npair);
    if (F.npair) {
        assert_memory_equal(T.aj, F.aj, F.npair * sizeof *F.aj);
        assert_memory_equal(T.ar, F.ar, F.npair * sizeof *F.ar);
        assert_memory_equal(T.bmap, F.bmap, F.npair * sizeof *F.bmap);
    }
    int64_t npair = F.npair;
    neighbour_cross_free(&F);
    neighbour_cross_free(&B);
    neighbour_cross_free(&T);
    free(xa);
    free(xb);
    return npair;
}

static void test_cross(void **st)
{
    (void)st;
    for (int dim = 2; dim <= 3; dim++) {
        assert_true(cross_case(dim, 200, 5000, 0.05, 0.1, 0.011) > 1000);
        assert_true(cross_case(dim, 1, 500, 0.05, 0.1, 0.03) > 0);
        assert_int_equal(cross_case(dim, 0, 500, 0.05, 0.1, 0.011), 0);
        assert_int_equal(cross_case(dim, 50, 0, 0.05, 0.1, 0.011), 0);
        assert_true(cross_case(dim, 30, 400, 0.01, 0.02, 0.5) > 1000);
        assert_true(cross_case(dim, 300, 3000, 50.0, 60.0, 0.3) > 0);
    }
}

/* Verlet skin: after moves with shift_A + shift_B < skin the list is only
 * refreshed, and its pairs within rc are exactly the brute-force ones at
 * the new positions; a larger move searches again. */
static void test_cross_update(void **st)
{
    (void)st;
    const int na = 150, nb = 4000, dim = 3;
    const double rc = 0.012, skin = 0.004;
    double *xa = malloc(3 * sizeof *xa * na), *xb = malloc(3 * sizeof *xb * nb);
    for (int k = 0; k < 3 * na; k++)
        xa[k] = 0.05 * urand();
    for (int i = 0; i < 3 * nb; i++)
        xb[i] = 0.08 * urand() - 0.015;
    struct neighbour_cross X = { 0 }, B = { 0 };
    int searched = -1;
    assert_int_equal(neighbour_cross_update(&X, dim, rc, skin, na, xa, nb, xb,
                                            &searched), 0);
    assert_int_equal(searched, 1);
    const double a = 0.24 * skin / sqrt(3.0);   /* |shift| < 0.24 skin */
    for (int move = 0; move < 3; move++) {
        double *y = move == 2 ? xb : xa;
        int m = move == 2 ? nb : na;
        for (int k = 0; k < 3 * m; k++)
            y[k] += (move == 2 ? 3 : 1) * a * (2 * urand() - 1);
        assert_int_equal(neighbour_cross_update(&X, dim, rc, skin, na, xa, nb,
                                                xb, &searched), 0);
        assert_int_equal(searched, move == 2);
        assert_int_equal(neighbour_cross_build_brute(&B, dim, rc, na, xa, nb,
                                                     xb), 0);
        int64_t within = 0;
        for (int k = 0; k < na; k++)
            for (int64_t e = X.astart[k]; e < X.astart[k + 1]; e++) {
                if (!(X.ar[e] < rc))
                    continue;
                within++;
                int hit = 0;
                for (int64_t f = B.astart[k]; f < B.astart[k + 1]; f++)
                    hit |= B.aj[f] == X.aj[e] && B.ar[f] == X.ar[e];
                assert_true(hit);
            }
        assert_int_equal(within, B.npair);
        assert_true(move == 2 || X.npair > B.npair);
    }
    neighbour_cross_invalidate(&X);
    assert_int_equal(neighbour_cross_update(&X, dim, rc, skin, na, xa, nb, xb,
                                            &searched), 0);
    assert_int_equal(searched, 1);
    xa[4] = INFINITY;
    assert_int_equal(neighbour_cross_update(&X, dim, rc, skin, na, xa, nb, xb,
                                            &searched), SIM_ERR_NUMERIC);
    neighbour_cross_free(&X);
    neighbour_cross_free(&B);
    free(xa);
    free(xb);
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
        cmocka_unit_test(test_half_3d),
        cmocka_unit_test(test_half_flat),
        cmocka_unit_test(test_half_carry),
        cmocka_unit_test(test_cross),
        cmocka_unit_test(test_cross_update),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
