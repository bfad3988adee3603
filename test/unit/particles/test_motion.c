/*
 * test_motion.c — wall motions (src/particles/motion): displacement and
 * velocity of translation and table by hand, the removal time, and the
 * refusals of bad input with the entry's location.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/dict.h"
#include "core/error.h"
#include "particles/motion/motion.h"

static struct dict *parse(const char *text)
{
    struct dict *d = NULL;
    assert_int_equal(dict_read_string(text, strlen(text), "particleDict", &d),
                     SIM_OK);
    return d;
}

/* Read region `r` of text; returns the code. */
static int read_region(const char *text, int is_wall, int dim,
                       const char *dir, struct wall_motion *w)
{
    struct dict *d = parse(text);
    const struct dict *r;
    assert_int_equal(dict_get_dict(d, "r", &r), SIM_OK);
    int rc = wall_motion_read(r, is_wall, dim, dir, w);
    dict_free(d);
    return rc;
}

static void test_translation(void **state)
{
    (void)state;
    struct wall_motion w;
    assert_int_equal(read_region("r { motion { type translation; velocity "
                                 "(0 0.5 7); start 0.1; end 0.3; } }",
                                 1, 2, NULL, &w), SIM_OK);
    double d[3], v[3];
    wall_motion_displacement(&w, 0.05, d);
    assert_true(d[0] == 0 && d[1] == 0 && d[2] == 0);
    wall_motion_displacement(&w, 0.2, d);
    assert_float_equal(d[1], 0.05, 1e-15);
    assert_true(d[2] == 0);          /* 2-D: z dropped */
    wall_motion_displacement(&w, 1.0, d);
    assert_float_equal(d[1], 0.1, 1e-15);
    wall_motion_velocity(&w, 0.2, v);
    assert_true(v[1] == 0.5);
    wall_motion_velocity(&w, 0.3, v);
    assert_true(v[1] == 0);          /* at rest from end on */
    assert_true(wall_motion_moves(&w));
    assert_false(wall_motion_removed(&w, 1e9));
    wall_motion_free(&w);
}

static void test_table_and_removal(void **state)
{
    (void)state;
    char dir[] = "/tmp/test_motionXXXXXX", path[64];
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/m.csv", dir);
    FILE *f = fopen(path, "w");
    fputs("# gate\nt,x,y,z\n0, 0, 0, 0\n0.5 1 0 0\n1.5 1 2 0\n", f);
    fclose(f);
    struct wall_motion w;
    assert_int_equal(read_region("r { motion { type table; file \"m.csv\"; }"
                                 " removeAt 2; }", 1, 3, dir, &w), SIM_OK);
    double d[3], v[3];
    wall_motion_displacement(&w, 0.25, d);
    assert_float_equal(d[0], 0.5, 1e-15);
    wall_motion_displacement(&w, 1.0, d);
    assert_float_equal(d[0], 1.0, 1e-15);
    assert_float_equal(d[1], 1.0, 1e-15);
    wall_motion_displacement(&w, 5.0, d);
    assert_float_equal(d[1], 2.0, 1e-15);
    wall_motion_velocity(&w, 1.0, v);
    assert_float_equal(v[1], 2.0, 1e-15);
    wall_motion_velocity(&w, 1.5, v);
    assert_true(v[0] == 0 && v[1] == 0);
    assert_false(wall_motion_removed(&w, 1.999));
    assert_true(wall_motion_removed(&w, 2.0 - 1e-12)); /* accumulated t */
    wall_motion_free(&w);
    /* rows out of order, named by line in the file */
    f = fopen(path, "w");
    fputs("0 0 0 0\n0.5 1 0 0\n0.5 2 0 0\n", f);
    fclose(f);
    assert_int_equal(read_region("r { motion { type table; file \"m.csv\"; }"
                                 " }", 1, 3, dir, &w), SIM_ERR_DICT);
    assert_non_null(strstr(sim_error_message(), "m.csv:3: time 0.5 s"));
    unlink(path);
    rmdir(dir);
}

static void test_refusals(void **state)
{
    (void)state;
    struct wall_motion w;
    assert_int_equal(read_region("r { motion { type translatoin; } }", 1, 3,
                                 NULL, &w), SIM_ERR_DICT);
    assert_non_null(strstr(sim_error_message(), "did you mean "
                                                "'translation'"));
    assert_int_equal(read_region("r { removeAt -1; }", 1, 3, NULL, &w),
                     SIM_ERR_DICT);
    assert_non_null(strstr(sim_error_message(), "particleDict:1:"));
    assert_int_equal(read_region("r { removeAt 1; }", 0, 3, NULL, &w),
                     SIM_ERR_DICT);
    assert_non_null(strstr(sim_error_message(), "wall and tankWall"));
    /* the shape is the wall at t = 0 */
    assert_int_equal(read_region("r { motion { type translation; velocity "
                                 "(1 0 0); start -1; } }", 1, 3, NULL, &w),
                     SIM_ERR_DICT);
    assert_int_equal(read_region("r { }", 1, 3, NULL, &w), SIM_OK);
    assert_false(wall_motion_moves(&w));
    assert_true(isinf(w.remove_at));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_translation),
        cmocka_unit_test(test_table_and_removal),
        cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
