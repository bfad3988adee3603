/*
 * test_rolling.c — rolling-resistance sub-models on a bead rolling without
 * slip on the floor (v = R w at start, mu large enough to keep rolling):
 *   constantTorque  M = mu_r R |F_n|  ->  dv/dt = -(5/7) mu_r g
 *   viscous         M = eta_r w       ->  v = v0 exp(-t/tau),
 *                                         tau = 7 m R^2/(5 eta_r)
 *   none            v constant
 * (from m dv/dt = F_t, I dw/dt = -R F_t - M, v = R w, I = 2/5 m R^2).
 * Tolerance 2 %. And a bead spinning about the vertical at 100 rad/s on
 * the floor (doc/theory.md A0-23): the rolling models leave the spin alone
 * (to 1e-9 after 0.1 s; before the fix constantTorque with mu_r = 0.1
 * stopped it within 0.1 s), `twisting viscous` damps it as
 * exp(-eta_tw t/I) (1 %).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>

#include "../../unit/dem/dem_test_helpers.h"

static double roll(const struct contact_rolling_ops *r, double mu_r,
                   double eta_r, double t_end)
{
    struct dem d;
    dem_init(&d);
    assert_int_equal(th_law(&d, &contact_normal_hertz,
                            &contact_damping_restitution,
                            &contact_tangential_coulomb, r, 0.5, 0.9),
                     SIM_OK);
    d.law.c.mu_roll = mu_r;
    d.law.c.eta_roll = eta_r;
    assert_int_equal(th_grains(&d, 1), SIM_OK);
    th_floor(&d);
    d.x[2] = T1_R - 2.14e-7;
    d.v[0] = 0.1;
    d.w[1] = 0.1 / T1_R;
    assert_int_equal(dem_setup(&d), SIM_OK);
    struct dem_integrator_params p = th_params();
    p.dt_fraction = 0.3;
    void *ctx;
    assert_int_equal(dem_integrator_verlet.create(&d, &p, &ctx), SIM_OK);
    assert_int_equal(dem_integrator_verlet.advance(ctx, &d, t_end), SIM_OK);
    double v = d.v[0];
    /* still rolling, not sliding */
    assert_true(fabs(d.v[0] - T1_R * d.w[1]) < 1e-3 * fabs(d.v[0]) + 1e-9);
    dem_integrator_verlet.destroy(ctx);
    dem_free(&d);
    return v;
}

static void test_rolling_models(void **state)
{
    (void)state;
    double t = 0.5, g = 9.81;
    double v_none = roll(&contact_rolling_none, 0, 0, t);
    double mu_r = 0.01;
    double v_cdt = roll(&contact_rolling_constant_torque, mu_r, 0, t);
    double v_cdt_ref = 0.1 - 5.0 / 7.0 * mu_r * g * t;
    double m = T1_RHO * 4.0 / 3.0 * M_PI * pow(T1_R, 3), eta = 1e-10;
    double tau = 7.0 * m * T1_R * T1_R / (5.0 * eta);
    double v_visc = roll(&contact_rolling_viscous, 0, eta, t);
    double v_visc_ref = 0.1 * exp(-t / tau);
    printf("  v(0.5 s): none %.6f (0.1), constantTorque %.6f (%.6f), "
           "viscous %.6f (%.6f)\n", v_none, v_cdt, v_cdt_ref, v_visc,
           v_visc_ref);
    assert_true(fabs(v_none - 0.1) < 1e-3 * 0.1);
    assert_true(fabs(v_cdt - v_cdt_ref) < 0.02 * (0.1 - v_cdt_ref));
    assert_true(fabs(v_visc - v_visc_ref) < 0.02 * (0.1 - v_visc_ref));
}

/* Spin w0 about the vertical for t_end; returns w_z. */
static double spin(const struct contact_rolling_ops *r,
                   const struct contact_twisting_ops *tw, double t_end)
{
    struct dem d;
    dem_init(&d);
    d.law.twisting = tw;
    assert_int_equal(th_law(&d, &contact_normal_hertz,
                            &contact_damping_restitution,
                            &contact_tangential_coulomb, r, 0.5, 0.9),
                     SIM_OK);
    d.law.c.mu_roll = 0.1;
    d.law.c.eta_roll = 1e-10;
    d.law.c.eta_twist = 1e-10;
    assert_int_equal(th_grains(&d, 1), SIM_OK);
    th_floor(&d);
    d.x[2] = T1_R - 2.14e-7;
    d.w[2] = 100;
    assert_int_equal(dem_setup(&d), SIM_OK);
    struct dem_integrator_params p = th_params();
    p.dt_fraction = 0.3;
    void *ctx;
    assert_int_equal(dem_integrator_verlet.create(&d, &p, &ctx), SIM_OK);
    assert_int_equal(dem_integrator_verlet.advance(ctx, &d, t_end), SIM_OK);
    double w = d.w[2];
    assert_true(fabs(d.w[0]) + fabs(d.w[1]) < 1e-9);
    dem_integrator_verlet.destroy(ctx);
    dem_free(&d);
    return w;
}

static void test_spin_about_normal(void **state)
{
    (void)state;
    double t = 0.1;
    const struct contact_rolling_ops *rl[] = {
        &contact_rolling_none, &contact_rolling_constant_torque,
        &contact_rolling_viscous};
    for (int k = 0; k < 3; k++) {
        double w = spin(rl[k], NULL, t);
        printf("  rolling %s, twisting none: w_z(0.1 s) = %.9f rad/s "
               "(100)\n", rl[k]->name, w);
        assert_true(fabs(w - 100) < 1e-9 * 100);
    }
    double m = T1_RHO * 4.0 / 3.0 * M_PI * pow(T1_R, 3);
    double inertia = 0.4 * m * T1_R * T1_R;
    double ref = 100 * exp(-1e-10 * t / inertia);
    double w = spin(&contact_rolling_constant_torque,
                    &contact_twisting_viscous, t);
    printf("  twisting viscous: w_z(0.1 s) = %.5f rad/s (%.5f)\n", w, ref);
    assert_true(fabs(w - ref) < 0.01 * (100 - ref));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rolling_models),
        cmocka_unit_test(test_spin_about_normal),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
