/*
 * test_store.c — the per-particle field registry (src/particles/store.c):
 * growth keeps the values and zeroes new entries, a permutation moves every
 * field (vectors whole, indices remapped), compaction keeps the listed
 * particles in order with removed index targets set to -1, the owner's
 * pointers follow a copy of the owner, the cloud view lists the written
 * fields in registration order, and lookup by name checks type and
 * components with an unknown name answered by the valid names and "did
 * you mean".
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "core/error.h"
#include "particles/store.h"

struct cloud {
    struct store st;
    double *x, *u, *p;
    int64_t *id;
    int32_t *partner;
    uint8_t *flag;
};

static void make(struct cloud *c, size_t n)
{
    memset(c, 0, sizeof *c);
    store_init(&c->st, "field of the test cloud");
    struct store *s = &c->st;
    assert_int_equal(store_add(s, "position", "[m]", VTU_FLOAT64, 3,
                               STORE_POINTS, &c->x), SIM_OK);
    assert_int_equal(store_add(s, "velocity", "[m/s]", VTU_FLOAT64, 3,
                               STORE_WRITE, &c->u), SIM_OK);
    assert_int_equal(store_add(s, "pressure", "[Pa]", VTU_FLOAT64, 1,
                               STORE_WRITE, &c->p), SIM_OK);
    assert_int_equal(store_add(s, "partner", "", VTU_INT32, 1, STORE_INDEX,
                               &c->partner), SIM_OK);
    assert_int_equal(store_add(s, "id", "", VTU_INT64, 1, STORE_WRITE,
                               &c->id), SIM_OK);
    assert_int_equal(store_add(s, "flag", "", VTU_UINT8, 1, STORE_WRITE,
                               &c->flag), SIM_OK);
    assert_int_equal(store_resize(s, n), SIM_OK);
    /* particle i carries values that name it */
    for (size_t i = 0; i < n; i++) {
        for (int a = 0; a < 3; a++) {
            c->x[3 * i + a] = 10.0 * (double)i + a;
            c->u[3 * i + a] = -10.0 * (double)i - a;
        }
        c->p[i] = 0.5 * (double)i;
        c->id[i] = 1000 + (int64_t)i;
        c->partner[i] = (int32_t)((i + 1) % n);
        c->flag[i] = (uint8_t)(i % 3);
    }
}

/* Particle k of the cloud is the one made as particle `was`. */
static void assert_is(const struct cloud *c, size_t k, size_t was)
{
    for (int a = 0; a < 3; a++) {
        assert_true(c->x[3 * k + a] == 10.0 * (double)was + a);
        assert_true(c->u[3 * k + a] == -10.0 * (double)was - a);
    }
    assert_true(c->p[k] == 0.5 * (double)was);
    assert_int_equal(c->id[k], 1000 + (int64_t)was);
    assert_int_equal(c->flag[k], was % 3);
}

static void test_growth(void **state)
{
    (void)state;
    struct cloud c;
    make(&c, 5);
    assert_int_equal(c.st.n, 5);
    assert_true(c.st.cap >= 5);
    double *x0 = c.x;
    /* within the capacity: nothing moves */
    assert_int_equal(store_resize(&c.st, 3), SIM_OK);
    assert_ptr_equal(c.x, x0);
    assert_int_equal(store_resize(&c.st, 5), SIM_OK);
    assert_ptr_equal(c.x, x0);
    /* entries 3 and 4 came back: they are new, so zero */
    assert_true(c.p[3] == 0 && c.id[4] == 0 && c.u[3 * 4 + 2] == 0);
    for (size_t i = 0; i < 3; i++)
        assert_is(&c, i, i);
    /* growth well past the capacity keeps every value */
    assert_int_equal(store_resize(&c.st, 100000), SIM_OK);
    assert_int_equal(c.st.n, 100000);
    assert_true(c.st.cap >= 100000);
    for (size_t i = 0; i < 3; i++)
        assert_is(&c, i, i);
    for (size_t i = 3; i < 100000; i++)
        assert_true(c.p[i] == 0 && c.x[3 * i] == 0 && c.partner[i] == 0
                    && c.flag[i] == 0 && c.id[i] == 0);
    store_free(&c.st);
    assert_null(c.x);
    assert_null(c.partner);
    assert_int_equal(c.st.nfields, 0);
}

