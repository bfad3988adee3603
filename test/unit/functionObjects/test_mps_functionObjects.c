/* test_mps_functionObjects.c — the MPS function objects (probes,
 * waveGauges, front, forces, volume) on synthetic clouds with known
 * answers, through fo_list_create/fo_list_execute and their output files.
 *
 * The 2-D scene: a hydrostatic tank on a lattice of spacing dp = 1/64 m
 * (binary-exact coordinates, so that ties and column edges are exact).
 *   fluid   columns i = 1..W, layers j = 1..H at (i dp, j dp), surface
 *           h = (H + 1/2) dp, p = rho g (h - y); a bump of two extra
 *           layers on column 7; one splash particle (n/n0 = 0.1) at
 *           ((W+2) dp, 15 dp); top layers n/n0 = 0.7, others 1
 *   walls   bottom (patch 0) j = 0, i = 0..W+6, normal (0 -1 0);
 *           left (patch 1) i = 0, right (patch 2) i = W+6, j = 1..H+5,
 *           normals (-1 0 0), (1 0 0); two dummy layers behind each,
 *           carrying a wrong pressure (they must never be used)
 *   dry     x > (W + 1/2) dp: p = 0
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "functionObjects/functionObject.h"
#include "functionObjects/mps_functionObjects.h"

#define DP 0.015625
#define W 10
#define H 20
#define RHO 1000.0
#define G 9.81
#define HS ((H + 0.5) * DP)
#define DUMMY_P 12345.0

static char tmpdir[64];

/* ---- a cloud with the fields of the contract ------------------------- */

struct cloud {
    size_t n, cap;
    double *x, *p, *u, *nrm, *nd;
    int32_t *type, *patch;
    uint8_t *fs;
    int64_t *id;
    struct vtu_field f[10];
    struct vtu_cloud c;
    struct store st;   /* what the function objects look fields up in */
};

static void grow(struct cloud *c)
{
    c->cap = c->cap ? 2 * c->cap : 256;
    c->x = realloc(c->x, 3 * c->cap * sizeof *c->x);
    c->u = realloc(c->u, 3 * c->cap * sizeof *c->u);
    c->nrm = realloc(c->nrm, 3 * c->cap * sizeof *c->nrm);
    c->p = realloc(c->p, c->cap * sizeof *c->p);
    c->nd = realloc(c->nd, c->cap * sizeof *c->nd);
    c->type = realloc(c->type, c->cap * sizeof *c->type);
    c->patch = realloc(c->patch, c->cap * sizeof *c->patch);
    c->fs = realloc(c->fs, c->cap * sizeof *c->fs);
    c->id = realloc(c->id, c->cap * sizeof *c->id);
    assert_non_null(c->x && c->u && c->nrm && c->p && c->nd && c->type
                    && c->patch && c->fs && c->id);
}

static void add(struct cloud *c, const double x[3], int type, int patch,
                const double nrm[3], double p, double nd)
{
    if (c->n == c->cap)
        grow(c);
    size_t i = c->n++;
    for (int k = 0; k < 3; k++) {
        c->x[3 * i + k] = x[k];
        c->u[3 * i + k] = 0;
        c->nrm[3 * i + k] = nrm[k];
    }
    c->p[i] = p;
    c->nd[i] = nd;
    c->type[i] = type;
    c->patch[i] = patch;
    c->fs[i] = nd < 0.9;
    c->id[i] = (int64_t)i;
}

static void set_field(struct vtu_field *f, const char *name,
                      enum vtu_type t, int ncomp, void *data)
{
    memset(f, 0, sizeof *f);
    snprintf(f->name, sizeof f->name, "%s", name);
    f->type = t;
    f->ncomp = ncomp;
    f->data = data;
}

/* The registry of the cloud's fields, as a solver's (particles/store.h). */
static void views(struct cloud *c)
{
    store_init(&c->st, "field of the fluid cloud");
    assert_int_equal(store_view_cloud(&c->st, &c->c), SIM_OK);
}

/* Point the vtu view at the arrays (again, after they moved). */
static void publish(struct cloud *c)
{
    set_field(&c->f[0], "type", VTU_INT32, 1, c->type);
    set_field(&c->f[1], "patch", VTU_INT32, 1, c->patch);
    set_field(&c->f[2], "pressure", VTU_FLOAT64, 1, c->p);
    set_field(&c->f[3], "velocity", VTU_FLOAT64, 3, c->u);
    set_field(&c->f[4], "normal", VTU_FLOAT64, 3, c->nrm);
    set_field(&c->f[5], "numberDensity", VTU_FLOAT64, 1, c->nd);
    set_field(&c->f[6], "freeSurface", VTU_UINT8, 1, c->fs);
    set_field(&c->f[7], "id", VTU_INT64, 1, c->id);
    c->c.n = c->n;
    c->c.points = c->x;
    c->c.nfields = 8;
    c->c.fields = c->f;
    views(c);
}

