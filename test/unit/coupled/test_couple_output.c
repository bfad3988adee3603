/* test_couple_output.c — the coupling fields of the output
 * (couple_output.h): the fluid's reaction -V_i f_A,i snapshot before
 * mps_step() and put back in the particle order of the written cloud
 * (renumbered and with a particle dropped, against a direct lookup), the
 * unchanged-order fast path, and the grains' slip u_k - v_k (0 for a dry
 * grain; nothing consistent to write after a grain was removed). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <stdlib.h>
#include <string.h>

#include "couplingDem/couple_dem.h"
#include "couplingMps/couple_fluid.h"
#include "couplingMps/couple_output.h"
#include "dem/dem.h"
#include "mps/mps.h"

#define N 257

static uint64_t rng = 99;
static uint64_t next(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return rng;
}

static void test_reaction_renumbered(void **state)
{
    (void)state;
    static struct couple_fluid cf;
    static struct mps_particles P;
    static int64_t id[N], id0[N];
    static double fA[3 * N];
    struct couple_output o = { 0 };
    double *out;
    memset(&cf, 0, sizeof cf);
    cf.Vp = 1.25e-7;
    cf.fA = fA;
    cf.pairs.np = N;
    for (int i = 0; i < N; i++) {
        id0[i] = id[i] = 1000 + 7 * (int64_t)((i * 37) % N);  /* unique */
        for (int c = 0; c < 3; c++)
            fA[3 * i + c] = (double)(next() % 100000) - 5e4;
    }
    P.n = N;
    P.id = id;
    assert_int_equal(couple_output_snapshot(&o, &cf, &P), 0);
    /* same order: a copy */
    assert_int_equal(couple_output_reaction(&o, &P, &out), 0);
    for (int e = 0; e < 3 * N; e++)
        assert_true(out[e] == -cf.Vp * fA[e]);
    /* shuffle the ids (what mps_step's renumbering does), drop the last */
    for (int i = N - 1; i > 0; i--) {
        int j = (int)(next() % (uint64_t)(i + 1));
        int64_t t = id[i];
        id[i] = id[j];
        id[j] = t;
    }
    P.n = N - 1;
    memset(fA, 0, sizeof fA);   /* the snapshot must not read cf again */
    assert_int_equal(couple_output_reaction(&o, &P, &out), 0);
    for (int i = 0; i < P.n; i++) {
        int k = 0;
        while (id0[k] != id[i])
            k++;
        for (int c = 0; c < 3; c++)
            assert_true(out[3 * i + c] == o.F[3 * k + c]);
    }
    couple_output_free(&o);
}

static void test_slip(void **state)
{
    (void)state;
    static struct couple_dem cd;
    static struct dem d;
    double uf[6] = { 1, 2, 3, 4, 5, 6 }, v[6] = { 0.5, 0.25, 0, 1, 1, 1 };
    double slip[6];
    uint8_t wet[2] = { 1, 0 };
    memset(&cd, 0, sizeof cd);
    memset(&d, 0, sizeof d);
    cd.n = d.n = 2;
    cd.uf = uf;
    cd.wet = wet;
    cd.slip = slip;
    d.v = v;
    assert_int_equal(couple_dem_output(&cd, &d), 1);
    for (int c = 0; c < 3; c++) {
        assert_true(slip[c] == uf[c] - v[c]);
        assert_true(slip[3 + c] == 0.0);
    }
    d.n = 1;   /* a grain removed after the exchange */
    assert_int_equal(couple_dem_output(&cd, &d), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reaction_renumbered),
        cmocka_unit_test(test_slip),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
