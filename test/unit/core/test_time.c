/* test_time.c — time names, write schedule and latestTime (core/time.h). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "core/time.h"

static void test_names(void **state)
{
    (void)state;
    char b[64];
    assert_string_equal(time_name(0.0, 6, b, sizeof b), "0");
    assert_string_equal(time_name(-0.0, 6, b, sizeof b), "0");
    assert_string_equal(time_name(0.05, 6, b, sizeof b), "0.05");
    assert_string_equal(time_name(0.1 + 0.2, 6, b, sizeof b), "0.3");
    assert_string_equal(time_name(1e-5, 6, b, sizeof b), "1e-05");
    assert_string_equal(time_name(2.5, 6, b, sizeof b), "2.5");
    assert_string_equal(time_name(3 * 0.1, 6, b, sizeof b), "0.3");
}

static int read_time(const char *text, struct run_time *t, struct dict **d)
{
    int rc = dict_read_string(text, strlen(text), "controlDict", d);
    if (rc)
        return rc;
    return time_read(*d, ".", NULL, t);
}

/* Run a loop and collect the names written. */
static int run_loop(struct run_time *t, double dt_wanted, char names[][64],
                    int max)
{
    int n = 0;
    while (time_running(t)) {
        time_set_step(t, dt_wanted);
        time_increment(t);
        if (t->write_now && n < max)
            snprintf(names[n++], 64, "%s", t->name);
        if (t->step > 1000000)
            break;
    }
    return n;
}

static void test_fixed_runtime(void **state)
{
    (void)state;
    struct run_time t;
    struct dict *d;
    assert_int_equal(read_time("endTime 0.2; deltaT 0.001; writeControl "
                               "runTime; writeInterval 0.05;", &t, &d), 0);
    char names[16][64];
    int n = run_loop(&t, 0, names, 16);
    assert_int_equal(n, 4);
    assert_string_equal(names[0], "0.05");
    assert_string_equal(names[1], "0.1");
    assert_string_equal(names[2], "0.15");
    assert_string_equal(names[3], "0.2");
    assert_int_equal(t.step, 200);
    assert_true(t.value == 0.2);
    dict_free(d);
}

static void test_adjustable(void **state)
{
    (void)state;
    struct run_time t;
    struct dict *d;
    assert_int_equal(read_time("endTime 0.1; deltaT 0.001; adjustTimeStep "
                               "yes; maxDeltaT 0.0033; writeControl "
                               "adjustableRunTime; writeInterval 0.025;",
                               &t, &d), 0);
    char names[16][64];
    int n = run_loop(&t, 0.0033, names, 16);
    assert_int_equal(n, 4);
    assert_string_equal(names[0], "0.025");
    assert_string_equal(names[3], "0.1");
    /* 0.025/0.0033 = 7.6: eight equal steps per interval. */
    assert_int_equal(t.step, 32);
    dict_free(d);
}

static void test_timestep_control(void **state)
{
    (void)state;
    struct run_time t;
    struct dict *d;
    assert_int_equal(read_time("endTime 1e-3; deltaT 1e-4; writeControl "
                               "timeStep; writeInterval 5;", &t, &d), 0);
    char names[16][64];
    int n = run_loop(&t, 0, names, 16);
    assert_int_equal(n, 2);
    assert_string_equal(names[0], "0.0005");
    assert_string_equal(names[1], "0.001");
    dict_free(d);
}

static void test_bad_settings(void **state)
{
    (void)state;
    struct run_time t;
    struct dict *d;
    int rc = read_time("startTime 1;\nendTime 0.5; deltaT 0.1; "
                       "writeInterval 1;", &t, &d);
    assert_int_equal(rc, SIM_ERR_DICT);
    assert_non_null(strstr(sim_error_message(), "controlDict:2"));
    assert_non_null(strstr(sim_error_message(), "before startTime"));
    dict_free(d);
    rc = read_time("endTime 1; deltaT -1; writeInterval 1;", &t, &d);
    assert_int_equal(rc, SIM_ERR_DICT);
    assert_non_null(strstr(sim_error_message(), "deltaT"));
    dict_free(d);
    rc = read_time("endTime 1; deltaT 0.1; writeControl timeStep; "
                   "writeInterval 2.5;", &t, &d);
    assert_int_equal(rc, SIM_ERR_DICT);
    dict_free(d);
    rc = read_time("endTime 1; deltaT 0.1; writeControl sometimes; "
                   "writeInterval 1;", &t, &d);
    assert_int_equal(rc, SIM_ERR_DICT);
    assert_non_null(strstr(sim_error_message(), "adjustableRunTime"));
    dict_free(d);
}

