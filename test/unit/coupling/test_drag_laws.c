/* test_drag_laws.c — each drag law against its formula at hand-computed
 * points, E1-12 (eps -> 1 is the single-sphere drag), the continuity of
 * gidaspowBlend and diFelice and the documented jump of ergunWenYu at
 * eps = 0.8, the Re -> 0 guard, the array entry against the scalar one,
 * E1-14's terminal balance, and selection from couplingDict. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "coupling/drag/drag.h"

/* Water and the Table 1 glass bead (doc/theory.md A.11). */
static const struct drag_fluid water = { 1000.0, 1.0e-3 };
static const double D = 2.7e-3, RHO_S = 2500.0, G = 9.81;

static double volume(double d) { return M_PI * d * d * d / 6; }

/* |F| for a slip s along x, from force_all (one grain). */
static double force(const struct drag_ops *m, double eps, double s, double d)
{
    double u[3] = { s, 0, 0 }, v[3] = { 0, 0, 0 }, F[3], V = volume(d);
    m->force_all(&water, 1, &eps, &d, &V, u, v, F);
    return F[0];
}

static int rel_close(double a, double b, double tol)
{
    return fabs(a - b) <= tol * fmax(fabs(a), fabs(b));
}

/* Hand-computed points (Python, straight from eqs. 25-28, the blend of
 * A0-12 and Di Felice's F = 1/2 C_d rho A |du| du eps^(2-chi)), d = 2.7 mm
 * in water: |F| [N] at (eps, |u - v|). */
static void test_formula_points(void **state)
{
    (void)state;
    static const struct { double eps, s, ewy, gb, df; } pt[] = {
        { 0.5, 0.05, 2.7302403655103795e-05, 2.7311775453315577e-05,
          2.2373963689940995e-05 },
        { 0.7, 0.2, 0.00028536881268358144, 0.00028347322006831786,
          0.00014181434190042646 },
        { 0.85, 0.1, 2.8496853360762848e-05, 2.951453262827641e-05,
          3.145290396670005e-05 },
        { 0.95, 0.5, 0.00034271739686731584, 0.00035348964581303127,
          0.0004516974353659976 },
        { 0.99, 1.0, 0.0012806841051115397, 0.0013151512143750159,
          0.0015200241946762725 },
    };
    for (size_t i = 0; i < sizeof pt / sizeof pt[0]; i++) {
        assert_true(rel_close(force(&drag_ergun_wen_yu, pt[i].eps, pt[i].s, D),
                              pt[i].ewy, 1e-12));
        assert_true(rel_close(force(&drag_gidaspow_blend, pt[i].eps, pt[i].s,
                                    D), pt[i].gb, 1e-12));
        assert_true(rel_close(force(&drag_di_felice, pt[i].eps, pt[i].s, D),
                              pt[i].df, 1e-12));
        assert_true(force(&drag_none, pt[i].eps, pt[i].s, D) == 0.0);
    }
}

/* Schiller-Naumann C_d (27) written independently of drag.h. */
static double cd_sn(double re)
{
    return re <= 1000 ? 24 / re * (1 + 0.15 * pow(re, 0.687)) : 0.44;
}

/* E1-12: at eps = 1 (and -> 1) eqs. (25)-(28) give 1/2 C_d rho A |du| du. */
static void test_single_sphere_limit(void **state)
{
    (void)state;
    const double slips[] = { 1e-4, 3e-3, 0.05, 0.343, 1.0, 7.0 };
    for (size_t i = 0; i < sizeof slips / sizeof slips[0]; i++) {
        double s = slips[i], re = water.rho * D * s / water.mu;
        double ref = 0.5 * cd_sn(re) * water.rho * M_PI * D * D / 4 * s * s;
        double f1 = force(&drag_ergun_wen_yu, 1.0, s, D);
        double f2 = force(&drag_ergun_wen_yu, 1.0 - 1e-13, s, D);
        assert_true(rel_close(f1, ref, 1e-10));
        assert_true(rel_close(f2, ref, 1e-10));
        /* Di Felice at eps = 1: single sphere with Dallavalle's C_d */
        double cdd = pow(0.63 + 4.8 / sqrt(re), 2);
        double refd = 0.5 * cdd * water.rho * M_PI * D * D / 4 * s * s;
        assert_true(rel_close(force(&drag_di_felice, 1.0, s, D), refd,
                              1e-10));
    }
}

/* Continuity in eps of gidaspowBlend and diFelice (and of ergunWenYu away
 * from its switch); the size of the ergunWenYu jump at eps = 0.8. */
