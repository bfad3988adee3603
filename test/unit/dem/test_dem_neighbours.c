/*
 * test_dem_neighbours.c — DEM's contact candidates (the half list of
 * particles/neighbour_half.h, through struct dem) against an O(N^2)
 * brute-force search (SWIFT test27cells style), the skin guarantee, history
 * carry-over across rebuilds and grain removal, and the threaded force loop
 * against a brute-force pair loop.
 */
#include <omp.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>

#include "dem_test_helpers.h"

static double urand(unsigned *s)
{
    *s = *s * 1103515245u + 12345u;
    return (double)((*s >> 8) & 0xFFFFFF) / 16777216.0;
}

/* n polydisperse grains (R in [0.5, 1] mm) at random in a 2 cm box. */
static void random_cloud(struct dem *d, size_t n, unsigned seed)
{
    dem_init(d);
    assert_int_equal(th_law(d, &contact_normal_hertz,
                            &contact_damping_restitution,
                            &contact_tangential_coulomb, &contact_rolling_none,
                            0.3, 0.8), SIM_OK);
    assert_int_equal(th_grains(d, n), SIM_OK);
    for (size_t i = 0; i < n; i++) {
        for (int a = 0; a < 3; a++)
            d->x[3 * i + a] = 0.02 * urand(&seed);
        d->r[i] = 5e-4 * (1 + urand(&seed));
        for (int a = 0; a < 3; a++) {
            d->v[3 * i + a] = urand(&seed) - 0.5;
            d->w[3 * i + a] = 100 * (urand(&seed) - 0.5);
        }
    }
    d->nl.skin = 3e-4;
    assert_int_equal(dem_setup(d), SIM_OK);
}

static int in_list(const struct neighbour_half *nl, size_t i, size_t j)
{
    if (i > j) { size_t t = i; i = j; j = t; }
    for (size_t p = nl->start[i]; p < nl->start[i + 1]; p++)
        if (nl->j[p] == j)
            return 1;
    return 0;
}

static double dist(const double *x, size_t i, size_t j)
{
    double s = 0;
    for (int a = 0; a < 3; a++)
        s += (x[3 * i + a] - x[3 * j + a]) * (x[3 * i + a] - x[3 * j + a]);
    return sqrt(s);
}

static void test_list_equals_brute_force(void **state)
{
    (void)state;
    struct dem d;
    random_cloud(&d, 3000, 7);
    size_t brute = 0;
    for (size_t i = 0; i < d.n; i++)
        for (size_t j = i + 1; j < d.n; j++)
            if (dist(d.x, i, j) < d.r[i] + d.r[j] + d.nl.skin) {
                brute++;
                assert_true(in_list(&d.nl, i, j));
            }
    assert_int_equal(brute, d.nl.npairs);      /* and nothing more */
    assert_true(brute > 1000);
    for (size_t i = 0; i < d.n; i++)            /* rows sorted, j > i */
        for (size_t p = d.nl.start[i]; p < d.nl.start[i + 1]; p++) {
            assert_true(d.nl.j[p] > i);
            if (p > d.nl.start[i])
                assert_true(d.nl.j[p] > d.nl.j[p - 1]);
        }
    dem_free(&d);
}

/* Moves below skin/2: the list stays valid (every touching pair listed);
 * a larger move marks it stale. */
static void test_skin_guarantee(void **state)
{
    (void)state;
    struct dem d;
    random_cloud(&d, 2000, 11);
    unsigned s = 3;
    for (size_t k = 0; k < 3 * d.n; k++)
        d.x[k] += 0.49 * d.nl.skin / sqrt(3.0) * (2 * urand(&s) - 1);
    assert_false(neighbour_half_stale(&d.nl, d.n, d.x));
    for (size_t i = 0; i < d.n; i++)
        for (size_t j = i + 1; j < d.n; j++)
            if (dist(d.x, i, j) < d.r[i] + d.r[j])
                assert_true(in_list(&d.nl, i, j));
    d.x[0] += 0.6 * d.nl.skin;
    assert_true(neighbour_half_stale(&d.nl, d.n, d.x));
    dem_free(&d);
}

