/*
 * dictTool — query, expand, check and edit case dictionaries, as OpenFOAM's
 * foamDictionary does; scripts (Allrun, tutorials/Alltest) and the
 * dictionary tests use it.
 *
 *   dictTool [-case DIR] FILE                 print FILE expanded
 *   dictTool FILE -entry a/b/c                print the value of a/b/c
 *   dictTool FILE -keys [-entry a/b]          list the keys (of a/b)
 *   dictTool FILE -set a/b/c=value [-set ...] edit the file in place
 *   dictTool FILE -new -set a/b/c=value       ... adding keys that are new
 *   dictTool FILE -check KEY:TYPE ...         read keys as a program would,
 *                                             then warn about unused ones
 *
 * TYPE for -check: scalar, label, bool, string, dict, list, vector:N,
 * dims:E1,...,E7 (a scalar with that dimension set), word:a,b,c (one of
 * these words) and model:a,b,c (selection through model_select); scalar?,
 * label?, bool?, string? and dict? read an optional key (with a default).
 *
 * Every -set is applied, in order, and the file written once. A key that
 * is not in the file is refused ("did you mean") unless -new is given: a
 * misspelt key must not become an entry nothing reads.
 *
 * FILE is relative to the case directory. Errors print a FATAL ERROR with
 * the file and line on stderr and exit 1; the file is never modified then.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "core/select.h"

#define MAX_CHECKS 64
#define MAX_SETS 64
#define MAX_NAMES 32

struct options {
    const char *case_dir, *file, *entry;
    int expand, keys, add_new;
    const char *checks[MAX_CHECKS];
    int nchecks;
    const char *sets[MAX_SETS];
    int nsets;
};

static void usage(FILE *f)
{
    fprintf(f, "Usage: dictTool [-case DIR] FILE [-entry a/b/c] "
               "[-set a/b/c=value]... [-new] [-expand] [-keys] "
               "[-check KEY:TYPE]...\n"
               "  -entry KEY    print the value of KEY (scoped a/b/c)\n"
               "  -keys         list the keys (of -entry's dictionary)\n"
               "  -expand       print the file with #include and $var "
               "resolved\n"
               "  -set KEY=VAL  replace the value of KEY in FILE, keeping "
               "comments;\n"
               "                may be repeated (applied in order, written "
               "once); a KEY\n"
               "                that is not in FILE is refused\n"
               "  -new          let -set add keys that are not in FILE "
               "(creating the\n"
               "                dictionaries on their path)\n"
               "  -check K:T    read K as type T (scalar label bool string "
               "dict list\n"
               "                vector:N dims:E1,..,E7 word:a,b model:a,b), "
               "then warn\n"
               "                about entries nothing read\n");
}

static int fatal(const char *msg)
{
    fflush(stdout);
    fprintf(stderr, "\n--> FATAL ERROR: %s\n\n", msg);
    return 1;
}

static int parse_args(int argc, char **argv, struct options *o)
{
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        int more = i + 1 < argc;
        if (strcmp(a, "-help") == 0 || strcmp(a, "--help") == 0) {
            usage(stdout);
            exit(0);
        } else if (strcmp(a, "-case") == 0 && more) {
            o->case_dir = argv[++i];
        } else if (strcmp(a, "-entry") == 0 && more) {
            o->entry = argv[++i];
        } else if (strcmp(a, "-set") == 0 && more) {
            if (o->nsets == MAX_SETS)
                return sim_error(SIM_ERR_INPUT, "too many -set options");
            o->sets[o->nsets++] = argv[++i];
        } else if (strcmp(a, "-new") == 0) {
            o->add_new = 1;
        } else if (strcmp(a, "-check") == 0 && more) {
            if (o->nchecks == MAX_CHECKS)
                return sim_error(SIM_ERR_INPUT, "too many -check options");
            o->checks[o->nchecks++] = argv[++i];
        } else if (strcmp(a, "-expand") == 0) {
            o->expand = 1;
        } else if (strcmp(a, "-keys") == 0) {
            o->keys = 1;
        } else if (a[0] == '-' && a[1]) {
            return sim_error(SIM_ERR_INPUT, "unknown option or missing "
                             "argument: '%s' (see dictTool -help)", a);
        } else if (!o->file) {
            o->file = a;
        } else {
            return sim_error(SIM_ERR_INPUT, "more than one FILE: '%s' and "
                             "'%s'", o->file, a);
        }
    }
    if (!o->file)
        return sim_error(SIM_ERR_INPUT, "no FILE given (see dictTool -help)");
    if (o->add_new && !o->nsets)
        return sim_error(SIM_ERR_INPUT, "-new is for -set (see dictTool "
                         "-help)");
    return SIM_OK;
}

/* "a,b,c" -> names[] (in buf) */
static int split_names(char *buf, const char **names, int max)
{
    int n = 0;
    for (char *s = strtok(buf, ","); s && n < max; s = strtok(NULL, ","))
        names[n++] = s;
    names[n] = NULL;
    return n;
}

