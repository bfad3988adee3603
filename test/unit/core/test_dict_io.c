/*
 * test_dict_io.c — the dictionary library's files and reports: #include
 * (relative, cycles, depth), unused-entry warnings with suggestions, the
 * usedParameters report, dict_set_in_file keeping comments, and expansion
 * re-parsing to the same content over the whole test/dictionary corpus.
 */
#include <dirent.h>
#include <fcntl.h>
#include <libgen.h>
#include <limits.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmocka.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"

static char tmpdir[256];

static void write_file(const char *rel, const char *text)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", tmpdir, rel);
    char dir[512];
    snprintf(dir, sizeof dir, "%s", path);
    char cmd[600];
    snprintf(cmd, sizeof cmd, "mkdir -p '%s'", dirname(dir));
    assert_int_equal(system(cmd), 0);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static char *read_text(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *s = malloc((size_t)n + 1);
    size_t got = fread(s, 1, (size_t)n, f);
    s[got] = '\0';
    fclose(f);
    return s;
}

static const char *tmp(const char *rel)
{
    static char buf[4][512];
    static int k;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", tmpdir, rel);
    return buf[k];
}

/* stdout of fn(d) (log_warn and log_info print there). */
static char *capture(int (*fn)(const struct dict *), const struct dict *d,
                     int *ret)
{
    fflush(stdout);
    const char *path = tmp("stdout.txt");
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    int saved = dup(1);
    dup2(fd, 1);
    close(fd);
    *ret = fn(d);
    fflush(stdout);
    dup2(saved, 1);
    close(saved);
    return read_text(path);
}

static struct dict *parse(const char *text, const char *name)
{
    struct dict *d = NULL;
    if (dict_read_string(text, strlen(text), name, &d) != SIM_OK)
        fail_msg("parse failed: %s", sim_error_message());
    return d;
}

static void contains(const char *text, const char *what)
{
    if (!strstr(text, what))
        fail_msg("'%s' not found in:\n%s", what, text);
}

/* ---- #include --------------------------------------------------------------- */

static void test_include_relative(void **state)
{
    (void)state;
    write_file("inc/main", "a 1;\nsub { #include \"parts/one.inc\" }\n");
    write_file("inc/parts/one.inc", "FoamFile { object one; }\n"
                                    "b 2;\n#include \"two.inc\"\n");
    write_file("inc/parts/two.inc", "c $b;\n");
    struct dict *d;
    assert_int_equal(dict_read(tmp("inc/main"), &d), SIM_OK);
    long x;
    assert_int_equal(dict_get_label(d, "sub/c", &x), SIM_OK);
    assert_int_equal(x, 2);
    assert_false(dict_has(d, "sub/FoamFile")); /* an include's header */
    char where[600], want[600];
    snprintf(want, sizeof want, "%s:1:1", tmp("inc/parts/two.inc"));
    assert_string_equal(dict_where(d, "sub/c", where, sizeof where), want);
    dict_free(d);
    /* dict_read_string resolves includes next to `name` */
    char name[600];
    snprintf(name, sizeof name, "%s/inc/virtual", tmpdir);
    write_file("inc/parts/three.inc", "d 4;\n");
    d = parse("#include \"parts/three.inc\"", name);
    assert_true(dict_has(d, "d"));
    dict_free(d);
}

static void test_include_cycle_and_depth(void **state)
{
    (void)state;
    write_file("cyc/x", "a 1;\n#include \"y\"\n");
    write_file("cyc/y", "b 1;\n  #include \"x\"\n");
    struct dict *d = (struct dict *)1;
    assert_int_equal(dict_read(tmp("cyc/x"), &d), SIM_ERR_PARSE);
    assert_null(d);
    char want[1200];
    snprintf(want, sizeof want, "%s:2:3: #include cycle: %s -> %s -> %s",
             tmp("cyc/y"), tmp("cyc/x"), tmp("cyc/y"), tmp("cyc/x"));
    assert_string_equal(sim_error_message(), want);
    for (int i = 0; i < 40; i++) {
        char rel[64], text[64];
        snprintf(rel, sizeof rel, "deep/f%d", i);
        snprintf(text, sizeof text, "k%d 1;\n#include \"f%d\"\n", i, i + 1);
        write_file(rel, text);
    }
    assert_int_equal(dict_read(tmp("deep/f0"), &d), SIM_ERR_PARSE);
    contains(sim_error_message(), "#include nested deeper than 32 files");
}

/* ---- unused entries ------------------------------------------------------------ */

static int warn_unused(const struct dict *d) { return dict_warn_unused(d); }