static void cloud_free(struct cloud *c)
{
    free(c->x); free(c->u); free(c->nrm); free(c->p); free(c->nd);
    free(c->type); free(c->patch); free(c->fs); free(c->id);
    memset(c, 0, sizeof *c);
}

static double hydro(double x, double y)
{
    return x > (W + 0.5) * DP || y > HS ? 0 : RHO * G * (HS - y);
}

static void add_wall(struct cloud *c, double i, double j, int patch,
                     const double nrm[3], int layers)
{
    double x[3] = {i * DP, j * DP, 0};
    add(c, x, 1, patch, nrm, hydro(x[0], x[1]), 1);
    for (int l = 1; l <= layers; l++) {
        double d[3] = {x[0] + l * DP * nrm[0], x[1] + l * DP * nrm[1], 0};
        add(c, d, 2, patch, nrm, DUMMY_P, 1);
    }
}

static void build_tank(struct cloud *c)
{
    static const double down[3] = {0, -1, 0}, left[3] = {-1, 0, 0},
                        right[3] = {1, 0, 0};
    memset(c, 0, sizeof *c);
    for (int i = 0; i <= W + 6; i++)
        add_wall(c, i, 0, 0, down, 2);
    for (int j = 1; j <= H + 5; j++) {
        add_wall(c, 0, j, 1, left, 2);
        add_wall(c, W + 6, j, 2, right, 2);
    }
    for (int i = 1; i <= W; i++)
        for (int j = 1; j <= H + (i == 7 ? 2 : 0); j++) {
            double x[3] = {i * DP, j * DP, 0}, z[3] = {0, 0, 0};
            add(c, x, 0, -1, z, hydro(x[0], x[1]), j >= H ? 0.7 : 1.0);
        }
    double s[3] = {(W + 2) * DP, 15 * DP, 0}, z[3] = {0, 0, 0};
    add(c, s, 0, -1, z, 0, 0.1);
    publish(c);
}

/* Reverse the particle order into freshly allocated arrays (the solver's
 * renumbering): results must not change. */
static void renumber(struct cloud *c)
{
    struct cloud r;
    memset(&r, 0, sizeof r);
    for (size_t k = c->n; k-- > 0;) {
        add(&r, c->x + 3 * k, c->type[k], c->patch[k], c->nrm + 3 * k,
            c->p[k], c->nd[k]);
        r.id[r.n - 1] = c->id[k];
    }
    cloud_free(c);
    *c = r;
    publish(c);
}

static const char *const patch_names[] = {"bottom", "left", "right"};
static const struct fo_ops *const *const tables[] = {fo_generic_table,
                                                     mps_fo_table, NULL};

static void make_scene(struct fo_scene *s, struct cloud *c)
{
    memset(s, 0, sizeof *s);
    s->store = &c->st;
    s->cloud_name = "fluid";
    s->dim = 2;
    s->dt = 1e-3;
    s->spacing = DP;
    s->patch_names = patch_names;
    s->npatches = 3;
}

/* ---- output files ----------------------------------------------------- */

static int setup(void **state)
{
    (void)state;
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mpsdem_mpsfo_XXXXXX");
    return mkdtemp(tmpdir) ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    return system(cmd);
}

/* The "# time ..." header line, the number of data rows and the values
 * of the last row of postProcessing/<name>/0/<file>.dat. */
static int read_output(const char *name, const char *file, char *cols,
                       size_t ncols, double *v, int nv, int *rows)
{
    char path[256], line[2048];
    snprintf(path, sizeof path, "%s/postProcessing/%s/0/%s.dat", tmpdir,
             name, file);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    int n = 0;
    *rows = 0;
    cols[0] = '\0';
    while (fgets(line, sizeof line, f)) {
        if (!strncmp(line, "# time", 6)) {
            size_t m = strlen(line) < ncols ? strlen(line) : ncols - 1;
            memcpy(cols, line, m);
            cols[m] = '\0';
        }
        if (line[0] == '#')
            continue;
        ++*rows;
        n = 0;
        char *p = line, *end;
        while (n < nv) {
            double x = strtod(p, &end);
            if (end == p)
                break;
            v[n++] = x;
            p = end;
        }
    }
    fclose(f);
    return n;
}

/* What changes in the cloud before step k (NULL: nothing). */
typedef void (*before_fn)(int k, struct fo_scene *s, struct cloud *c);

