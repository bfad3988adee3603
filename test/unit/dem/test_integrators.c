/*
 * test_integrators.c — the ARKode ERKStep integrator against the Verlet
 * reference and against exact solutions:
 *   - free flight is exact and takes few steps (the point of adaptivity);
 *   - a settling cluster of grains in a box: both integrators agree;
 *   - sliding to rolling (E2-06): t* = 2 v0/(7 mu g), v = 5 v0/7 within 2 %;
 *   - stop times are hit exactly; a fixed step above the Rayleigh bound is
 *     refused with the bound;
 *   - coupling: drag evaluated each sub-step with the current velocity, its
 *     time average returned, momentum balance exact;
 *   - oblique sphere-wall impacts (10 ... 80 deg, mu 0.3, mindlin and
 *     xie2025 stiffness): ARKode's rebound spin and tangential velocity
 *     converge with rtol to an independent reference of the same law
 *     (oblique_reference.h; the springs are in the error-controlled
 *     state, slip phases located exactly), Verlet's with dt;
 *   - Verlet keeps the forces between advances: N steps cost N + 1 force
 *     evaluations however they are split, with bit-identical results;
 *   - auto (ARKode out of contact, Verlet in it): a bouncing bead keeps
 *     e = 0.9 with far fewer evaluations than Verlet, the drag of the
 *     coupling is averaged over the whole interval across the hand-overs;
 *     a pack in contact throughout is Verlet's to the bit.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>

#include "dem_test_helpers.h"
#include "oblique_reference.h"

static double rel(double a, double b) { return fabs(a - b) / fabs(b); }

static const struct dem_integrator_ops *const both[] = {
    &dem_integrator_verlet, &dem_integrator_arkode};

static void test_free_flight(void **state)
{
    (void)state;
    struct dem d;
    dem_init(&d);
    assert_int_equal(th_law(&d, &contact_normal_hertz,
                            &contact_damping_restitution,
                            &contact_tangential_coulomb,
                            &contact_rolling_none, T1_MU, 0.9), SIM_OK);
    assert_int_equal(th_grains(&d, 1), SIM_OK);
    d.v[0] = 1, d.v[2] = 3;
    assert_int_equal(dem_setup(&d), SIM_OK);
    struct dem_integrator_params p = th_params();
    void *ctx;
    assert_int_equal(dem_integrator_arkode.create(&d, &p, &ctx), SIM_OK);
    for (int k = 1; k <= 4; k++)
        assert_int_equal(dem_integrator_arkode.advance(ctx, &d, 0.25 * k),
                         SIM_OK);
    assert_true(d.t == 1.0);
    assert_true(fabs(d.x[0] - 1.0) < 1e-12);
    assert_true(fabs(d.x[2] - (3.0 - 0.5 * 9.81)) < 1e-12);
    printf("  free flight 1 s: %ld steps, %ld force evaluations\n",
           d.stats.steps, d.stats.fevals);
    assert_true(d.stats.steps < 40);
    dem_integrator_arkode.destroy(ctx);
    dem_free(&d);
}

static void test_bad_step_refused(void **state)
{
    (void)state;
    struct dem d;
    dem_init(&d);
    assert_int_equal(th_law(&d, &contact_normal_hertz,
                            &contact_damping_restitution,
                            &contact_tangential_coulomb,
                            &contact_rolling_none, T1_MU, 0.9), SIM_OK);
    assert_int_equal(th_grains(&d, 1), SIM_OK);
    assert_int_equal(dem_setup(&d), SIM_OK);
    struct dem_integrator_params p = th_params();
    p.dt = 1e-4;
    void *ctx;
    assert_int_equal(dem_integrator_verlet.create(&d, &p, &ctx),
                     SIM_ERR_INPUT);
    assert_non_null(strstr(sim_error_message(), "3.61"));
    p = th_params();
    p.rtol = 0;
    assert_int_equal(dem_integrator_arkode.create(&d, &p, &ctx),
                     SIM_ERR_INPUT);
    dem_free(&d);
}

/* 27 grains dropped in a small box: both integrators give the same final
 * positions (a short, non-chaotic interval). */
