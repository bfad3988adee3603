/*
 * test_dict.c — the dictionary API (src/core/dict.h): grammar, substitution,
 * every getter with and without a default, and every error path's code and
 * message. Book-keeping, usedParameters, expansion and editing are in
 * test_dict_io.c.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"

static struct dict *parse(const char *text)
{
    struct dict *d = NULL;
    int rc = dict_read_string(text, strlen(text), "case/system/testDict", &d);
    if (rc != SIM_OK)
        fail_msg("parse failed: %s", sim_error_message());
    return d;
}

/* Parsing `text` fails with `code` and a message containing `where` and
 * `what`. */
static void parse_fails(const char *text, int code, const char *where,
                        const char *what)
{
    struct dict *d = (struct dict *)1;
    sim_error_clear();
    int rc = dict_read_string(text, strlen(text), "t.dict", &d);
    assert_int_equal(rc, code);
    assert_null(d);
    const char *msg = sim_error_message();
    if (strncmp(msg, where, strlen(where)) != 0 || !strstr(msg, what))
        fail_msg("message '%s' lacks '%s' ... '%s'", msg, where, what);
}

static void msg_has(const char *where, const char *what)
{
    const char *msg = sim_error_message();
    if (strncmp(msg, where, strlen(where)) != 0 || !strstr(msg, what))
        fail_msg("message '%s' lacks '%s' ... '%s'", msg, where, what);
}

/* ---- grammar ------------------------------------------------------------- */

static void test_structure(void **state)
{
    (void)state;
    struct dict *d = parse(
        "FoamFile { version 2.0; format ascii; }\n"
        "a 1;\nsub { x 2; inner { y 3; } }\nempty;\n");
    assert_int_equal(dict_size(d), 4);
    assert_string_equal(dict_key_at(d, 0), "FoamFile");
    struct dict *bom = parse("\xEF\xBB\xBF" "FoamFile { }\r\na\t1;\r\n");
    assert_string_equal(dict_key_at(bom, 0), "FoamFile");
    assert_true(dict_has(bom, "a"));
    dict_free(bom);
    assert_string_equal(dict_key_at(d, 3), "empty");
    assert_null(dict_key_at(d, 4));
    assert_true(dict_has(d, "sub/inner/y"));
    assert_false(dict_has(d, "sub/inner/z"));
    assert_false(dict_has(d, "a/b"));
    assert_true(dict_is_dict(d, "sub/inner"));
    assert_false(dict_is_dict(d, "a"));
    assert_string_equal(dict_file(d), "case/system/testDict");
    assert_string_equal(dict_name(d), "");
    const struct dict *in;
    assert_int_equal(dict_get_dict(d, "sub/inner", &in), SIM_OK);
    assert_string_equal(dict_name(in), "sub/inner");
    assert_string_equal(dict_file(in), "case/system/testDict");
    dict_free(d);
}

static void test_numbers_exact(void **state)
{
    (void)state;
    struct dict *d = parse("a 0.1; b -2.5e-3; c 1e-310; d +.5; e 123456789;"
                           "f 9007199254740993; g 1E2;");
    double x;
    assert_int_equal(dict_get_scalar(d, "a", &x), SIM_OK);
    assert_true(x == 0.1); /* strtod-exact, not accumulated digit by digit */
    assert_int_equal(dict_get_scalar(d, "b", &x), SIM_OK);
    assert_true(x == -2.5e-3);
    assert_int_equal(dict_get_scalar(d, "c", &x), SIM_OK);
    assert_true(x == 1e-310);
    assert_int_equal(dict_get_scalar(d, "d", &x), SIM_OK);
    assert_true(x == 0.5);
    assert_int_equal(dict_get_scalar(d, "g", &x), SIM_OK);
    assert_true(x == 100.0);
    const struct dict_value *v;
    assert_int_equal(dict_get_value(d, "f", &v), SIM_OK);
    /* integers keep their exact text */
    assert_string_equal(dict_value_text(dict_value_at(v, 0)),
                        "9007199254740993");
    dict_free(d);
}

