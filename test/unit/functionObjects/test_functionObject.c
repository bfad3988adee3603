/* test_functionObject.c — selection, schedules and output files of the
 * function-object framework, with the generic cloudInfo type. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <string.h>
#include <unistd.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "functionObjects/functionObject.h"

static char tmpdir[64];

static int setup(void **state)
{
    (void)state;
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mpsdem_fo_XXXXXX");
    return mkdtemp(tmpdir) ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    return system(cmd);
}

/* Four particles: two fluid (type 0), one wall, one dummy. */
static double pts[12] = {0, 0, 0, 1, 2, 0, 5, 5, 5, -1, -1, -1};
static int32_t types[4] = {0, 0, 1, 2};

static struct store st;

static void make_scene(struct fo_scene *s, struct vtu_cloud *c,
                       struct vtu_field *f)
{
    memset(f, 0, sizeof *f);
    snprintf(f->name, sizeof f->name, "type");
    f->type = VTU_INT32;
    f->ncomp = 1;
    f->data = types;
    memset(c, 0, sizeof *c);
    c->n = 4;
    c->points = pts;
    c->nfields = 1;
    c->fields = f;
    memset(s, 0, sizeof *s);
    store_init(&st, "field of the fluid cloud");
    assert_int_equal(store_view_cloud(&st, c), SIM_OK);
    s->store = &st;
    s->cloud_name = "fluid";
    s->dim = 3;
    s->dt = 0.01;
}

static int count_rows(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    char line[1024];
    int n = 0;
    while (fgets(line, sizeof line, f))
        n += line[0] != '#';
    fclose(f);
    return n;
}

static const struct fo_ops *const *const tables[] = {fo_generic_table, NULL};

/* The list of the `functions` dictionary in text, over make_scene's
 * scene; *d holds the dictionary (the caller frees it). */
static struct fo_list *make_list(const char *text, struct dict **d,
                                 struct fo_scene *s, struct vtu_cloud *c,
                                 struct vtu_field *f)
{
    const struct dict *fd;
    struct fo_list *l;
    assert_int_equal(dict_read_string(text, strlen(text), "controlDict", d),
                     0);
    assert_int_equal(dict_get_dict(*d, "functions", &fd), 0);
    make_scene(s, c, f);
    assert_int_equal(fo_list_create(fd, tables, s, tmpdir, 0.0, 6, &l), 0);
    return l;
}

static void test_schedules(void **state)
{
    (void)state;
    const char *text =
        "functions {\n"
        "  everyStep { type cloudInfo; }\n"
        "  every5    { type cloudInfo; writeControl timeStep; writeInterval 5; }\n"
        "  runTime   { type cloudInfo; writeControl runTime; writeInterval 0.1; }\n"
        "  window    { type cloudInfo; timeStart 0.2; timeEnd 0.3; }\n"
        "  atWrite   { type cloudInfo; writeControl writeTime; }\n"
        "  off       { type cloudInfo; enabled no; }\n"
        "}\n";
    struct dict *d;
    struct fo_scene s;
    struct vtu_cloud c;
    struct vtu_field f;
    struct fo_list *l = make_list(text, &d, &s, &c, &f);
    for (long step = 0; step <= 100; step++) {
        s.step = step;
        s.time = step * 0.01;
        assert_int_equal(fo_list_execute(l, &s, step % 25 == 0), 0);
    }
    fo_list_free(l);
    char p[256];
    snprintf(p, sizeof p, "%s/postProcessing/everyStep/0/cloudInfo.dat", tmpdir);
    assert_int_equal(count_rows(p), 101);
    snprintf(p, sizeof p, "%s/postProcessing/every5/0/cloudInfo.dat", tmpdir);
    assert_int_equal(count_rows(p), 21);
    snprintf(p, sizeof p, "%s/postProcessing/runTime/0/cloudInfo.dat", tmpdir);
    assert_int_equal(count_rows(p), 11);
    snprintf(p, sizeof p, "%s/postProcessing/window/0/cloudInfo.dat", tmpdir);
    assert_int_equal(count_rows(p), 11);
    snprintf(p, sizeof p, "%s/postProcessing/atWrite/0/cloudInfo.dat", tmpdir);
    assert_int_equal(count_rows(p), 5);
    snprintf(p, sizeof p, "%s/postProcessing/off", tmpdir);
    assert_int_not_equal(access(p, F_OK), 0);
    dict_free(d);
}