static void renumber_last(int k, struct fo_scene *s, struct cloud *c)
{
    if (k == 2) {
        renumber(c);
        s->store = &c->st;
    }
}

/* Create the functions of `text`, execute them at times 0, 0.1, ...,
 * calling `before` ahead of each step, and free them. */
static void run(const char *text, struct fo_scene *s, struct cloud *c,
                int nsteps, before_fn before)
{
    struct dict *d;
    const struct dict *fd;
    struct fo_list *l;
    assert_int_equal(dict_read_string(text, strlen(text), "controlDict", &d),
                     SIM_OK);
    assert_int_equal(dict_get_dict(d, "functions", &fd), SIM_OK);
    int rc = fo_list_create(fd, tables, s, tmpdir, 0.0, 6, &l);
    if (rc != SIM_OK)
        fprintf(stderr, "%s\n", sim_error_message());
    assert_int_equal(rc, SIM_OK);
    for (int k = 0; k < nsteps; k++) {
        if (before)
            before(k, s, c);
        s->step = k;
        s->time = 0.1 * k;
        assert_int_equal(fo_list_execute(l, s, 0), SIM_OK);
    }
    fo_list_free(l);
    assert_int_equal(dict_warn_unused(d), 0);
    dict_free(d);
}

static double p_at(double y) { return RHO * G * (HS - y); }

#define assert_close(a, b, tol)                                          \
    do {                                                                 \
        double a_ = (a), b_ = (b);                                       \
        if (!(fabs(a_ - b_) <= (tol))) {                                 \
            print_error("%s = %.17g, expected %.17g (tol %g)\n", #a, a_, \
                        b_, (double)(tol));                              \
            fail();                                                      \
        }                                                                \
    } while (0)

/* ---- probes ------------------------------------------------------------ */

static void test_probes(void **state)
{
    (void)state;
    struct cloud c;
    struct fo_scene s;
    build_tank(&c);
    make_scene(&s, &c);
    char text[2048];
    snprintf(text, sizeof text,
             "functions {\n"
             "  sh { type probes; probeLocations ((%.17g %.17g 0) "
             "(%.17g %.17g 0) (%.17g %.17g 0) (0 %.17g 0) (1 1 0)); }\n"
             "  nw { type probes; interpolation nearestWall; probeLocations "
             "((%.17g %.17g) (%.17g %.17g 0) (%.17g %.17g)); }\n"
             "}\n",
             5 * DP, 8 * DP, 5.3 * DP, 8 * DP, 5 * DP, 8.4 * DP, 5 * DP,
             0.3 * DP, 5.2 * DP, 0.4 * DP, 5.5 * DP, 5 * DP, 8 * DP);
    long warn0 = log_warning_count();
    run(text, &s, &c, 3, renumber_last);
    assert_int_equal(log_warning_count() - warn0, 2); /* once per dry probe */

    char cols[256];
    double v[8];
    int rows;
    assert_int_equal(read_output("sh", "probes", cols, sizeof cols, v, 8,
                                 &rows), 6);
    assert_int_equal(rows, 3);
    assert_string_equal(cols, "# time p0 p1 p2 p3 p4\n");
    double tol = 1e-12 * p_at(0);
    assert_close(v[0], 0.2, 1e-15);
    /* Particles in reach symmetric about the point in y, p linear in y:
     * the Shepard average is exact. */
    assert_close(v[1], p_at(8 * DP), tol);
    assert_close(v[2], p_at(8 * DP), tol);
    /* Asymmetric reach: within |grad p| R, R = 2.1 dp. */
    assert_close(v[3], p_at(8.4 * DP), RHO * G * 2.1 * DP);
    /* On the left wall: wall and fluid particles, never the dummies. */
    assert_close(v[4], p_at(5 * DP), tol);
    assert_true(isnan(v[5]));

    assert_int_equal(read_output("nw", "probes", cols, sizeof cols, v, 8,
                                 &rows), 4);
    assert_string_equal(cols, "# time p0 p1 p2\n");
    assert_true(v[1] == p_at(5 * DP));
    /* Equidistant from the wall particles at 5 dp and 6 dp: the smaller id
     * (5 dp) wins, also after the particle order was reversed. */
    assert_true(v[2] == p_at(5 * DP));
    assert_true(isnan(v[3])); /* no wall particle within 2.1 dp */
    cloud_free(&c);
}

/* field U: Shepard average of the fluid velocity only. Fluid particles
 * carry u = (2 y, -x, 0), walls and dummies 99 in x. */