static void test_words_strings_lists(void **state)
{
    (void)state;
    struct dict *d = parse(
        "div(phi,U) Gauss linear;\n"
        "s \"a \\\"b\\\" \\\\ \\n\";\n"
        "l (1 (2 3) w \"s\" [0 1 0 0 0 0 0] { k 1; });\n"
        "b ( inlet { type patch; } );\n"
        "c 3(1 2 3);\n");
    const struct dict_value *v;
    assert_int_equal(dict_get_value(d, "div(phi,U)", &v), SIM_OK);
    assert_int_equal(dict_value_kind(v), DICT_ENTRY);
    assert_int_equal(dict_value_len(v), 2);
    assert_string_equal(dict_value_text(dict_value_at(v, 1)), "linear");
    const char *s;
    assert_int_equal(dict_get_string(d, "s", &s), SIM_OK);
    assert_string_equal(s, "a \"b\" \\ \n");
    assert_int_equal(dict_get_list(d, "l", &v), SIM_OK);
    assert_int_equal(dict_value_kind(v), DICT_LIST);
    assert_int_equal(dict_value_len(v), 6);
    assert_int_equal(dict_value_kind(dict_value_at(v, 0)), DICT_NUMBER);
    assert_true(dict_value_number(dict_value_at(v, 0)) == 1.0);
    assert_int_equal(dict_value_len(dict_value_at(v, 1)), 2);
    assert_int_equal(dict_value_kind(dict_value_at(v, 2)), DICT_WORD);
    assert_int_equal(dict_value_kind(dict_value_at(v, 3)), DICT_STRING);
    assert_int_equal(dict_value_kind(dict_value_at(v, 4)), DICT_DIMS);
    assert_int_equal(dict_value_dims(dict_value_at(v, 4))[1], 1);
    assert_int_equal(dict_value_kind(dict_value_at(v, 5)), DICT_DICT);
    long k;
    assert_int_equal(dict_get_label(dict_value_dict(dict_value_at(v, 5)), "k",
                                    &k), SIM_OK);
    assert_int_equal(k, 1);
    assert_null(dict_value_at(v, 6));
    assert_int_equal(dict_get_list(d, "b", &v), SIM_OK);
    assert_int_equal(dict_value_len(v), 2);
    assert_string_equal(dict_value_text(dict_value_at(v, 0)), "inlet");
    const struct dict *patch = dict_value_dict(dict_value_at(v, 1));
    assert_string_equal(dict_name(patch), "b/inlet");
    assert_int_equal(dict_get_string(patch, "type", &s), SIM_OK);
    assert_string_equal(s, "patch");
    assert_int_equal(dict_get_value(d, "c", &v), SIM_OK);
    assert_int_equal(dict_value_len(v), 2); /* count, then list */
    dict_free(d);
}

static void test_comments_and_duplicates(void **state)
{
    (void)state;
    struct dict *d = parse("/* a // b */ a 1; // x;\n"
                           "b /* in */ 2;\n"
                           "a 3;\n"
                           "s { x 1; } s { y 2; }\n"
                           "path a/b/c;\n");
    assert_int_equal(dict_size(d), 4);
    assert_string_equal(dict_key_at(d, 0), "a"); /* first position kept */
    long a;
    assert_int_equal(dict_get_label(d, "a", &a), SIM_OK);
    assert_int_equal(a, 3); /* last one wins */
    assert_false(dict_has(d, "s/x"));
    assert_true(dict_has(d, "s/y"));
    const char *p;
    assert_int_equal(dict_get_string(d, "path", &p), SIM_OK);
    assert_string_equal(p, "a/b/c");
    dict_free(d);
}

static void test_substitution_scoping(void **state)
{
    (void)state;
    struct dict *d = parse(
        "top 1;\n"
        "v (1 2 3);\n"
        "a { top 2; b { x $top; y $../top; z $/top; w $../../top; } }\n"
        "c $a/b/x;\n"
        "l ($top $v);\n"
        "t ${top};\n"
        "vv $v;\n");
    long x;
    assert_int_equal(dict_get_label(d, "a/b/x", &x), SIM_OK);
    assert_int_equal(x, 2); /* nearest enclosing scope first */
    assert_int_equal(dict_get_label(d, "a/b/y", &x), SIM_OK);
    assert_int_equal(x, 2);
    assert_int_equal(dict_get_label(d, "a/b/z", &x), SIM_OK);
    assert_int_equal(x, 1);
    assert_int_equal(dict_get_label(d, "a/b/w", &x), SIM_OK);
    assert_int_equal(x, 1);
    assert_int_equal(dict_get_label(d, "c", &x), SIM_OK);
    assert_int_equal(x, 2);
    assert_int_equal(dict_get_label(d, "t", &x), SIM_OK);
    assert_int_equal(x, 1);
    const struct dict_value *l;
    assert_int_equal(dict_get_list(d, "l", &l), SIM_OK);
    assert_int_equal(dict_value_len(l), 2);
    assert_int_equal(dict_value_len(dict_value_at(l, 1)), 3);
    double v[3];
    assert_int_equal(dict_get_vector(d, "vv", 3, v), SIM_OK);
    assert_true(v[2] == 3.0);
    dict_free(d);
}

