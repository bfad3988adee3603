/*
 * test_linsolve_dict.c — linsolve_create() from a PPE dictionary: defaults,
 * selections, and located errors for bad entries (kept apart from
 * test_linsolve.c so that solver tests do not depend on the parser).
 */
#include "linsolve_testutil.h"

#include "core/dict.h"

static struct dict *parse(const char *text)
{
    struct dict *d = NULL;
    int rc = dict_read_string(text, strlen(text), "system/mpsSolution", &d);
    if (rc)
        print_error("%s\n", sim_error_message());
    assert_int_equal(rc, SIM_OK);
    return d;
}

static void test_defaults(void **state)
{
    (void)state;
    struct dict *d = parse("");
    struct linsolve *ls = NULL;
    assert_int_equal(linsolve_create(d, &ls), SIM_OK);
    assert_string_equal(ls->solver->name, "pcg");
    assert_string_equal(ls->pc.ops->name, "jacobi");
    assert_true(ls->tol == 1e-8);
    assert_int_equal(ls->maxiter, 1000);
    assert_int_equal(ls->warm_start, 1);
    linsolve_free(ls);
    dict_free(d);
}

static void test_selection_and_solve(void **state)
{
    (void)state;
    struct dict *d = parse("solver pcg;\npreconditioner ic0;\n"
                           "tolerance 1e-10;\nmaxIter 300;\nwarmStart no;\n");
    struct linsolve *ls = NULL;
    assert_int_equal(linsolve_create(d, &ls), SIM_OK);
    assert_string_equal(ls->pc.ops->name, "ic0");
    assert_int_equal(ls->warm_start, 0);
    struct sys s;
    tu_lattice(&s, 2, 20, 2.1, 0);
    double *x = malloc((size_t)s.A.n * sizeof *x);
    for (int i = 0; i < s.A.n; i++)
        x[i] = 1e30; /* ignored: warmStart no */
    struct linsolve_stats st;
    assert_int_equal(linsolve_solve(ls, &s.A, s.b, x, &st), SIM_OK);
    assert_true(st.res_rel <= 1e-10);
    free(x);
    tu_free(&s);
    linsolve_free(ls);
    dict_free(d);
}

/* Each bad entry: SIM_ERR_DICT, message located at file:line of the key. */
static void expect_error(const char *text, const char *line, const char *word)
{
    struct dict *d = parse(text);
    struct linsolve *ls = NULL;
    int rc = linsolve_create(d, &ls);
    const char *m = sim_error_message();
    if (rc != SIM_ERR_DICT || !strstr(m, line) || !strstr(m, word))
        print_error("'%s' -> %d: %s\n", text, rc, m);
    assert_int_equal(rc, SIM_ERR_DICT);
    assert_non_null(strstr(m, "system/mpsSolution"));
    assert_non_null(strstr(m, line));
    assert_non_null(strstr(m, word));
    assert_null(ls);
    dict_free(d);
}

static void test_bad_entries(void **state)
{
    (void)state;
    expect_error("\nsolver gmers;\n", ":2", "bicgstab gmres");
    expect_error("solver pcg;\n\n\npreconditioner ilu;\n", ":4", "ic0");
    expect_error("solver pcg;\npreconditioner ilu0;\n", ":2", "ilu0");
    expect_error("solver bicgstab;\npreconditioner ic0;\n", ":2", "ic0");
    expect_error("\ntolerance 2;\n", ":2", "tolerance");
    expect_error("\n\nmaxIter 0;\n", ":3", "maxIter");
    expect_error("warmStart maybe;\n", ":1", "warmStart");
#ifndef MPSDEM_HAVE_HYPRE
    expect_error("solver hypre;\n", ":1", "not available");
#endif
}

int main(void)
{
    log_set_quiet(1);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_defaults),
        cmocka_unit_test(test_selection_and_solve),
        cmocka_unit_test(test_bad_entries),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
