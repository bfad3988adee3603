/* test_operators.c — MPS lattice constants and operators against doc/theory.md
 * E1-01 ... E1-06, on lattices built particle by particle and searched with
 * the cell/neighbour lists that the solver uses. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "mps/kernel/kernel.h"
#include "mps/operators.h"
#include "particles/cells.h"
#include "particles/neighbour.h"

static void rel(double got, double want, double tol)
{
    if (fabs(got - want) > tol * fabs(want)) {
        print_error("got %.9g want %.9g (rel tol %g)\n", got, want, tol);
        fail();
    }
}

/* E1-01 / E1-02: n0, lambda and neighbour counts, Zhang kernel. */
static void test_lattice_constants(void **s)
{
    (void)s;
    static const struct { int dim; double re, n0, lambda; int nnb; } t[] = {
        { 3, 2.1, 11.079345, 1.737413, 32 },
        { 3, 3.1, 40.323180, 3.407209, 122 },
        { 3, 4.0, 90.607797, 5.562669, 250 },
        { 3, 4.1, 97.346970, 5.778138, 256 },
        { 2, 2.1, 4.915982, 1.415614, 12 },
        { 2, 4.0, 24.536028, 4.065986, 44 },
    };
    const double dp = 0.0027;
    for (size_t i = 0; i < sizeof t / sizeof *t; i++) {
        struct pop_lattice L;
        assert_int_equal(mps_lattice_constants(&mps_kernel_zhang2014, t[i].dim,
                                               dp, t[i].re * dp, &L), 0);
        rel(L.n0, t[i].n0, 1e-6);
        rel(L.lambda / (dp * dp), t[i].lambda, 1e-6);
        assert_int_equal(L.nnb, t[i].nnb);
    }
}

/* E1-06: |F0| and surface number density on a flat free surface, 3-D. */
static void test_surface_constants(void **s)
{
    (void)s;
    struct pop_lattice L;
    assert_int_equal(mps_lattice_constants(&mps_kernel_zhang2014, 3, 1.0, 2.1,
                                           &L), 0);
    assert_true(fabs(L.f0 - 0.6324) < 1e-4);
    assert_true(fabs(L.n_surf / L.n0 - 0.7219) < 1e-4);
    assert_int_equal(mps_lattice_constants(&mps_kernel_zhang2014, 3, 1.0, 4.1,
                                           &L), 0);
    assert_true(fabs(L.f0 - 0.7036) < 1e-4);
    assert_true(fabs(L.n_surf / L.n0 - 0.6330) < 1e-4);
    /* r_e not larger than dp is refused. */
    assert_int_not_equal(mps_lattice_constants(&mps_kernel_zhang2014, 3, 1.0,
                                               0.9, &L), 0);
}

struct lat {
    int n, dim, centre;
    double *x;
    struct cell_grid g;
    struct neighbour_list nl;
    double *w;
};

/* Lattice of (2m+1)^dim particles, or the lower half (surface at 0). */
static void lat_make(struct lat *l, int dim, int m, double dp, double re,
                     int half)
{
    int side = 2 * m + 1, zs = dim == 3 ? side : 1;
    memset(l, 0, sizeof *l);
    l->dim = dim;
    l->x = calloc(3 * (size_t)side * side * zs, sizeof *l->x);
    for (int a = -m; a <= m; a++)
        for (int b = -m; b <= m; b++)
            for (int c = (dim == 3 ? -m : 0); c <= (dim == 3 ? m : 0); c++) {
                int up = dim == 3 ? c : b;
                if (half && up > 0)
                    continue;
                if (!a && !b && !c)
                    l->centre = l->n;
                double *p = l->x + 3 * l->n++;
                /* a rotation-free offset keeps the lattice exact */
                p[0] = 0.3 + a * dp;
                p[1] = 0.2 + b * dp;
                p[2] = dim == 3 ? 0.1 + c * dp : 0;
            }
    assert_int_equal(cells_build(&l->g, dim, l->x, l->n, re, NULL, NULL), 0);
    assert_int_equal(neighbour_build(&l->nl, &l->g, l->x, re), 0);
    l->w = malloc(sizeof *l->w * (l->nl.nnz + 1));
    mps_kernel_zhang2014.weights(l->nl.r, l->nl.nnz, re, l->w);
}