static int check_model(const struct dict *d, const char *key, char *list)
{
    const char *names[MAX_NAMES + 1];
    struct model_head heads[MAX_NAMES];
    const void *table[MAX_NAMES + 1];
    int n = split_names(list, names, MAX_NAMES);
    for (int i = 0; i < n; i++) {
        heads[i].name = names[i];
        heads[i].reference = "";
        table[i] = &heads[i];
    }
    table[n] = NULL;
    const void *sel;
    TRY(model_select(d, key, "model", table, NULL, &sel));
    printf("%s %s\n", key, ((const struct model_head *)sel)->name);
    return SIM_OK;
}

/* KEY:TYPE? reads KEY with the _or getter, as a program with a default. */
static int check_optional(const struct dict *d, const char *key,
                          const char *type, const char *spec)
{
    if (strcmp(type, "scalar") == 0) {
        double x;
        TRY(dict_get_scalar_or(d, key, 0.0, &x));
        printf("%s %.17g\n", key, x);
    } else if (strcmp(type, "label") == 0) {
        long x;
        TRY(dict_get_label_or(d, key, 0, &x));
        printf("%s %ld\n", key, x);
    } else if (strcmp(type, "bool") == 0) {
        int x;
        TRY(dict_get_bool_or(d, key, 0, &x));
        printf("%s %s\n", key, x ? "true" : "false");
    } else if (strcmp(type, "string") == 0) {
        const char *s;
        TRY(dict_get_string_or(d, key, "", &s));
        printf("%s %s\n", key, s);
    } else if (strcmp(type, "dict") == 0) {
        const struct dict *sub;
        TRY(dict_find_dict(d, key, &sub));
        printf("%s %s\n", key, sub ? "{ ... }" : "absent");
    } else {
        return sim_error(SIM_ERR_INPUT, "-check '%s': an optional TYPE? is "
                         "one of scalar? label? bool? string? dict?", spec);
    }
    return SIM_OK;
}

static int check_one(const struct dict *d, const char *spec)
{
    char buf[1024];
    snprintf(buf, sizeof buf, "%s", spec);
    char *type = strchr(buf, ':');
    if (!type)
        return sim_error(SIM_ERR_INPUT, "-check '%s': expected KEY:TYPE",
                         spec);
    *type++ = '\0';
    const char *key = buf;
    char *arg = strchr(type, ':');
    if (arg)
        *arg++ = '\0';
    size_t nt = strlen(type);
    if (nt && type[nt - 1] == '?') { /* optional: read with a default */
        type[nt - 1] = '\0';
        return check_optional(d, key, type, spec);
    }
    if (strcmp(type, "scalar") == 0) {
        double x;
        TRY(dict_get_scalar(d, key, &x));
        printf("%s %.17g\n", key, x);
    } else if (strcmp(type, "dims") == 0 && arg) {
        int dims[7] = { 0 };
        if (sscanf(arg, "%d,%d,%d,%d,%d,%d,%d", &dims[0], &dims[1], &dims[2],
                   &dims[3], &dims[4], &dims[5], &dims[6]) != 7)
            return sim_error(SIM_ERR_INPUT, "-check '%s': dims needs 7 "
                             "exponents", spec);
        double x;
        TRY(dict_get_scalar_dim(d, key, dims, &x));
        printf("%s %.17g\n", key, x);
    } else if (strcmp(type, "label") == 0) {
        long x;
        TRY(dict_get_label(d, key, &x));
        printf("%s %ld\n", key, x);
    } else if (strcmp(type, "bool") == 0) {
        int x;
        TRY(dict_get_bool(d, key, &x));
        printf("%s %s\n", key, x ? "true" : "false");
    } else if (strcmp(type, "string") == 0) {
        const char *s;
        TRY(dict_get_string(d, key, &s));
        printf("%s %s\n", key, s);
    } else if (strcmp(type, "dict") == 0) {
        const struct dict *sub;
        TRY(dict_get_dict(d, key, &sub));
        printf("%s { %d entries }\n", key, dict_size(sub));
    } else if (strcmp(type, "list") == 0) {
        const struct dict_value *l;
        TRY(dict_get_list(d, key, &l));
        printf("%s (%d items)\n", key, dict_value_len(l));
    } else if (strcmp(type, "vector") == 0 && arg) {
        int n = atoi(arg);
        double v[64];
        if (n < 1 || n > 64)
            return sim_error(SIM_ERR_INPUT, "-check '%s': vector:N with "
                             "1 <= N <= 64", spec);
        TRY(dict_get_vector(d, key, n, v));
        printf("%s (", key);
        for (int i = 0; i < n; i++)
            printf(i ? " %.17g" : "%.17g", v[i]);
        printf(")\n");
    } else if (strcmp(type, "word") == 0 && arg) {
        const char *names[MAX_NAMES + 1];
        split_names(arg, names, MAX_NAMES);
        int idx;
        TRY(dict_get_word(d, key, names, &idx));
        printf("%s %s\n", key, names[idx]);
    } else if (strcmp(type, "model") == 0 && arg) {
        TRY(check_model(d, key, arg));
    } else {
        return sim_error(SIM_ERR_INPUT, "-check '%s': unknown TYPE (scalar "
                         "label bool string dict list vector:N dims:... "
                         "word:a,b model:a,b)", spec);
    }
    return SIM_OK;
}

