/* test_mlpg_box.c — what the fluid exerts on the walls of an MLPG cloud
 * (src/mlpg/wall_stress.c, doc/theory.md M0-24) and node shifting
 * (src/mlpg/shifting.c, M0-25), on a closed box of (N+1)^2 nodes after
 * one solver step:
 *   wall_stress_quadratic  for a quadratic velocity field the viscous
 *                          traction mu (grad u + grad u^T) . n_f of every
 *                          wall node, corners included, is exact to
 *                          round-off (the second-order fit is exact);
 *   wall_stress_area       each wall node stands for dl on a straight wall
 *                          and dl/sqrt(2) at a right-angled corner, so
 *                          that sum A n over a closed box is zero;
 *   wall_stress_dry        a dry wall node (left out of every row) gets
 *                          neither area nor traction;
 *   shift_lattice          on the regular lattice no node moves (to
 *                          1e-12 dl), walls and corners included;
 *   shift_restores         an interior node put 0.3 dl off its site moves
 *                          back towards it by at most the cap 0.1 dl, and
 *                          its neighbours move less;
 *   shift_surface          a free-surface node moves only across its
 *                          F = sum r_ij/|r_ij| w.
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
#include "linsolve/linsolve.h"
#include "mlpg/mlpg_solver.h"
#include "particles/operators/operators.h"

#define N 10
#define DL 0.1
#define RHO 1000.0
#define NU 1e-3

/* The quadratic field and its gradient g[c][d] = d u_c / d x_d. */
static void field(double x, double y, double u[3])
{
    u[0] = 0.3 + 0.7 * y - 1.1 * y * y + 0.4 * x * y;
    u[1] = -0.2 * x + 0.9 * x * x - 0.4 * y * y / 2 + 0.5 * x * y;
    u[2] = 0;
}

static void gradient(double x, double y, double g[2][2])
{
    g[0][0] = 0.4 * y;
    g[0][1] = 0.7 - 2.2 * y + 0.4 * x;
    g[1][0] = -0.2 + 1.8 * x + 0.5 * y;
    g[1][1] = -0.4 * y + 0.5 * x;
}

static void make_box_shift(struct mlpg_solver *s, int shift)
{
    memset(s, 0, sizeof *s);
    int n = (N + 1) * (N + 1);
    assert_int_equal(mlpg_fields_alloc(s, n), SIM_OK);
    for (int j = 0; j <= N; j++)
        for (int i = 0; i <= N; i++) {
            int a = j * (N + 1) + i;
            double nx = i == 0 ? -1 : i == N ? 1 : 0;
            double ny = j == 0 ? -1 : j == N ? 1 : 0;
            double len = hypot(nx, ny);
            s->x[3 * a] = i * DL;
            s->x[3 * a + 1] = j * DL;
            s->type[a] = len > 0 ? MLPG_WALL : MLPG_FLUID;
            s->patch[a] = len > 0 ? 0 : -1;
            s->normal[3 * a] = len > 0 ? nx / len : 0;
            s->normal[3 * a + 1] = len > 0 ? ny / len : 0;
            s->id[a] = a;
        }
    struct mlpg_settings S = {
        .rho = RHO, .nu = NU, .dl = DL, .wall = &mlpg_wall_improved,
        .nodes = shift ? MLPG_NODES_LAGRANGIAN : MLPG_NODES_FIXED,
        .support = 1.85, .radius = 0.8,
        .has_pref = 1, .pref_point = { 0.5, 0.5, 0 },
        .shift = shift, .shift_coeff = 0.05,
    };
    struct linsolve *ls;
    assert_int_equal(linsolve_create_named("bicgstab", "ilu0", 1e-10, 500,
                                           &ls), SIM_OK);
    assert_int_equal(mlpg_solver_init(s, &S, ls), SIM_OK);
    assert_int_equal(mlpg_step(s, 1e-3), SIM_OK); /* the rows exist */
    for (int a = 0; a < n; a++)
        field(s->x[3 * a], s->x[3 * a + 1], s->u + 3 * a);
}

static void make_box(struct mlpg_solver *s) { make_box_shift(s, 0); }

/* The largest move of any node by one mlpg_shift [dl], x0 before it. */
static double largest_move(const struct mlpg_solver *s, const double *x0)
{
    double m = 0;
    for (int a = 0; a < s->n; a++)
        m = fmax(m, hypot(s->x[3 * a] - x0[3 * a],
                          s->x[3 * a + 1] - x0[3 * a + 1]) / DL);
    return m;
}

static void test_shift_lattice(void **state)
{
    (void)state;
    struct mlpg_solver s;
    make_box_shift(&s, MLPG_SHIFT_LIND2012);
    double *x0 = malloc(3 * sizeof(double) * s.n);
    assert_non_null(x0);
    memcpy(x0, s.x, 3 * sizeof(double) * s.n);
    mlpg_shift(&s);
    assert_true(largest_move(&s, x0) < 1e-12);
    free(x0);
    mlpg_solver_free(&s);
}

