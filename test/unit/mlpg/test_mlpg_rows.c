/*
 * test_mlpg_rows.c — the rows of the MLPG_R pressure equation
 * (src/mlpg; doc/theory.md M.2-M.6), checks E3-01 ... E3-05 of
 * doc/theory.md E.3, on jittered clouds whose wall is rotated by 30
 * degrees (so that no check leans on an axis-aligned frame):
 *
 *   E3-01 fluid row: p constant and p linear give 0; uniform u* gives a
 *         zero domain integral over the full circle (1e-12)
 *   E3-02 fluid row, u* = (D/2)(x - x_I): (rho/dt) D_I = f R^2/4 (1e-12);
 *         the row on p = f r^2/4 (MLS is linear: error reported, bound)
 *   E3-03 wall row, hydrostatic: LHS = RHS = -rho g R/pi within 0.3 %
 *         (4-point half-circle quadrature: -0.16 %), both wall schemes,
 *         and the quarter disc of a container corner (doc M0-07)
 *   E3-04 wall row, fluid and wall translating together: b = 0 (1e-12)
 *   E3-05 (S-6): int_0^R ln(s/R)/2pi ds = -R/2pi per side (1e-8)
 * plus the MLS shape functions (partition of unity, linear
 * reproduction) and the SFDI gradient (exact for linear p).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/error.h"
#include "linsolve/csr.h"
#include "mlpg/mlpg.h"
#include "particles/lattice.h"
#include "particles/neighbour.h"

#define PI 3.141592653589793

/* A cloud on [0, (nx-1) dl] x [0, (ny-1) dl] rotated by rot about the
 * origin: the row y = 0 is a wall (normal +y), and with `corner` the
 * column x = 0 too (normal +x), the node at the origin a 90-degree
 * corner (bisector normal, sector pi/2). Fluid nodes are jittered by
 * +-k dl/2 per coordinate, wall nodes along their wall only. */
struct cloud {
    struct mlpg_cloud c;
    struct neighbour_list nl;
    double *x, *normal, *sector, *R;
    int32_t *type;
};

static void make_cloud(struct cloud *cl, int nx, int ny, double dl, double k,
                       double rot, int corner, uint64_t seed)
{
    int n = nx * ny;
    *cl = (struct cloud){ 0 };
    cl->x = calloc(3 * (size_t)n, sizeof(double));
    cl->normal = calloc(3 * (size_t)n, sizeof(double));
    cl->sector = calloc((size_t)n, sizeof(double));
    cl->R = calloc((size_t)n, sizeof(double));
    cl->type = calloc((size_t)n, sizeof(int32_t));
    double *jit = calloc(3 * (size_t)n, sizeof(double));
    lattice_jitter(jit, (size_t)n, 2, k * dl / 2, seed);
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            int a = j * nx + i;
            double px = i * dl, py = j * dl, nx_ = 0, ny_ = 0;
            int wall = j == 0 || (corner && i == 0);
            if (!wall) {
                px += jit[3 * a];
                py += jit[3 * a + 1];
            } else if (j == 0 && !(corner && i == 0)) {
                px += jit[3 * a];
                ny_ = 1;
            } else if (i == 0 && j > 0) {
                py += jit[3 * a + 1];
                nx_ = 1;
            } else {
                nx_ = ny_ = sqrt(0.5);
            }
            cl->x[3 * a] = cos(rot) * px - sin(rot) * py;
            cl->x[3 * a + 1] = sin(rot) * px + cos(rot) * py;
            cl->normal[3 * a] = cos(rot) * nx_ - sin(rot) * ny_;
            cl->normal[3 * a + 1] = sin(rot) * nx_ + cos(rot) * ny_;
            cl->type[a] = wall ? MLPG_WALL : MLPG_FLUID;
            cl->sector[a] = !wall ? 2 * PI : (nx_ != 0 && ny_ != 0) ? PI / 2
                                                                   : PI;
        }
    free(jit);
    cl->c = (struct mlpg_cloud){
        .n = n, .dl = dl, .rs = 1.85 * dl, .R0 = 0.8 * dl, .x = cl->x,
        .type = cl->type, .normal = cl->normal, .sector = cl->sector,
        .R = cl->R, .nl = &cl->nl,
    };
    assert_int_equal(neighbour_build_brute(&cl->nl, 2, cl->x, n, 2.7 * dl),
                     SIM_OK);
    mlpg_radii(&cl->c, cl->R);
}