/* Histories follow their pairs through a rebuild and a removal. */
static void test_history_carry(void **state)
{
    (void)state;
    struct dem d;
    random_cloud(&d, 1500, 5);
    /* encode (id_i, id_j) in each pair's history */
    for (size_t i = 0; i < d.n; i++)
        for (size_t p = d.nl.start[i]; p < d.nl.start[i + 1]; p++) {
            d.hist[3 * p] = (double)d.id[i];
            d.hist[3 * p + 1] = (double)d.id[d.nl.j[p]];
            d.hist[3 * p + 2] = 1;
        }
    size_t kept = 0, before = d.nl.npairs;
    unsigned s = 9;
    for (size_t k = 0; k < 3 * d.n; k++)
        d.x[k] += 0.8 * d.nl.skin * (2 * urand(&s) - 1);
    assert_int_equal(dem_update_neighbours(&d, d.x), SIM_OK);
    assert_int_equal(d.stats.rebuilds, 2);
    for (size_t i = 0; i < d.n; i++)
        for (size_t p = d.nl.start[i]; p < d.nl.start[i + 1]; p++) {
            if (d.hist[3 * p + 2] == 0)
                continue;
            assert_true(d.hist[3 * p] == (double)d.id[i]);
            assert_true(d.hist[3 * p + 1] == (double)d.id[d.nl.j[p]]);
            kept++;
        }
    assert_true(kept > before / 4 && kept <= before);
    /* remove the grains with x > 1 cm: remaining pairs keep their data */
    d.have_domain = 1, d.remove_outside = 1;
    d.dom_lo[0] = d.dom_lo[1] = d.dom_lo[2] = -1;
    d.dom_hi[0] = 0.01, d.dom_hi[1] = d.dom_hi[2] = 1;
    size_t n0 = d.n;
    long out = dem_check_domain(&d);
    assert_true(out > 100);
    assert_int_equal(d.n + (size_t)out, n0);
    size_t kept2 = 0;
    for (size_t i = 0; i < d.n; i++) {
        assert_true(d.x[3 * i] <= 0.01);
        for (size_t p = d.nl.start[i]; p < d.nl.start[i + 1]; p++) {
            if (d.hist[3 * p + 2] == 0)
                continue;
            assert_true(d.hist[3 * p] == (double)d.id[i]);
            assert_true(d.hist[3 * p + 1] == (double)d.id[d.nl.j[p]]);
            kept2++;
        }
    }
    assert_true(kept2 > 0);
    dem_free(&d);
}

/* Forces of the list-based, threaded loop against every pair by brute
 * force with contact_eval. */