static void test_latest(void **state)
{
    (void)state;
    char tmpl[] = "/tmp/mpsdem_time_XXXXXX";
    char *dir = mkdtemp(tmpl), p[512], name[64];
    assert_non_null(dir);
    const char *sub[] = {"0", "0.05", "0.1", "1e-05", "constant", "system"};
    for (int i = 0; i < 6; i++) {
        snprintf(p, sizeof p, "%s/%s", dir, sub[i]);
        assert_int_equal(mkdir(p, 0777), 0);
    }
    snprintf(p, sizeof p, "%s/0.2", dir);   /* a file, not a directory */
    fclose(fopen(p, "w"));
    double t = -1;
    assert_int_equal(time_latest(dir, NULL, &t, name, sizeof name), 0);
    assert_string_equal(name, "0.1");
    assert_true(t == 0.1);
    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    assert_int_equal(system(cmd), 0);
    assert_int_equal(time_latest(dir, NULL, &t, name, sizeof name), SIM_ERR_IO);
}

static void touch(const char *dir, const char *rel)
{
    char p[600];
    snprintf(p, sizeof p, "%s/%s", dir, rel);
    FILE *f = fopen(p, "w");
    assert_non_null(f);
    fclose(f);
}

/* A coupled restart takes the newest time that holds both clouds: a run
 * whose peer died wrote its own cloud alone at a newer time (0.3), a
 * failure dump is failed.<t>/ (never a time), a full disk leaves an empty
 * directory (0.4) and a kill during a write a "*.tmp.<pid>" of a dead pid;
 * time_clean_debris removes the last two and nothing else. */
static void test_latest_coupled(void **state)
{
    (void)state;
    char tmpl[] = "/tmp/mpsdem_time_XXXXXX";
    char *dir = mkdtemp(tmpl), p[512], name[64];
    assert_non_null(dir);
    const char *sub[] = {"0", "0.1", "0.2", "0.3", "0.4", "failed.0.5"};
    for (int i = 0; i < 6; i++) {
        snprintf(p, sizeof p, "%s/%s", dir, sub[i]);
        assert_int_equal(mkdir(p, 0777), 0);
    }
    touch(dir, "0/fluid.vtu");
    touch(dir, "0/dem.vtu");
    touch(dir, "0.1/fluid.vtu");
    touch(dir, "0.1/dem.vtu");
    touch(dir, "0.2/fluid.vtu");
    touch(dir, "0.2/dem.vtu");
    touch(dir, "0.2/fluid.vtu.tmp.999999999");   /* no such pid */
    touch(dir, "0.3/dem.vtu");
    touch(dir, "failed.0.5/fluid.vtu");
    touch(dir, "failed.0.5/dem.vtu");
    char own[64];
    snprintf(own, sizeof own, "0.1/dem.vtu.tmp.%ld", (long)getpid());
    touch(dir, own);                             /* a live writer's */
    const char *const both[] = { "fluid.vtu", "dem.vtu", NULL };
    double t = -1;
    assert_int_equal(time_latest(dir, both, &t, name, sizeof name), 0);
    assert_string_equal(name, "0.2");
    assert_int_equal(time_latest(dir, NULL, &t, name, sizeof name), 0);
    assert_string_equal(name, "0.4");
    assert_int_equal(time_clean_debris(dir), 2);
    snprintf(p, sizeof p, "%s/0.4", dir);
    assert_int_not_equal(access(p, F_OK), 0);
    snprintf(p, sizeof p, "%s/0.2/fluid.vtu.tmp.999999999", dir);
    assert_int_not_equal(access(p, F_OK), 0);
    snprintf(p, sizeof p, "%s/%s", dir, own);
    assert_int_equal(access(p, F_OK), 0);
    snprintf(p, sizeof p, "%s/0", dir);
    assert_int_equal(access(p, F_OK), 0);
    assert_int_equal(time_latest(dir, NULL, &t, name, sizeof name), 0);
    assert_string_equal(name, "0.3");
    const char *const none[] = { "fluid.vtu", "nothing.vtu", NULL };
    assert_int_equal(time_latest(dir, none, &t, name, sizeof name),
                     SIM_ERR_IO);
    assert_non_null(strstr(sim_error_message(), "0.3 (no fluid.vtu)"));
    sim_error_clear();
    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    assert_int_equal(system(cmd), 0);
}

int main(void)
{
    log_set_quiet(1);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_names),
        cmocka_unit_test(test_fixed_runtime),
        cmocka_unit_test(test_adjustable),
        cmocka_unit_test(test_timestep_control),
        cmocka_unit_test(test_bad_settings),
        cmocka_unit_test(test_latest),
        cmocka_unit_test(test_latest_coupled),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