static void free_cloud(struct cloud *cl)
{
    neighbour_free(&cl->nl);
    free(cl->x), free(cl->normal), free(cl->sector), free(cl->R);
    free(cl->type);
}

/* Row of node i under scheme w applied to the nodal field p: sum coef p. */
static double row_dot(const struct cloud *cl, const struct mlpg_wall_ops *w,
                      int i, const double *p)
{
    int32_t cand[64];
    double coef[64], work[5 * 64];
    int m = mlpg_candidates(&cl->c, i, cand);
    assert_true(m <= 64);
    assert_int_equal(w->row(&cl->c, i, cand, m, coef, work), SIM_OK);
    double s = 0;
    for (int k = 0; k < m; k++)
        s += coef[k] * p[cand[k]];
    return s;
}

static double domain(const struct cloud *cl, int i, const double *ustar)
{
    int32_t cand[64];
    double work[5 * 64], D;
    int m = mlpg_candidates(&cl->c, i, cand);
    assert_int_equal(mlpg_domain_integral(&cl->c, i, cand, m, ustar, work,
                                          &D), SIM_OK);
    return D;
}

static void test_mls(void **state)
{
    (void)state;
    struct cloud cl;
    make_cloud(&cl, 9, 9, 0.1, 0.5, 0.3, 1, 7);
    int32_t cand[81];
    double phi[81];
    for (int i = 0; i < 81; i++)
        cand[i] = i;
    double pts[3][2] = { { 0.31, 0.47 }, { 0.02, 0.05 }, { 0.4, 0.05 } };
    for (int t = 0; t < 3; t++) {
        double p[2] = { cos(0.3) * pts[t][0] - sin(0.3) * pts[t][1],
                        sin(0.3) * pts[t][0] + cos(0.3) * pts[t][1] };
        assert_int_equal(mlpg_mls(&cl.c, cand, 81, p, phi), SIM_OK);
        double s = 0, sx = 0, sy = 0;
        for (int k = 0; k < 81; k++) {
            s += phi[k];
            sx += phi[k] * cl.x[3 * k];
            sy += phi[k] * cl.x[3 * k + 1];
        }
        assert_true(fabs(s - 1) < 1e-12);
        assert_true(fabs(sx - p[0]) < 1e-12 && fabs(sy - p[1]) < 1e-12);
    }
    /* too few nodes: an error, not a NaN */
    double far[2] = { 5, 5 };
    assert_int_equal(mlpg_mls(&cl.c, cand, 81, far, phi), SIM_ERR_NUMERIC);
    sim_error_clear();
    /* SFDI: exact gradient of a linear field at a wall node */
    int i = 4; /* bottom wall */
    double (*a)[2] = calloc(64, sizeof *a);
    int m = mlpg_candidates(&cl.c, i, cand);
    assert_int_equal(mlpg_sfdi(&cl.c, i, cand, m, a), SIM_OK);
    double g[2] = { 0, 0 };
    for (int k = 0; k < m; k++) {
        double dp = 2 * (cl.x[3 * cand[k]] - cl.x[3 * i])
                  - 3 * (cl.x[3 * cand[k] + 1] - cl.x[3 * i + 1]);
        g[0] += a[k][0] * dp;
        g[1] += a[k][1] * dp;
    }
    assert_true(fabs(g[0] - 2) < 1e-12 && fabs(g[1] + 3) < 1e-12);
    free(a);
    free_cloud(&cl);
}

