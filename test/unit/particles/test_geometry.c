/*
 * test_geometry.c — analytic solids (src/particles/geometry.c): hand-worked
 * values for each primitive, and, on random points, the signed distance
 * against a brute-force minimum over a dense sampling of the surface, the
 * closest point on the surface at that distance, and the normal against a
 * finite-difference gradient of the distance.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "core/error.h"
#include "particles/geometry.h"

#define EPS 1e-12

static void assert_vec(const double a[3], double x, double y, double z,
                       double tol)
{
    if (fabs(a[0] - x) > tol || fabs(a[1] - y) > tol || fabs(a[2] - z) > tol)
        fail_msg("(%.17g %.17g %.17g) != (%g %g %g)", a[0], a[1], a[2], x, y,
                 z);
}

static void assert_close(double a, double b, double tol)
{
    if (fabs(a - b) > tol)
        fail_msg("%.17g != %.17g (tol %g)", a, b, tol);
}

static void test_box_values(void **state)
{
    struct geom g;
    double n[3], c[3];
    (void)state;
    assert_int_equal(geom_box(&g, 3, (double[]){ 0, 0, 0 },
                              (double[]){ 1, 2, 3 }), SIM_OK);
    assert_close(geom_distance(&g, (double[]){ 0.5, 1, 1.5 }), -0.5, EPS);
    assert_close(geom_distance(&g, (double[]){ 2, 1, 1.5 }), 1.0, EPS);
    assert_close(geom_distance(&g, (double[]){ 2, 3, 4 }), sqrt(3.0), EPS);
    assert_true(geom_inside(&g, (double[]){ 1, 2, 3 }));   /* corner */
    assert_false(geom_inside(&g, (double[]){ 1, 2, 3.0000001 }));
    geom_normal(&g, (double[]){ 2, 3, 4 }, n);
    assert_vec(n, 1 / sqrt(3.0), 1 / sqrt(3.0), 1 / sqrt(3.0), EPS);
    geom_closest(&g, (double[]){ 2, 3, 4 }, c);
    assert_vec(c, 1, 2, 3, EPS);
    geom_normal(&g, (double[]){ 0.1, 1, 1.5 }, n);
    assert_vec(n, -1, 0, 0, EPS);
    geom_closest(&g, (double[]){ 0.1, 1, 1.5 }, c);
    assert_vec(c, 0, 1, 1.5, EPS);
    /* Inside, equally close to two faces: the diagonal. */
    geom_normal(&g, (double[]){ 0.1, 0.1, 1.5 }, n);
    assert_vec(n, -sqrt(0.5), -sqrt(0.5), 0, EPS);
    /* On a face: the face normal, not NaN. */
    geom_normal(&g, (double[]){ 1, 1, 1.5 }, n);
    assert_vec(n, 1, 0, 0, EPS);
    assert_int_equal(geom_box(&g, 3, (double[]){ 0, 0, 0 },
                              (double[]){ 1, 0, 3 }), SIM_ERR_INPUT);
}

static void test_box_2d(void **state)
{
    struct geom g;
    double n[3], lo[3], hi[3];
    (void)state;
    /* z extents are ignored in 2-D, even an empty one. */
    assert_int_equal(geom_box(&g, 2, (double[]){ 0, 0, 5 },
                              (double[]){ 1, 2, 5 }), SIM_OK);
    assert_close(geom_distance(&g, (double[]){ 0.5, 1.5, 0 }), -0.5, EPS);
    assert_close(geom_distance(&g, (double[]){ 4, 6, 0 }), 5.0, EPS);
    geom_normal(&g, (double[]){ 4, 6, 0 }, n);
    assert_vec(n, 0.6, 0.8, 0, EPS);
    assert_int_equal(geom_bbox(&g, lo, hi), 1);
    assert_vec(lo, 0, 0, 0, 0);
    assert_vec(hi, 1, 2, 0, 0);
}