static void test_unused_warnings(void **state)
{
    (void)state;
    struct dict *d = parse(
        "FoamFile { version 2.0; }\n"
        "endTime 1;\n"
        "writeIntervall 0.1;\n"
        "helper 5;\n"
        "x $helper;\n"
        "solvers { p { tol 1; relTol 2; } unusedSub { a 1; } }\n"
        "list ( { a 1; b 2; } );\n"
        "maxCo 1;\n",
        "case/system/controlDict");
    double v;
    assert_int_equal(dict_get_scalar(d, "endTime", &v), SIM_OK);
    assert_int_equal(dict_get_scalar_or(d, "writeInterval", 1, &v), SIM_OK);
    assert_int_equal(dict_get_scalar_or(d, "deltaT", 1, &v), SIM_OK);
    assert_int_equal(dict_get_scalar(d, "x", &v), SIM_OK);
    assert_int_equal(dict_get_scalar(d, "solvers/p/tol", &v), SIM_OK);
    const struct dict *p;
    assert_int_equal(dict_get_dict(d, "solvers/p", &p), SIM_OK);
    assert_int_equal(dict_get_scalar_or(p, "reltol", 0, &v), SIM_OK);
    const struct dict_value *l;
    assert_int_equal(dict_get_list(d, "list", &l), SIM_OK);
    assert_int_equal(dict_get_scalar(dict_value_dict(dict_value_at(l, 0)),
                                     "a", &v), SIM_OK);
    int n;
    char *out = capture(warn_unused, d, &n);
    assert_int_equal(n, 5);
    contains(out, "--> WARNING: case/system/controlDict:3:1: keyword "
                  "'writeIntervall' is not used (did you mean "
                  "'writeInterval'?)");
    contains(out, "case/system/controlDict:6:22: keyword 'relTol' in "
                  "'solvers/p' is not used (did you mean 'reltol'?)");
    contains(out, "case/system/controlDict:6:34: keyword 'unusedSub' in "
                  "'solvers' is not used\n");
    contains(out, "case/system/controlDict:7:15: keyword 'b' in 'list/0' is "
                  "not used\n");
    /* far from every key asked for: no suggestion */
    contains(out, "case/system/controlDict:8:1: keyword 'maxCo' is not "
                  "used\n");
    assert_null(strstr(out, "helper")); /* used through $helper */
    assert_null(strstr(out, "FoamFile"));
    free(out);
    dict_free(d);
}

static void test_mark_used(void **state)
{
    (void)state;
    struct dict *d = parse("a 1; s { b 1; } t { c 1; }", "m");
    dict_mark_used(d, "a");
    dict_mark_used(d, "s");   /* the entry only: b is still reported */
    dict_mark_used(d, "t/c"); /* the inner key only: t is not marked */
    int n;
    char *out = capture(warn_unused, d, &n);
    assert_int_equal(n, 2);
    contains(out, "keyword 'b' in 's' is not used");
    contains(out, "keyword 't' is not used");
    free(out);
    dict_free(d);
}

/* ---- usedParameters --------------------------------------------------------- */

static int write_report_echo(const struct dict *d)
{
    (void)d;
    return params_write(tmp("echo/usedParameters"), 1);
}