static void test_probes_velocity(void **state)
{
    (void)state;
    struct cloud c;
    struct fo_scene s;
    build_tank(&c);
    for (size_t i = 0; i < c.n; i++) {
        const double *x = c.x + 3 * i;
        c.u[3 * i] = c.type[i] == 0 ? 2 * x[1] : 99;
        c.u[3 * i + 1] = c.type[i] == 0 ? -x[0] : 0;
    }
    make_scene(&s, &c);
    char text[1024];
    snprintf(text, sizeof text,
             "functions {\n"
             "  v { type probes; field U; probeLocations ((%.17g %.17g) "
             "(%.17g %.17g) (%.17g %.17g) (1 1)); }\n"
             "}\n",
             5 * DP, 8 * DP, 1 * DP, 8 * DP, 5.3 * DP, 8 * DP);
    long warn0 = log_warning_count();
    run(text, &s, &c, 2, NULL);
    assert_int_equal(log_warning_count() - warn0, 1); /* the dry probe */
    char cols[256];
    double v[16];
    int rows;
    assert_int_equal(read_output("v", "probes", cols, sizeof cols, v, 16,
                                 &rows), 13);
    assert_string_equal(cols, "# time Ux0 Uy0 Uz0 Ux1 Uy1 Uz1 Ux2 Uy2 Uz2 "
                              "Ux3 Uy3 Uz3\n");
    /* Symmetric reach about the point: a linear field is exact. */
    assert_close(v[1], 2 * 8 * DP, 1e-14);
    assert_close(v[2], -5 * DP, 1e-14);
    assert_close(v[3], 0, 0);
    /* Beside the left wall: the wall's 99 is not averaged in, and the
     * fluid in reach is symmetric in y (x is one-sided). */
    assert_close(v[4], 2 * 8 * DP, 1e-14);
    assert_true(v[5] < -DP && v[5] > -3.1 * DP);
    /* Asymmetric in x: u_x = 2 y still exact, u_y within |grad| R. */
    assert_close(v[7], 2 * 8 * DP, 1e-14);
    assert_close(v[8], -5.3 * DP, 2.1 * DP);
    assert_true(isnan(v[10]) && isnan(v[11]) && isnan(v[12]));
    cloud_free(&c);
}

/* ---- wave gauges ------------------------------------------------------- */

static void test_wave_gauges(void **state)
{
    (void)state;
    struct cloud c;
    struct fo_scene s;
    build_tank(&c);
    make_scene(&s, &c);
    char text[2048];
    snprintf(text, sizeof text,
             "functions {\n"
             "  g1 { type waveGauges; gaugeLocations ((%.17g) (%.17g 0) "
             "(%.17g) (%.17g) (%.17g) (%.17g) (1)); }\n"
             "  g2 { type waveGauges; gaugeLocations (%.17g %.17g); "
             "halfWidth 2; minNumberDensity 0.05; }\n"
             "}\n",
             3.5 * DP, 6.5 * DP, 5.5 * DP, (W + 2.5) * DP, (W + 4.5) * DP,
             (W + 5.5) * DP, (W + 2.5) * DP, 5.5 * DP);
    long warn0 = log_warning_count();
    run(text, &s, &c, 3, renumber_last);
    assert_int_equal(log_warning_count() - warn0, 1);

    char cols[256];
    double v[8];
    int rows;
    assert_int_equal(read_output("g1", "waveGauges", cols, sizeof cols, v, 8,
                                 &rows), 8);
    assert_string_equal(cols, "# time eta0 eta1 eta2 eta3 eta4 eta5 eta6\n");
    double tol = 1e-15;
    assert_close(v[1], HS, tol);                 /* top layer + dp/2     */
    assert_close(v[2], (H + 2.5) * DP, tol);     /* the bump, column 7   */
    assert_close(v[3], HS, tol);                 /* bump out of reach    */
    assert_close(v[4], 0.5 * DP, tol);           /* splash ignored: dry  */
    assert_close(v[5], 0.5 * DP, tol);           /* dry: floor + dp/2    */
    assert_close(v[6], 0.5 * DP, tol);           /* side wall is no floor */
    assert_true(isnan(v[7]));                    /* outside the tank     */

    assert_int_equal(read_output("g2", "waveGauges", cols, sizeof cols, v, 8,
                                 &rows), 3);
    assert_close(v[1], 15.5 * DP, tol);          /* splash counted       */
    assert_close(v[2], (H + 2.5) * DP, tol);     /* wider column         */
    cloud_free(&c);
}

/* ---- front ------------------------------------------------------------- */