static void lat_free(struct lat *l)
{
    cells_free(&l->g);
    neighbour_free(&l->nl);
    free(l->w);
    free(l->x);
}

/* E1-03, E1-04, E1-05 (interior), for both dimensions and two radii; the
 * number density of the centre equals the lattice n0 (fast path against
 * the direct lattice sum). */
static void test_interior_operators(void **s)
{
    (void)s;
    const double dp = 0.01, res[2] = { 2.1, 4.0 };
    for (int dim = 2; dim <= 3; dim++)
        for (int ir = 0; ir < 2; ir++) {
            double re = res[ir] * dp;
            struct lat l;
            lat_make(&l, dim, 5, dp, re, 0);
            struct pop_lattice L;
            mps_lattice_constants(&mps_kernel_zhang2014, dim, dp, re, &L);
            int n = l.n, c = l.centre;
            double *phi = malloc(sizeof *phi * n), *out = malloc(3 * sizeof *out * n);
            double *n_d = malloc(sizeof *n_d * n);
            mps_number_density(&l.nl, POP_STORED(l.w), NULL, NULL, n_d);
            rel(n_d[c], L.n0, 1e-12);
            /* Laplacian of |r - r_c|^2 is 2d. */
            const double *xc = l.x + 3 * c;
            for (int i = 0; i < n; i++) {
                double d2 = 0;
                for (int q = 0; q < 3; q++)
                    d2 += pow(l.x[3 * i + q] - xc[q], 2);
                phi[i] = d2;
            }
            mps_laplacian(&l.nl, POP_STORED(l.w), dim, L.n0, L.lambda, 1, phi, NULL, NULL, out);
            rel(out[c], 2.0 * dim, 1e-12);
            /* Gradient of a linear field is exact. */
            const double a[3] = { 1.5, -2.0, dim == 3 ? 0.7 : 0 };
            for (int i = 0; i < n; i++)
                phi[i] = 3.0 + a[0] * l.x[3*i] + a[1] * l.x[3*i+1] + a[2] * l.x[3*i+2];
            mps_gradient(&l.nl, POP_STORED(l.w), dim, L.n0, l.x, phi, NULL, NULL, out);
            for (int q = 0; q < dim; q++)
                assert_true(fabs(out[3 * c + q] - a[q]) < 1e-9 * 2.0);
            /* Constant field: zero gradient, interior (E1-05). */
            for (int i = 0; i < n; i++)
                phi[i] = 1000.0;
            mps_gradient(&l.nl, POP_STORED(l.w), dim, L.n0, l.x, phi, NULL, NULL, out);
            for (int q = 0; q < 3; q++)
                assert_true(fabs(out[3 * c + q]) < 1e-9 * 1000.0 / dp);
            /* Divergence of u = (x, y, z) is d; of a rigid rotation, 0. */
            double *u = malloc(3 * sizeof *u * n);
            for (int i = 0; i < n; i++)
                for (int q = 0; q < 3; q++)
                    u[3 * i + q] = q < dim ? l.x[3 * i + q] : 0;
            mps_divergence(&l.nl, POP_STORED(l.w), dim, L.n0, l.x, u, NULL, NULL, out);
            rel(out[c], dim, 1e-12);
            for (int i = 0; i < n; i++) {
                u[3*i] = -l.x[3*i+1]; u[3*i+1] = l.x[3*i]; u[3*i+2] = 0;
            }
            mps_divergence(&l.nl, POP_STORED(l.w), dim, L.n0, l.x, u, NULL, NULL, out);
            assert_true(fabs(out[c]) < 1e-12);
            /* Surface vector vanishes inside. */
            mps_surface_vector(&l.nl, POP_STORED(l.w), dim, L.n0, l.x, NULL, NULL, out);
            assert_true(fabs(out[3*c]) + fabs(out[3*c+1]) + fabs(out[3*c+2]) < 1e-12);
            free(u); free(phi); free(out); free(n_d);
            lat_free(&l);
        }
}

