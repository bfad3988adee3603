/*
 * test_surface_quadrant.c — the quadrant + column free-surface detector
 * (src/particles/operators/surface_quadrant.c): on a still tank (square
 * lattice, spacing 1, 40 x 20 water nodes inside one layer of wall nodes,
 * open top) exactly the top row of water is flagged (the E4-10 check at
 * t = 0), also with the water jittered by +-0.1 spacing; a drop (a disc
 * of water in the air) is flagged on its rim only, not in its interior;
 * walls given a facing direction occupy its quadrant (a surge's tip).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "particles/lattice.h"
#include "particles/neighbour.h"
#include "particles/operators/surface_quadrant.h"

static void tank(double jitter)
{
    const int nx = 40, ny = 20;
    int n = 0;
    double *x = calloc(3 * (size_t)(nx + 2) * (ny + 1), sizeof *x);
    uint8_t *water = calloc((size_t)(nx + 2) * (ny + 1), 1), *flag;
    int *top = calloc((size_t)(nx + 2) * (ny + 1), sizeof *top);
    for (int j = 0; j <= ny; j++)
        for (int i = 0; i <= nx + 1; i++) {
            int wall = j == 0 || i == 0 || i == nx + 1;
            x[3 * n] = i;
            x[3 * n + 1] = j;
            water[n] = !wall;
            top[n] = !wall && j == ny;
            n++;
        }
    double *jit = calloc(3 * (size_t)n, sizeof *jit);
    lattice_jitter(jit, (size_t)n, 2, jitter, 5);
    for (int a = 0; a < n; a++)
        if (water[a])
            for (int q = 0; q < 2; q++)
                x[3 * a + q] += jit[3 * a + q];
    flag = calloc((size_t)n, 1);
    struct neighbour_list nl = { 0 };
    assert_int_equal(neighbour_build_brute(&nl, 2, x, n, 2.5), 0);
    pop_surface_quadrant(&nl, x, 2.5, 0.4, water, NULL, NULL, flag);
    int wrong = 0, flagged = 0;
    for (int a = 0; a < n; a++) {
        if (!water[a])
            continue;
        flagged += flag[a];
        wrong += flag[a] != top[a];
    }
    print_message("jitter %.2f: %d flagged, %d wrong (top row %d)\n", jitter,
                  flagged, wrong, nx);
    assert_int_equal(wrong, 0);
    neighbour_free(&nl);
    free(x), free(water), free(flag), free(top), free(jit);
}

static void test_still_tank(void **state)
{
    (void)state;
    tank(0);
    tank(0.1);
}

static void test_drop(void **state)
{
    (void)state;
    double x[3 * 400];
    int n = 0;
    for (int j = -10; j <= 10; j++)
        for (int i = -10; i <= 10; i++)
            if (i * i + j * j <= 64) {
                x[3 * n] = i;
                x[3 * n + 1] = j;
                x[3 * n + 2] = 0;
                n++;
            }
    uint8_t flag[400];
    struct neighbour_list nl = { 0 };
    assert_int_equal(neighbour_build_brute(&nl, 2, x, n, 2.5), 0);
    pop_surface_quadrant(&nl, x, 2.5, 0.4, NULL, NULL, NULL, flag);
    for (int a = 0; a < n; a++) {
        double r = hypot(x[3 * a], x[3 * a + 1]);
        if (r < 6.5)
            assert_int_equal(flag[a], 0);
        if (r > 7.9)
            assert_int_equal(flag[a], 1);
    }
    neighbour_free(&nl);
}

/* The tip of a surge: two rows of water (x = 0..5, y = 1, 2) on a floor
 * of wall nodes (y = 0, x = -3..12). By position, the floor ahead of the
 * tip fills the tip's eastern quadrant (dx 1, dy -1 lies on the sector's
 * edge, dx 2, dy -1 inside it) and the bottom tip node is not on the
 * surface; with the floor facing down (its normal into the solid), it
 * occupies the southern quadrant and column only, and the bottom tip
 * node is on the surface, the nodes behind it not. */
static void test_facing_walls(void **state)
{
    (void)state;
    double x[3 * 64] = { 0 }, facing[3 * 64] = { 0 };
    uint8_t water[64] = { 0 }, flag[64];
    int n = 0, tip = -1, behind = -1;
    for (int i = -3; i <= 12; i++, n++) {
        x[3 * n] = i;
        facing[3 * n + 1] = -1;
    }
    for (int j = 1; j <= 2; j++)
        for (int i = 0; i <= 5; i++, n++) {
            x[3 * n] = i;
            x[3 * n + 1] = j;
            water[n] = 1;
            if (j == 1 && i == 5)
                tip = n;
            if (j == 1 && i == 2)
                behind = n;
        }
    struct neighbour_list nl = { 0 };
    assert_int_equal(neighbour_build_brute(&nl, 2, x, n, 2.5), 0);
    pop_surface_quadrant(&nl, x, 2.5, 0.4, water, NULL, NULL, flag);
    assert_int_equal(flag[tip], 0);
    pop_surface_quadrant(&nl, x, 2.5, 0.4, water, NULL, facing, flag);
    assert_int_equal(flag[tip], 1);
    assert_int_equal(flag[behind], 0);
    neighbour_free(&nl);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_still_tank),
        cmocka_unit_test(test_drop),
        cmocka_unit_test(test_facing_walls),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