static void cluster(const struct dem_integrator_ops *ops, double *xout,
                    struct dem_stats *st)
{
    struct dem d;
    dem_init(&d);
    assert_int_equal(th_law(&d, &contact_normal_hertz,
                            &contact_damping_restitution,
                            &contact_tangential_coulomb,
                            &contact_rolling_none, T1_MU, 0.9), SIM_OK);
    assert_int_equal(th_grains(&d, 27), SIM_OK);
    for (int i = 0; i < 27; i++) {
        d.x[3 * i] = 0.005 + 2.1 * T1_R * (i % 3) + 1e-5 * (i % 5);
        d.x[3 * i + 1] = 0.005 + 2.1 * T1_R * ((i / 3) % 3);
        d.x[3 * i + 2] = 1.05 * T1_R + 2.05 * T1_R * (i / 9);
    }
    d.walls = malloc(6 * sizeof *d.walls);
    double lo[3] = {0, 0, 0}, hi[3] = {0.02, 0.02, 0.05};
    assert_int_equal(wall_add_box_inside(d.walls, &d.nwalls, 3, lo, hi, 0),
                     SIM_OK);
    assert_int_equal(dem_setup(&d), SIM_OK);
    struct dem_integrator_params p = th_params();
    p.dt_fraction = 0.05;
    p.rtol = 1e-9, p.atol_x = 1e-13, p.atol_v = 1e-10, p.atol_w = 1e-7;
    void *ctx;
    assert_int_equal(ops->create(&d, &p, &ctx), SIM_OK);
    for (int k = 1; k <= 10; k++)
        assert_int_equal(ops->advance(ctx, &d, 0.001 * k), SIM_OK);
    memcpy(xout, d.x, 81 * sizeof *xout);
    *st = d.stats;
    ops->destroy(ctx);
    dem_free(&d);
}

static void test_cluster_agreement(void **state)
{
    (void)state;
    double xv[81], xa[81];
    struct dem_stats sv, sa;
    cluster(&dem_integrator_verlet, xv, &sv);
    cluster(&dem_integrator_arkode, xa, &sa);
    double err = 0;
    for (int k = 0; k < 81; k++)
        err = fmax(err, fabs(xv[k] - xa[k]));
    printf("  27 grains, 10 ms: max |x_verlet - x_arkode| = %.2e m (%.2e R);"
           " verlet %ld steps, arkode %ld steps (%ld rejected, %ld "
           "stability-limited), %ld + %ld evaluations\n", err, err / T1_R,
           sv.steps, sa.steps, sa.rejected, sa.stab_limited, sa.fevals,
           sa.hist_evals);
    assert_true(err < 1e-3 * T1_R);
}

/* E2-06: v0 = 1 m/s, w0 = 0 on the floor, mu = 0.2. */
static void test_sliding_to_rolling(void **state)
{
    (void)state;
    double v0 = 0.5, g = 9.81;
    double tstar = 2 * v0 / (7 * T1_MU * g), vroll = 5 * v0 / 7;
    for (int k = 0; k < 2; k++) {
        struct dem d;
        dem_init(&d);
        assert_int_equal(th_law(&d, &contact_normal_hertz,
                                &contact_damping_restitution,
                                &contact_tangential_coulomb,
                                &contact_rolling_none, T1_MU, 0.9), SIM_OK);
        assert_int_equal(th_grains(&d, 1), SIM_OK);
        th_floor(&d);
        d.x[2] = T1_R - 2.14e-7;  /* static overlap */
        d.v[0] = v0;
        assert_int_equal(dem_setup(&d), SIM_OK);
        struct dem_integrator_params p = th_params();
        p.rtol = 1e-6;
        p.dt_fraction = 0.2;
        void *ctx;
        assert_int_equal(both[k]->create(&d, &p, &ctx), SIM_OK);
        double dto = 2e-4, t_roll = -1, prev_slip = v0;
        for (int s = 1; s <= 450; s++) {
            assert_int_equal(both[k]->advance(ctx, &d, s * dto), SIM_OK);
            double slip = d.v[0] - T1_R * d.w[1];
            if (t_roll < 0 && slip < 1e-3 * v0)
                t_roll = d.t - dto * (slip - 1e-3 * v0) / (slip - prev_slip);
            prev_slip = slip;
        }
        printf("  %s: t* = %.5f s (ref %.5f), v = %.5f m/s (ref %.5f); "
               "%ld steps, %ld evaluations\n", both[k]->name, t_roll, tstar,
               d.v[0], vroll, d.stats.steps, d.stats.fevals);
        assert_true(rel(t_roll, tstar) < 0.02);
        assert_true(rel(d.v[0], vroll) < 0.02);
        both[k]->destroy(ctx);
        dem_free(&d);
    }
}