static void test_used_parameters(void **state)
{
    (void)state;
    params_clear();
    struct dict *d = parse("endTime 1;\nwriteFormat binary;\n"
                           "functions { probes { type probes; "
                           "fields (p U); } }\n",
                           "case/system/controlDict");
    double x, g[3];
    const char *s;
    const struct dict_value *l;
    static const char *const fmts[] = { "ascii", "binary", NULL };
    int i;
    assert_int_equal(dict_get_scalar(d, "endTime", &x), SIM_OK);
    assert_int_equal(dict_get_scalar_or(d, "writeInterval", 0.1, &x), SIM_OK);
    assert_int_equal(dict_get_word(d, "writeFormat", fmts, &i), SIM_OK);
    assert_int_equal(dict_get_string(d, "functions/probes/type", &s), SIM_OK);
    assert_int_equal(dict_get_list(d, "functions/probes/fields", &l), SIM_OK);
    const double g0[3] = { 0, 0, -9.81 };
    assert_int_equal(dict_get_vector_or(d, "g", 3, g0, g), SIM_OK);
    params_record("command line", "parallel", "no", 0);
    const char *path = tmp("case/postProcessing/usedParameters");
    assert_int_equal(params_write(path, 0), SIM_OK);
    char *text = read_text(path);
    assert_non_null(text);
    contains(text, "    writeInterval   0.1;  // default\n");
    contains(text, "    endTime         1;\n");
    contains(text, "    g               (0 0 -9.81);  // default\n");
    /* the report is itself a dictionary: read it back */
    struct dict *r;
    assert_int_equal(dict_read(path, &r), SIM_OK);
    const struct dict *cd;
    assert_int_equal(dict_get_dict(r, "case/system/controlDict", &cd),
                     SIM_OK);
    assert_int_equal(dict_get_scalar(cd, "endTime", &x), SIM_OK);
    assert_true(x == 1.0);
    assert_int_equal(dict_get_scalar(cd, "writeInterval", &x), SIM_OK);
    assert_true(x == 0.1);
    assert_int_equal(dict_get_string(cd, "writeFormat", &s), SIM_OK);
    assert_string_equal(s, "binary");
    assert_int_equal(dict_get_string(cd, "functions/probes/type", &s),
                     SIM_OK);
    assert_string_equal(s, "probes");
    assert_int_equal(dict_get_list(cd, "functions/probes/fields", &l),
                     SIM_OK);
    assert_int_equal(dict_value_len(l), 2);
    assert_int_equal(dict_get_string(r, "command line/parallel", &s), SIM_OK);
    dict_free(r);
    free(text);
    /* nothing but the report in the directory: the temporary is gone */
    DIR *dir = opendir(tmp("case/postProcessing"));
    assert_non_null(dir);
    int files = 0;
    for (struct dirent *e; (e = readdir(dir));)
        files += e->d_name[0] != '.';
    closedir(dir);
    assert_int_equal(files, 1);
    int rc;
    char *out = capture(write_report_echo, d, &rc);
    assert_int_equal(rc, SIM_OK);
    contains(out, "    endTime         1;\n");
    free(out);
    /* a getter reading the same key again replaces its record */
    params_clear();
    assert_int_equal(dict_get_scalar_or(d, "endTime", 5, &x), SIM_OK);
    assert_int_equal(dict_get_scalar_or(d, "endTime", 5, &x), SIM_OK);
    assert_int_equal(params_write(path, 0), SIM_OK);
    text = read_text(path);
    assert_non_null(strstr(text, "endTime"));
    assert_null(strstr(strstr(text, "endTime") + 1, "endTime"));
    free(text);
    params_clear();
    dict_free(d);
}

/* ---- dict_set_in_file -------------------------------------------------------- */

static const char *edit_src =
    "/* header */\n"
    "endTime     1;      // end [s]\n"
    "deltaT      1e-4;\n"
    "empty;\n"
    "p { solver PCG; tol 1e-6; }\n"
    "pFinal $p;\n"
    "functions\n"
    "{\n"
    "    probes1\n"
    "    {\n"
    "        type probes;  // keep me\n"
    "    }\n"
    "}\n";

static void set_ok(const char *file, const char *key, const char *value)
{
    if (dict_set_in_file(tmp(file), key, value) != SIM_OK)
        fail_msg("set %s=%s: %s", key, value, sim_error_message());
}

static void test_set_in_file(void **state)
{
    (void)state;
    write_file("set/dict", edit_src);
    chmod(tmp("set/dict"), 0640);
    set_ok("set/dict", "endTime", "2.5");
    set_ok("set/dict", "functions/probes1/type", "sets");
    set_ok("set/dict", "functions/probes1/fields", "(p U)");
    set_ok("set/dict", "functions/gauges/type", "waveGauge");
    set_ok("set/dict", "new/sub/key", "yes");
    set_ok("set/dict", "empty", "3");
    set_ok("set/dict", "pFinal/tol", "0");
    char *text = read_text(tmp("set/dict"));
    assert_string_equal(text,
        "/* header */\n"
        "endTime     2.5;      // end [s]\n"
        "deltaT      1e-4;\n"
        "empty 3;\n"
        "p { solver PCG; tol 1e-6; }\n"
        "pFinal\n"
        "{\n"
        "    $p;\n"
        "    tol             0;\n"
        "};\n"
        "functions\n"
        "{\n"
        "    probes1\n"
        "    {\n"
        "        type sets;  // keep me\n"
        "        fields          (p U);\n"
        "    }\n"
        "    gauges\n"
        "    {\n"
        "        type            waveGauge;\n"
        "    }\n"
        "}\n"
        "\n"
        "new\n"
        "{\n"
        "    sub\n"
        "    {\n"
        "        key             yes;\n"
        "    }\n"
        "}\n");
    free(text);
    struct stat st;
    assert_int_equal(stat(tmp("set/dict"), &st), 0);
    assert_int_equal(st.st_mode & 0777, 0640);
    struct dict *d;
    assert_int_equal(dict_read(tmp("set/dict"), &d), SIM_OK);
    double x;
    assert_int_equal(dict_get_scalar(d, "pFinal/tol", &x), SIM_OK);
    assert_true(x == 0.0);
    assert_int_equal(dict_get_scalar(d, "p/tol", &x), SIM_OK);
    assert_true(x == 1e-6);
    dict_free(d);
}