static void test_permute(void **state)
{
    (void)state;
    struct cloud c;
    make(&c, 6);
    /* reverse, and drop old particle 2 (the target of old 1's partner) */
    const int32_t perm[5] = { 5, 4, 3, 1, 0 };
    assert_int_equal(store_permute(&c.st, perm, 5), SIM_OK);
    assert_int_equal(c.st.n, 5);
    for (size_t k = 0; k < 5; k++)
        assert_is(&c, k, (size_t)perm[k]);
    /* old i pointed at old i + 1 (mod 6); new index of old j is
     * position of j in perm, old 2 removed -> -1 */
    const int32_t want[5] = { 4, 0, 1, -1, 3 };
    for (size_t k = 0; k < 5; k++)
        assert_int_equal(c.partner[k], want[k]);
    /* a renumbering and its inverse give the cloud back */
    const int32_t rot[5] = { 1, 2, 3, 4, 0 }, back[5] = { 4, 0, 1, 2, 3 };
    assert_int_equal(store_permute(&c.st, rot, 5), SIM_OK);
    assert_int_equal(store_permute(&c.st, back, 5), SIM_OK);
    for (size_t k = 0; k < 5; k++) {
        assert_is(&c, k, (size_t)perm[k]);
        assert_int_equal(c.partner[k], want[k]);
    }
    store_free(&c.st);
}

static void test_compact(void **state)
{
    (void)state;
    struct cloud c;
    make(&c, 8);
    const int32_t kept[4] = { 0, 3, 4, 7 };
    assert_int_equal(store_compact(&c.st, kept, 4), SIM_OK);
    assert_int_equal(c.st.n, 4);
    for (size_t k = 0; k < 4; k++)
        assert_is(&c, k, (size_t)kept[k]);
    /* partners: 0 -> 1 (removed), 3 -> 4 (now 2), 4 -> 5 (removed),
     * 7 -> 0 (now 0) */
    const int32_t want[4] = { -1, 2, -1, 0 };
    for (size_t k = 0; k < 4; k++)
        assert_int_equal(c.partner[k], want[k]);
    /* compaction to nothing, then growth again */
    assert_int_equal(store_compact(&c.st, kept, 0), SIM_OK);
    assert_int_equal(c.st.n, 0);
    assert_int_equal(store_resize(&c.st, 2), SIM_OK);
    assert_true(c.p[0] == 0 && c.p[1] == 0);
    store_free(&c.st);
}

static void test_moved_and_views(void **state)
{
    (void)state;
    struct cloud a, b;
    make(&a, 4);
    b = a;  /* the owner moves (mps_solver_init takes P by value) */
    store_moved(&b.st, &a, &b, sizeof a);
    assert_int_equal(store_resize(&b.st, 5000), SIM_OK);
    assert_is(&b, 3, 3);
    /* a view is written and found but neither grown nor freed */
    double eps[8] = { 0 };
    double *view = eps;
    assert_int_equal(store_add(&b.st, "porosity", "", VTU_FLOAT64, 1,
                               STORE_VIEW | STORE_WRITE, &view), SIM_OK);
    assert_ptr_equal(view, eps);
    struct vtu_cloud cl;
    struct vtu_field out[STORE_MAX_FIELDS];
    store_cloud(&b.st, 1.5, out, &cl);
    assert_int_equal(cl.n, 5000);
    assert_ptr_equal(cl.points, b.x);
    assert_true(cl.time == 1.5);
    const char *names[] = { "velocity", "pressure", "id", "flag",
                            "porosity" };
    assert_int_equal(cl.nfields, 5);
    assert_ptr_equal(cl.fields, out);
    for (int k = 0; k < 5; k++)
        assert_string_equal(cl.fields[k].name, names[k]);
    assert_ptr_equal(cl.fields[4].data, eps);
    assert_ptr_equal(cl.fields[0].data, b.u);
    assert_int_equal(cl.fields[3].type, VTU_UINT8);
    assert_int_equal(cl.fields[0].ncomp, 3);
    store_free(&b.st);
    assert_ptr_equal(view, eps);
    assert_null(b.u);
}