/* Linear drag F = c (u_f - v) toward a fluid at rest: the grain falls to
 * the terminal velocity m g/c; the time-averaged drag returned satisfies
 * m (v1 - v0) = (m g + <F_d>) T. */
struct drag_ctx {
    double c;
    long calls;
};

static int linear_drag(void *ctx, size_t n, const double *r, const double *v,
                       const double *uf, const double *eps, double *fd)
{
    struct drag_ctx *c = ctx;
    (void)r, (void)eps;
    for (size_t k = 0; k < 3 * n; k++)
        fd[k] = c->c * (uf[k] - v[k]);
    c->calls++;
    return SIM_OK;
}

static void test_coupling_drag(void **state)
{
    (void)state;
    for (int k = 0; k < 2; k++) {
        struct dem d;
        dem_init(&d);
        assert_int_equal(th_law(&d, &contact_normal_hertz,
                                &contact_damping_restitution,
                                &contact_tangential_coulomb,
                                &contact_rolling_none, T1_MU, 0.9), SIM_OK);
        assert_int_equal(th_grains(&d, 1), SIM_OK);
        assert_int_equal(dem_setup(&d), SIM_OK);
        double uf[3] = {0, 0, 0}, eps = 1, fext[3] = {1e-5, 0, 0};
        /* relaxation time m/c = 1 ms: much shorter than the interval */
        struct drag_ctx dc = {.c = d.m[0] / 1e-3};
        dem_coupling_set(&d, fext, uf, &eps, linear_drag, &dc);
        struct dem_integrator_params p = th_params();
        p.rtol = 1e-8;
        void *ctx;
        assert_int_equal(both[k]->create(&d, &p, &ctx), SIM_OK);
        double v0 = d.v[2], T = 0.01, fd[3];
        assert_int_equal(both[k]->advance(ctx, &d, T), SIM_OK);
        assert_true(rel(dem_mean_drag(&d, fd), T) < 1e-12);
        double mom = d.m[0] * (d.v[2] - v0), imp = (d.m[0] * -9.81 + fd[2]) * T;
        double vt = -9.81 * 1e-3 * (1 - exp(-10.0));
        printf("  %s: v_z(T) = %.6f m/s (exact %.6f), momentum balance "
               "error %.1e, drag calls %ld\n", both[k]->name, d.v[2], vt,
               fabs(mom - imp) / fabs(mom), dc.calls);
        assert_true(rel(d.v[2], vt) < 1e-3);
        assert_true(fabs(mom - imp) < 1e-9 * fabs(mom));
        /* external force: x velocity fext/c at steady state */
        assert_true(rel(d.v[0], fext[0] / dc.c) < 1e-3);
        assert_true(dc.calls > 10);
        both[k]->destroy(ctx);
        dem_free(&d);
    }
}

/* Oblique impact of a sphere on the floor (no gravity), Hertz with
 * restitution damping, Coulomb mu = 0.3, e = 0.9, speed 1 m/s at angle
 * theta from the normal, tangential stiffness st: the rebound tangential
 * velocity and spin depend on the whole spring history (stick, slip,
 * reversal). */
struct rebound {
    double vt, w;          /* v_x and w_y after the contact      */
    long steps, evals;
};

static void oblique(const struct dem_integrator_ops *ops,
                    const struct dem_integrator_params *p, double theta,
                    const struct contact_stiffness_ops *st,
                    struct rebound *out)
{
    struct dem d;
    dem_init(&d);
    d.law.stiffness = st;
    assert_int_equal(th_law(&d, &contact_normal_hertz,
                            &contact_damping_restitution,
                            &contact_tangential_coulomb,
                            &contact_rolling_none, 0.3, 0.9), SIM_OK);
    assert_int_equal(th_grains(&d, 1), SIM_OK);
    th_floor(&d);
    d.gravity[2] = 0;
    d.x[2] = T1_R + 1e-6;
    d.v[0] = sin(theta);
    d.v[2] = -cos(theta);
    assert_int_equal(dem_setup(&d), SIM_OK);
    void *ctx;
    assert_int_equal(ops->create(&d, p, &ctx), SIM_OK);
    /* contact from 1-2 us to about 135-150 us; split in intervals so that
     * interval ends fall inside the contact */
    for (int k = 1; k <= 8; k++)
        assert_int_equal(ops->advance(ctx, &d, 5e-5 * k), SIM_OK);
    assert_true(d.x[2] > T1_R);   /* the contact has ended */
    out->vt = d.v[0];
    out->w = d.w[1];
    out->steps = d.stats.steps;
    out->evals = d.stats.fevals + d.stats.hist_evals;
    ops->destroy(ctx);
    dem_free(&d);
}