static void test_sphere_values(void **state)
{
    struct geom g;
    double n[3], c[3], lo[3], hi[3];
    (void)state;
    assert_int_equal(geom_sphere(&g, 3, (double[]){ 1, 1, 1 }, 2), SIM_OK);
    assert_close(geom_distance(&g, (double[]){ 1, 1, 1 }), -2, EPS);
    assert_close(geom_distance(&g, (double[]){ 1, 4, 5 }), 3, EPS);
    geom_normal(&g, (double[]){ 1, 4, 5 }, n);
    assert_vec(n, 0, 0.6, 0.8, EPS);
    geom_closest(&g, (double[]){ 1, 4, 5 }, c);
    assert_vec(c, 1, 2.2, 2.6, EPS);
    geom_normal(&g, (double[]){ 1, 1, 1 }, n); /* centre: any unit vector */
    assert_close(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1, EPS);
    assert_int_equal(geom_bbox(&g, lo, hi), 1);
    assert_vec(lo, -1, -1, -1, EPS);
    assert_vec(hi, 3, 3, 3, EPS);
    assert_int_equal(geom_sphere(&g, 3, (double[]){ 0, 0, 0 }, 0),
                     SIM_ERR_INPUT);
    /* 2-D: a circle, centre z ignored. */
    assert_int_equal(geom_sphere(&g, 2, (double[]){ 0, 0, 7 }, 1), SIM_OK);
    assert_close(geom_distance(&g, (double[]){ 3, 4, 0 }), 4, EPS);
}

static void test_cylinder_values(void **state)
{
    struct geom g;
    double n[3], c[3], lo[3], hi[3];
    (void)state;
    /* Along z from z = 0 to 2, radius 1. */
    assert_int_equal(geom_cylinder(&g, 3, (double[]){ 0, 0, 0 },
                                   (double[]){ 0, 0, 2 }, 1), SIM_OK);
    assert_close(geom_distance(&g, (double[]){ 0, 0, 1 }), -1, EPS);
    assert_close(geom_distance(&g, (double[]){ 0.5, 0, 1.9 }), -0.1, EPS);
    assert_close(geom_distance(&g, (double[]){ 3, 0, 1 }), 2, EPS);
    assert_close(geom_distance(&g, (double[]){ 0.2, 0, 5 }), 3, EPS);
    assert_close(geom_distance(&g, (double[]){ 4, 0, 6 }), 5, EPS); /* rim */
    geom_normal(&g, (double[]){ 4, 0, 6 }, n);
    assert_vec(n, 0.6, 0, 0.8, EPS);
    geom_normal(&g, (double[]){ 0.5, 0, 1.9 }, n);
    assert_vec(n, 0, 0, 1, EPS);
    geom_normal(&g, (double[]){ 0, 0.8, 1 }, n);
    assert_vec(n, 0, 1, 0, EPS);
    geom_closest(&g, (double[]){ 0, 0.8, 1 }, c);
    assert_vec(c, 0, 1, 1, EPS);
    geom_closest(&g, (double[]){ 0.3, 0, -0.1 }, c);
    assert_vec(c, 0.3, 0, 0, EPS);
    geom_closest(&g, (double[]){ 0.3, 0, 0.1 }, c);
    assert_vec(c, 0.3, 0, 0, EPS);
    assert_int_equal(geom_bbox(&g, lo, hi), 1);
    assert_vec(lo, -1, -1, 0, EPS);
    assert_vec(hi, 1, 1, 2, EPS);
    assert_int_equal(geom_cylinder(&g, 3, (double[]){ 1, 1, 1 },
                                   (double[]){ 1, 1, 1 }, 1), SIM_ERR_INPUT);
    /* 2-D: along z a circle; in-plane a rectangle; oblique an error. */
    assert_int_equal(geom_cylinder(&g, 2, (double[]){ 1, 0, -1 },
                                   (double[]){ 1, 0, 1 }, 1), SIM_OK);
    assert_int_equal(g.shape, GEOM_SPHERE);
    assert_close(geom_distance(&g, (double[]){ 4, 0, 0 }), 2, EPS);
    assert_int_equal(geom_cylinder(&g, 2, (double[]){ 0, 0, 0 },
                                   (double[]){ 2, 0, 0 }, 0.5), SIM_OK);
    assert_close(geom_distance(&g, (double[]){ 1, 0.2, 0 }), -0.3, EPS);
    assert_close(geom_distance(&g, (double[]){ 3, 0, 0 }), 1, EPS);
    assert_int_equal(geom_cylinder(&g, 2, (double[]){ 0, 0, 0 },
                                   (double[]){ 1, 0, 1 }, 0.5),
                     SIM_ERR_INPUT);
}

