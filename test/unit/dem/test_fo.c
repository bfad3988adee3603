/*
 * test_fo.c — DEM function objects on hand-made scenes: front (largest
 * cluster only), kineticEnergy (translation + rotation), bedHeight.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>

#include "core/dict.h"
#include "core/log.h"
#include "dem/functionObjects/dem_fo.h"
#include "dem_test_helpers.h"

/* Run one function object on d, return its last output line in buf. */
static void run_fo(const struct fo_ops *ops, const char *keys, struct dem *d,
                   char *buf, size_t n)
{
    struct dict *dd;
    assert_int_equal(dict_read_string(keys, strlen(keys), "test", &dd),
                     SIM_OK);
    struct fo_scene s = {.time = 0.5, .solver = d, .store = &d->st};
    void *data = NULL;
    assert_int_equal(ops->create(dd, &s, &data), SIM_OK);
    FILE *f = tmpfile();
    assert_non_null(f);
    assert_int_equal(ops->header(data, &s, f), SIM_OK);
    assert_int_equal(ops->execute(data, &s, f), SIM_OK);
    rewind(f);
    while (fgets(buf, (int)n, f))
        ;
    fclose(f);
    ops->destroy(data);
    dict_free(dd);
}

static void scene(struct dem *d)
{
    dem_init(d);
    assert_int_equal(th_law(d, &contact_normal_hertz,
                            &contact_damping_restitution,
                            &contact_tangential_coulomb,
                            &contact_rolling_none, T1_MU, 0.9), SIM_OK);
    assert_int_equal(th_grains(d, 5), SIM_OK);
    th_floor(d);
    /* a pack of 3 touching beads on the floor, a pair touching each other
     * further on (2 grains: a smaller cluster), all at rest but one */
    /* neighbours overlap by 1e-7 m */
    double xs[5] = {0.010, 0.0127 - 1e-7, 0.0154 - 2e-7, 0.030,
                    0.0327 - 1e-7};
    for (int i = 0; i < 5; i++) {
        d->x[3 * i] = xs[i];
        d->x[3 * i + 2] = T1_R - 1e-7;
        d->id[i] = 100 + i;
    }
    d->v[3] = 0.2;      /* grain 1 moves: 1/2 m v^2 */
    d->w[5] = 10;       /* and spins: 1/2 I w^2    */
    assert_int_equal(dem_setup(d), SIM_OK);
}

static void test_front_largest_cluster(void **state)
{
    (void)state;
    struct dem d;
    scene(&d);
    char line[512];
    run_fo(&dem_fo_front, "direction (1 0 0);", &d, line, sizeof line);
    double t, front;
    long long id;
    size_t count;
    assert_int_equal(sscanf(line, "%lg %lg %lld %zu", &t, &front, &id,
                            &count), 4);
    /* grains 3 and 4 are further ahead but form the smaller cluster */
    assert_int_equal(count, 3);
    assert_int_equal(id, 102);
    assert_true(fabs(front - (0.0154 - 2e-7 + T1_R)) < 1e-12);
    /* against -x the pack's leading grain is grain 0 */
    run_fo(&dem_fo_front, "direction (-1 0 0);", &d, line, sizeof line);
    assert_int_equal(sscanf(line, "%lg %lg %lld %zu", &t, &front, &id,
                            &count), 4);
    assert_int_equal(id, 100);
    assert_true(fabs(front - (-0.010 + T1_R)) < 1e-12);
    dem_free(&d);
}

static void test_kinetic_energy(void **state)
{
    (void)state;
    struct dem d;
    scene(&d);
    char line[512];
    run_fo(&dem_fo_kinetic_energy, "", &d, line, sizeof line);
    double t, et, er, e;
    assert_int_equal(sscanf(line, "%lg %lg %lg %lg", &t, &et, &er, &e), 4);
    double m = d.m[1], I = 0.4 * m * T1_R * T1_R;
    /* the file holds 9 significant digits */
    assert_true(fabs(et - 0.5 * m * 0.04) < 1e-8 * et);
    assert_true(fabs(er - 0.5 * I * 100) < 1e-8 * er);
    assert_true(fabs(e - (et + er)) < 1e-8 * e);
    dem_free(&d);
}

static void test_bed_height(void **state)
{
    (void)state;
    struct dem d;
    scene(&d);
    char line[512];
    /* minContacts 2: every grain touches the floor and a neighbour */
    run_fo(&dem_fo_bed_height, "minContacts 2;", &d, line, sizeof line);
    double t, top, mean;
    long k;
    assert_int_equal(sscanf(line, "%lg %lg %lg %ld", &t, &top, &mean, &k), 4);
    assert_true(fabs(top - (2 * T1_R - 1e-7)) < 1e-12);
    assert_int_equal(k, 5);
    /* a window that holds only the pair */
    run_fo(&dem_fo_bed_height, "minContacts 2; min (0.025 -1 -1);", &d,
           line, sizeof line);
    assert_int_equal(sscanf(line, "%lg %lg %lg %ld", &t, &top, &mean, &k), 4);
    assert_int_equal(k, 2);
    dem_free(&d);
}

/* grainState follows a grain by id through the removal of another (the
 * registry compacts every field), and reports nan for an unknown id. */
static void test_grain_state(void **state)
{
    (void)state;
    struct dem d;
    scene(&d);
    char line[512];
    double v[19];
    for (int pass = 0; pass < 2; pass++) {
        run_fo(&dem_fo_grain_state, "ids (101 7);", &d, line, sizeof line);
        char *p = line, *end;
        int n = 0;
        while (n < 19 && (v[n] = strtod(p, &end), end != p))
            n++, p = end;
        assert_int_equal(n, 19);
        assert_true(v[1] == 0.0127 - 1e-7 && v[3] == T1_R - 1e-7);
        assert_true(v[4] == 0.2 && v[5] == 0 && v[9] == 10);
        for (int k = 10; k < 19; k++)
            assert_true(isnan(v[k]));
        if (pass == 0) {
            /* grain 100 (at x = 0.010) leaves the domain */
            d.have_domain = d.remove_outside = 1;
            double lo[3] = {0.011, -1, -1}, hi[3] = {1, 1, 1};
            memcpy(d.dom_lo, lo, sizeof lo);
            memcpy(d.dom_hi, hi, sizeof hi);
            assert_int_equal(dem_check_domain(&d), 1);
            assert_int_equal(d.n, 4);
            assert_int_equal(d.st.n, 4);
            assert_int_equal(d.id[0], 101);
        }
    }
    dem_free(&d);
}

int main(void)
{
    log_set_quiet(1);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_front_largest_cluster),
        cmocka_unit_test(test_kinetic_energy),
        cmocka_unit_test(test_bed_height),
        cmocka_unit_test(test_grain_state),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
