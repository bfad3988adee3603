/* test_soil.c — the forces of Kim's solid-soil model (doc/theory.md K.3,
 * K.4) on small clouds: the column weight (13) on 2-D and 3-D blocks, the
 * friction (10)-(14) of a particle sliding over a wall row, worked out by
 * hand, with the kernel-weighted variant (K0-04) and the cap (K0-05); the
 * drag K.1 of a uniform stream against the closed form of E5-05 and the
 * momentum balance of its reaction (E5-06). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"
#include "mps/kernel/kernel.h"
#include "mps/operators.h"
#include "mps/mps.h"
#include "linsolve/csr.h"
#include "mps/soil/soil.h"
#include "particles/operators/matrix.h"
#include "mps/soil/soil_step.h"
#include "mps/stabiliser/stabiliser.h"
#include "particles/neighbour.h"

#define G 9.81

static void near(double got, double want, double tol)
{
    if (!(fabs(got - want) <= tol * fmax(fabs(want), 1e-300))) {
        print_error("got %.12g want %.12g (rel tol %g)\n", got, want, tol);
        fail();
    }
}

/* Poly6 weights of every list entry at radius re. */
static double *weights(const struct neighbour_list *nl, double re)
{
    double *w = malloc((size_t)(nl->nnz ? nl->nnz : 1) * sizeof *w);
    assert_non_null(w);
    mps_kernel_poly6.weights(nl->r, nl->nnz, re, w);
    return w;
}

/* eq. (13), 2-D: 6 x 5 soil block (top row denser) with fluid above; b =
 * l0/2 is the particle's own column, b = 1.5 l0 three columns (fewer at
 * the block's sides). */
static void test_column_weight_2d(void **s)
{
    (void)s;
    enum { NX = 6, NY = 5, N = NX * NY + NX };
    const double l0 = 0.01;
    double x[3 * N], rho[N], p_h[N];
    uint8_t role[N];
    for (int k = 0; k < N; k++) {
        int ix = k % NX, iy = k / NX;
        x[3 * k] = ix * l0 + 0.3;
        x[3 * k + 1] = iy * l0 - 0.02;
        x[3 * k + 2] = 0;
        role[k] = iy < NY ? SOIL_SOIL : SOIL_FLUID;
        rho[k] = iy == NY - 1 ? 2000 : 1900;
    }
    assert_int_equal(soil_column_weight(N, 2, x, role, rho, G, 0.5 * l0, p_h), SIM_OK);
    for (int k = 0; k < N; k++) {
        int iy = k / NX;
        double want = iy >= NY ? 0 : iy == NY - 1 ? 0 : ((NY - 2 - iy) * 1900.0 + 2000.0) * G;
        near(p_h[k], want, 1e-14);
    }
    assert_int_equal(soil_column_weight(N, 2, x, role, rho, G, 1.5 * l0, p_h), SIM_OK);
    for (int k = 0; k < NX * NY; k++) {
        int ix = k % NX, iy = k / NX;
        int cols = 3 - (ix == 0) - (ix == NX - 1);
        double want = iy == NY - 1 ? 0 : cols * ((NY - 2 - iy) * 1900.0 + 2000.0) * G;
        near(p_h[k], want, 1e-14);
    }
    assert_int_equal(soil_column_weight(N, 2, x, role, rho, G, 0, p_h), SIM_ERR_INPUT);
    sim_error_clear();
}

/* eq. (13), 3-D: 4 x 4 x 3 block; b = 0.5 l0 one column, 1.5 l0 the 3 x 3
 * columns (horizontal distance sqrt(2) l0 < 1.5 l0) cut by the sides. */