static void test_shift_restores(void **state)
{
    (void)state;
    struct mlpg_solver s;
    make_box_shift(&s, MLPG_SHIFT_LIND2012);
    int a = 4 * (N + 1) + 4; /* not the pinned centre node */
    double site[2] = { s.x[3 * a], s.x[3 * a + 1] };
    s.x[3 * a] += 0.3 * DL;
    double *x0 = malloc(3 * sizeof(double) * s.n);
    assert_non_null(x0);
    memcpy(x0, s.x, 3 * sizeof(double) * s.n);
    mlpg_shift(&s);
    double before = 0.3 * DL;
    double after = hypot(s.x[3 * a] - site[0], s.x[3 * a + 1] - site[1]);
    double own = hypot(s.x[3 * a] - x0[3 * a], s.x[3 * a + 1] - x0[3 * a + 1]);
    assert_true(after < before - 1e-3 * DL);             /* back ...      */
    assert_true(own <= 0.1 * DL * (1 + 1e-12));          /* ... capped    */
    assert_true(fabs(s.x[3 * a + 1] - site[1]) < 1e-12); /* along x only  */
    for (int b = 0; b < s.n; b++)
        if (b != a)
            assert_true(hypot(s.x[3 * b] - x0[3 * b],
                              s.x[3 * b + 1] - x0[3 * b + 1]) < own);
    for (int b = 0; b < s.n; b++) /* walls stay */
        if (s.type[b] == MLPG_WALL)
            assert_true(s.x[3 * b] == x0[3 * b]
                        && s.x[3 * b + 1] == x0[3 * b + 1]);
    free(x0);
    mlpg_solver_free(&s);
}

static void test_shift_surface(void **state)
{
    (void)state;
    struct mlpg_solver s;
    make_box_shift(&s, MLPG_SHIFT_LIND2012);
    int a = 5 * (N + 1) + 5;
    s.x[3 * a] += 0.3 * DL;
    s.x[3 * a + 1] += 0.2 * DL;
    s.surface[a] = 1;
    double G[3], F[3], x0[2] = { s.x[3 * a], s.x[3 * a + 1] };
    double *count = malloc(sizeof(double) * s.n);
    assert_non_null(count);
    for (int b = 0; b < s.n; b++)
        count[b] = 1;
    pop_concentration_gradient(&s.nl, s.x, count, mlpg_weight, s.c.rs, 1, a,
                               G, F);
    free(count);
    mlpg_shift(&s);
    double d[2] = { s.x[3 * a] - x0[0], s.x[3 * a + 1] - x0[1] };
    assert_true(hypot(d[0], d[1]) > 1e-3 * DL);               /* it moves */
    assert_true(fabs(d[0] * F[0] + d[1] * F[1])
                < 1e-12 * hypot(F[0], F[1]) * DL);           /* across F */
    mlpg_solver_free(&s);
}

static void test_wall_stress_quadratic(void **state)
{
    (void)state;
    struct mlpg_solver s;
    make_box(&s);
    mlpg_wall_stress(&s);
    const double mu = RHO * NU;
    int walls = 0;
    for (int a = 0; a < s.n; a++) {
        const double *t = s.traction + 3 * a;
        if (s.type[a] != MLPG_WALL) {
            assert_true(t[0] == 0 && t[1] == 0 && s.wall_area[a] == 0);
            continue;
        }
        double g[2][2], nf[2] = { -s.normal[3 * a], -s.normal[3 * a + 1] };
        gradient(s.x[3 * a], s.x[3 * a + 1], g);
        for (int c = 0; c < 2; c++) {
            double want = mu * ((g[c][0] + g[0][c]) * nf[0]
                                + (g[c][1] + g[1][c]) * nf[1]);
            if (fabs(t[c] - want) > 1e-9 * mu) {
                print_error("node %d (%g, %g): t_%d = %.15g, expected "
                            "%.15g\n", a, s.x[3 * a], s.x[3 * a + 1], c,
                            t[c], want);
                fail();
            }
        }
        walls++;
    }
    assert_int_equal(walls, 4 * N);
    mlpg_solver_free(&s);
}

static void test_wall_stress_area(void **state)
{
    (void)state;
    struct mlpg_solver s;
    make_box(&s);
    mlpg_wall_stress(&s);
    double sum[2] = { 0, 0 }, total = 0;
    for (int a = 0; a < s.n; a++) {
        if (s.type[a] != MLPG_WALL)
            continue;
        int corner = s.normal[3 * a] != 0 && s.normal[3 * a + 1] != 0;
        assert_true(fabs(s.wall_area[a] - (corner ? DL / sqrt(2) : DL))
                    < 1e-12);
        for (int c = 0; c < 2; c++)
            sum[c] += s.wall_area[a] * s.normal[3 * a + c];
        total += s.wall_area[a];
    }
    /* a closed polygon: sum A n = 0, and 4 N dl less the four corners'
     * (1 - 1/sqrt 2) dl */
    assert_true(fabs(sum[0]) < 1e-12 && fabs(sum[1]) < 1e-12);
    assert_true(fabs(total - (4 * N - 4 + 4 / sqrt(2)) * DL) < 1e-12);
    mlpg_solver_free(&s);
}

static void test_wall_stress_dry(void **state)
{
    (void)state;
    struct mlpg_solver s;
    make_box(&s);
    int a = N / 2; /* a bottom wall node */
    s.exclude[a] = 1;
    mlpg_wall_stress(&s);
    assert_true(s.wall_area[a] == 0 && s.traction[3 * a] == 0
                && s.traction[3 * a + 1] == 0);
    assert_true(s.wall_area[a + 1] > 0);
    mlpg_solver_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_wall_stress_quadratic),
        cmocka_unit_test(test_wall_stress_area),
        cmocka_unit_test(test_wall_stress_dry),
        cmocka_unit_test(test_shift_lattice),
        cmocka_unit_test(test_shift_restores),
        cmocka_unit_test(test_shift_surface),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