static void test_halfspace_values(void **state)
{
    struct geom g;
    double n[3], c[3], lo[3], hi[3];
    (void)state;
    assert_int_equal(geom_halfspace(&g, 3, (double[]){ 0, 0, 1 },
                                    (double[]){ 0, 0, 2 }), SIM_OK);
    assert_close(geom_distance(&g, (double[]){ 5, -3, 0.25 }), -0.75, EPS);
    geom_normal(&g, (double[]){ 5, -3, 0.25 }, n);
    assert_vec(n, 0, 0, 1, EPS);
    geom_closest(&g, (double[]){ 5, -3, 0.25 }, c);
    assert_vec(c, 5, -3, 1, EPS);
    assert_int_equal(geom_bbox(&g, lo, hi), 0);
    assert_true(hi[2] == 1 && isinf(lo[2]) && isinf(hi[0]));
    /* Sloping: normal (-1, 1) in 2-D, solid below the line y = x. */
    assert_int_equal(geom_halfspace(&g, 2, (double[]){ 0, 0, 0 },
                                    (double[]){ -1, 1, 9 }), SIM_OK);
    assert_close(geom_distance(&g, (double[]){ 1, 0, 0 }), -sqrt(0.5), EPS);
    assert_int_equal(geom_halfspace(&g, 2, (double[]){ 0, 0, 0 },
                                    (double[]){ 0, 0, 1 }), SIM_ERR_INPUT);
}

/* ---- property tests against brute force ------------------------------------ */

static double urand(double a, double b)
{
    return a + (b - a) * (double)rand() / RAND_MAX;
}

/* Dense samples of the surface of g (box, sphere, cylinder; 3-D). */
static int sample_surface(const struct geom *g, double (*s)[3], int max)
{
    int n = 0, m = 60;
    for (int a = 0; a <= m; a++)
        for (int b = 0; b <= m; b++) {
            double u = (double)a / m, v = (double)b / m;
            if (g->shape == GEOM_BOX) {
                for (int f = 0; f < 6 && n < max; f++) {
                    int ax = f / 2, a1 = (ax + 1) % 3, a2 = (ax + 2) % 3;
                    s[n][ax] = f % 2 ? g->hi[ax] : g->lo[ax];
                    s[n][a1] = g->lo[a1] + u * (g->hi[a1] - g->lo[a1]);
                    s[n][a2] = g->lo[a2] + v * (g->hi[a2] - g->lo[a2]);
                    n++;
                }
            } else if (g->shape == GEOM_SPHERE && n < max) {
                double th = M_PI * u, ph = 2 * M_PI * v;
                s[n][0] = g->p[0] + g->radius * sin(th) * cos(ph);
                s[n][1] = g->p[1] + g->radius * sin(th) * sin(ph);
                s[n][2] = g->p[2] + g->radius * cos(th);
                n++;
            } else if (g->shape == GEOM_CYLINDER) {
                /* Mantle (t, phi) and both caps (rho, phi). */
                double e1[3], e2[3], *a = (double *)g->axis;
                double t0[3] = { 1, 0, 0 };
                if (fabs(a[0]) > 0.9) { t0[0] = 0; t0[1] = 1; }
                e1[0] = a[1] * t0[2] - a[2] * t0[1];
                e1[1] = a[2] * t0[0] - a[0] * t0[2];
                e1[2] = a[0] * t0[1] - a[1] * t0[0];
                double l = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
                for (int i = 0; i < 3; i++) e1[i] /= l;
                e2[0] = a[1] * e1[2] - a[2] * e1[1];
                e2[1] = a[2] * e1[0] - a[0] * e1[2];
                e2[2] = a[0] * e1[1] - a[1] * e1[0];
                double ph = 2 * M_PI * v;
                for (int part = 0; part < 3 && n < max; part++) {
                    double t = part == 0 ? u * g->length
                                         : (part == 1 ? 0 : g->length);
                    double r = part == 0 ? g->radius : u * g->radius;
                    for (int i = 0; i < 3; i++)
                        s[n][i] = g->p[i] + t * a[i] +
                                  r * (cos(ph) * e1[i] + sin(ph) * e2[i]);
                    n++;
                }
            }
        }
    return n;
}

