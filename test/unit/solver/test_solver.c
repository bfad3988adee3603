/* test_solver.c — the run solver_main makes around a toy solver
 * (solver/solver.h): the order of the hooks (alone and coupled, which
 * doc/design.md §4 relies on), the .pvd on a restart, what a failed
 * exchange and a failed advance leave behind, and the relaxed start
 * (-relax T). Each run is a child
 * process: solver_main holds the case lock until exit, and stops a
 * failed run through app_fatal. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/error.h"
#include "solver/solver.h"

struct toy {
    struct solver sv;
    struct store store;     /* an empty cloud                      */
    int fail_before_step;   /* coupled: the exchange of this step fails */
    int fail_advance;       /* the advance of this step fails           */
};

static void trace(struct solver *sv, const char *fmt, ...)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/trace", sv->app.case_abs);
    FILE *f = fopen(path, "a");
    if (!f)
        return;
    va_list ap;
    va_start(ap, fmt);
    vfprintf(f, fmt, ap);
    va_end(ap);
    fputc(' ', f);
    fclose(f);
}

static int create(struct solver *sv)
{
    trace(sv, "create");
    return SIM_OK;
}

static int refresh_scene(struct solver *sv)
{
    struct toy *t = (struct toy *)sv;
    store_init(&t->store, "field of the toy cloud");
    sv->scene = (struct fo_scene){ .time = sv->rt.value, .dt = sv->rt.dt,
                                   .step = sv->rt.step, .dim = 3,
                                   .cloud_name = "toy", .store = &t->store,
                                   .spacing = 1 };
    return SIM_OK;
}

static int advance(struct solver *sv)
{
    struct toy *t = (struct toy *)sv;
    trace(sv, "advance(%s)", sv->rt.name);
    if (sv->rt.step == t->fail_advance)
        return sim_error(SIM_ERR_NUMERIC, "toy: advance failed");
    return SIM_OK;
}

static int write_toy(struct solver *sv, const char *dir)
{
    char path[4400];
    snprintf(path, sizeof path, "%s/toy.vtu", dir);
    FILE *f = fopen(path, "w");
    if (!f)
        return sim_error(SIM_ERR_IO, "%s: cannot write", path);
    fprintf(f, "%s\n", sv->rt.name);
    fclose(f);
    trace(sv, "write(%s)", strrchr(dir, '/') + 1);
    return SIM_OK;
}

static void stats(struct solver *sv) { trace(sv, "stats"); }

static int rest(struct solver *sv)
{
    trace(sv, "rest(%s)", sv->rt.name);
    return SIM_OK;
}

static int c_open(struct solver *sv) { trace(sv, "open"); return SIM_OK; }

static int c_before(struct solver *sv)
{
    struct toy *t = (struct toy *)sv;
    trace(sv, "before");
    if (sv->rt.step + 1 == t->fail_before_step)
        return sim_error(SIM_ERR_PEER, "toy: the peer left");
    return SIM_OK;
}

static int c_after(struct solver *sv) { trace(sv, "after"); return SIM_OK; }
static void c_finish(struct solver *sv) { trace(sv, "finish"); }
static void c_close(struct solver *sv, int rc) { trace(sv, "close(%d)", rc); }

static const struct solver_coupling toy_coupling = {
    .open = c_open, .before_step = c_before, .after_step = c_after,
    .finish = c_finish, .close = c_close,
};

static const struct fo_ops *const *const tables[] = { NULL };

static const struct solver_ops toy_ops = {
    .name = "toySolver", .description = "a solver that does nothing",
    .cloud = "toy", .peer_cloud = "peer", .create = create,
    .fo_tables = tables, .refresh_scene = refresh_scene,
    .advance = advance, .dump_failed_advance = 1, .write = write_toy,
    .stats = stats, .rest = rest, .coupling = &toy_coupling,
};

static char case_dir[64];

static void put(const char *rel, const char *text)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%s", case_dir, rel);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static char *get(const char *rel)
{
    static char buf[4096];
    char path[256];
    snprintf(path, sizeof path, "%s/%s", case_dir, rel);
    FILE *f = fopen(path, "r");
    buf[0] = '\0';
    if (!f)
        return buf;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = '\0';
    fclose(f);
    return buf;
}

static int exists(const char *rel)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%s", case_dir, rel);
    return access(path, F_OK) == 0;
}

static void make_dir(const char *rel)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%s", case_dir, rel);
    assert_int_equal(mkdir(path, 0755), 0);
}

static void new_case(const char *control)
{
    snprintf(case_dir, sizeof case_dir, "/tmp/test_solver.XXXXXX");
    assert_non_null(mkdtemp(case_dir));
    make_dir("system");
    put("system/controlDict", control);
}

/* Run toySolver on the case in a child (with -relax T when relax is not
 * NULL); its exit status. */
static int run_relax(int fail_before_step, int fail_advance,
                     const char *relax)
{
    fflush(NULL);
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        static struct toy t;
        t.fail_before_step = fail_before_step;
        t.fail_advance = fail_advance;
        if (!freopen("/dev/null", "w", stdout)
            || !freopen("/dev/null", "w", stderr))
            _exit(3);
        char *argv[] = { "toySolver", "-case", case_dir, "-relax",
                         (char *)relax, NULL };
        exit(solver_main(&toy_ops, &t.sv, relax ? 5 : 3, argv));
    }
    int st;
    assert_int_equal(waitpid(pid, &st, 0), pid);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static int run(int fail_before_step, int fail_advance)
{
    return run_relax(fail_before_step, fail_advance, NULL);
}