/* fo_list_due: the steps at which some entry would run, without marking
 * a runTime interval as done (asking twice gives the same answer, and the
 * execution after it still writes the row). */
static void test_due(void **state)
{
    (void)state;
    const char *text =
        "functions {\n"
        "  every5  { type cloudInfo; writeControl timeStep; writeInterval 5; }\n"
        "  runTime { type cloudInfo; writeControl runTime; writeInterval 0.07; }\n"
        "  atWrite { type cloudInfo; writeControl writeTime; }\n"
        "}\n";
    struct dict *d;
    struct fo_scene s;
    struct vtu_cloud c;
    struct vtu_field f;
    struct fo_list *l = make_list(text, &d, &s, &c, &f);
    assert_int_equal(fo_list_due(NULL, 0.0, 0, 0.01, 1), 0);
    int last_k = -1, n_due = 0;
    for (long step = 0; step <= 100; step++) {
        s.step = step;
        s.time = step * 0.01;
        int k = (int)floor(s.time / 0.07 + 1e-6), write = step % 3 == 0;
        int want = step % 5 == 0 || k > last_k || write;
        last_k = k;
        assert_int_equal(fo_list_due(l, s.time, step, 0.01, write), want);
        assert_int_equal(fo_list_due(l, s.time, step, 0.01, write), want);
        n_due += want;
        assert_int_equal(fo_list_execute(l, &s, write), 0);
    }
    fo_list_free(l);
    char p[256];
    snprintf(p, sizeof p, "%s/postProcessing/runTime/0/cloudInfo.dat", tmpdir);
    assert_int_equal(count_rows(p), 15);   /* k = 0 ... 14 */
    assert_true(n_due > 34 && n_due < 101);
    dict_free(d);
}

static void test_cloud_info_row(void **state)
{
    (void)state;
    const char *text = "functions { info { type cloudInfo; } }";
    struct dict *d;
    const struct dict *fd;
    assert_int_equal(dict_read_string(text, strlen(text), "controlDict", &d), 0);
    assert_int_equal(dict_get_dict(d, "functions", &fd), 0);
    struct fo_scene s;
    struct vtu_cloud c;
    struct vtu_field f;
    make_scene(&s, &c, &f);
    struct fo_list *l;
    assert_int_equal(fo_list_create(fd, tables, &s, tmpdir, 0.5, 6, &l), 0);
    s.time = 0.5;
    assert_int_equal(fo_list_execute(l, &s, 0), 0);
    fo_list_free(l);
    char p[256], line[512], last[512] = "";
    snprintf(p, sizeof p, "%s/postProcessing/info/0.5/cloudInfo.dat", tmpdir);
    FILE *fp = fopen(p, "r");
    assert_non_null(fp);
    while (fgets(line, sizeof line, fp))
        snprintf(last, sizeof last, "%s", line);
    fclose(fp);
    /* time n n_type0..7 then the box of the two fluid particles */
    assert_string_equal(last, "0.5 4 2 1 1 0 0 0 0 0 0 0 0 1 2 0\n");
    dict_free(d);
}

static void test_errors(void **state)
{
    (void)state;
    struct fo_scene s;
    struct vtu_cloud c;
    struct vtu_field f;
    make_scene(&s, &c, &f);
    const char *bad[] = {
        "functions {\n  a { type cloudInfoo; }\n}",
        "functions {\n  a { type cloudInfo; timeStart 2; timeEnd 1; }\n}",
        "functions {\n  a 3;\n}",
        "functions {\n  a { type cloudInfo; writeInterval 0; }\n}",
    };
    const char *expect[] = {"valid: cloudInfo", "before timeStart",
                            "sub-dictionary", "positive"};
    for (int i = 0; i < 4; i++) {
        struct dict *d;
        const struct dict *fd;
        struct fo_list *l = NULL;
        assert_int_equal(dict_read_string(bad[i], strlen(bad[i]),
                                          "controlDict", &d), 0);
        assert_int_equal(dict_get_dict(d, "functions", &fd), 0);
        assert_int_equal(fo_list_create(fd, tables, &s, tmpdir, 0, 6, &l),
                         SIM_ERR_DICT);
        assert_non_null(strstr(sim_error_message(), "controlDict:2"));
        assert_non_null(strstr(sim_error_message(), expect[i]));
        dict_free(d);
    }
}

int main(void)
{
    log_set_quiet(1);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_schedules),
        cmocka_unit_test(test_due),
        cmocka_unit_test(test_cloud_info_row),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
