/* test_drag_reference.c — small-system reference data per drag law
 * (doc/design.md C12 level 2, LAMMPS force-style tests): 32 grains from a fixed
 * seed (porosity 0.35..1, diameter 0.5..5 mm, slips up to ~1 m/s in
 * water), the force of every registered law against the stored values in
 * drag_reference.dat, relative tolerance `epsilon` from that file.
 *
 * After an intended and reviewed change of a law, rewrite the file with
 *     MPSDEM_BLESS=1 build/test/models/coupling/test_drag_reference
 * A law without stored values fails until the file is blessed. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <libgen.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "coupling/drag/drag.h"

enum { N = 32 };
static double eps[N], d[N], V[N], u[3 * N], v[3 * N];
static const struct drag_fluid water = { 1000.0, 1.0e-3 };

static void make_grains(void)
{
    uint64_t s = 0x9e3779b97f4a7c15ull;
    for (int k = 0; k < N; k++) {
        double r[8];
        for (int q = 0; q < 8; q++) {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            r[q] = (s >> 11) * (1.0 / 9007199254740992.0);
        }
        eps[k] = k == 0 ? 1.0 : 0.35 + 0.65 * r[0];
        d[k] = 5e-4 * pow(10.0, r[1]);
        V[k] = M_PI * d[k] * d[k] * d[k] / 6;
        for (int c = 0; c < 3; c++) {
            u[3 * k + c] = r[2 + c] - 0.5;
            v[3 * k + c] = r[5 + c] - 0.5;
        }
    }
}

/* <repo>/test/models/coupling/drag_reference.dat from the executable's
 * place, <repo>/build/test/models/coupling/<exe> (or build-san). */
static void reference_path(char *out, size_t n)
{
    char exe[4096];
    ssize_t m = readlink("/proc/self/exe", exe, sizeof exe - 1);
    assert_true(m > 0);
    exe[m] = 0;
    char *dir = exe;
    for (int up = 0; up < 5; up++)
        dir = dirname(dir);
    snprintf(out, n, "%s/test/models/coupling/drag_reference.dat", dir);
}

static void bless(const char *path)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fprintf(f, "# drag forces [N] of 32 grains (test_drag_reference.c), "
               "water, per law: k Fx Fy Fz\nepsilon 1e-13\n");
    double F[3 * N];
    for (int m = 0; drag_table[m]; m++) {
        drag_table[m]->force_all(&water, N, eps, d, V, u, v, F);
        fprintf(f, "law %s\n", drag_table[m]->name);
        for (int k = 0; k < N; k++)
            fprintf(f, "%d %.17g %.17g %.17g\n", k, F[3 * k], F[3 * k + 1],
                    F[3 * k + 2]);
    }
    fclose(f);
    print_message("blessed %s\n", path);
}

static void test_reference(void **state)
{
    (void)state;
    char path[4200];
    make_grains();
    reference_path(path, sizeof path);
    const char *b = getenv("MPSDEM_BLESS");
    if (b && strcmp(b, "1") == 0) {
        bless(path);
        return;
    }
    FILE *f = fopen(path, "r");
    if (!f)
        fail_msg("cannot read %s", path);
    char line[512], name[128] = "";
    double epsilon = -1, F[3 * N];
    int checked[64] = { 0 }, law = -1, rows = 0;
    while (fgets(line, sizeof line, f)) {
        int k;
        double r[3];
        if (line[0] == '#')
            continue;
        if (sscanf(line, "epsilon %lf", &epsilon) == 1)
            continue;
        if (sscanf(line, "law %127s", name) == 1) {
            law = -1;
            for (int m = 0; drag_table[m]; m++)
                if (strcmp(drag_table[m]->name, name) == 0)
                    law = m;
            if (law < 0)
                fail_msg("%s: law '%s' is not registered any more", path,
                         name);
            drag_table[law]->force_all(&water, N, eps, d, V, u, v, F);
            checked[law] = 1;
            continue;
        }
        assert_int_equal(sscanf(line, "%d %lf %lf %lf", &k, r, r + 1, r + 2),
                         4);
        assert_true(law >= 0 && k >= 0 && k < N && epsilon > 0);
        double scale = fmax(fabs(r[0]), fmax(fabs(r[1]), fabs(r[2])));
        for (int c = 0; c < 3; c++)
            if (!(fabs(F[3 * k + c] - r[c]) <= epsilon * scale))
                fail_msg("%s grain %d component %d: %.17g, reference "
                         "%.17g", name, k, c, F[3 * k + c], r[c]);
        rows++;
    }
    fclose(f);
    for (int m = 0; drag_table[m]; m++)
        if (!checked[m])
            fail_msg("no reference for drag law %s: review, then run with "
                     "MPSDEM_BLESS=1", drag_table[m]->name);
    assert_true(rows > 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = { cmocka_unit_test(test_reference) };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