/* A list of the Laplacian's radius split at the gradient's (what the
 * solver does at 2.1 / 3.1 dp): the operators of the smaller radius give
 * the same values over the inner view as over whole rows, to round-off
 * (the zero weights are skipped, the order of the sum changes); weights
 * computed where they are read give the stored weights' results to the
 * bit. */
static void test_inner_view(void **s)
{
    (void)s;
    const double dp = 0.01, re = 2.1 * dp, rl = 3.1 * dp;
    const int dim = 3, side = 11;
    int n = 0;
    double *x = malloc(3 * sizeof *x * side * side * side);
    for (int a = 0; a < side; a++)
        for (int b = 0; b < side; b++)
            for (int c = 0; c < side; c++, n++) {
                double *p = x + 3 * n;
                p[0] = a * dp + 0.1 * dp * sin(1.3 * n);
                p[1] = b * dp + 0.1 * dp * cos(0.7 * n);
                p[2] = c * dp + 0.1 * dp * sin(2.9 * n);
            }
    struct cell_grid g = { 0 };
    struct neighbour_list nl = { .r_inner = re };
    assert_int_equal(cells_build(&g, dim, x, n, rl, NULL, NULL), 0);
    assert_int_equal(neighbour_build(&nl, &g, x, rl), 0);
    struct neighbour_list in = neighbour_inner(&nl);
    double *w = malloc(sizeof *w * (nl.nnz + 1));
    mps_kernel_zhang2014.weights(nl.r, nl.nnz, re, w);
    double *phi = malloc(sizeof *phi * n), *u = malloc(3 * sizeof *u * n);
    for (int i = 0; i < n; i++) {
        phi[i] = sin(40 * x[3 * i]) + x[3 * i + 1] * x[3 * i + 2] * 1e3;
        for (int q = 0; q < 3; q++)
            u[3 * i + q] = cos(30 * x[3 * i + q] + q);
    }
    double *a = malloc(3 * sizeof *a * n), *b = malloc(3 * sizeof *b * n);
    double *c = malloc(3 * sizeof *c * n);
    /* the same weights computed row by row where read (weights.h), on a
     * list that measures its distances again (neighbour.h measure_r):
     * every operator's result is the stored weights' to the bit */
    struct neighbour_list nm = { .r_inner = re, .measure_r = 1 };
    assert_int_equal(neighbour_build(&nm, &g, x, rl), 0);
    assert_true(nm.r == NULL && nm.nnz == nl.nnz);
    const int64_t cap = nm.max_row;
    double *buf = malloc(sizeof *buf * (size_t)(cap * omp_get_max_threads()));
    const struct pop_weights Wc = { .fn = mps_kernel_zhang2014.weights,
                                    .re = re, .buf = buf, .cap = cap };
    for (int op = 0; op < 5; op++) {
        const struct neighbour_list *v[2] = { &nl, &in };
        double *o[2] = { a, b };
        for (int k = 0; k < 3; k++) {
            const struct pop_weights *W = k < 2 ? POP_STORED(w) : &Wc;
            const struct neighbour_list *L = k < 2 ? v[k] : &nm;
            double *out = k < 2 ? o[k] : c;
            switch (op) {
            case 0: mps_number_density(L, W, NULL, NULL, out); break;
            case 1: mps_gradient(L, W, dim, 1.0, x, phi, NULL, NULL, out); break;
            case 2: mps_divergence(L, W, dim, 1.0, x, u, NULL, NULL, out); break;
            case 3: mps_surface_vector(L, W, dim, 1.0, x, NULL, NULL, out); break;
            default: mps_laplacian(L, W, dim, 1.0, 1.0, 3, u, NULL, NULL, out);
            }
        }
        int m = op == 0 || op == 2 ? n : 3 * n;
        double big = 0, d = 0;
        for (int i = 0; i < m; i++) {
            big = fmax(big, fabs(a[i]));
            d = fmax(d, fabs(a[i] - b[i]));
        }
        assert_true(big > 0 && d <= 1e-12 * big);
        assert_memory_equal(a, c, sizeof *a * (size_t)m);
    }
    free(buf); free(c);
    neighbour_free(&nm);
    /* the view really is shorter: 2.1 of 3.1 dp keeps under 40 % */
    int64_t kept = 0;
    for (int i = 0; i < n; i++)
        kept += neighbour_row_end(&in, i) - nl.start[i];
    assert_true(kept > 0 && kept < 0.4 * nl.nnz);
    free(a); free(b); free(phi); free(u); free(w); free(x);
    cells_free(&g);
    neighbour_free(&nl);
}