static void test_merge(void **state)
{
    (void)state;
    struct dict *d = parse("p { solver PCG; tol 1e-6; relTol 0.01; }\n"
                           "pFinal { $p; relTol 0; }\n"
                           "U $p;\n");
    double x;
    const char *s;
    assert_int_equal(dict_get_string(d, "pFinal/solver", &s), SIM_OK);
    assert_string_equal(s, "PCG");
    assert_int_equal(dict_get_scalar(d, "pFinal/relTol", &x), SIM_OK);
    assert_true(x == 0.0);
    assert_int_equal(dict_get_scalar(d, "p/relTol", &x), SIM_OK);
    assert_true(x == 0.01); /* the source is not changed by the override */
    assert_true(dict_is_dict(d, "U"));
    assert_int_equal(dict_get_scalar(d, "U/tol", &x), SIM_OK);
    assert_true(x == 1e-6);
    const struct dict *u;
    assert_int_equal(dict_get_dict(d, "U", &u), SIM_OK);
    assert_string_equal(dict_name(u), "U");
    dict_free(d);
}

/* ---- getters -------------------------------------------------------------- */

static void test_scalar_getters(void **state)
{
    (void)state;
    struct dict *d = parse("a 2; w abc; l (1 2); nu [0 2 -1 0 0 0 0] 1e-6;"
                           "old nu [0 2 -1 0 0 0 0] 2e-6; two 1 2;");
    double x = 0;
    assert_int_equal(dict_get_scalar(d, "a", &x), SIM_OK);
    assert_true(x == 2.0);
    assert_int_equal(dict_get_scalar_or(d, "a", 5.0, &x), SIM_OK);
    assert_true(x == 2.0);
    assert_int_equal(dict_get_scalar_or(d, "absent", 5.0, &x), SIM_OK);
    assert_true(x == 5.0);
    assert_int_equal(dict_get_scalar(d, "absent", &x), SIM_ERR_DICT);
    msg_has("case/system/testDict:1:1: ", "missing keyword 'absent'");
    assert_int_equal(dict_get_scalar(d, "w", &x), SIM_ERR_DICT);
    msg_has("case/system/testDict:1:8: ",
            "expected a scalar for 'w', got word 'abc'");
    assert_int_equal(dict_get_scalar(d, "l", &x), SIM_ERR_DICT);
    msg_has("case/system/testDict:1:15: ", "got a list of 2 items");
    assert_int_equal(dict_get_scalar(d, "two", &x), SIM_ERR_DICT);
    msg_has("case/system/testDict:", "got 2 values");
    /* the default does not hide a bad value */
    assert_int_equal(dict_get_scalar_or(d, "w", 1.0, &x), SIM_ERR_DICT);
    assert_int_equal(dict_get_scalar(d, "nu", &x), SIM_OK);
    assert_true(x == 1e-6);
    assert_int_equal(dict_get_scalar(d, "old", &x), SIM_OK);
    assert_true(x == 2e-6);
    dict_free(d);
}

static void test_dimensions(void **state)
{
    (void)state;
    static const int visc[7] = { 0, 2, -1, 0, 0, 0, 0 };
    struct dict *d = parse("nu [0 2 -1 0 0 0 0] 1e-6;\n"
                           "bad [0 1 -1 0 0 0 0] 1e-6;\n"
                           "plain 3e-6;\n"
                           "five [0 2 -1 0 0] 4e-6;\n"
                           "old nu [0 1 -1 0 0 0 0] 1;\n");
    double x;
    assert_int_equal(dict_get_scalar_dim(d, "nu", visc, &x), SIM_OK);
    assert_true(x == 1e-6);
    assert_int_equal(dict_get_scalar_dim(d, "plain", visc, &x), SIM_OK);
    assert_true(x == 3e-6); /* no set written: nothing to check */
    assert_int_equal(dict_get_scalar_dim(d, "five", visc, &x), SIM_OK);
    assert_true(x == 4e-6);
    assert_int_equal(dict_get_scalar_dim(d, "bad", visc, &x), SIM_ERR_DICT);
    msg_has("case/system/testDict:2:5: ",
            "dimensions of 'bad' are [0 1 -1 0 0 0 0], expected "
            "[0 2 -1 0 0 0 0]");
    assert_int_equal(dict_get_scalar_dim(d, "old", visc, &x), SIM_ERR_DICT);
    assert_int_equal(dict_get_scalar_dim_or(d, "absent", visc, 7.0, &x),
                     SIM_OK);
    assert_true(x == 7.0);
    assert_int_equal(dict_get_scalar_dim_or(d, "bad", visc, 7.0, &x),
                     SIM_ERR_DICT);
    dict_free(d);
    parse_fails("nu [0 2 -1] 1;", SIM_ERR_PARSE, "t.dict:1:4: ",
                "a dimension set has 7 exponents");
    parse_fails("nu [0 2 x 0 0 0 0] 1;", SIM_ERR_PARSE, "t.dict:1:9: ",
                "expected an integer exponent");
    parse_fails("nu [0 2.5 0 0 0 0 0] 1;", SIM_ERR_PARSE, "t.dict:1:7: ",
                "expected an integer exponent");
}

