/*
 * fuzz_dict.c — libFuzzer target for the dictionary library.
 *
 * Any input must either parse or fail with a located message, never crash,
 * hang or leak. Whatever parses is expanded, parsed again and expanded
 * again: the two texts must be equal (dict_write_expanded's promise), and
 * the getters are exercised on the first entries with every type. Then
 * dict_set_entries_in_file edits a copy of the input (in /dev/shm), with
 * and without allowing new keys: it must either fail with a message and
 * leave the file as it was, or leave a file whose entry reads back as the
 * value.
 * Build and run with test/fuzz/run.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"

static char *expand(const struct dict *d, size_t *len)
{
    char *buf = NULL;
    FILE *f = open_memstream(&buf, len);
    if (!f)
        abort();
    if (dict_write_expanded(d, f) != SIM_OK)
        abort();
    fclose(f);
    return buf;
}

static void poke(const struct dict *d, int depth)
{
    static const char *const words[] = { "yes", "no", "ascii", NULL };
    for (int i = 0; i < dict_size(d) && i < 8; i++) {
        const char *k = dict_key_at(d, i);
        double x, v[3];
        long l;
        int b, w;
        const char *s;
        const struct dict *sub;
        const struct dict_value *val;
        int dims[7] = { 0, 2, -1, 0, 0, 0, 0 };
        char where[256];
        dict_get_scalar(d, k, &x);
        dict_get_scalar_dim(d, k, dims, &x);
        dict_get_label(d, k, &l);
        dict_get_bool(d, k, &b);
        dict_get_word(d, k, words, &w);
        dict_get_string(d, k, &s);
        dict_get_vector(d, k, 3, v);
        dict_get_list(d, k, &val);
        dict_where(d, k, where, sizeof where);
        if (dict_get_value(d, k, &val) == SIM_OK) {
            dict_value_where(val, where, sizeof where);
            for (int j = 0; j < dict_value_len(val) && j < 4; j++) {
                const struct dict_value *it = dict_value_at(val, j);
                dict_value_get_scalar(it, &x);
                dict_value_get_vector(it, 3, v);
                dict_value_get_word(it, &s);
                if (dict_value_kind(it) == DICT_DICT && depth < 4)
                    poke(dict_value_dict(it), depth + 1);
            }
        }
        if (depth < 4 && dict_find_dict(d, k, &sub) == SIM_OK && sub)
            poke(sub, depth + 1);
        sim_error_clear();
    }
    dict_get_scalar_or(d, "notThere", 1.0, &(double){ 0 });
    dict_get_label(d, "a/b/c", &(long){ 0 });
    sim_error_clear();
}

static char workdir[64];

static void remove_workdir(void)
{
    char path[128];
    snprintf(path, sizeof path, "%s/input", workdir);
    unlink(path);
    rmdir(workdir);
}

static const char *work_file(void)
{
    static char path[128];
    if (!workdir[0]) {
        snprintf(workdir, sizeof workdir, "/dev/shm/fuzz_dict.XXXXXX");
        if (!mkdtemp(workdir)) {
            snprintf(workdir, sizeof workdir, "/tmp/fuzz_dict.XXXXXX");
            if (!mkdtemp(workdir))
                abort();
        }
        atexit(remove_workdir);
        snprintf(path, sizeof path, "%s/input", workdir);
    }
    return path;
}

/* A refused edit leaves the file as it was. */
static void unchanged(const char *path, const uint8_t *data, size_t size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        abort();
    uint8_t *back = malloc(size + 1);
    size_t got = back ? fread(back, 1, size + 1, f) : 0;
    fclose(f);
    if (!back || got != size || memcmp(back, data, size) != 0) {
        fprintf(stderr, "a refused edit changed the file\n");
        abort();
    }
    free(back);
}

static void check_set(const uint8_t *data, size_t size, const struct dict *d)
{
    static const char *const values[] = { "42", "(1 2 3)", "{ x 1; }",
                                          "word", "\"s;\"" };
    char key[256];
    const char *value = values[size % 5];
    if (dict_size(d) == 0 || strlen(dict_key_at(d, 0)) > 100)
        return;
    const char *k0 = dict_key_at(d, 0);
    if (strchr(k0, '/'))
        return; /* a quoted key with '/' is not a path */
    if (size % 3 == 1)
        snprintf(key, sizeof key, "%s/newKey", k0);
    else if (size % 3 == 2)
        snprintf(key, sizeof key, "brandNew/%s", k0);
    else
        snprintf(key, sizeof key, "%s", k0);
    const char *path = work_file();
    FILE *f = fopen(path, "wb");
    if (!f)
        abort();
    fwrite(data, 1, size, f);
    fclose(f);
    /* every other input without -new: an absent key is then refused */
    int allow_new = (size / 15) % 2 == 0;
    const char *keys[1] = { key }, *vals[1] = { value };
    if (dict_set_entries_in_file(path, 1, keys, vals, allow_new) != SIM_OK) {
        if (sim_error_message()[0] == '\0')
            abort();
        sim_error_clear();
        unchanged(path, data, size);
        return;
    }
    struct dict *e;
    if (dict_read(path, &e) != SIM_OK) {
        fprintf(stderr, "edited file does not parse: %s\n",
                sim_error_message());
        abort();
    }
    const struct dict_value *v;
    if (dict_get_value(e, key, &v) != SIM_OK)
        abort();
    char *buf = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&buf, &len);
    dict_write_value(v, m);
    fclose(m);
    int same = strcmp(buf, values[size % 5]) == 0
               || (size % 5 == 2 && strcmp(buf, "{\n    x               1;\n}")
                                        == 0);
    if (!same) {
        fprintf(stderr, "set %s=%s gave %s\n", key, value, buf);
        abort();
    }
    free(buf);
    dict_free(e);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct dict *d, *d2;
    log_set_quiet(1);
    if (dict_read_string((const char *)data, size, "fuzz/input", &d)
        != SIM_OK) {
        if (sim_error_message()[0] == '\0')
            abort(); /* every failure must say why */
        sim_error_clear();
        return 0;
    }
    size_t n1, n2;
    char *t1 = expand(d, &n1);
    if (dict_read_string(t1, n1, "fuzz/expanded", &d2) != SIM_OK) {
        fprintf(stderr, "expanded text does not parse: %s\n%s\n",
                sim_error_message(), t1);
        abort();
    }
    char *t2 = expand(d2, &n2);
    if (n1 != n2 || memcmp(t1, t2, n1) != 0) {
        fprintf(stderr, "expansion is not a fixed point:\n%s\n---\n%s\n", t1,
                t2);
        abort();
    }
    poke(d, 0);
    dict_warn_unused(d);
    check_set(data, size, d);
    free(t1);
    free(t2);
    dict_free(d2);
    dict_free(d);
    params_clear();
    return 0;
}