static void test_e3_01_fluid_row(void **state)
{
    (void)state;
    struct cloud cl;
    make_cloud(&cl, 11, 11, 0.01, 0.3, PI / 6, 0, 3);
    int n = cl.c.n, i = 5 * 11 + 5;
    double *p = calloc((size_t)n, sizeof *p), *u = calloc(3 * (size_t)n, 8);
    for (int a = 0; a < n; a++)
        p[a] = 4.2;
    assert_true(fabs(row_dot(&cl, &mlpg_wall_improved, i, p)) < 1e-12 * 4.2);
    for (int a = 0; a < n; a++)
        p[a] = 1 + 30 * cl.x[3 * a] - 70 * cl.x[3 * a + 1];
    assert_true(fabs(row_dot(&cl, &mlpg_wall_improved, i, p)) < 1e-12);
    for (int a = 0; a < n; a++) {
        u[3 * a] = 0.7;
        u[3 * a + 1] = -1.3;
    }
    assert_true(fabs(domain(&cl, i, u)) < 1e-12 * 0.01);
    free(p), free(u);
    free_cloud(&cl);
}

static void test_e3_02_poisson(void **state)
{
    (void)state;
    struct cloud cl;
    make_cloud(&cl, 11, 11, 0.01, 0.3, PI / 6, 0, 5);
    int n = cl.c.n, i = 5 * 11 + 5;
    const double f = 3e4, rho_dt = 1e6, Dc = f / rho_dt, R = cl.R[i];
    double *p = calloc((size_t)n, sizeof *p), *u = calloc(3 * (size_t)n, 8);
    const double *xi = cl.x + 3 * i;
    for (int a = 0; a < n; a++) {
        double dx = cl.x[3 * a] - xi[0], dy = cl.x[3 * a + 1] - xi[1];
        u[3 * a] = Dc / 2 * dx;
        u[3 * a + 1] = Dc / 2 * dy;
        p[a] = f / 4 * (dx * dx + dy * dy);
    }
    double rhs = rho_dt * domain(&cl, i, u), want = f * R * R / 4;
    assert_true(fabs(rhs - want) < 1e-12 * want);
    /* the row's sign: -(mean on the circle - p_I) */
    double lhs = -row_dot(&cl, &mlpg_wall_improved, i, p);
    print_message("E3-02: (rho/dt) D = %.15g, f R^2/4 = %.15g; row on "
                  "f r^2/4 (linear MLS) %.6g (%.1f %%)\n",
                  rhs, want, lhs, 100 * (lhs / want - 1));
    /* measured -3.3 % on this cloud: linear MLS cannot carry r^2 exactly */
    assert_true(fabs(lhs / want - 1) < 0.1);
    free(p), free(u);
    free_cloud(&cl);
}

/* Hydrostatic wall data: g_s = (rho/dt) n_s.(u* - U), u* = -g dt n_w. */
struct hydro { double rho_dt, gdt; const double *nw; };

static double hydro_b(const struct cloud *cl, const struct mlpg_wall_ops *w,
                      int i, const struct hydro *h, const double *ustar)
{
    double t0, ang, ns[2][2], g[2];
    int nseg;
    mlpg_sector(&cl->c, i, &t0, &ang, &nseg, ns);
    for (int s = 0; s < nseg; s++)
        g[s] = h->rho_dt * (ns[s][0] * ustar[3 * i]
                            + ns[s][1] * ustar[3 * i + 1]);
    return w->rhs(&cl->c, i, h->rho_dt, domain(cl, i, ustar), ustar + 3 * i,
                  nseg, ns, g);
}