static void test_front(void **state)
{
    (void)state;
    struct cloud c;
    struct fo_scene s;
    build_tank(&c);
    make_scene(&s, &c);
    char text[2048];
    snprintf(text, sizeof text,
             "functions {\n"
             "  f1 { type front; }\n"
             "  f2 { type front; direction (2 0 0); origin (%.17g 0 0); "
             "referenceLength 0.05; gravity 9.81; }\n"
             "  f3 { type front; direction (0 1 0); }\n"
             "  f4 { type front; minNumberDensity 0.05; }\n"
             "  f5 { type front; direction (-1 0 0); }\n"
             "  f6 { type front; minNumberDensity 0.05; maxHeight %.17g; }\n"
             "  f7 { type front; minNumberDensity 0.05; maxHeight %.17g; }\n"
             "  f8 { type front; direction (0 1 0); maxHeight %.17g; }\n"
             "  f9 { type front; minHeight %.17g; }\n"
             "}\n", DP, 14.5 * DP, 15 * DP, (H + 0.5) * DP, (H + 0.5) * DP);
    run(text, &s, &c, 3, renumber_last);
    char cols[256];
    double v[8];
    int rows;
    double tol = 1e-15;
    assert_int_equal(read_output("f1", "front", cols, sizeof cols, v, 8,
                                 &rows), 2);
    assert_string_equal(cols, "# time X\n");
    assert_close(v[1], W * DP, tol);             /* splash ignored       */
    assert_int_equal(read_output("f2", "front", cols, sizeof cols, v, 8,
                                 &rows), 4);
    assert_string_equal(cols, "# time X Z T\n");
    assert_close(v[1], (W - 1) * DP, tol);
    assert_close(v[2], (W - 1) * DP / 0.05, 1e-14);
    assert_close(v[3], 0.2 * sqrt(2 * 9.81 / 0.05), 1e-14);
    assert_int_equal(read_output("f3", "front", cols, sizeof cols, v, 8,
                                 &rows), 2);
    assert_close(v[1], (H + 2) * DP, tol);
    assert_int_equal(read_output("f4", "front", cols, sizeof cols, v, 8,
                                 &rows), 2);
    assert_close(v[1], (W + 2) * DP, tol);
    assert_int_equal(read_output("f5", "front", cols, sizeof cols, v, 8,
                                 &rows), 2);
    assert_close(v[1], -DP, tol);
    assert_int_equal(read_output("f6", "front", cols, sizeof cols, v, 8,
                                 &rows), 2);
    assert_close(v[1], W * DP, tol);             /* splash above maxHeight */
    assert_int_equal(read_output("f7", "front", cols, sizeof cols, v, 8,
                                 &rows), 2);
    assert_close(v[1], (W + 2) * DP, tol);       /* at maxHeight: counted */
    assert_int_equal(read_output("f8", "front", cols, sizeof cols, v, 8,
                                 &rows), 2);
    assert_close(v[1], H * DP, tol);             /* bump cut off         */
    assert_int_equal(read_output("f9", "front", cols, sizeof cols, v, 8,
                                 &rows), 2);
    assert_close(v[1], 7 * DP, tol);             /* only the bump        */
    cloud_free(&c);
}

/* ---- forces ------------------------------------------------------------ */

/* The simple reference: the definition, summed by a plain loop. */
static void direct_forces(const struct cloud *c, int patch, double F[3])
{
    F[0] = F[1] = F[2] = 0;
    for (size_t i = 0; i < c->n; i++)
        if (c->type[i] == 1 && c->patch[i] == patch)
            for (int k = 0; k < 3; k++)
                F[k] += c->p[i] * DP * c->nrm[3 * i + k];
}

static void test_forces(void **state)
{
    (void)state;
    struct cloud c;
    struct fo_scene s;
    build_tank(&c);
    make_scene(&s, &c);
    const char *text =
        "functions {\n  F { type forces; patches (left bottom right); }\n}\n";
    double ref[3][3];
    direct_forces(&c, 1, ref[0]);
    direct_forces(&c, 0, ref[1]);
    direct_forces(&c, 2, ref[2]);
    run(text, &s, &c, 3, renumber_last);
    char cols[256];
    double v[16];
    int rows;
    assert_int_equal(read_output("F", "forces", cols, sizeof cols, v, 16,
                                 &rows), 10);
    assert_string_equal(cols, "# time left_Fx left_Fy left_Fz bottom_Fx "
                        "bottom_Fy bottom_Fz right_Fx right_Fy right_Fz\n");
    /* Closed forms of the discrete sums (see fo_forces.c). */
    double side = RHO * G * DP * DP * H * H / 2;
    double floor_ = (W + 1) * RHO * G * HS * DP;
    double tol = 1e-12 * side;
    assert_close(v[1], -side, tol);
    assert_close(v[2], 0, tol);
    assert_close(v[4], 0, tol);
    assert_close(v[5], -floor_, 1e-12 * floor_);
    for (int k = 7; k <= 9; k++)
        assert_close(v[k], 0, tol);
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++)
            assert_close(v[1 + 3 * j + k], ref[j][k], tol);
    double cont = RHO * G * HS * HS / 2;
    printf("forces: left wall %.6f N/m, continuous rho g h^2/2 = %.6f N/m "
           "(h = %d.5 dp), relative difference %.4f (~1/H = %.4f)\n", side,
           cont, H, (cont - side) / cont, 1.0 / H);
    cloud_free(&c);
}