static void test_continuity(void **state)
{
    (void)state;
    const double slips[] = { 1e-3, 0.1, 1.0 };
    for (size_t i = 0; i < sizeof slips / sizeof slips[0]; i++)
        for (double e = 0.31; e < 1.0; e += 0.0123) {
            const double h = 1e-9;
            double es[] = { e, 0.8 };
            for (int q = 0; q < 2; q++) {
                double a = force(&drag_gidaspow_blend, es[q] - h, slips[i], D);
                double b = force(&drag_gidaspow_blend, es[q] + h, slips[i], D);
                assert_true(rel_close(a, b, 1e-6));
                a = force(&drag_di_felice, es[q] - h, slips[i], D);
                b = force(&drag_di_felice, es[q] + h, slips[i], D);
                assert_true(rel_close(a, b, 1e-6));
            }
            if (fabs(e - 0.8) > 2 * h) {
                double a = force(&drag_ergun_wen_yu, e - h, slips[i], D);
                double b = force(&drag_ergun_wen_yu, e + h, slips[i], D);
                assert_true(rel_close(a, b, 1e-6));
            }
        }
    /* The documented jump (A0-12): 2.7 mm beads, |u - v| = 0.1 m/s. */
    double ke = drag_ergun_wen_yu.coeff(&water, 0.8, 0.1, D);
    double kw = drag_ergun_wen_yu.coeff(&water, nextafter(0.8, 1.0), 0.1, D);
    double be = 0.2 * ke, bw = 0.2 * kw;
    print_message("ergunWenYu jump at eps = 0.8, d = 2.7 mm, |u-v| = 0.1 "
                  "m/s: beta_Ergun = %.4g, beta_WenYu = %.4g, ratio %.4f\n",
                  be, bw, be / bw);
    assert_true(rel_close(be, 13991.769547325099, 1e-12));
    assert_true(rel_close(bw, 6265.423712425629, 1e-9));
    for (double s = 1e-4; s < 10; s *= 3.7) {
        double r = drag_ergun_wen_yu.coeff(&water, 0.8, s, D) /
                   drag_ergun_wen_yu.coeff(&water, nextafter(0.8, 1), s, D);
        print_message("  |u-v| = %8.2e m/s: K_Ergun/K_WenYu = %.4f\n", s, r);
        assert_true(r > 1.0 && r < 4.0);
    }
    assert_true(drag_ergun_wen_yu.jump_eps == 0.8);
    assert_true(drag_gidaspow_blend.jump_eps == 0 &&
                drag_di_felice.jump_eps == 0);
}

/* Re -> 0: K finite and continuous down to slip 0, force 0 at slip 0.
 * (Di Felice's K approaches its limit like sqrt|u - v|, hence 1e-16.) */
static void test_zero_slip(void **state)
{
    (void)state;
    for (int m = 0; drag_table[m]; m++) {
        const struct drag_ops *L = drag_table[m];
        for (double e = 0.3; e <= 1.0; e += 0.05) {
            double k0 = L->coeff(&water, e, 0.0, D);
            double k1 = L->coeff(&water, e, 1e-16, D);
            assert_true(isfinite(k0) && k0 >= 0);
            assert_true(rel_close(k0, k1, 1e-5) || (k0 == 0 && k1 == 0));
            assert_true(force(L, e, 0.0, D) == 0.0);
        }
    }
    /* Stokes limit of eq. (25) at eps = 1: F = 3 pi mu d |u - v|; the
     * Schiller-Naumann correction 0.15 Re^0.687 is 2e-7 at this slip. */
    double s = 1e-12;
    assert_true(rel_close(force(&drag_ergun_wen_yu, 1.0, s, D),
                          3 * M_PI * water.mu * D * s, 1e-6));
}

/* Array entry = scalar coefficient, grain by grain. */
static void test_array_entry(void **state)
{
    (void)state;
    enum { N = 700 };
    static double eps[N], d[N], V[N], u[3 * N], v[3 * N], F[3 * N];
    for (int k = 0; k < N; k++) {
        eps[k] = 0.3 + 0.7 * k / (N - 1.0);
        d[k] = 1e-3 * (1 + k % 5);
        V[k] = volume(d[k]);
        for (int c = 0; c < 3; c++) {
            u[3 * k + c] = sin(0.1 * k + c);
            v[3 * k + c] = cos(0.07 * k * c);
        }
    }
    for (int m = 0; drag_table[m]; m++) {
        const struct drag_ops *L = drag_table[m];
        L->force_all(&water, N, eps, d, V, u, v, F);
        for (int k = 0; k < N; k++) {
            double du[3], s2 = 0;
            for (int c = 0; c < 3; c++) {
                du[c] = u[3 * k + c] - v[3 * k + c];
                s2 += du[c] * du[c];
            }
            double kv = L->coeff(&water, eps[k], sqrt(s2), d[k]) * V[k];
            for (int c = 0; c < 3; c++)
                assert_true(rel_close(F[3 * k + c], kv * du[c], 1e-15) ||
                            F[3 * k + c] == kv * du[c]);
        }
    }
}