static void check_shape(const struct geom *g, double spread)
{
    static double s[6 * 61 * 61][3];
    int ns = sample_surface(g, s, 6 * 61 * 61);
    double lo[3], hi[3];
    assert_true(ns > 1000);
    assert_int_equal(geom_bbox(g, lo, hi), 1);
    for (int k = 0; k < ns; k++) {
        /* Samples lie on the surface and inside the bounding box. */
        assert_close(geom_distance(g, s[k]), 0, 1e-12 * spread);
        for (int i = 0; i < 3; i++)
            assert_true(s[k][i] >= lo[i] - 1e-12 && s[k][i] <= hi[i] + 1e-12);
    }
    for (int trial = 0; trial < 300; trial++) {
        double x[3], c[3], n[3], d, dmin = HUGE_VAL, h = 1e-6;
        for (int i = 0; i < 3; i++)
            x[i] = urand(lo[i] - spread, hi[i] + spread);
        d = geom_distance(g, x);
        for (int k = 0; k < ns; k++) {
            double r = hypot(hypot(x[0] - s[k][0], x[1] - s[k][1]),
                             x[2] - s[k][2]);
            dmin = fmin(dmin, r);
        }
        /* |d| is the distance to the surface: no sample is closer, and
         * the sampling (step ~ size/60) finds one nearly as close. */
        assert_true(fabs(d) <= dmin + 1e-12);
        assert_true(dmin - fabs(d) <= 0.05 * spread);
        geom_closest(g, x, c);
        assert_close(geom_distance(g, c), 0, 1e-12 * spread);
        assert_close(hypot(hypot(x[0] - c[0], x[1] - c[1]), x[2] - c[2]),
                     fabs(d), 1e-10 * spread);
        geom_normal(g, x, n);
        assert_close(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1, 1e-12);
        for (int i = 0; i < 3; i++) /* x = c + d n */
            assert_close(x[i], c[i] + d * n[i], 1e-9 * spread);
        for (int i = 0; i < 3; i++) { /* n = grad d away from ridges */
            double xp[3] = { x[0], x[1], x[2] }, xm[3] = { x[0], x[1], x[2] };
            xp[i] += h;
            xm[i] -= h;
            double gi = (geom_distance(g, xp) - geom_distance(g, xm)) / (2 * h);
            if (fabs(gi - n[i]) > 1e-5) {
                /* Only where the closest point is not unique (medial
                 * surface of the inside): check we are on such a ridge. */
                assert_true(d < 0);
            }
        }
    }
}

static void test_properties(void **state)
{
    struct geom g;
    (void)state;
    srand(12345);
    assert_int_equal(geom_box(&g, 3, (double[]){ -1, 0, 2 },
                              (double[]){ 0.5, 3, 2.5 }), SIM_OK);
    check_shape(&g, 1.0);
    assert_int_equal(geom_sphere(&g, 3, (double[]){ 0.3, -0.2, 1 }, 0.7),
                     SIM_OK);
    check_shape(&g, 1.0);
    assert_int_equal(geom_cylinder(&g, 3, (double[]){ 0.1, 0.2, 0.3 },
                                   (double[]){ 1.1, -0.8, 1.0 }, 0.4), SIM_OK);
    check_shape(&g, 1.0);
    assert_int_equal(geom_cylinder(&g, 3, (double[]){ 0, 0, 0 },
                                   (double[]){ 2, 0, 0 }, 0.25), SIM_OK);
    check_shape(&g, 0.5);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_box_values),
        cmocka_unit_test(test_box_2d),
        cmocka_unit_test(test_sphere_values),
        cmocka_unit_test(test_cylinder_values),
        cmocka_unit_test(test_halfspace_values),
        cmocka_unit_test(test_properties),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