/* A solver's own wall areas and viscous tractions (mlpgFluid): forces
 * sums A_i (p_i n_i + t_i) and writes the viscous part beside. */
static void test_forces_traction(void **state)
{
    (void)state;
    struct cloud c;
    struct fo_scene s;
    build_tank(&c);
    double *area = calloc(c.n, sizeof *area), *t = calloc(3 * c.n, sizeof *t);
    assert_non_null(area && t);
    for (size_t i = 0; i < c.n; i++) {
        area[i] = (1 + (double)(i % 3) / 4) * DP;
        t[3 * i] = 0.5 + (double)(i % 5);
        t[3 * i + 1] = -0.25 * (double)(i % 7);
    }
    set_field(&c.f[8], "wallArea", VTU_FLOAT64, 1, area);
    set_field(&c.f[9], "viscousTraction", VTU_FLOAT64, 3, t);
    c.c.nfields = 10;
    views(&c);
    make_scene(&s, &c);
    run("functions {\n  F { type forces; patches (right left); }\n}\n", &s,
        &c, 2, NULL);
    char cols[256];
    double v[16];
    int rows;
    assert_int_equal(read_output("F", "forces", cols, sizeof cols, v, 16,
                                 &rows), 13);
    assert_string_equal(cols, "# time right_Fx right_Fy right_Fz right_Fvx "
                        "right_Fvy right_Fvz left_Fx left_Fy left_Fz "
                        "left_Fvx left_Fvy left_Fvz\n");
    const int patch[2] = { 2, 1 };
    for (int q = 0; q < 2; q++) {
        double F[3] = { 0 }, Fv[3] = { 0 };
        for (size_t i = 0; i < c.n; i++)
            if (c.type[i] == 1 && c.patch[i] == patch[q])
                for (int k = 0; k < 3; k++) {
                    F[k] += area[i] * (c.p[i] * c.nrm[3 * i + k] + t[3 * i + k]);
                    Fv[k] += area[i] * t[3 * i + k];
                }
        for (int k = 0; k < 3; k++) {
            assert_close(v[1 + 6 * q + k], F[k], 1e-12 * (fabs(F[k]) + 1));
            assert_close(v[4 + 6 * q + k], Fv[k], 1e-12 * (fabs(Fv[k]) + 1));
        }
    }
    assert_true(fabs(v[10]) > 0.1 && fabs(v[7] - v[10]) > 1); /* both parts */
    free(area);
    free(t);
    cloud_free(&c);
}

/* ---- volume ------------------------------------------------------------ */

static struct fo_value escaped = {"escaped", 1, {1}};

/* Step 1: the splash particle (the last one) leaves and is counted as
 * escaped by the solver. */
static void remove_splash(int k, struct fo_scene *s, struct cloud *c)
{
    if (k != 1)
        return;
    c->n--;
    publish(c);
    s->values = &escaped;
    s->nvalues = 1;
}

static void test_volume(void **state)
{
    (void)state;
    struct cloud c;
    struct fo_scene s;
    build_tank(&c);
    make_scene(&s, &c);
    const char *text = "functions {\n  V { type volume; }\n}\n";
    run(text, &s, &c, 2, remove_splash);
    char cols[256];
    double v[8];
    int rows;
    assert_int_equal(read_output("V", "volume", cols, sizeof cols, v, 8,
                                 &rows), 5);
    assert_int_equal(rows, 2);
    assert_string_equal(cols, "# time N V dV escaped\n");
    double n0 = W * H + 2 + 1;
    assert_close(v[1], n0 - 1, 0);
    assert_close(v[2], (n0 - 1) * DP * DP, 1e-18);
    assert_close(v[3], -1 / n0, 1e-15);
    assert_close(v[4], 1, 0);
    /* The first row: no change, and nothing published. */
    char path[256], line[256];
    snprintf(path, sizeof path, "%s/postProcessing/V/0/volume.dat", tmpdir);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    while (fgets(line, sizeof line, f) && line[0] == '#')
        ;
    fclose(f);
    char expect[128];
    snprintf(expect, sizeof expect, "0 %d %.15g 0 nan\n", (int)n0,
             n0 * DP * DP);
    assert_string_equal(line, expect);
    cloud_free(&c);
}