static void test_label_getters(void **state)
{
    (void)state;
    struct dict *d = parse("a 2; b 2.0; c 2.5; d 9007199254740993; e 1e3;"
                           "f -9007199254740992; g 1e300; h x;");
    long l = 0;
    assert_int_equal(dict_get_label(d, "a", &l), SIM_OK);
    assert_int_equal(l, 2);
    assert_int_equal(dict_get_label(d, "b", &l), SIM_OK);
    assert_int_equal(l, 2);
    assert_int_equal(dict_get_label(d, "e", &l), SIM_OK);
    assert_int_equal(l, 1000);
    assert_int_equal(dict_get_label(d, "f", &l), SIM_OK);
    assert_true(l == -9007199254740992L);
    assert_int_equal(dict_get_label(d, "c", &l), SIM_ERR_DICT);
    msg_has("case/system/testDict:1:15: ",
            "expected an integer for 'c', got 2.5");
    assert_int_equal(dict_get_label(d, "d", &l), SIM_ERR_DICT);
    msg_has("case/system/testDict:1:22: ", "beyond the exact range");
    assert_int_equal(dict_get_label(d, "g", &l), SIM_ERR_DICT);
    msg_has("case/system/testDict:", "beyond the exact range");
    assert_int_equal(dict_get_label(d, "h", &l), SIM_ERR_DICT);
    msg_has("case/system/testDict:", "expected an integer for 'h'");
    assert_int_equal(dict_get_label_or(d, "absent", 42, &l), SIM_OK);
    assert_int_equal(l, 42);
    assert_int_equal(dict_get_label_or(d, "a", 42, &l), SIM_OK);
    assert_int_equal(l, 2);
    assert_int_equal(dict_get_label(d, "absent", &l), SIM_ERR_DICT);
    dict_free(d);
}

static void test_bool_getters(void **state)
{
    (void)state;
    static const char *const yes[] = { "yes", "on", "true", "1" };
    static const char *const no[] = { "no", "off", "false", "0" };
    for (int i = 0; i < 4; i++) {
        char text[64];
        snprintf(text, sizeof text, "a %s; b %s;", yes[i], no[i]);
        struct dict *d = parse(text);
        int b = -1;
        assert_int_equal(dict_get_bool(d, "a", &b), SIM_OK);
        assert_int_equal(b, 1);
        assert_int_equal(dict_get_bool(d, "b", &b), SIM_OK);
        assert_int_equal(b, 0);
        dict_free(d);
    }
    struct dict *d = parse("m maybe; t 2;");
    int b = -1;
    assert_int_equal(dict_get_bool(d, "m", &b), SIM_ERR_DICT);
    msg_has("case/system/testDict:1:3: ",
            "expected yes/no, on/off, true/false or 1/0 for 'm', got word "
            "'maybe'");
    assert_int_equal(dict_get_bool(d, "t", &b), SIM_ERR_DICT);
    assert_int_equal(dict_get_bool_or(d, "absent", 1, &b), SIM_OK);
    assert_int_equal(b, 1);
    assert_int_equal(dict_get_bool(d, "absent", &b), SIM_ERR_DICT);
    dict_free(d);
}

