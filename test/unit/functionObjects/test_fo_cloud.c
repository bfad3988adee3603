/* test_fo_cloud.c — the per-entry `cloud fluid|dem;` key of function
 * objects (functionObject.c), which lets mpsFluid and demSolid share the
 * controlDict of a coupled case: an entry for the other cloud is skipped
 * (its type is not even looked up, its keys are not reported unused), an
 * entry for this cloud or without the key runs, and an entry for this
 * cloud with a wrong type is still an error. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "functionObjects/functionObject.h"

static char tmpdir[64];
static double pts[6] = { 0, 0, 0, 1, 2, 0 };
static int32_t types[2] = { 0, 0 };
static const struct fo_ops *const *const tables[] = { fo_generic_table, NULL };

static int run(const char *text, const char *cloud_name)
{
    struct dict *d;
    const struct dict *fd;
    struct vtu_field f = { .type = VTU_INT32, .ncomp = 1, .data = types };
    snprintf(f.name, sizeof f.name, "type");
    struct vtu_cloud c = { .n = 2, .points = pts, .nfields = 1, .fields = &f };
    struct store st;
    store_init(&st, "field of the cloud");
    assert_int_equal(store_view_cloud(&st, &c), SIM_OK);
    struct fo_scene s = { .store = &st, .cloud_name = cloud_name, .dim = 3,
                          .dt = 0.01 };
    struct fo_list *l = NULL;
    assert_int_equal(dict_read_string(text, strlen(text), "controlDict", &d),
                     0);
    assert_int_equal(dict_get_dict(d, "functions", &fd), 0);
    int rc = fo_list_create(fd, tables, &s, tmpdir, 0.0, 6, &l);
    if (!rc)
        rc = fo_list_execute(l, &s, 0);
    long warn0 = log_warning_count();
    dict_warn_unused(fd);
    int unused = (int)(log_warning_count() - warn0);
    fo_list_free(l);
    dict_free(d);
    return rc ? -rc : unused;
}

static int exists(const char *name)
{
    char p[256];
    snprintf(p, sizeof p, "%s/postProcessing/%s/0/cloudInfo.dat", tmpdir,
             name);
    return access(p, F_OK) == 0;
}

static void test_cloud_key(void **state)
{
    (void)state;
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mpsdem_focloud_XXXXXX");
    assert_non_null(mkdtemp(tmpdir));
    const char *text =
        "functions {\n"
        "  both    { type cloudInfo; }\n"
        "  mine    { type cloudInfo; cloud fluid; }\n"
        "  theirs  { type someDemOnlyType; cloud dem; direction (1 0 0); }\n"
        "}\n";
    assert_int_equal(run(text, "fluid"), 0);    /* no error, nothing unused */
    assert_true(exists("both"));
    assert_true(exists("mine"));
    assert_false(exists("theirs"));
    const char *bad = "functions { mine { type someDemOnlyType; cloud fluid; } }\n";
    assert_int_equal(run(bad, "fluid"), -SIM_ERR_DICT);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    assert_int_equal(system(cmd), 0);
}

int main(void)
{
    log_set_quiet(1);
    const struct CMUnitTest tests[] = { cmocka_unit_test(test_cloud_key) };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