static void test_column_weight_3d(void **s)
{
    (void)s;
    enum { NX = 4, NZ = 3, N = NX * NX * NZ };
    const double l0 = 0.02;
    double x[3 * N], rho[N], p_h[N];
    uint8_t role[N];
    for (int k = 0; k < N; k++) {
        x[3 * k] = (k % NX) * l0 - 0.05;
        x[3 * k + 1] = (k / NX % NX) * l0;
        x[3 * k + 2] = (k / (NX * NX)) * l0;
        role[k] = SOIL_SOIL;
        rho[k] = 1800;
    }
    assert_int_equal(soil_column_weight(N, 3, x, role, rho, G, 0.5 * l0, p_h), SIM_OK);
    for (int k = 0; k < N; k++)
        near(p_h[k], (NZ - 1 - k / (NX * NX)) * 1800 * G, 1e-14);
    assert_int_equal(soil_column_weight(N, 3, x, role, rho, G, 1.5 * l0, p_h), SIM_OK);
    for (int k = 0; k < N; k++) {
        int ix = k % NX, iy = k / NX % NX;
        int cx = 3 - (ix == 0) - (ix == NX - 1), cy = 3 - (iy == 0) - (iy == NX - 1);
        near(p_h[k], cx * cy * (NZ - 1 - k / (NX * NX)) * 1800 * G, 1e-14);
    }
}

/* One soil particle at (0, l0) sliding at V along x over a row of wall
 * particles at y = 0, r_e = 2.1 l0: three wall neighbours, (0, -l0) and
 * (+-l0, -l0). With a = 0 only (11) acts: sin(theta) = 1 and 1/sqrt(2),
 * t = -x and -(1, +-1)/sqrt(2), p_s = p_h: F = -2 mu p_h x. With a_i =
 * (0, -A) the loads of (10) are rho A and rho A/sqrt(2) (each diagonal),
 * adding -2 mu rho A x. */
static void test_friction_wall(void **s)
{
    (void)s;
    enum { N = 6 };
    const double l0 = 0.01, re = 2.1 * l0, V = 0.2, rho_s = 1900, mu = 0.5;
    double x[3 * N] = { 0 }, v[3 * N] = { 0 }, a[3 * N] = { 0 }, rho[N], p_h[N] = { 0 }, F[3 * N];
    uint8_t role[N];
    x[1] = l0;
    v[0] = V;
    role[0] = SOIL_SOIL;
    for (int k = 1; k < N; k++) {
        x[3 * k] = (k - 3) * l0;
        role[k] = SOIL_WALL;
    }
    for (int k = 0; k < N; k++)
        rho[k] = 1000;
    rho[0] = rho_s;
    const double ph = 3 * rho_s * G;
    p_h[0] = ph;
    struct neighbour_list nl = { 0 };
    assert_int_equal(neighbour_build_brute(&nl, 2, x, N, re), SIM_OK);
    double *w = weights(&nl, re);
    struct pop_lattice L;
    assert_int_equal(mps_lattice_constants(&mps_kernel_poly6, 2, l0, re, &L), SIM_OK);
    struct soil_friction_params p = { .mu = mu, .n0 = L.n0 };

    soil_friction(&p, 2, &nl, w, x, v, a, rho, p_h, role, F);
    near(F[0], -2 * mu * ph, 1e-14);
    assert_true(fabs(F[1]) < 1e-12 * ph && F[2] == 0);
    for (int k = 1; k < N; k++)
        assert_true(F[3 * k] == 0 && F[3 * k + 1] == 0);

    const double A = 3.0;
    a[1] = -A;
    soil_friction(&p, 2, &nl, w, x, v, a, rho, p_h, role, F);
    near(F[0], -2 * mu * ph - 2 * mu * rho_s * A, 1e-14);

    /* K0-04: every pair term times d w/n0 */
    p.kernel_weight = 1;
    a[1] = 0;
    soil_friction(&p, 2, &nl, w, x, v, a, rho, p_h, role, F);
    const double w1 = mps_kernel_poly6.w(l0, re), w2 = mps_kernel_poly6.w(sqrt(2) * l0, re);
    near(F[0], -mu * ph * 2 / L.n0 * (w1 + w2), 1e-14);

    /* K0-05: a step long enough to reverse the sliding is capped at the
     * largest sliding speed, V (the pair below) */
    p.kernel_weight = 0;
    p.cap = 1;
    p.dt = 1.0;
    soil_friction(&p, 2, &nl, w, x, v, a, rho, p_h, role, F);
    near(F[0], -V * rho_s / p.dt, 1e-14);
    p.dt = 1e-6;
    soil_friction(&p, 2, &nl, w, x, v, a, rho, p_h, role, F);
    near(F[0], -2 * mu * ph, 1e-14);

    /* at rest relative to the wall: nothing */
    v[0] = 0;
    soil_friction(&p, 2, &nl, w, x, v, a, rho, p_h, role, F);
    assert_true(F[0] == 0 && F[1] == 0);
    free(w);
    neighbour_free(&nl);
}

