/*
 * test_channel_dict.c — channel settings from system/couplingDict: keys,
 * defaults, located errors, and the settings digest (same for the same
 * settings written differently, different for different settings).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "coupling/channel.h"
#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"

#include <string.h>

static int from_text(const char *text, struct channel_settings *s)
{
    struct dict *d;
    int rc = dict_read_string(text, strlen(text), "system/couplingDict", &d);
    if (rc)
        return rc;
    channel_settings_default(s, CHANNEL_FLUID, "mpsFluid", "/tmp");
    rc = channel_settings_from_dict(d, s);
    dict_free(d);
    return rc;
}

static void test_keys_and_defaults(void **state)
{
    struct channel_settings s;
    (void)state;
    assert_int_equal(from_text("coupled yes;\n", &s), SIM_OK);
    assert_string_equal(s.name, "");
    assert_true(s.timeout == 60.0 && s.heartbeat_interval == 0.1);
    assert_int_equal(s.nslots, 2);
    assert_int_equal(from_text("channel \"/myCase\";\ntimeout 5;\n"
                               "heartbeatInterval 0.02;\nframesInFlight 4;\n",
                               &s), SIM_OK);
    assert_string_equal(s.name, "/myCase");
    assert_true(s.timeout == 5.0 && s.heartbeat_interval == 0.02);
    assert_int_equal(s.nslots, 4);
    assert_int_equal(from_text("channel myCase;\n", &s), SIM_OK);
    assert_string_equal(s.name, "/myCase");
}

static void test_bad_values_located(void **state)
{
    struct channel_settings s;
    static const char *const bad[] = {
        "coupled yes;\ntimeout -1;\n",
        "coupled yes;\nheartbeatInterval 0;\n",
        "coupled yes;\nframesInFlight 0;\n",
        "coupled yes;\nchannel a/b;\n",
    };
    (void)state;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        assert_int_equal(from_text(bad[i], &s), SIM_ERR_DICT);
        assert_non_null(strstr(sim_error_message(), "system/couplingDict:2"));
    }
}

static void test_digest(void **state)
{
    struct channel_settings a, b, c;
    (void)state;
    assert_int_equal(from_text("model B; // comment\ndragLaw ergun;\n", &a),
                     SIM_OK);
    assert_int_equal(from_text("/* other layout */ model   B;\n\n"
                               "dragLaw ergun ;\n", &b), SIM_OK);
    assert_int_equal(from_text("model A;\ndragLaw ergun;\n", &c), SIM_OK);
    assert_true(a.digest != 0);
    assert_true(a.digest == b.digest);
    assert_true(a.digest != c.digest);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_keys_and_defaults),
        cmocka_unit_test(test_bad_values_located),
        cmocka_unit_test(test_digest),
    };
    log_set_quiet(1);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