static void test_lookup(void **state)
{
    (void)state;
    struct cloud c;
    make(&c, 3);
    const void *d = NULL;
    assert_int_equal(store_require(&c.st, "probe1", "velocity", VTU_FLOAT64,
                                   3, &d), SIM_OK);
    assert_ptr_equal(d, c.u);
    assert_int_equal(store_require(&c.st, "probe1", "id", -1, 0, &d), SIM_OK);
    assert_ptr_equal(d, c.id);
    assert_ptr_equal(store_find(&c.st, "partner")->ref, (void **)&c.partner);
    assert_null(store_find(&c.st, "Velocity "));
    /* misspelt: the valid names and the nearest one */
    assert_int_equal(store_require(&c.st, "probe1", "velocty", VTU_FLOAT64, 3,
                                   &d), SIM_ERR_INPUT);
    const char *m = sim_error_message();
    assert_non_null(strstr(m, "probe1: unknown field of the test cloud "
                              "'velocty'"));
    assert_non_null(strstr(m, "valid: position velocity pressure partner "
                              "id flag"));
    assert_non_null(strstr(m, "did you mean 'velocity'?"));
    /* nothing near: no suggestion */
    assert_int_equal(store_require(&c.st, "probe1", "temperature", -1, 0, &d),
                     SIM_ERR_INPUT);
    assert_null(strstr(sim_error_message(), "did you mean"));
    /* wrong type or components */
    assert_int_equal(store_require(&c.st, "gauge", "pressure", VTU_FLOAT64, 3,
                                   &d), SIM_ERR_INPUT);
    assert_non_null(strstr(sim_error_message(), "gauge: field of the test "
                           "cloud 'pressure' is Float64 x1, not Float64 x3"));
    assert_int_equal(store_require(&c.st, "gauge", "id", VTU_INT32, 1, &d),
                     SIM_ERR_INPUT);
    /* registration errors */
    double *dup = NULL;
    assert_int_equal(store_add(&c.st, "pressure", "", VTU_FLOAT64, 1, 0,
                               &dup), SIM_ERR_INTERNAL);
    assert_int_equal(store_add(&c.st, "link", "", VTU_INT64, 1, STORE_INDEX,
                               &dup), SIM_ERR_INTERNAL);
    assert_null(dup);
    store_free(&c.st);
}

static void test_view_cloud(void **state)
{
    (void)state;
    double pts[6] = { 0, 1, 2, 3, 4, 5 };
    int32_t type[2] = { 0, 1 };
    struct vtu_field f[1] = { { "type", VTU_INT32, 1, type } };
    struct vtu_cloud cl = { .n = 2, .points = pts, .nfields = 1,
                            .fields = f };
    struct store s;
    store_init(&s, "field of the fluid cloud");
    assert_int_equal(store_view_cloud(&s, &cl), SIM_OK);
    assert_int_equal(s.n, 2);
    const void *d;
    assert_int_equal(store_require(&s, "x", "type", VTU_INT32, 1, &d),
                     SIM_OK);
    assert_ptr_equal(d, type);
    assert_int_equal(store_require(&s, "x", "position", VTU_FLOAT64, 3, &d),
                     SIM_OK);
    assert_ptr_equal(d, pts);
    assert_int_equal(store_require(&s, "x", "typ", -1, 0, &d), SIM_ERR_INPUT);
    assert_non_null(strstr(sim_error_message(), "did you mean 'type'?"));
    store_free(&s);
    assert_ptr_equal(cl.points, pts);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_growth),
        cmocka_unit_test(test_permute),
        cmocka_unit_test(test_compact),
        cmocka_unit_test(test_moved_and_views),
        cmocka_unit_test(test_lookup),
        cmocka_unit_test(test_view_cloud),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