static void remove_case(void)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", case_dir);
    assert_int_equal(system(cmd), 0);
}

static const char *control =
    "startFrom latestTime;\nstartTime 0;\nendTime 0.3;\ndeltaT 0.1;\n"
    "writeControl adjustableRunTime;\nwriteInterval 0.1;\n"
    "writeFormat ascii;\n";

static void test_alone_and_restart(void **state)
{
    (void)state;
    new_case(control);
    make_dir("0");
    put("0/toy.vtu", "0\n");
    assert_int_equal(run(0, 0), 0);
    assert_string_equal(get("trace"),
                        "create advance(0.1) write(0.1) advance(0.2) "
                        "write(0.2) advance(0.3) write(0.3) stats ");
    /* A run killed before 0.3 was complete: the restart from 0.2 lists
     * every time once. */
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -r %s/0.3", case_dir);
    assert_int_equal(system(cmd), 0);
    put("trace", "");
    assert_int_equal(run(0, 0), 0);
    assert_string_equal(get("trace"), "create advance(0.3) write(0.3) stats ");
    const char *pvd = get("toy.pvd");
    const char *files[] = { "\"0/toy.vtu\"", "\"0.1/toy.vtu\"",
                            "\"0.2/toy.vtu\"", "\"0.3/toy.vtu\"" };
    for (int k = 0; k < 4; k++) {
        const char *p = strstr(pvd, files[k]);
        assert_non_null(p);
        assert_null(strstr(p + 1, files[k]));
    }
    remove_case();
}

static void test_coupled_order(void **state)
{
    (void)state;
    new_case(control);
    put("system/couplingDict", "coupled yes;\n");
    make_dir("0");
    put("0/toy.vtu", "0\n");
    put("0/peer.vtu", "0\n");
    assert_int_equal(run(0, 0), 0);
    assert_string_equal(get("trace"),
                        "create open before advance(0.1) after write(0.1) "
                        "before advance(0.2) after write(0.2) before "
                        "advance(0.3) after write(0.3) finish close(0) "
                        "stats ");
    remove_case();
}

/* The peer leaves before the third step: the state at 0.2 is complete
 * and goes to failed.0.2/, not into the .pvd; then the peer is told. */
static void test_coupled_failure(void **state)
{
    (void)state;
    new_case(control);
    put("system/couplingDict", "coupled yes;\n");
    make_dir("0");
    put("0/toy.vtu", "0\n");
    put("0/peer.vtu", "0\n");
    assert_int_equal(run(3, 0), 1);
    assert_string_equal(get("trace"),
                        "create open before advance(0.1) after write(0.1) "
                        "before advance(0.2) after write(0.2) before "
                        "write(failed.0.2) close(9) close(9) ");
    assert_true(exists("failed.0.2/toy.vtu"));
    assert_null(strstr(get("toy.pvd"), "failed"));
    remove_case();
}

/* A failed advance leaves the state reached in failed.<t>/. */
static void test_failed_advance(void **state)
{
    (void)state;
    new_case(control);
    make_dir("0");
    put("0/toy.vtu", "0\n");
    assert_int_equal(run(0, 2), 1);
    assert_string_equal(get("trace"), "create advance(0.1) write(0.1) "
                        "advance(0.2) write(failed.0.2) ");
    assert_true(exists("failed.0.2/toy.vtu"));
    assert_false(exists("0.2"));
    remove_case();
}

/* -relax 0.45: the program steps past endTime (0.3) from the start time
 * with no write, then writes the state at rest as the start time's cloud
 * (named 0 again) and stops; no .pvd, no other time directory. A coupled
 * case and a bad time are refused before any step. */
static void test_relax(void **state)
{
    (void)state;
    new_case(control);
    make_dir("0");
    put("0/toy.vtu", "lattice\n");
    assert_int_equal(run_relax(0, 0, "0.45"), 0);
    assert_string_equal(get("trace"),
                        "create rest(0) advance(0.1) advance(0.2) "
                        "advance(0.3) advance(0.4) advance(0.45) rest(0) "
                        "write(0) stats ");
    assert_string_equal(get("0/toy.vtu"), "0\n");
    assert_false(exists("0.1"));
    assert_false(exists("toy.pvd"));
    put("trace", "");
    assert_int_equal(run_relax(0, 0, "0.1s"), 1);
    assert_string_equal(get("trace"), "create ");
    put("trace", "");
    put("system/couplingDict", "coupled yes;\n");
    put("0/peer.vtu", "0\n");
    assert_int_equal(run_relax(0, 0, "1"), 1);
    assert_string_equal(get("trace"), "create ");
    assert_string_equal(get("0/toy.vtu"), "0\n");
    remove_case();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_alone_and_restart),
        cmocka_unit_test(test_coupled_order),
        cmocka_unit_test(test_coupled_failure),
        cmocka_unit_test(test_failed_advance),
        cmocka_unit_test(test_relax),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