/* E5-05: a soil particle in a uniform stream with a full support (2-D
 * lattice of fluid around it, sum w = n0) slows relative to the stream as
 * dv(t) = dv0/(1 + dv0 t/L_d), L_d = 2 rho_s l0/(C_D rho_f). The stream is
 * held; the particle's velocity is advanced by RK4 with the drag of K.1. */
static void test_drag_stream(void **s)
{
    (void)s;
    enum { M = 7, N = M * M };
    const double l0 = 0.004, re = 2.1 * l0, U = 0.3, rho_s = 2650, rho_f = 1000, cd = 1.2;
    double x[3 * N] = { 0 }, v[3 * N] = { 0 }, F[3 * N], S[N];
    uint8_t role[N];
    int c = N / 2;
    for (int k = 0; k < N; k++) {
        x[3 * k] = (k % M - M / 2) * l0;
        x[3 * k + 1] = (k / M - M / 2) * l0;
        role[k] = k == c ? SOIL_SOIL : SOIL_FLUID;
        v[3 * k] = k == c ? 0 : U;
    }
    struct neighbour_list nl = { 0 };
    assert_int_equal(neighbour_build_brute(&nl, 2, x, N, re), SIM_OK);
    double *w = weights(&nl, re);
    struct pop_lattice L;
    assert_int_equal(mps_lattice_constants(&mps_kernel_poly6, 2, l0, re, &L), SIM_OK);
    const struct soil_drag_params p = { .cd = cd, .rho_f = rho_f, .l0 = l0, .n0 = L.n0 };
    const double Ld = 2 * rho_s * l0 / (cd * rho_f), T = 5 * Ld / U, h = T / 4000;
    double t = 0;
    for (int step = 1; step <= 4000; step++) {
        double k1, k2, k3, k4, u0 = v[3 * c];
#define ACC(u) (v[3 * c] = (u), soil_drag(&p, &nl, w, v, role, F, NULL, S), F[3 * c] / rho_s)
        k1 = ACC(u0);
        k2 = ACC(u0 + 0.5 * h * k1);
        k3 = ACC(u0 + 0.5 * h * k2);
        k4 = ACC(u0 + h * k3);
#undef ACC
        v[3 * c] = u0 + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        t += h;
        if (step % 800 == 0)
            near(U - v[3 * c], U / (1 + U * t / Ld), 1e-9);
    }
    free(w);
    neighbour_free(&nl);
}

/* E5-06: on a random cloud of fluid, soil, wall and other particles the
 * drag and its reaction cancel: sum_i F_i V + sum_j rho_f V a_j = 0 to
 * round-off; walls and others get nothing. */
static void test_drag_momentum(void **s)
{
    (void)s;
    enum { N = 400 };
    const double l0 = 0.01, re = 2.1 * l0, rho_f = 998;
    double x[3 * N], v[3 * N], F[3 * N], a[3 * N] = { 0 }, S[N];
    uint8_t role[N];
    srand(7);
    for (int k = 0; k < N; k++) {
        for (int q = 0; q < 3; q++) {
            x[3 * k + q] = 0.1 * rand() / (double)RAND_MAX;
            v[3 * k + q] = rand() / (double)RAND_MAX - 0.5;
        }
        role[k] = (uint8_t)(rand() % 4);
    }
    struct neighbour_list nl = { 0 };
    assert_int_equal(neighbour_build_brute(&nl, 3, x, N, re), SIM_OK);
    double *w = weights(&nl, re);
    const struct soil_drag_params p = { .cd = 1, .rho_f = rho_f, .l0 = l0, .n0 = 11.0 };
    soil_drag(&p, &nl, w, v, role, F, a, S);
    double sum[3] = { 0 }, scale = 0;
    int nsoil = 0;
    for (int k = 0; k < N; k++) {
        for (int q = 0; q < 3; q++) {
            sum[q] += F[3 * k + q] + rho_f * a[3 * k + q];
            scale += fabs(F[3 * k + q]);
        }
        if (role[k] != SOIL_SOIL)
            assert_true(F[3 * k] == 0 && F[3 * k + 1] == 0 && F[3 * k + 2] == 0);
        if (role[k] != SOIL_FLUID)
            assert_true(a[3 * k] == 0 && a[3 * k + 1] == 0 && a[3 * k + 2] == 0);
        nsoil += role[k] == SOIL_SOIL && (F[3 * k] != 0);
    }
    assert_true(nsoil > 20 && scale > 0);
    for (int q = 0; q < 3; q++)
        assert_true(fabs(sum[q]) < 1e-12 * scale);
    free(w);
    neighbour_free(&nl);
}