static void test_word_string_getters(void **state)
{
    (void)state;
    static const char *const fmt[] = { "ascii", "binary", NULL };
    struct dict *d = parse("f binary; g bianry; q \"quoted\"; n 1; l (a);");
    int i = -1;
    assert_int_equal(dict_get_word(d, "f", fmt, &i), SIM_OK);
    assert_int_equal(i, 1);
    assert_int_equal(dict_get_word(d, "g", fmt, &i), SIM_ERR_DICT);
    msg_has("case/system/testDict:1:13: ",
            "unknown value 'bianry' for 'g' (did you mean 'binary'?); "
            "valid: ascii binary");
    assert_int_equal(dict_get_word_or(d, "absent", fmt, 0, &i), SIM_OK);
    assert_int_equal(i, 0);
    assert_int_equal(dict_get_word(d, "absent", fmt, &i), SIM_ERR_DICT);
    const char *s = NULL;
    assert_int_equal(dict_get_string(d, "q", &s), SIM_OK);
    assert_string_equal(s, "quoted");
    assert_int_equal(dict_get_string(d, "f", &s), SIM_OK);
    assert_string_equal(s, "binary");
    assert_int_equal(dict_get_string(d, "n", &s), SIM_ERR_DICT);
    msg_has("case/system/testDict:", "expected a word or a quoted string "
            "for 'n', got number 1");
    assert_int_equal(dict_get_string(d, "l", &s), SIM_ERR_DICT);
    assert_int_equal(dict_get_string_or(d, "absent", "dflt", &s), SIM_OK);
    assert_string_equal(s, "dflt");
    assert_int_equal(dict_get_string(d, "absent", &s), SIM_ERR_DICT);
    dict_free(d);
}

static void test_vector_getters(void **state)
{
    (void)state;
    struct dict *d = parse("g (0 0 -9.81); two (1 2); w (1 a 3); s 1;"
                           "dg [0 1 -2 0 0 0 0] (0 0 -1);");
    double v[3] = { 0 };
    assert_int_equal(dict_get_vector(d, "g", 3, v), SIM_OK);
    assert_true(v[0] == 0.0 && v[2] == -9.81);
    assert_int_equal(dict_get_vector(d, "dg", 3, v), SIM_OK);
    assert_true(v[2] == -1.0);
    assert_int_equal(dict_get_vector(d, "two", 3, v), SIM_ERR_DICT);
    msg_has("case/system/testDict:", "expected a vector of 3 numbers for "
            "'two', got a list of 2 items");
    assert_int_equal(dict_get_vector(d, "w", 3, v), SIM_ERR_DICT);
    msg_has("case/system/testDict:1:32: ", "got word 'a'");
    assert_int_equal(dict_get_vector(d, "s", 3, v), SIM_ERR_DICT);
    const double def[3] = { 1, 2, 3 };
    assert_int_equal(dict_get_vector_or(d, "absent", 3, def, v), SIM_OK);
    assert_true(v[0] == 1 && v[1] == 2 && v[2] == 3);
    assert_int_equal(dict_get_vector_or(d, "g", 3, def, v), SIM_OK);
    assert_true(v[2] == -9.81);
    assert_int_equal(dict_get_vector(d, "absent", 3, v), SIM_ERR_DICT);
    dict_free(d);
}

/* A forgotten ';' runs one entry into the next: the message names it
 * instead of counting the values (issue 15 item 6). */
static void test_missing_semicolon(void **state)
{
    (void)state;
    struct dict *d = parse("min (0.01 0.005 0.01) max (0.02 0.015 0.02);\n"
                           "dp 0.01 layers 3;\n"
                           "g [0 1 -2 0 0 0 0] (0 0 -9.81) rho 1;\n"
                           "type fluid shape box;\n"
                           "on yes seed 2;\n"
                           "two (1 2) max (1 2 3);\n"
                           "n 3 q;\n"
                           "open (zmax) velocity (0 0 0);\n");
    double v[3], x;
    long n;
    int b;
    const char *w;
    const struct dict_value *l;
    assert_int_equal(dict_get_vector(d, "min", 3, v), SIM_ERR_DICT);
    msg_has("case/system/testDict:1:23: ", "'min' holds a vector of 3 "
            "numbers followed by 'max': missing ';' before 'max'?");
    assert_null(strstr(sim_error_message(), "values"));
    assert_int_equal(dict_get_scalar(d, "dp", &x), SIM_ERR_DICT);
    msg_has("case/system/testDict:2:9: ", "'dp' holds a scalar followed by "
            "'layers': missing ';'");
    assert_int_equal(dict_get_vector(d, "g", 3, v), SIM_ERR_DICT);
    msg_has("case/system/testDict:3:32: ", "followed by 'rho'");
    assert_int_equal(dict_get_string(d, "type", &w), SIM_ERR_DICT);
    msg_has("case/system/testDict:4:12: ", "'type' holds a word or a quoted "
            "string followed by 'shape'");
    assert_int_equal(dict_get_bool(d, "on", &b), SIM_ERR_DICT);
    msg_has("case/system/testDict:5:8: ", "followed by 'seed'");
    assert_int_equal(dict_get_label(d, "n", &n), SIM_ERR_DICT);
    msg_has("case/system/testDict:7:5: ", "'n' holds an integer followed by "
            "'q'");
    assert_int_equal(dict_get_list(d, "open", &l), SIM_ERR_DICT);
    msg_has("case/system/testDict:8:13: ", "followed by 'velocity'");
    /* a prefix of the wrong shape is not a missing ';' */
    assert_int_equal(dict_get_vector(d, "two", 3, v), SIM_ERR_DICT);
    msg_has("case/system/testDict:6:5: ", "expected a vector of 3 numbers "
            "for 'two', got 3 values");
    dict_free(d);
}