/* ARKode's rebound against the reference of oblique_reference.h (the
 * same law written out for one sphere, classical Runge-Kutta with every
 * switch located; its own error, from a halved step, is checked below
 * 1e-10), for both tangential stiffnesses (mindlin, the default, and
 * xie2025, 2.8 times softer) at 10 deg (stick, slip at the end of the
 * contact), 30 deg (slip, stick, reversed slip), 45, 60 deg (slip nearly
 * throughout, the slider sliding on while the contact unloads, A0-24) and
 * 80 deg (gross slip). Errors in units of the incoming tangential speed
 * v_t0 and v_t0/R; every case must converge with rtol (the rtol 1e-8
 * error below both others) to below 1e-4 at rtol 1e-8. Verlet with the
 * same law converges to the same reference at first order (printed, and
 * checked to 5e-5 at dt = 1e-9 s). Measured values: doc/theory.md A.6,
 * test/bench/README.dem.md. */
static void test_oblique_impact_order(void **state)
{
    (void)state;
    const double angles[5] = {10, 30, 45, 60, 80};
    const struct contact_stiffness_ops *const st[2] = {
        &contact_stiffness_mindlin, &contact_stiffness_xie2025};
    for (int is = 0; is < 2; is++)
        for (int ia = 0; ia < 5; ia++) {
            double th = angles[ia] * M_PI / 180, vt0 = sin(th);
            struct dem d;
            dem_init(&d);
            d.law.stiffness = st[is];
            assert_int_equal(th_law(&d, &contact_normal_hertz,
                                    &contact_damping_restitution,
                                    &contact_tangential_coulomb,
                                    &contact_rolling_none, 0.3, 0.9),
                             SIM_OK);
            double m = T1_RHO * 4.0 / 3.0 * M_PI * pow(T1_R, 3);
            struct oref op = {
                .m = m, .inertia = 0.4 * m * T1_R * T1_R, .r = T1_R,
                .chi = contact_chi(&d.law.c, T1_R),
                .ratio_t = d.law.c.ratio_t, .zeta = d.law.c.zeta,
                .mu = d.law.c.mu};
            dem_free(&d);
            struct oref_out ref, ref2;
            oblique_reference(&op, th, 1.5e-4, 50000, &ref);
            oblique_reference(&op, th, 1.5e-4, 100000, &ref2);
            double rerr = fmax(fabs(ref2.vt - ref.vt) / vt0,
                               fabs(ref2.w - ref.w) * T1_R / vt0);
            printf("  %s %g deg: reference v_t %.10f m/s, w %.7f rad/s "
                   "(%d switches, %d sign changes of F^n; halved step: "
                   "%.1e)\n", st[is]->name, angles[ia], ref2.vt, ref2.w,
                   ref2.switches, ref2.fn_signs, rerr);
            struct dem_integrator_params p = th_params();
            struct rebound rv;
            double evv[2];
            for (int k = 0; k < 2; k++) {
                p.dt = k ? 1e-9 : 2e-9;
                oblique(&dem_integrator_verlet, &p, th, st[is], &rv);
                evv[k] = fabs(rv.vt - ref2.vt) / vt0;
                printf("    verlet dt %g s: v_t error %.2e, w error %.2e\n",
                       p.dt, evv[k], fabs(rv.w - ref2.w) * T1_R / vt0);
            }
            double ev[3], ew[3];
            const double rtols[3] = {1e-4, 1e-6, 1e-8};
            for (int k = 0; k < 3; k++) {
                struct rebound ra;
                p = th_params();
                p.rtol = rtols[k];
                p.atol_x = rtols[k] * 1e-3;
                p.atol_v = rtols[k];
                p.atol_w = rtols[k] * 1e3;
                oblique(&dem_integrator_arkode, &p, th, st[is], &ra);
                ev[k] = fabs(ra.vt - ref2.vt) / vt0;
                ew[k] = fabs(ra.w - ref2.w) * T1_R / vt0;
                printf("    arkode rtol %g: v_t %.10f, w %.7f; error %.2e, "
                       "%.2e; %ld steps, %ld evaluations\n", rtols[k],
                       ra.vt, ra.w, ev[k], ew[k], ra.steps, ra.evals);
            }
            assert_true(rerr < 1e-10);
            assert_true(evv[1] < 5e-5);
            assert_true(ev[2] < ev[1] && ev[2] < ev[0]);
            assert_true(ew[2] < ew[1] && ew[2] < ew[0]);
            assert_true(ev[2] < 1e-4 && ew[2] < 1e-4);
        }
}