/* K.6a-c: on a 7 x 7 lattice of soil in simple shear u = (gd y, 0), the
 * corrected gradient is exact, |D| = gd/2 and nu = (c + mu p)/(rho gd)
 * at every particle; a negative pressure counts as 0; at rest, and below
 * the cap, nu_max; against a wall the yield stress adds mu p_wall. */
static void test_vp_viscosity(void **s)
{
    (void)s;
    enum { M = 7, N = M * M };
    const double l0 = 0.01, re = 3.1 * l0, gd = 2.0, rho = 1900, mu = 0.6, c = 50;
    double x[3 * N] = { 0 }, v[3 * N] = { 0 }, p[N], nu[N], nu_w[N];
    uint8_t role[N];
    for (int k = 0; k < N; k++) {
        x[3 * k] = (k % M) * l0;
        x[3 * k + 1] = (k / M) * l0;
        v[3 * k] = gd * x[3 * k + 1];
        p[k] = 100.0 * (k % 5) - 100.0;
        role[k] = SOIL_SOIL;
    }
    struct neighbour_list nl = { 0 };
    assert_int_equal(neighbour_build_brute(&nl, 2, x, N, re), SIM_OK);
    double *w = weights(&nl, re);
    struct pop_lattice L;
    assert_int_equal(mps_lattice_constants(&mps_kernel_poly6, 2, l0, re, &L), SIM_OK);
    struct soil_vp_params vp = { .mu = mu, .cohesion = c, .rho = rho, .nu_max = 1e3, .p_wall = 40 };
    soil_vp_viscosity(&vp, 2, &nl, w, L.n0, x, v, p, role, nu, nu_w);
    for (int k = 0; k < N; k++) {
        near(nu[k], (c + mu * fmax(p[k], 0)) / (rho * gd), 1e-10);
        near(nu_w[k], (c + mu * (fmax(p[k], 0) + 40)) / (rho * gd), 1e-10);
    }
    memset(v, 0, sizeof v);
    vp.nu_max = 0.5;
    soil_vp_viscosity(&vp, 2, &nl, w, L.n0, x, v, p, role, nu, nu_w);
    for (int k = 0; k < N; k++)
        assert_true(nu[k] == 0.5 && nu_w[k] == 0.5);
    role[0] = SOIL_WALL;
    soil_vp_viscosity(&vp, 2, &nl, w, L.n0, x, v, p, role, nu, nu_w);
    assert_true(nu[0] == 0 && nu_w[0] == 0);
    free(w);
    neighbour_free(&nl);
}

/* K.6d on 3 x 3 soil particles over a wall row (normal (0, -1), into the
 * wall; v = 0) and a water particle at rest: the matrix is symmetric, its
 * row sums are 1 plus the wall and water pair terms (nu_w against the
 * wall, the harmonic mean with nu_f against water), its soil pair entries
 * the arithmetic mean of the two viscosities; the wall drags the
 * tangential velocity only (the right-hand side keeps the normal one). */