static void test_set_in_file_errors(void **state)
{
    (void)state;
    write_file("seterr/dict", edit_src);
    static const char *const bad[][2] = {
        { "endTime", "1; x 2" },     /* two entries                */
        { "endTime", "1; endTime 2" },
        { "endTime", "(1 2" },       /* does not parse             */
        { "endTime", "$undefined" },
        { "endTime/sub", "1" },      /* below a non-dictionary     */
        { "", "1" },
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        sim_error_clear();
        assert_int_not_equal(dict_set_in_file(tmp("seterr/dict"), bad[i][0],
                                              bad[i][1]), SIM_OK);
        assert_true(sim_error_message()[0] != '\0');
    }
    contains(sim_error_message(), "bad key path");
    char *text = read_text(tmp("seterr/dict"));
    assert_string_equal(text, edit_src);
    free(text);
    write_file("seterr/broken", "a 1;\nb {\n");
    assert_int_equal(dict_set_in_file(tmp("seterr/broken"), "a", "2"),
                     SIM_ERR_PARSE);
    text = read_text(tmp("seterr/broken"));
    assert_string_equal(text, "a 1;\nb {\n");
    free(text);
    assert_int_equal(dict_set_in_file(tmp("seterr/none"), "a", "2"),
                     SIM_ERR_IO);
    contains(sim_error_message(), "No such file or directory");
}

static void test_set_overrides_include(void **state)
{
    (void)state;
    write_file("setinc/dict", "#include \"defaults\"\nb 1;\n");
    write_file("setinc/defaults", "a 1;\n");
    set_ok("setinc/dict", "a", "7");
    struct dict *d;
    assert_int_equal(dict_read(tmp("setinc/dict"), &d), SIM_OK);
    long a;
    assert_int_equal(dict_get_label(d, "a", &a), SIM_OK);
    assert_int_equal(a, 7);
    dict_free(d);
    char *inc = read_text(tmp("setinc/defaults"));
    assert_string_equal(inc, "a 1;\n"); /* the included file is untouched */
    free(inc);
    /* a dictionary from an #include is replaced by one that merges it */
    write_file("setinc/sub", "#include \"subs\"\nc 1;\n");
    write_file("setinc/subs", "s { a 1; t { x 1; y 2; } }\n");
    set_ok("setinc/sub", "s/t/x", "9");
    assert_int_equal(dict_read(tmp("setinc/sub"), &d), SIM_OK);
    long x;
    assert_int_equal(dict_get_label(d, "s/t/x", &x), SIM_OK);
    assert_int_equal(x, 9);
    assert_int_equal(dict_get_label(d, "s/t/y", &x), SIM_OK);
    assert_int_equal(x, 2);
    assert_int_equal(dict_get_label(d, "s/a", &x), SIM_OK);
    assert_int_equal(x, 1);
    dict_free(d);
    params_clear();
}

/* ---- expansion ------------------------------------------------------------------ */

static int values_equal(const struct dict_value *a,
                        const struct dict_value *b);

static int dicts_equal(const struct dict *a, const struct dict *b)
{
    if (dict_size(a) != dict_size(b))
        return 0;
    for (int i = 0; i < dict_size(a); i++) {
        const char *k = dict_key_at(a, i);
        const struct dict_value *va, *vb;
        if (strcmp(k, dict_key_at(b, i)) != 0
            || dict_get_value(a, k, &va) != SIM_OK
            || dict_get_value(b, k, &vb) != SIM_OK || !values_equal(va, vb))
            return 0;
    }
    return 1;
}

static int values_equal(const struct dict_value *a,
                        const struct dict_value *b)
{
    if (dict_value_kind(a) != dict_value_kind(b))
        return 0;
    switch (dict_value_kind(a)) {
    case DICT_WORD:
    case DICT_NUMBER:
    case DICT_STRING:
        return strcmp(dict_value_text(a), dict_value_text(b)) == 0;
    case DICT_DIMS:
        return memcmp(dict_value_dims(a), dict_value_dims(b),
                      7 * sizeof(int)) == 0;
    case DICT_DICT:
        return dicts_equal(dict_value_dict(a), dict_value_dict(b));
    case DICT_LIST:
    case DICT_ENTRY:
        if (dict_value_len(a) != dict_value_len(b))
            return 0;
        for (int i = 0; i < dict_value_len(a); i++)
            if (!values_equal(dict_value_at(a, i), dict_value_at(b, i)))
                return 0;
        return 1;
    }
    return 0;
}