static void test_forces_vs_brute_force(void **state)
{
    (void)state;
    struct dem d;
    random_cloud(&d, 1200, 21);
    /* squeeze so that many pairs overlap */
    for (size_t k = 0; k < 3 * d.n; k++)
        d.x[k] *= 0.45;
    d.gravity[2] = 0;
    d.walls = malloc(6 * sizeof *d.walls);
    double lo[3] = {0.001, 0.001, 0.001}, hi[3] = {0.008, 0.008, 0.008};
    assert_int_equal(wall_add_box_inside(d.walls, &d.nwalls, 3, lo, hi, 0),
                     SIM_OK);
    assert_int_equal(dem_setup(&d), SIM_OK);
    unsigned s = 1;
    for (size_t p = 0; p < 3 * d.nl.npairs; p++)
        d.hist[p] = 1e-7 * (urand(&s) - 0.5);
    double tau = 1e-6;
    d.omp_min = 0;   /* exercise the threaded path */
    int nth = omp_get_max_threads();
    omp_set_num_threads(nth > 1 ? 2 : 1);
    assert_int_equal(dem_forces(&d, 0, d.x, d.v, d.w, tau, 0, d.acc, d.alpha),
                     SIM_OK);
    double *f = calloc(6 * d.n, sizeof *f), *t = f + 3 * d.n;
    long contacts = 0;
    for (size_t i = 0; i < d.n; i++)
        for (size_t j = i + 1; j < d.n; j++) {
            double dd = dist(d.x, i, j);
            if (dd >= d.r[i] + d.r[j])
                continue;
            assert_true(in_list(&d.nl, i, j));
            size_t p = d.nl.start[i];
            while (d.nl.j[p] != j)
                p++;
            struct contact_geom g;
            for (int a = 0; a < 3; a++)
                g.n[a] = (d.x[3 * j + a] - d.x[3 * i + a]) / dd;
            g.delta = d.r[i] + d.r[j] - dd;
            g.rstar = d.r[i] * d.r[j] / (d.r[i] + d.r[j]);
            g.mstar = d.m[i] * d.m[j] / (d.m[i] + d.m[j]);
            /* relative velocity written out from its definition */
            double c[3] = {d.r[i] * d.w[3 * i] + d.r[j] * d.w[3 * j],
                           d.r[i] * d.w[3 * i + 1] + d.r[j] * d.w[3 * j + 1],
                           d.r[i] * d.w[3 * i + 2] + d.r[j] * d.w[3 * j + 2]};
            double vr[3] = {
                d.v[3 * i] - d.v[3 * j] + c[1] * g.n[2] - c[2] * g.n[1],
                d.v[3 * i + 1] - d.v[3 * j + 1] + c[2] * g.n[0] - c[0] * g.n[2],
                d.v[3 * i + 2] - d.v[3 * j + 2] + c[0] * g.n[1] - c[1] * g.n[0]};
            g.vn = vr[0] * g.n[0] + vr[1] * g.n[1] + vr[2] * g.n[2];
            for (int a = 0; a < 3; a++) {
                g.vt[a] = vr[a] - g.vn * g.n[a];
                g.wrel[a] = d.w[3 * i + a] - d.w[3 * j + a];
            }
            struct contact_result res;
            double hn[3];
            contact_eval(&d.law, &g, &d.hist[3 * p], tau, hn, &res);
            double tc[3] = {g.n[1] * res.ft[2] - g.n[2] * res.ft[1],
                            g.n[2] * res.ft[0] - g.n[0] * res.ft[2],
                            g.n[0] * res.ft[1] - g.n[1] * res.ft[0]};
            for (int a = 0; a < 3; a++) {
                f[3 * i + a] += res.f[a];
                f[3 * j + a] -= res.f[a];
                t[3 * i + a] += d.r[i] * tc[a];
                t[3 * j + a] += d.r[j] * tc[a];
            }
            contacts++;
        }
    assert_int_equal(contacts, d.ncontacts);
    assert_true(contacts > 500);
    assert_true(d.nwall_contacts > 0);
    /* walls by brute force too */
    for (size_t i = 0; i < d.n; i++)
        for (int wl = 0; wl < d.nwalls; wl++) {
            double nrm[3], delta;
            if (!wall_contact(&d.walls[wl], &d.x[3 * i], d.r[i], nrm, &delta))
                continue;
            /* only check that the wall force is there: its value enters
             * the comparison below */
            struct contact_geom g = {.delta = delta, .rstar = d.r[i],
                                     .mstar = d.m[i]};
            memcpy(g.n, nrm, sizeof nrm);
            double vr[3] = {
                d.v[3 * i] + d.r[i] * (d.w[3 * i + 1] * nrm[2] - d.w[3 * i + 2] * nrm[1]),
                d.v[3 * i + 1] + d.r[i] * (d.w[3 * i + 2] * nrm[0] - d.w[3 * i] * nrm[2]),
                d.v[3 * i + 2] + d.r[i] * (d.w[3 * i] * nrm[1] - d.w[3 * i + 1] * nrm[0])};
            g.vn = vr[0] * nrm[0] + vr[1] * nrm[1] + vr[2] * nrm[2];
            for (int a = 0; a < 3; a++) {
                g.vt[a] = vr[a] - g.vn * nrm[a];
                g.wrel[a] = d.w[3 * i + a];
            }
            size_t hk = 3 * (i * (size_t)d.nwalls + (size_t)wl);
            struct contact_result res;
            double hn[3];
            contact_eval(&d.law, &g, &d.whist[hk], tau, hn, &res);
            double tc[3] = {nrm[1] * res.ft[2] - nrm[2] * res.ft[1],
                            nrm[2] * res.ft[0] - nrm[0] * res.ft[2],
                            nrm[0] * res.ft[1] - nrm[1] * res.ft[0]};
            for (int a = 0; a < 3; a++) {
                f[3 * i + a] += res.f[a];
                t[3 * i + a] += d.r[i] * tc[a];
            }
        }
    double fscale = 0, err = 0, terr = 0, tscale = 0;
    for (size_t k = 0; k < 3 * d.n; k++) {
        size_t i = k / 3;
        fscale = fmax(fscale, fabs(f[k]));
        tscale = fmax(tscale, fabs(t[k]));
        err = fmax(err, fabs(d.acc[k] * d.m[i] - f[k]));
        terr = fmax(terr, fabs(d.alpha[k] / d.inv_i[i] - t[k]));
    }
    printf("  %ld contacts, %ld wall contacts, %d threads: max force error "
           "%.2e of %.2e N, torque %.2e of %.2e N m\n", contacts,
           d.nwall_contacts, nth > 1 ? 2 : 1, err, fscale, terr, tscale);
    assert_true(err <= 1e-12 * fscale);
    assert_true(terr <= 1e-12 * tscale);
    /* the wall candidate list (Verlet's fast path) gives the same forces */
    double *acc0 = malloc(6 * d.n * sizeof *acc0);
    memcpy(acc0, d.acc, 3 * d.n * sizeof *acc0);
    memcpy(acc0 + 3 * d.n, d.alpha, 3 * d.n * sizeof *acc0);
    long nwc = d.nwall_contacts;
    d.use_wlist = 1;
    assert_int_equal(dem_forces(&d, 0, d.x, d.v, d.w, tau, 0, d.acc, d.alpha),
                     SIM_OK);
    assert_int_equal(d.nwall_contacts, nwc);
    for (size_t k = 0; k < 3 * d.n; k++) {
        size_t i = k / 3;
        assert_true(fabs(acc0[k] - d.acc[k]) * d.m[i] <= 1e-12 * fscale);
        assert_true(fabs(acc0[3 * d.n + k] - d.alpha[k]) / d.inv_i[i]
                    <= 1e-12 * tscale);
    }
    free(acc0);
    omp_set_num_threads(nth);
    free(f);
    dem_free(&d);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_list_equals_brute_force),
        cmocka_unit_test(test_skin_guarantee),
        cmocka_unit_test(test_history_carry),
        cmocka_unit_test(test_forces_vs_brute_force),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