static void hydrostatic(const struct cloud *cl, int i, double gvec[2],
                        const struct mlpg_wall_ops *w, double want,
                        double tol)
{
    int n = cl->c.n;
    const double rho = 1000, dt = 1e-3, gm = 9.81;
    double *p = calloc((size_t)n, sizeof *p), *u = calloc(3 * (size_t)n, 8);
    for (int a = 0; a < n; a++) {
        /* p = p_K + rho g.(x - x_K) */
        p[a] = 5e3 + rho * gm * (gvec[0] * (cl->x[3 * a] - cl->x[3 * i])
                                 + gvec[1] * (cl->x[3 * a + 1]
                                              - cl->x[3 * i + 1]));
        u[3 * a] = gm * dt * gvec[0];
        u[3 * a + 1] = gm * dt * gvec[1];
    }
    struct hydro h = { rho / dt, gm * dt, NULL };
    double lhs = row_dot(cl, w, i, p), b = hydro_b(cl, w, i, &h, u);
    print_message("E3-03 %s node %d (sector %.3f): row %.8g, rhs %.8g, "
                  "rho g R/pi %.8g\n", w->name, i, cl->sector[i], lhs, b,
                  want);
    assert_true(fabs(lhs - b) < tol * fabs(want));
    if (w == &mlpg_wall_improved)
        assert_true(fabs(b - want) < 1e-12 * fabs(want));
    free(p), free(u);
}

static void test_e3_03_hydrostatic(void **state)
{
    (void)state;
    struct cloud cl;
    const double rot = PI / 6;
    make_cloud(&cl, 11, 9, 0.01, 0.3, rot, 1, 11);
    /* gravity into the bottom wall: -n_w */
    double g[2] = { sin(rot), -cos(rot) };
    const double rgr = 1000 * 9.81 * 0.8 * 0.01 / PI;
    /* improved: rows in the -SK sign, so b = +rho g R/pi */
    hydrostatic(&cl, 5, g, &mlpg_wall_improved, rgr, 3e-3);
    hydrostatic(&cl, 5, g, &mlpg_wall_original, rgr, 1e-10);
    /* the corner: quarter disc, LHS = RHS = -rho g R/2pi */
    hydrostatic(&cl, 0, g, &mlpg_wall_improved, rgr / 2, 3e-3);
    free_cloud(&cl);
}

static void test_e3_04_translation(void **state)
{
    (void)state;
    struct cloud cl;
    make_cloud(&cl, 11, 9, 0.01, 0.3, PI / 6, 0, 13);
    int n = cl.c.n, i = 5;
    const double rho_dt = 1e6, U[2] = { 0.8, -0.45 };
    double *u = calloc(3 * (size_t)n, 8), *p = calloc((size_t)n, 8);
    for (int a = 0; a < n; a++) {
        u[3 * a] = U[0];
        u[3 * a + 1] = U[1];
        p[a] = 1e3;
    }
    double t0, ang, ns[2][2], g[2];
    int nseg;
    mlpg_sector(&cl.c, i, &t0, &ang, &nseg, ns);
    for (int s = 0; s < nseg; s++) /* (S-2) with u* = U: no flux */
        g[s] = 0;
    double D = domain(&cl, i, u);
    double b = mlpg_wall_improved.rhs(&cl.c, i, rho_dt, D, u + 3 * i, nseg,
                                      ns, g);
    double scale = rho_dt * cl.R[i] / PI * sqrt(U[0] * U[0] + U[1] * U[1]);
    print_message("E3-04: (rho/dt) D = %.12g, rho R/(pi dt) n_w.U = %.12g, "
                  "b = %.3g\n", rho_dt * D,
                  rho_dt * cl.R[i] / PI * (cl.normal[3 * i] * U[0]
                                           + cl.normal[3 * i + 1] * U[1]),
                  b);
    assert_true(fabs(b) < 1e-12 * scale);
    assert_true(fabs(row_dot(&cl, &mlpg_wall_improved, i, p)) < 1e-12 * 1e3);
    free(u), free(p);
    free_cloud(&cl);
}