static void test_dict_list_value_getters(void **state)
{
    (void)state;
    struct dict *d = parse("s { a 1; } x 1; l (1 2 3); e;");
    const struct dict *sub = NULL;
    assert_int_equal(dict_get_dict(d, "s", &sub), SIM_OK);
    assert_non_null(sub);
    assert_int_equal(dict_find_dict(d, "absent", &sub), SIM_OK);
    assert_null(sub);
    assert_int_equal(dict_find_dict(d, "x", &sub), SIM_ERR_DICT);
    msg_has("case/system/testDict:1:14: ",
            "expected a dictionary { ... } for 'x', got number 1");
    assert_int_equal(dict_get_dict(d, "absent", &sub), SIM_ERR_DICT);
    msg_has("case/system/testDict:1:1: ", "missing keyword 'absent' in "
            "case/system/testDict");
    const struct dict_value *v;
    assert_int_equal(dict_get_list(d, "l", &v), SIM_OK);
    assert_int_equal(dict_value_len(v), 3);
    assert_int_equal(dict_get_list(d, "x", &v), SIM_ERR_DICT);
    assert_int_equal(dict_get_value(d, "s", &v), SIM_OK);
    assert_int_equal(dict_value_kind(v), DICT_DICT);
    assert_int_equal(dict_get_value(d, "e", &v), SIM_OK);
    assert_int_equal(dict_value_kind(v), DICT_ENTRY);
    assert_int_equal(dict_value_len(v), 0);
    assert_int_equal(dict_get_value(d, "absent", &v), SIM_ERR_DICT);
    dict_free(d);
}

static void test_checked_value_forms(void **state)
{
    (void)state;
    struct dict *d = parse("l ( 1.5 (1 2 3) w (1 2) );");
    const struct dict_value *l;
    assert_int_equal(dict_get_list(d, "l", &l), SIM_OK);
    double x, v[3];
    const char *w;
    assert_int_equal(dict_value_get_scalar(dict_value_at(l, 0), &x), SIM_OK);
    assert_true(x == 1.5);
    assert_int_equal(dict_value_get_vector(dict_value_at(l, 1), 3, v), SIM_OK);
    assert_true(v[1] == 2.0);
    assert_int_equal(dict_value_get_word(dict_value_at(l, 2), &w), SIM_OK);
    assert_string_equal(w, "w");
    assert_int_equal(dict_value_get_scalar(dict_value_at(l, 2), &x),
                     SIM_ERR_DICT);
    msg_has("case/system/testDict:1:17: ", "expected a scalar, got word 'w'");
    assert_int_equal(dict_value_get_vector(dict_value_at(l, 3), 3, v),
                     SIM_ERR_DICT);
    msg_has("case/system/testDict:1:19: ", "expected a vector of 3 numbers");
    assert_int_equal(dict_value_get_word(dict_value_at(l, 0), &w),
                     SIM_ERR_DICT);
    dict_free(d);
}

/* ---- error paths ------------------------------------------------------------ */

