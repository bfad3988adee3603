/* test_couple_output.c — the coupling fields of the output: the fluid's
 * reaction -V_i f_A,i (couple_fluid_reaction_field; 0 beyond the pairs'
 * particles, V_i = phi_i Vp with volume fractions), which as a field of
 * the particles' store follows them through a renumbering and the removal
 * of a particle; and the grains' slip u_k - v_k (0 for a dry grain;
 * nothing consistent to write after a grain was removed). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <stdlib.h>
#include <string.h>

#include "couplingDem/couple_dem.h"
#include "couplingMps/couple_fluid.h"
#include "dem/dem.h"
#include "mps/mps.h"
#include "particles/store.h"

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
    static double fA[3 * N], phi[N];
    static int64_t id0[N];
    static int32_t perm[N];
    struct store st;
    int64_t *id = NULL;
    double *F = NULL;
    memset(&cf, 0, sizeof cf);
    store_init(&st, "test");
    assert_int_equal(store_add(&st, "id", "", VTU_INT64, 1, 0, &id), 0);
    assert_int_equal(store_add(&st, "reaction", "", VTU_FLOAT64, 3,
                               STORE_WRITE, &F), 0);
    assert_int_equal(store_resize(&st, N), 0);
    cf.Vp = 1.25e-7;
    cf.fA = fA;
    cf.pairs.np = N - 3;        /* particles arrived after the pair search */
    for (int i = 0; i < N; i++) {
        id0[i] = id[i] = 1000 + 7 * (int64_t)i;
        phi[i] = 0.5 + (double)(next() % 1000) / 2000;
        for (int c = 0; c < 3; c++)
            fA[3 * i + c] = (double)(next() % 100000) - 5e4;
    }
    P.n = N;
    P.id = id;
    couple_fluid_reaction_field(&cf, &P, F);
    for (int i = 0; i < N; i++)
        for (int c = 0; c < 3; c++)
            assert_true(F[3 * i + c] == (i < N - 3 ? -cf.Vp * fA[3 * i + c]
                                                   : 0.0));
    P.phi = phi;
    couple_fluid_reaction_field(&cf, &P, F);
    assert_true(F[5] == -cf.Vp * phi[1] * fA[5]);
    /* renumber (what mps_step does), then drop one particle */
    for (int i = 0; i < N; i++)
        perm[i] = (int32_t)((i * 37) % N);
    assert_int_equal(store_permute(&st, perm, N), 0);
    int32_t keep[N];
    for (int i = 0; i < N - 1; i++)
        keep[i] = i + (i >= 100);
    assert_int_equal(store_compact(&st, keep, N - 1), 0);
    for (int i = 0; i < N - 1; i++) {
        int k = (int)((id[i] - 1000) / 7);
        assert_true(id[i] == id0[k]);
        for (int c = 0; c < 3; c++)
            assert_true(F[3 * i + c] == (k < N - 3 ? -cf.Vp * phi[k]
                                                     * fA[3 * k + c] : 0.0));
    }
    store_free(&st);
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