static void test_e3_05_side_integral(void **state)
{
    (void)state;
    /* int_0^R ln(s/R)/2pi ds with s = R e^-t: (R/2pi) int_0^inf -t e^-t dt,
     * by composite Simpson on t in [0, 60] */
    const double R = 0.008;
    const int N = 200000;
    const double h = 60.0 / N;
    double s = 0;
    for (int k = 0; k <= N; k++) {
        double t = k * h, f = -t * exp(-t);
        s += f * (k == 0 || k == N ? 1 : k % 2 ? 4 : 2);
    }
    s *= h / 3 * R / (2 * PI);
    assert_true(fabs(s - (-R / (2 * PI))) < 1e-8 * R);
    /* and the two sides of a half disc make -R/pi (S-6): the improved rhs
     * with only Neumann data g on both sides returns -(R/pi) g ... */
    struct cloud cl;
    make_cloud(&cl, 5, 5, 0.01, 0, 0, 0, 1);
    double ns[2][2] = { { 0, -1 }, { 0, -1 } }, g[2] = { 2.5, 2.5 },
           u[3] = { 0, 0, 0 };
    double b = mlpg_wall_improved.rhs(&cl.c, 2, 0, 0, u, 2, ns, g);
    /* ... in the row's sign: b = -int_b phi g dS = (R/pi) g */
    assert_true(fabs(b - cl.R[2] / PI * 2.5) < 1e-15);
    free_cloud(&cl);
}

static void neumann(void *ctx, int i, int nseg, const double nn[2][2], double g[2])
{
    (void)ctx, (void)i;
    for (int s = 0; s < nseg; s++)
        g[s] = 3 * nn[s][0] - 2 * nn[s][1];
}

static void test_assemble(void **state)
{
    (void)state;
    /* A 0.3-jittered box solved for a linear p with consistent Neumann
     * data on two walls, Dirichlet elsewhere; every diagonal is positive
     * (csr_validate inside linsolve). The original scheme (SFDI) gives p
     * exactly; the improved one to its 4-point quadrature, which carries
     * the normal derivative as 0.9984 of itself (measured 1.2e-3). */
    struct cloud cl;
    make_cloud(&cl, 12, 12, 1.0 / 11, 0.3, 0.2, 1, 21);
    int n = cl.c.n;
    uint8_t *dir = calloc((size_t)n, 1);
    double *pg = calloc((size_t)n, 8), *b = calloc((size_t)n, 8),
           *p = calloc((size_t)n, 8);
    const double gr[2] = { 3, -2 };
    for (int a = 0; a < n; a++) {
        pg[a] = 1 + gr[0] * cl.x[3 * a] + gr[1] * cl.x[3 * a + 1];
        int i = a % 12, j = a / 12;
        dir[a] = i == 11 || j == 11;
    }
    cl.c.dirichlet = dir;
    for (int w = 0; mlpg_wall_schemes[w]; w++) {
        struct mlpg_system S = { .wall = mlpg_wall_schemes[w],
                                 .neumann = NULL, .p_given = pg };
        S.neumann = neumann; /* n.grad p = n.gr */
        struct csr_matrix A = { 0 };
        size_t cap = 0;
        assert_int_equal(mlpg_assemble(&cl.c, &S, &A, &cap, b), SIM_OK);
        struct linsolve *ls;
        assert_int_equal(linsolve_create_named("bicgstab", "ilu0", 1e-13,
                                               500, &ls), SIM_OK);
        for (int a = 0; a < n; a++)
            p[a] = 0;
        struct linsolve_stats st;
        assert_int_equal(linsolve_solve(ls, &A, b, p, &st), SIM_OK);
        double err = 0;
        for (int a = 0; a < n; a++)
            err = fmax(err, fabs(p[a] - pg[a]));
        print_message("linear p, %s scheme: max error %.3g\n",
                      mlpg_wall_schemes[w]->name, err);
        assert_true(err < (w == 0 ? 3e-3 : 1e-9));
        linsolve_free(ls);
        csr_free(&A);
    }
    free(dir), free(pg), free(b), free(p);
    free_cloud(&cl);
}


int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mls),
        cmocka_unit_test(test_e3_01_fluid_row),
        cmocka_unit_test(test_e3_02_poisson),
        cmocka_unit_test(test_e3_03_hydrostatic),
        cmocka_unit_test(test_e3_04_translation),
        cmocka_unit_test(test_e3_05_side_integral),
        cmocka_unit_test(test_assemble),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