static void test_parse_errors(void **state)
{
    (void)state;
    parse_fails("a 1;\nendTime 1\nb 2;\n", SIM_ERR_PARSE, "t.dict:2:10: ",
                "expected ';' after the value of 'endTime'");
    parse_fails("a 1;\ns { x 1;\n", SIM_ERR_PARSE, "t.dict:3:1: ",
                "unbalanced '{' opened at 2:3");
    parse_fails("a 1 }", SIM_ERR_PARSE, "t.dict:1:4: ",
                "expected ';' after the value of 'a'");
    parse_fails("}", SIM_ERR_PARSE, "t.dict:1:1: ", "unexpected '}'");
    parse_fails("a (1 2;", SIM_ERR_PARSE, "t.dict:1:7: ",
                "unbalanced '(' opened at 1:3");
    parse_fails("a 1e;", SIM_ERR_PARSE, "t.dict:1:3: ", "bad number '1e'");
    parse_fails("a 2.5x;", SIM_ERR_PARSE, "t.dict:1:3: ", "bad number '2.5x'");
    parse_fails("a 1e400;", SIM_ERR_PARSE, "t.dict:1:3: ", "out of range");
    parse_fails("a \"open;\n", SIM_ERR_PARSE, "t.dict:1:9: ",
                "missing closing '\"' of the string opened at 1:3");
    parse_fails("a 1; /* open", SIM_ERR_PARSE, "t.dict:1:13: ",
                "unterminated comment '/*' opened at 1:6");
    parse_fails("nu 1;\nmu $nuu;", SIM_ERR_PARSE, "t.dict:2:4: ",
                "undefined variable '$nuu' (did you mean '$nu'?)");
    parse_fails("mu $zzz;", SIM_ERR_PARSE, "t.dict:1:4: ",
                "undefined variable '$zzz'");
    parse_fails("a 1; b $a/c;", SIM_ERR_PARSE, "t.dict:1:8: ",
                "'a' is not a dictionary");
    parse_fails("s { x $../../a; }", SIM_ERR_PARSE, "t.dict:1:7: ",
                "goes above the top level");
    parse_fails("a 1; $a;", SIM_ERR_PARSE, "t.dict:1:6: ",
                "'a' is not a dictionary");
    parse_fails("s { $s; }", SIM_ERR_PARSE, "t.dict:1:5: ",
                "undefined variable '$s'");
    parse_fails("s { x 1; } $s", SIM_ERR_PARSE, "t.dict:1:14: ",
                "expected ';' after '$s'");
    parse_fails("p { a 1; }\nx w $p;", SIM_ERR_PARSE, "t.dict:2:5: ",
                "a dictionary cannot be one of several values of 'x'");
    parse_fails("#calc \"1+1\";", SIM_ERR_PARSE, "t.dict:1:1: ",
                "unsupported directive '#calc'");
    parse_fails("#include x;", SIM_ERR_PARSE, "t.dict:1:10: ",
                "expected a quoted file name");
    parse_fails("( 1 );", SIM_ERR_PARSE, "t.dict:1:1: ",
                "expected a keyword, got '('");
    parse_fails("a $;", SIM_ERR_PARSE, "t.dict:1:3: ",
                "expected a variable name after '$'");
    struct dict *d;
    assert_int_equal(dict_read_string("a 1\0;", 5, "t.dict", &d),
                     SIM_ERR_PARSE);
    msg_has("t.dict:1:4: ", "unexpected NUL byte");
}

static void test_nesting_limit(void **state)
{
    (void)state;
    enum { n = 5000 };
    static char text[2 * n + 8] = "a ";
    for (size_t i = 0; i < n; i++) {
        text[2 + i] = '(';
        text[2 + n + i] = ')';
    }
    text[2 + 2 * n] = ';';
    struct dict *d;
    assert_int_equal(dict_read_string(text, strlen(text), "t.dict", &d),
                     SIM_ERR_PARSE);
    msg_has("t.dict:1:", "nested deeper than");
}

static void test_missing_file(void **state)
{
    (void)state;
    struct dict *d = (struct dict *)1;
    assert_int_equal(dict_read("/nonexistent/dir/controlDict", &d),
                     SIM_ERR_IO);
    assert_null(d);
    assert_string_equal(sim_error_message(),
                        "cannot open '/nonexistent/dir/controlDict': No such "
                        "file or directory");
    assert_int_equal(dict_read("/tmp", &d), SIM_ERR_IO);
    msg_has("cannot open '/tmp'", "Is a directory");
    parse_fails("a 1;\n#include \"/nonexistent/x\"\n", SIM_ERR_IO,
                "t.dict:2:10: ", "cannot open included file "
                "'/nonexistent/x': No such file or directory");
    parse_fails("#include \"/dev/null\"\n", SIM_ERR_IO, "t.dict:1:10: ",
                "not a regular file");
    struct dict *ok = parse("#includeIfPresent \"/nonexistent/x\"\na 1;");
    assert_int_equal(dict_size(ok), 1);
    dict_free(ok);
}