static void test_vp_system(void **s)
{
    (void)s;
    enum { NS = 9, NW = 5, N = NS + NW + 1 };
    const double l0 = 0.01, re = 2.1 * l0, nu_f = 1e-6;
    double x[3 * N] = { 0 }, v[3 * N] = { 0 }, wn[3 * N] = { 0 }, nu[N] = { 0 }, nu_w[N] = { 0 };
    uint8_t role[N];
    int32_t unk[N];
    for (int k = 0; k < NS; k++) {
        x[3 * k] = (k % 3) * l0;
        x[3 * k + 1] = (1 + k / 3) * l0;
        role[k] = SOIL_SOIL;
        unk[k] = k;
        nu[k] = 0.1 * (k + 1);
        nu_w[k] = 2 * nu[k];
        v[3 * k] = 0.3;
        v[3 * k + 1] = -0.2;
    }
    for (int k = NS; k < NS + NW; k++) {
        x[3 * k] = (k - NS - 1) * l0;
        role[k] = SOIL_WALL;
        unk[k] = -1;
        wn[3 * k + 1] = -1;
    }
    x[3 * (N - 1)] = 3 * l0;
    x[3 * (N - 1) + 1] = 3 * l0;
    role[N - 1] = SOIL_FLUID;
    unk[N - 1] = -1;
    nu[N - 1] = 7;              /* not read: water pairs use nu_f */
    struct neighbour_list nl = { 0 };
    assert_int_equal(neighbour_build_brute(&nl, 2, x, N, re), SIM_OK);
    double *w = weights(&nl, re);
    struct csr_matrix A = { 0 };
    size_t cap = 0;
    int64_t rp[NS + 1];
    A.rowptr = rp;
    const int64_t nnz = pop_matrix_rowptr(&nl, N, POP_STORED(w), unk, NS, rp);
    assert_int_equal(csr_reserve(&A, &cap, nnz), SIM_OK);
    A.n = NS;
    A.nnz = nnz;
    double b[3 * NS];
    const double cdt = 0.7;
    soil_vp_system(&nl, w, cdt, nu_f, nu, nu_w, role, unk, v, wn, rp, A.col, A.val, b);
    int row;
    assert_true(csr_is_symmetric(&A, 1e-14, &row));
    for (int i = 0; i < NS; i++) {
        double sum = 0, want = 1;
        for (int64_t k = rp[i]; k < rp[i + 1]; k++)
            sum += A.val[k];
        for (int64_t k = nl.start[i]; k < nl.start[i + 1]; k++) {
            const int j = nl.j[k];
            if (w[k] > 0 && role[j] == SOIL_WALL)
                want += cdt * nu_w[i] * w[k];
            else if (w[k] > 0 && role[j] == SOIL_FLUID)
                want += cdt * 2 * nu[i] * nu_f / (nu[i] + nu_f) * w[k];
        }
        near(sum, want, 1e-12);
        /* the walls (v = 0) keep the normal component (-0.2) and drag the
         * tangential one: the row's right-hand side is v_i plus, per wall
         * pair, a (0, v_i,y) */
        double ay = 0;
        for (int64_t k = nl.start[i]; k < nl.start[i + 1]; k++)
            if (w[k] > 0 && role[nl.j[k]] == SOIL_WALL)
                ay += cdt * nu_w[i] * w[k];
        near(b[3 * i], 0.3, 1e-14);
        near(b[3 * i + 1], -0.2 * (1 + ay), 1e-14);
    }
    /* the pair entries: arithmetic mean of the two soil viscosities */
    for (int i = 0; i < NS; i++)
        for (int64_t k = nl.start[i]; k < nl.start[i + 1]; k++) {
            const int j = nl.j[k];
            if (!(w[k] > 0) || role[j] != SOIL_SOIL)
                continue;
            int64_t e = rp[i] + 1;
            while (e < rp[i + 1] && A.col[e] != j)
                e++;
            assert_true(e < rp[i + 1]);
            near(-A.val[e], cdt * 0.5 * (nu[i] + nu[j]) * w[k], 1e-14);
        }
    free(A.col);
    free(A.val);
    free(w);
    neighbour_free(&nl);
}

/* constant/soilProperties: the defaults of doc/theory.md K0-03 ... K0-09,
 * and bad entries refused with the file, line and key (unknown names with
 * the valid ones and the nearest). */
static int props(const char *text, struct soil_props *p)
{
    struct dict *d;
    assert_int_equal(dict_read_string(text, strlen(text), "constant/soilProperties", &d), SIM_OK);
    int rc = soil_props_read(d, p);
    dict_free(d);
    return rc;
}