/* 27 grains settling in a box with Verlet at a step of
 * 2^-17 s, 1024 steps as one advance or as 64 advances of 16 steps (all
 * times exact binary fractions, so both take identical steps): the same
 * 1025 force evaluations and bit-identical grains (the forces of the last
 * step are kept, not re-evaluated at the start of an advance). */
static void packed(const struct dem_integrator_ops *ops, int nadv,
                   double *out, struct dem_stats *st)
{
    struct dem d;
    dem_init(&d);
    assert_int_equal(th_law(&d, &contact_normal_hertz,
                            &contact_damping_restitution,
                            &contact_tangential_coulomb,
                            &contact_rolling_none, T1_MU, 0.9), SIM_OK);
    assert_int_equal(th_grains(&d, 27), SIM_OK);
    for (int i = 0; i < 27; i++) {
        d.x[3 * i] = 0.005 + 2.01 * T1_R * (i % 3) + 1e-5 * (i % 5);
        d.x[3 * i + 1] = 0.005 + 2.01 * T1_R * ((i / 3) % 3);
        d.x[3 * i + 2] = 1.0 * T1_R + 2.0 * T1_R * (i / 9);
        d.v[3 * i] = 0.05 * ((i % 3) - 1);
    }
    d.walls = malloc(6 * sizeof *d.walls);
    double lo[3] = {0, 0, 0}, hi[3] = {0.02, 0.02, 0.05};
    assert_int_equal(wall_add_box_inside(d.walls, &d.nwalls, 3, lo, hi, 0),
                     SIM_OK);
    assert_int_equal(dem_setup(&d), SIM_OK);
    struct dem_integrator_params p = th_params();
    p.dt = ldexp(1.0, -17);
    void *ctx;
    assert_int_equal(ops->create(&d, &p, &ctx), SIM_OK);
    for (int k = 1; k <= nadv; k++)
        assert_int_equal(ops->advance(ctx, &d, ldexp(1.0, -7) * k / nadv),
                         SIM_OK);
    memcpy(out, d.x, 81 * sizeof *out);
    memcpy(out + 81, d.v, 81 * sizeof *out);
    memcpy(out + 162, d.w, 81 * sizeof *out);
    *st = d.stats;
    assert_true(d.ncontacts + d.nwall_contacts > 10);
    ops->destroy(ctx);
    dem_free(&d);
}

static void test_verlet_keeps_forces(void **state)
{
    (void)state;
    double a[243], b[243];
    struct dem_stats sa, sb;
    packed(&dem_integrator_verlet, 1, a, &sa);
    packed(&dem_integrator_verlet, 64, b, &sb);
    printf("  1 advance: %ld steps, %ld evaluations; 64 advances: %ld steps,"
           " %ld evaluations; identical: %s\n", sa.steps, sa.fevals,
           sb.steps, sb.fevals, memcmp(a, b, sizeof a) ? "no" : "yes");
    assert_int_equal(sa.steps, 1024);
    assert_int_equal(sb.steps, 1024);
    assert_int_equal(sa.fevals, 1025);
    assert_int_equal(sb.fevals, 1025);
    assert_memory_equal(a, b, sizeof a);
}

/* The same pack with auto: in contact at every step, so Verlet's steps
 * from the first (no hand-over), to the bit. */