/* E1-05 (surface) and E1-06 through the fast path: a half lattice. The
 * constant-field gradient points into the fluid (down) and we record its
 * magnitude in units of p/dp. */
static void test_surface_particle(void **s)
{
    (void)s;
    const double dp = 0.01, re = 2.1 * dp;
    struct lat l;
    lat_make(&l, 3, 5, dp, re, 1);
    struct pop_lattice L;
    mps_lattice_constants(&mps_kernel_zhang2014, 3, dp, re, &L);
    int n = l.n, c = l.centre;
    double *out = malloc(3 * sizeof *out * n), *nd = malloc(sizeof *nd * n);
    double *phi = malloc(sizeof *phi * n);
    mps_surface_vector(&l.nl, POP_STORED(l.w), 3, L.n0, l.x, NULL, NULL, out);
    double F = sqrt(out[3*c]*out[3*c] + out[3*c+1]*out[3*c+1] + out[3*c+2]*out[3*c+2]);
    assert_true(fabs(F - 0.6324) < 1e-4);
    assert_true(out[3 * c + 2] < 0);
    mps_number_density(&l.nl, POP_STORED(l.w), NULL, NULL, nd);
    assert_true(fabs(nd[c] / L.n0 - 0.7219) < 1e-4);
    for (int i = 0; i < n; i++)
        phi[i] = 1.0;
    mps_gradient(&l.nl, POP_STORED(l.w), 3, L.n0, l.x, phi, NULL, NULL, out);
    assert_true(out[3 * c + 2] < 0);
    assert_true(fabs(out[3 * c]) < 1e-9 && fabs(out[3 * c + 1]) < 1e-9);
    print_message("constant-field gradient at a flat surface: %.4f p/dp "
                  "(downwards)\n", -out[3 * c + 2] * dp);
    free(out); free(nd); free(phi);
    lat_free(&l);
}

/* Porosity hook: 1/eps_j = 1 gives the same numbers as NULL; a uniform
 * eps = 0.5 doubles every sum (eqs. 7-10). */
static void test_inv_eps(void **s)
{
    (void)s;
    const double dp = 0.01, re = 2.1 * dp;
    struct lat l;
    lat_make(&l, 2, 4, dp, re, 0);
    int n = l.n;
    double *ie = malloc(sizeof *ie * n), *a = malloc(sizeof *a * n),
           *b = malloc(sizeof *b * n);
    for (int i = 0; i < n; i++)
        ie[i] = 1.0;
    mps_number_density(&l.nl, POP_STORED(l.w), NULL, NULL, a);
    mps_number_density(&l.nl, POP_STORED(l.w), ie, NULL, b);
    assert_memory_equal(a, b, sizeof *a * n);
    for (int i = 0; i < n; i++)
        ie[i] = 2.0;
    mps_number_density(&l.nl, POP_STORED(l.w), ie, NULL, b);
    for (int i = 0; i < n; i++)
        rel(b[i], 2 * a[i], 1e-15);
    free(ie); free(a); free(b);
    lat_free(&l);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lattice_constants),
        cmocka_unit_test(test_surface_constants),
        cmocka_unit_test(test_interior_operators),
        cmocka_unit_test(test_inner_view),
        cmocka_unit_test(test_surface_particle),
        cmocka_unit_test(test_inv_eps),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