/* ---- 3-D: vertical is z, faces of dp^2 --------------------------------- */

static void build_box_3d(struct cloud *c)
{
    static const double down[3] = {0, 0, -1}, z[3] = {0, 0, 0};
    const double h = 3.5 * DP;
    memset(c, 0, sizeof *c);
    for (int i = 0; i <= 5; i++)
        for (int j = 0; j <= 5; j++) {
            double x[3] = {i * DP, j * DP, 0};
            add(c, x, 1, 0, down, RHO * G * h, 1);
            for (int k = 1; k <= 3 && i >= 1 && i <= 4 && j >= 1 && j <= 4;
                 k++) {
                double y[3] = {i * DP, j * DP, k * DP};
                add(c, y, 0, -1, z, RHO * G * (h - y[2]), k == 3 ? 0.7 : 1);
            }
        }
    publish(c);
}

static void test_3d(void **state)
{
    (void)state;
    static const char *const floor_name[] = {"floor"};
    struct cloud c;
    struct fo_scene s;
    build_box_3d(&c);
    make_scene(&s, &c);
    s.dim = 3;
    s.patch_names = floor_name;
    s.npatches = 1;
    char text[2048];
    snprintf(text, sizeof text,
             "functions {\n"
             "  g { type waveGauges; gaugeLocations ((%.17g %.17g) "
             "(%.17g %.17g)); }\n"
             "  p { type probes; probeLocations ((%.17g %.17g %.17g)); }\n"
             "  F { type forces; patches (floor); }\n"
             "  V { type volume; }\n"
             "}\n", 2.5 * DP, 2.5 * DP, 8 * DP, 2.5 * DP, 2.5 * DP, 2.5 * DP,
             1.5 * DP);
    run(text, &s, &c, 3, renumber_last);
    char cols[256];
    double v[8];
    int rows;
    assert_int_equal(read_output("g", "waveGauges", cols, sizeof cols, v, 8,
                                 &rows), 3);
    assert_close(v[1], 3.5 * DP, 1e-15);
    assert_true(isnan(v[2]));
    /* Reach symmetric about z = 1.5 dp (floor particles included). */
    assert_int_equal(read_output("p", "probes", cols, sizeof cols, v, 8,
                                 &rows), 2);
    assert_close(v[1], RHO * G * 2 * DP, 1e-12 * RHO * G * DP);
    assert_int_equal(read_output("F", "forces", cols, sizeof cols, v, 8,
                                 &rows), 4);
    double fz = 36 * RHO * G * 3.5 * DP * DP * DP;
    assert_close(v[1], 0, 1e-12 * fz);
    assert_close(v[2], 0, 1e-12 * fz);
    assert_close(v[3], -fz, 1e-12 * fz);
    assert_int_equal(read_output("V", "volume", cols, sizeof cols, v, 8,
                                 &rows), 5);
    assert_close(v[1], 48, 0);
    assert_close(v[2], 48 * DP * DP * DP, 1e-20);
    cloud_free(&c);
}

/* ---- bad input --------------------------------------------------------- */

struct bad_case {
    int dim;
    const char *entry;  /* on line 2 of controlDict */
    const char *expect; /* in the message           */
};

static const struct bad_case bad[] = {
    {2, "a { type forces; patches (left obstacle); }",
     "unknown wall patch 'obstacle'; valid: bottom left right"},
    {2, "a { type forces; patches (left left); }", "listed twice"},
    {2, "a { type forces; patches (); }", "at least one"},
    {2, "a { type forces; }", "patches"},
    {2, "a { type probes; }", "probeLocations"},
    {2, "a { type probes; probeLocations ((0 0)); field T; }", "valid: p U"},
    {2, "a { type probes; probeLocations ((0 0)); field U; "
        "interpolation nearestWall; }", "nearestWall"},
    {2, "a { type probes; probeLocations ((1 2 3 4)); }",
     "point 0 must be a list of 2 to 3 numbers"},
    {3, "a { type probes; probeLocations ((1 2 3) (1 2)); }",
     "point 1 must be a list of 3 numbers"},
    {2, "a { type probes; probeLocations ((1 a)); }", "number"},
    {2, "a { type probes; probeLocations ((1 2 0) (1 2 3)); }",
     "probe 1: a 2-D case lies in the plane z = 0"},
    {2, "a { type probes; probeLocations ((1 2)); interpolation linear; }",
     "nearestWall"},
    {2, "a { type probes; probeLocations ((1 2)); radius -1; }", "radius"},
    {2, "a { type waveGauges; gaugeLocations ((0.1 0.2)); }",
     "(x) or (x 0)"},
    {2, "a { type waveGauges; gaugeLocations (0.1 word); }",
     "point 1 must be a list of 1 to 2 numbers"},
    {3, "a { type waveGauges; gaugeLocations (0.1 0.2); }",
     "point 0 must be a list of 2 numbers"},
    {3, "a { type waveGauges; gaugeLocations ((0.1)); }",
     "point 0 must be a list of 2 numbers"},
    {2, "a { type waveGauges; gaugeLocations ((0.1)); halfWidth 0; }",
     "halfWidth"},
    {2, "a { type waveGauges; gaugeLocations ((0.1)); "
        "minNumberDensity -1; }", "minNumberDensity"},
    {2, "a { type front; direction (0 0 0); }", "non-zero"},
    {2, "a { type front; direction (1 0 1); }", "x-y plane"},
    {2, "a { type front; direction (1 0); }", "3"},
    {2, "a { type front; gravity 9.81; }", "referenceLength"},
    {2, "a { type front; referenceLength 0; }", "positive"},
    {2, "a { type front; maxHeight 0; }", "maxHeight"},
    {2, "a { type front; maxHeight -0.1; }", "maxHeight"},
    {2, "a { type front; maxHeight 0.1; minHeight 0.1; }", "minHeight"},
};