static void test_auto_packed_is_verlet(void **state)
{
    (void)state;
    double a[243], b[243];
    struct dem_stats sa, sb;
    packed(&dem_integrator_verlet, 8, a, &sa);
    packed(&dem_integrator_auto, 8, b, &sb);
    assert_int_equal(sa.steps, sb.steps);
    assert_int_equal(sa.fevals, sb.fevals);
    assert_memory_equal(a, b, sizeof a);
}

/* A bead dropped from 5 cm on the floor under a weak linear drag
 * (relaxation time 100 s), 0.2 s in 8 advances: one bounce near 0.1 s.
 * The rebound speed, from the energy of the flight after it, is e = 0.9
 * times the impact speed (restitution damping returns e) to 0.1 %, as
 * with ARKode alone (to 1e-3); auto takes a tenth of Verlet's
 * evaluations at the same fraction; the drag is averaged over all of
 * every interval, the one with the two hand-overs included. */
static void bounce(const struct dem_integrator_ops *ops, double *vreb,
                   double *vimp, long *evals)
{
    struct dem d;
    dem_init(&d);
    assert_int_equal(th_law(&d, &contact_normal_hertz,
                            &contact_damping_restitution,
                            &contact_tangential_coulomb,
                            &contact_rolling_none, T1_MU, 0.9), SIM_OK);
    assert_int_equal(th_grains(&d, 1), SIM_OK);
    th_floor(&d);
    d.x[2] = 0.05;
    assert_int_equal(dem_setup(&d), SIM_OK);
    double uf[3] = {0, 0, 0}, eps = 1, fd[3];
    struct drag_ctx dc = {.c = d.m[0] / 100.0};
    dem_coupling_set(&d, NULL, uf, &eps, linear_drag, &dc);
    struct dem_integrator_params p = th_params();
    p.rtol = 1e-8, p.atol_x = 1e-12, p.atol_v = 1e-9;
    p.dt_fraction = 0.02;
    void *ctx;
    assert_int_equal(ops->create(&d, &p, &ctx), SIM_OK);
    double vmin = 0;
    for (int k = 1; k <= 8; k++) {
        double t0 = d.t;
        assert_int_equal(ops->advance(ctx, &d, 0.025 * k), SIM_OK);
        assert_true(d.t == 0.025 * k);
        assert_true(rel(dem_mean_drag(&d, fd), d.t - t0) < 1e-12);
        dem_coupling_set(&d, NULL, uf, &eps, linear_drag, &dc);
        if (k == 3)   /* 0.075 s: falling; the impact speed from energy */
            vmin = sqrt(d.v[2] * d.v[2] + 2 * 9.81 * (d.x[2] - T1_R));
    }
    assert_true(d.x[2] > T1_R + 0.01);   /* in flight after the bounce */
    *vimp = vmin;
    *vreb = sqrt(d.v[2] * d.v[2] + 2 * 9.81 * (d.x[2] - T1_R));
    *evals = d.stats.fevals + d.stats.hist_evals;
    ops->destroy(ctx);
    dem_free(&d);
}

static void test_auto_bounce(void **state)
{
    (void)state;
    const struct dem_integrator_ops *const ops[3] = {
        &dem_integrator_auto, &dem_integrator_arkode, &dem_integrator_verlet};
    double vr[3], vi[3];
    long ev[3];
    for (int k = 0; k < 3; k++) {
        bounce(ops[k], &vr[k], &vi[k], &ev[k]);
        printf("  %s: rebound/impact speed %.5f, %ld evaluations\n",
               ops[k]->name, vr[k] / vi[k], ev[k]);
    }
    /* the weak drag takes ~5e-4 of the speeds over the flights */
    assert_true(fabs(vr[0] / vi[0] - 0.9) < 1e-3);
    assert_true(fabs(vr[0] / vi[0] - vr[1] / vi[1]) < 1e-3);
    assert_true(ev[0] < ev[2] / 10);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_free_flight),
        cmocka_unit_test(test_bad_step_refused),
        cmocka_unit_test(test_cluster_agreement),
        cmocka_unit_test(test_sliding_to_rolling),
        cmocka_unit_test(test_coupling_drag),
        cmocka_unit_test(test_oblique_impact_order),
        cmocka_unit_test(test_verlet_keeps_forces),
        cmocka_unit_test(test_auto_packed_is_verlet),
        cmocka_unit_test(test_auto_bounce),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