/* E1-14 algebra: the Table 1 bead in water at eps = 1, terminal slip from
 * (rho_s - rho_f) V g = F^d/eps: 0.343 m/s, Re = 926, C_d = 0.450 (1 %). */
static void test_terminal_velocity(void **state)
{
    (void)state;
    double lo = 1e-6, hi = 10.0, V = volume(D);
    double W = (RHO_S - water.rho) * V * G;
    for (int it = 0; it < 200; it++) {
        double s = 0.5 * (lo + hi);
        if (force(&drag_ergun_wen_yu, 1.0, s, D) < W)
            lo = s;
        else
            hi = s;
    }
    double s = 0.5 * (lo + hi), re = water.rho * D * s / water.mu;
    double cd = force(&drag_ergun_wen_yu, 1.0, s, D) /
                (0.5 * water.rho * M_PI * D * D / 4 * s * s);
    print_message("E1-14 terminal slip %.5f m/s, Re %.1f, C_d %.4f\n", s, re,
                  cd);
    assert_true(fabs(s / 0.343 - 1) < 0.01);
    assert_true(fabs(re / 926 - 1) < 0.01);
    assert_true(fabs(cd / 0.450 - 1) < 0.01);
}

/* E1-15 algebra: hindered settling of a homogeneous suspension. The slip
 * dU solves (rho_s - rho_f) V g = F^d(dU)/eps and the solids settle at
 * v = eps dU; in the Stokes regime of the Wen-Yu branch this is
 * Richardson-Zaki, v = v_Stokes eps^4.65. 20 um beads (Re < 0.01). */
static void test_hindered_settling(void **state)
{
    (void)state;
    const double d = 2e-5, V = volume(d);
    const double vst = (RHO_S - water.rho) * G * d * d / (18 * water.mu);
    for (double e = 0.85; e < 1.0; e += 0.05) {
        double lo = 0, hi = 1;
        for (int it = 0; it < 200; it++) {
            double s = 0.5 * (lo + hi);
            if (force(&drag_ergun_wen_yu, e, s, d) / e <
                (RHO_S - water.rho) * V * G)
                lo = s;
            else
                hi = s;
        }
        double v = e * 0.5 * (lo + hi), rz = vst * pow(e, 4.65);
        print_message("E1-15 eps = %.2f: v/v_Stokes = %.5f, eps^4.65 = "
                      "%.5f\n", e, v / vst, rz / vst);
        assert_true(fabs(v / rz - 1) < 0.01);
    }
}

static void test_select(void **state)
{
    (void)state;
    log_set_quiet(1);
    struct dict *d;
    const struct drag_ops *m = NULL;
    const char *t1 = "model B;\n";
    assert_int_equal(dict_read_string(t1, strlen(t1), "system/couplingDict",
                                      &d), 0);
    assert_int_equal(drag_select(d, &m), 0);
    assert_ptr_equal(m, &drag_ergun_wen_yu);
    dict_free(d);
    const char *t2 = "model B;\ndragModel diFelice;\n";
    assert_int_equal(dict_read_string(t2, strlen(t2), "system/couplingDict",
                                      &d), 0);
    assert_int_equal(drag_select(d, &m), 0);
    assert_ptr_equal(m, &drag_di_felice);
    dict_free(d);
    const char *t3 = "model B;\ndragModel diFelise;\n";
    assert_int_equal(dict_read_string(t3, strlen(t3), "system/couplingDict",
                                      &d), 0);
    assert_int_equal(drag_select(d, &m), SIM_ERR_DICT);
    const char *msg = sim_error_message();
    assert_non_null(strstr(msg, "system/couplingDict:2"));
    assert_non_null(strstr(msg, "diFelise"));
    assert_non_null(strstr(msg, "ergunWenYu gidaspowBlend diFelice none"));
    sim_error_clear();
    dict_free(d);
    log_set_quiet(0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_formula_points),
        cmocka_unit_test(test_single_sphere_limit),
        cmocka_unit_test(test_continuity),
        cmocka_unit_test(test_zero_slip),
        cmocka_unit_test(test_array_entry),
        cmocka_unit_test(test_terminal_velocity),
        cmocka_unit_test(test_hindered_settling),
        cmocka_unit_test(test_select),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