static void test_where_and_error(void **state)
{
    (void)state;
    struct dict *d = parse("a 1;\n  sub\n  {\n    b   (1 2);\n  }\n");
    char buf[256];
    assert_string_equal(dict_where(d, "a", buf, sizeof buf),
                        "case/system/testDict:1:1");
    assert_string_equal(dict_where(d, "sub/b", buf, sizeof buf),
                        "case/system/testDict:4:5");
    assert_string_equal(dict_where(d, "nope", buf, sizeof buf),
                        "case/system/testDict:1:1");
    const struct dict *sub;
    assert_int_equal(dict_get_dict(d, "sub", &sub), SIM_OK);
    assert_string_equal(dict_where(sub, "nope", buf, sizeof buf),
                        "case/system/testDict:3:3"); /* its '{' */
    assert_int_equal(dict_error(sub, "b", SIM_ERR_INPUT, "bad %s %d", "b", 7),
                     SIM_ERR_INPUT);
    assert_string_equal(sim_error_message(),
                        "case/system/testDict:4:5: bad b 7");
    assert_int_equal(dict_error(sub, NULL, SIM_ERR_DICT, "whole"),
                     SIM_ERR_DICT);
    assert_string_equal(sim_error_message(),
                        "case/system/testDict:3:3: whole");
    const struct dict_value *v;
    assert_int_equal(dict_get_value(sub, "b", &v), SIM_OK);
    assert_string_equal(dict_value_where(v, buf, sizeof buf),
                        "case/system/testDict:4:9");
    assert_string_equal(dict_value_where(dict_value_at(dict_value_at(v, 0), 1),
                                         buf, sizeof buf),
                        "case/system/testDict:4:12");
    assert_int_equal(dict_value_error(v, SIM_ERR_DICT, "too %s", "short"),
                     SIM_ERR_DICT);
    assert_string_equal(sim_error_message(),
                        "case/system/testDict:4:9: too short");
    dict_free(d);
}

static void test_large_list(void **state)
{
    (void)state;
    /* probe-location sized input: built, parsed and checked value by
     * value (the speed is measured by a benchmark, not here) */
    int n = 200000;
    size_t cap = (size_t)n * 32 + 64, len = 0;
    char *text = malloc(cap);
    if (!text)
        fail();
    len += (size_t)snprintf(text + len, cap - len, "probes\n(\n");
    for (int i = 0; i < n; i++)
        len += (size_t)snprintf(text + len, cap - len, "(%d %d.5 -%de-3)\n",
                                i, i, i);
    len += (size_t)snprintf(text + len, cap - len, ");\n");
    struct dict *d;
    assert_int_equal(dict_read_string(text, len, "big", &d), SIM_OK);
    const struct dict_value *l;
    assert_int_equal(dict_get_list(d, "probes", &l), SIM_OK);
    assert_int_equal(dict_value_len(l), n);
    for (int i = 0; i < n; i += 9973) {
        double v[3];
        assert_int_equal(dict_value_get_vector(dict_value_at(l, i), 3, v),
                         SIM_OK);
        assert_true(v[0] == i && v[1] == i + 0.5 && v[2] == -i * 1e-3);
    }
    dict_free(d);
    free(text);
}

static int quiet(void **state)
{
    (void)state;
    log_set_quiet(1);
    return 0;
}

static int clear(void **state)
{
    (void)state;
    params_clear();
    return 0;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_structure),
        cmocka_unit_test(test_numbers_exact),
        cmocka_unit_test(test_words_strings_lists),
        cmocka_unit_test(test_comments_and_duplicates),
        cmocka_unit_test(test_substitution_scoping),
        cmocka_unit_test(test_merge),
        cmocka_unit_test(test_scalar_getters),
        cmocka_unit_test(test_dimensions),
        cmocka_unit_test(test_label_getters),
        cmocka_unit_test(test_bool_getters),
        cmocka_unit_test(test_word_string_getters),
        cmocka_unit_test(test_vector_getters),
        cmocka_unit_test(test_missing_semicolon),
        cmocka_unit_test(test_dict_list_value_getters),
        cmocka_unit_test(test_checked_value_forms),
        cmocka_unit_test(test_parse_errors),
        cmocka_unit_test(test_nesting_limit),
        cmocka_unit_test(test_missing_file),
        cmocka_unit_test(test_where_and_error),
        cmocka_unit_test(test_large_list),
    };
    return cmocka_run_group_tests(tests, quiet, clear);
}