static char *expand(const struct dict *d)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    assert_int_equal(dict_write_expanded(d, f), SIM_OK);
    fclose(f);
    return buf;
}

static void corpus_dir(char *buf, size_t n)
{
    /* the executable is <root>/build(-san)/test/unit/core/<name> */
    static char exe[PATH_MAX];
    ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
    assert_true(len > 0);
    exe[len] = '\0';
    for (int i = 0; i < 5; i++)
        *strrchr(exe, '/') = '\0';
    assert_true(strlen(exe) + 20 < n);
    strcpy(buf, exe);
    strcat(buf, "/test/dictionary");
}

static void test_expand_corpus(void **state)
{
    (void)state;
    char dir[PATH_MAX];
    corpus_dir(dir, sizeof dir);
    DIR *dd = opendir(dir);
    assert_non_null(dd);
    int checked = 0;
    for (struct dirent *e; (e = readdir(dd));) {
        size_t n = strlen(e->d_name);
        if (n < 6 || strcmp(e->d_name + n - 5, ".dict") != 0
            || strncmp(e->d_name, "bad_", 4) == 0)
            continue;
        char path[PATH_MAX + 300], ref[PATH_MAX + 300];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        snprintf(ref, sizeof ref, "%s/%.*s.expanded", dir, (int)(n - 5),
                 e->d_name);
        struct dict *d, *d2;
        if (dict_read(path, &d) != SIM_OK)
            fail_msg("%s: %s", path, sim_error_message());
        char *t1 = expand(d);
        char *want = read_text(ref);
        assert_non_null(want);
        if (strcmp(t1, want) != 0)
            fail_msg("%s: expansion differs from %s:\n%s", path, ref, t1);
        assert_int_equal(dict_read_string(t1, strlen(t1), "expanded", &d2),
                         SIM_OK);
        if (!dicts_equal(d, d2))
            fail_msg("%s: the expansion parses to different content", path);
        char *t2 = expand(d2);
        assert_string_equal(t1, t2);
        free(t1);
        free(t2);
        free(want);
        dict_free(d);
        dict_free(d2);
        checked++;
    }
    closedir(dd);
    assert_true(checked >= 13);
    params_clear();
}

static void test_write_value(void **state)
{
    (void)state;
    struct dict *d = parse("a 1; s \"q\\\"\"; l (1 (2 3)); sub { x 1; }"
                           "m nonuniform List<scalar> 2(1 2);"
                           "o (f((x) );", "w");
    static const char *const key[] = { "a", "s", "l", "sub", "m", "o" };
    /* "f((x)" keeps a '(' open: the list's ')' must stay apart from it */
    static const char *const want[] = {
        "1", "\"q\\\"\"", "(1 (2 3))",
        "{\n    x               1;\n}", "nonuniform List<scalar> 2 (1 2)",
        "(f((x) )" };
    for (int i = 0; i < 6; i++) {
        const struct dict_value *v;
        assert_int_equal(dict_get_value(d, key[i], &v), SIM_OK);
        char *buf = NULL;
        size_t len = 0;
        FILE *f = open_memstream(&buf, &len);
        assert_int_equal(dict_write_value(v, f), SIM_OK);
        fclose(f);
        assert_string_equal(buf, want[i]);
        free(buf);
    }
    params_clear();
    dict_free(d);
}

static int setup(void **state)
{
    (void)state;
    log_set_quiet(0);
    snprintf(tmpdir, sizeof tmpdir, "/tmp/test_dict_io.XXXXXX");
    return mkdtemp(tmpdir) ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    params_clear();
    return system(cmd) == 0 ? 0 : -1;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_include_relative),
        cmocka_unit_test(test_include_cycle_and_depth),
        cmocka_unit_test(test_unused_warnings),
        cmocka_unit_test(test_mark_used),
        cmocka_unit_test(test_used_parameters),
        cmocka_unit_test(test_set_in_file),
        cmocka_unit_test(test_set_in_file_errors),
        cmocka_unit_test(test_set_overrides_include),
        cmocka_unit_test(test_expand_corpus),
        cmocka_unit_test(test_write_value),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