static int print_entry(const struct dict *d, const char *key, int keys)
{
    if (key && !dict_has(d, key))
        return dict_error(d, key, SIM_ERR_DICT, "no entry '%s' in %s", key,
                          dict_file(d));
    if (!keys) { /* a sub-dictionary prints in braces */
        const struct dict_value *v;
        TRY(dict_get_value(d, key, &v));
        TRY(dict_write_value(v, stdout));
        putchar('\n');
        return SIM_OK;
    }
    const struct dict *sub = d;
    if (key && !dict_is_dict(d, key))
        return dict_error(d, key, SIM_ERR_DICT, "'%s' is not a dictionary: "
                          "it has no keys", key);
    if (key)
        TRY(dict_get_dict(d, key, &sub));
    for (int i = 0; i < dict_size(sub); i++)
        printf("%s\n", dict_key_at(sub, i));
    return SIM_OK;
}

static int run(const struct options *o)
{
    if (o->case_dir && chdir(o->case_dir) != 0)
        return sim_error(SIM_ERR_IO, "cannot use case directory '%s': %s",
                         o->case_dir, strerror(errno));
    if (o->nsets) {
        static char buf[MAX_SETS][4096];
        const char *keys[MAX_SETS], *values[MAX_SETS];
        for (int k = 0; k < o->nsets; k++) {
            snprintf(buf[k], sizeof buf[k], "%s", o->sets[k]);
            char *eq = strchr(buf[k], '=');
            if (!eq || eq == buf[k])
                return sim_error(SIM_ERR_INPUT, "-set '%s': expected "
                                 "KEY=VALUE", o->sets[k]);
            *eq = '\0';
            keys[k] = buf[k];
            values[k] = eq + 1;
        }
        return dict_set_entries_in_file(o->file, o->nsets, keys, values,
                                        o->add_new);
    }
    struct dict *d;
    TRY(dict_read(o->file, &d));
    int rc = SIM_OK;
    if (o->nchecks) {
        log_set_quiet(0);
        for (int i = 0; i < o->nchecks && rc == SIM_OK; i++)
            rc = check_one(d, o->checks[i]);
        if (rc == SIM_OK)
            dict_warn_unused(d);
    } else if (o->entry || o->keys) {
        rc = print_entry(d, o->entry, o->keys);
    } else {
        rc = dict_write_expanded(d, stdout);
    }
    dict_free(d);
    return rc;
}

int main(int argc, char **argv)
{
    struct options o = { 0 };
    int rc = parse_args(argc, argv, &o);
    if (rc == SIM_OK)
        rc = run(&o);
    if (rc != SIM_OK)
        return fatal(sim_error_message());
    if (fflush(stdout) != 0)
        return fatal(strerror(errno));
    return 0;
}