static void test_props(void **s)
{
    (void)s;
    struct soil_props p;
    assert_int_equal(props("rho 1900;\n", &p), SIM_OK);
    assert_int_equal(p.model, SOIL_MODEL_SOLID);
    assert_true(p.rho == 1900 && p.mu == 0.577 && p.column_half_width == 0.5);
    assert_true(p.kernel_weight == 0 && p.cap == 0 && p.cd == 1.0 && p.drag_reaction == 1);
    assert_true(p.nu == 1e-3);
    assert_int_equal(props("soilModel liquid; rho 900; nu 2e-3; frictionWeight kernel;\n", &p), SIM_OK);
    assert_true(p.model == SOIL_MODEL_LIQUID && p.rho == 900 && p.nu == 2e-3 && p.kernel_weight == 1);
    assert_true(p.cohesion == 0 && p.nu_max == 1000);
    assert_int_equal(props("soilModel viscoplastic; rho 1900; cohesion 10; maxViscosity 500;\n", &p), SIM_OK);
    assert_true(p.model == SOIL_MODEL_VISCOPLASTIC && p.cohesion == 10 && p.nu_max == 500);
    static const struct { const char *text, *msg; } bad[] = {
        { "soilModel soild; rho 1900;\n", "did you mean 'solid'" },
        { "rho 1900;\nmu -0.1;\n", "constant/soilProperties:2" },
        { "rho 0;\n", "rho = 0 is out of range" },
        { "mu 0.5;\n", "rho" },
        { "rho 1900; frictionWeight kernal;\n", "valid: none kernel" },
        { "rho 1900;\n\ncolumnHalfWidth 0;\n", "constant/soilProperties:3" },
        { "soilModel viscoplastc; rho 1900;\n", "did you mean 'viscoplastic'" },
        { "rho 1900;\nmaxViscosity 0;\n", "constant/soilProperties:2" },
        { "rho 1900; cohesion -1;\n", "cohesion" },
    };
    for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
        assert_int_not_equal(props(bad[k].text, &p), SIM_OK);
        if (!strstr(sim_error_message(), bad[k].msg)) {
            print_error("'%s': message '%s' lacks '%s'\n", bad[k].text, sim_error_message(), bad[k].msg);
            fail();
        }
        sim_error_clear();
    }
}

/* The collision model between a soil particle (1900 kg/m^3) and a water
 * particle approaching head-on at 0.3 dp: the momentum rho u of the pair
 * is kept (masses rho dp^d) and the relative normal velocity is reversed
 * times e (Lee et al. 2011 with the masses of the two phases). */
static void test_collision_masses(void **st)
{
    (void)st;
    double x[6] = { 0, 0, 0, 0.3, 0, 0 };
    double u[6] = { 1, 0, 0, -2, 0, 0 }, du[6];
    int32_t type[2] = { MPS_FLUID, MPS_FLUID };
    double rho[2] = { 1900, 1000 };
    struct mps_soil soil = { .rho = rho };
    struct mps_solver s = { 0 };
    s.P.n = 2;
    s.P.dim = 3;
    s.P.x = x;
    s.P.type = type;
    s.ustar = u;
    s.grad = du;
    s.dp = 1;
    s.soil = &soil;
    s.S.collision_ratio = 0.5;
    s.S.collision_restitution = 0.2;
    assert_int_equal(neighbour_build_brute(&s.nl, 2, x, 3, 1.0), SIM_OK);
    const double p0 = rho[0] * 1 + rho[1] * -2;
    assert_int_equal(mps_collision_lee2011.apply(&s, 1e-4), SIM_OK);
    near(rho[0] * u[0] + rho[1] * u[3], p0, 1e-12);
    near(u[0] - u[3], -0.2 * 3, 1e-12);
    near(u[1] + u[2] + u[4] + u[5], 0, 0);
    neighbour_free(&s.nl);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_column_weight_2d),
        cmocka_unit_test(test_column_weight_3d),
        cmocka_unit_test(test_friction_wall),
        cmocka_unit_test(test_drag_stream),
        cmocka_unit_test(test_drag_momentum),
        cmocka_unit_test(test_props),
        cmocka_unit_test(test_collision_masses),
        cmocka_unit_test(test_vp_viscosity),
        cmocka_unit_test(test_vp_system),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