static void test_errors(void **state)
{
    (void)state;
    struct cloud c;
    struct fo_scene s;
    build_tank(&c);
    make_scene(&s, &c);
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char text[512];
        struct dict *d;
        const struct dict *fd;
        struct fo_list *l = NULL;
        snprintf(text, sizeof text, "functions {\n  %s\n}\n", bad[i].entry);
        s.dim = bad[i].dim;
        assert_int_equal(dict_read_string(text, strlen(text), "controlDict",
                                          &d), SIM_OK);
        assert_int_equal(dict_get_dict(d, "functions", &fd), SIM_OK);
        int rc = fo_list_create(fd, tables, &s, tmpdir, 0, 6, &l);
        const char *msg = sim_error_message();
        if (rc != SIM_ERR_DICT || !strstr(msg, "controlDict:2")
            || !strstr(msg, bad[i].expect))
            print_error("case %zu (%s): rc %d, message '%s'\n", i,
                        bad[i].entry, rc, msg);
        assert_int_equal(rc, SIM_ERR_DICT);
        assert_non_null(strstr(msg, "controlDict:2"));
        assert_non_null(strstr(msg, bad[i].expect));
        dict_free(d);
    }
    cloud_free(&c);
}

/* A solver that does not publish a field the type needs. */
static void test_missing_field(void **state)
{
    (void)state;
    struct cloud c;
    struct fo_scene s;
    build_tank(&c);
    make_scene(&s, &c);
    c.f[2] = c.f[7]; /* drop "pressure" */
    c.c.nfields = 7;
    views(&c);
    const char *text = "functions {\n  a { type probes; "
                       "probeLocations ((0 0)); }\n}\n";
    struct dict *d;
    const struct dict *fd;
    struct fo_list *l = NULL;
    assert_int_equal(dict_read_string(text, strlen(text), "controlDict", &d),
                     SIM_OK);
    assert_int_equal(dict_get_dict(d, "functions", &fd), SIM_OK);
    assert_int_equal(fo_list_create(fd, tables, &s, tmpdir, 0, 6, &l),
                     SIM_ERR_INPUT);
    assert_non_null(strstr(sim_error_message(), "controlDict:2"));
    assert_non_null(strstr(sim_error_message(), "unknown field of the fluid "
                           "cloud 'pressure'; valid: position type patch"));
    dict_free(d);
    cloud_free(&c);
}

/* Every registered type has a name, a reference and all its ops. */
static void test_table(void **state)
{
    (void)state;
    const char *names[] = {"probes", "waveGauges", "front", "forces",
                           "volume"};
    int n = 0;
    for (; mps_fo_table[n]; n++) {
        const struct fo_ops *o = mps_fo_table[n];
        assert_true(n < 5);
        assert_string_equal(o->name, names[n]);
        assert_non_null(o->reference);
        assert_true(o->create && o->header && o->execute && o->destroy);
    }
    assert_int_equal(n, 5);
}

int main(void)
{
    log_set_quiet(1);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_table),
        cmocka_unit_test(test_probes),
        cmocka_unit_test(test_probes_velocity),
        cmocka_unit_test(test_wave_gauges),
        cmocka_unit_test(test_front),
        cmocka_unit_test(test_forces),
        cmocka_unit_test(test_forces_traction),
        cmocka_unit_test(test_volume),
        cmocka_unit_test(test_3d),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_missing_field),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
