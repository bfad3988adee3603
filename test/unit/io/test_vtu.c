/*
 * test_vtu.c — VTU/PVD writer and reader (src/io): bit-exact round trips in
 * ascii and binary for every type and every base64 padding, foreign
 * variants (UInt32 headers, one-stream base64, line breaks, Float32),
 * corrupted and truncated files, .pvd editing, and no temporary files left.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <float.h>
#include <ftw.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/error.h"
#include "io/base64.h"
#include "io/vtu.h"

static char dir[64];

static void path_in(char *buf, size_t n, const char *name)
{
    snprintf(buf, n, "%s/%s", dir, name);
}

static int rm_one(const char *p, const struct stat *s, int f, struct FTW *w)
{
    (void)s; (void)f; (void)w;
    return remove(p);
}

static int setup(void **state)
{
    (void)state;
    strcpy(dir, "/tmp/test_vtu.XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    return nftw(dir, rm_one, 16, FTW_DEPTH | FTW_PHYS);
}

/* Number of "*.tmp.*" names in the test directory. */
static int count_tmp(void)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int n = 0;
    assert_non_null(d);
    while ((e = readdir(d)))
        n += strstr(e->d_name, ".tmp.") != NULL;
    closedir(d);
    return n;
}

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *s;
    long n;
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    rewind(f);
    s = malloc((size_t)n + 1);
    assert_int_equal(fread(s, 1, (size_t)n, f), (size_t)n);
    s[n] = '\0';
    fclose(f);
    if (len)
        *len = (size_t)n;
    return s;
}

static void spit(const char *path, const char *text, size_t len)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(text, 1, len, f), len);
    fclose(f);
}

/* ---- base64 ----------------------------------------------------------------- */

static void test_base64_vectors(void **state)
{
    /* RFC 4648 §10 test vectors. */
    static const char *const plain[] = { "", "f", "fo", "foo", "foob",
                                         "fooba", "foobar" };
    static const char *const coded[] = { "", "Zg==", "Zm8=", "Zm9v",
                                         "Zm9vYg==", "Zm9vYmE=", "Zm9vYmFy" };
    char out[32];
    unsigned char back[32];
    size_t n;
    (void)state;
    for (int i = 0; i < 7; i++) {
        size_t len = strlen(plain[i]);
        assert_int_equal(b64_encode(plain[i], len, out), strlen(coded[i]));
        assert_string_equal(out, coded[i]);
        assert_int_equal(b64_decode(out, strlen(out), back, &n), 0);
        assert_int_equal(n, len);
        assert_memory_equal(back, plain[i], len);
    }
    assert_int_equal(b64_decode("Zm9", 3, back, &n), -1);      /* length */
    assert_int_equal(b64_decode("Zm!v", 4, back, &n), -1);     /* char   */
    assert_int_equal(n, 2);
    assert_int_equal(b64_decode("Zg==Zm9v", 8, back, &n), -1); /* inner = */
    assert_int_equal(b64_decode("Z===", 4, back, &n), -1);
    assert_int_equal(b64_decode("Zm=v", 4, back, &n), -1);
}

static void test_base64_all_bytes(void **state)
{
    unsigned char in[256], back[256];
    char out[400];
    size_t n;
    (void)state;
    for (int i = 0; i < 256; i++)
        in[i] = (unsigned char)(255 - i);
    for (size_t len = 0; len <= 256; len += 1) {
        size_t k = b64_encode(in, len, out);
        assert_int_equal(k, b64_encoded_len(len));
        assert_int_equal(b64_decode(out, k, back, &n), 0);
        assert_int_equal(n, len);
        assert_memory_equal(back, in, len);
    }
}

/* ---- round trips ------------------------------------------------------------ */

static const double specials[] = {
    0.0, -0.0, 1.0, -1.0, 0.1, 1.0 / 3.0, DBL_MAX, -DBL_MAX, DBL_MIN,
    -DBL_MIN, 4.9406564584124654e-324, -4.9406564584124654e-324,
    2.2250738585072009e-308 /* largest subnormal */, 1e300, 1e-300,
    123456789.123456789, -2.5e-17, INFINITY, -INFINITY };
#define NSPECIAL (sizeof specials / sizeof specials[0])

/* A cloud of n points with fields of every type, filled with awkward
 * values; the caller frees it with vtu_cloud_free. */
static void make_cloud(struct vtu_cloud *c, size_t n)
{
    double *p, *v;
    int64_t *id;
    int32_t *ty;
    uint8_t *u8;
    memset(c, 0, sizeof *c);
    c->n = n;
    c->time = 0.1 + 0.2; /* not exactly 0.3 */
    c->points = malloc(3 * n * sizeof(double) + 1);
    assert_int_equal(vtu_cloud_add_field(c, "pressure", VTU_FLOAT64, 1,
                                         (void **)&p), SIM_OK);
    assert_int_equal(vtu_cloud_add_field(c, "velocity", VTU_FLOAT64, 3,
                                         (void **)&v), SIM_OK);
    assert_int_equal(vtu_cloud_add_field(c, "id", VTU_INT64, 1,
                                         (void **)&id), SIM_OK);
    assert_int_equal(vtu_cloud_add_field(c, "type", VTU_INT32, 1,
                                         (void **)&ty), SIM_OK);
    assert_int_equal(vtu_cloud_add_field(c, "flag", VTU_UINT8, 1,
                                         (void **)&u8), SIM_OK);
    for (size_t i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++) {
            c->points[3 * i + k] = specials[(i + (size_t)k) % (NSPECIAL - 2)];
            v[3 * i + k] = ldexp(sin((double)(i * 3 + (size_t)k)),
                                 (int)(i % 2000) - 1000);
        }
        p[i] = specials[i % NSPECIAL];
        id[i] = i % 3 == 0 ? INT64_MIN + (int64_t)i
                           : INT64_MAX - (int64_t)(i * i);
        ty[i] = i % 2 ? INT32_MIN + (int32_t)i : INT32_MAX - (int32_t)i;
        u8[i] = (uint8_t)(i * 37);
    }
}

static void assert_same_cloud(const struct vtu_cloud *a,
                              const struct vtu_cloud *b)
{
    static const size_t sz[] = { 8, 8, 4, 1 };
    assert_int_equal(a->n, b->n);
    assert_memory_equal(&a->time, &b->time, sizeof a->time);
    if (a->n)
        assert_memory_equal(a->points, b->points, 3 * a->n * sizeof(double));
    assert_int_equal(a->nfields, b->nfields);
    for (int i = 0; i < a->nfields; i++) {
        const struct vtu_field *f = &a->fields[i];
        const struct vtu_field *g = vtu_find(b, f->name);
        assert_non_null(g);
        assert_int_equal(f->type, g->type);
        assert_int_equal(f->ncomp, g->ncomp);
        if (a->n)
            assert_memory_equal(f->data, g->data,
                                a->n * (size_t)f->ncomp * sz[f->type]);
    }
}

static void round_trip(int binary)
{
    static const size_t sizes[] = { 0, 1, 2, 3, 4, 5, 1000, 20000 };
    char path[128];
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        struct vtu_cloud c, r;
        make_cloud(&c, sizes[s]);
        path_in(path, sizeof path, binary ? "rt_bin.vtu" : "rt_ascii.vtu");
        assert_int_equal(vtu_write(path, &c, binary), SIM_OK);
        assert_int_equal(vtu_read(path, &r), SIM_OK);
        assert_same_cloud(&c, &r);
        vtu_cloud_free(&c);
        vtu_cloud_free(&r);
        assert_int_equal(count_tmp(), 0);
    }
}

static void test_round_trip_binary(void **state) { (void)state; round_trip(1); }

/* A .pvtu of pieces of 0, 3 and 1000 particles reads as the cloud of all
 * (in piece order, the first piece's time); pieces with other arrays, a
 * missing piece and a .pvtu without pieces are refused with the file. */
static void test_pvtu(void **state)
{
    (void)state;
    static const size_t sizes[] = { 0, 3, 1000 };
    struct vtu_cloud whole, part, r;
    char path[128];
    make_cloud(&whole, 1003);
    size_t first = 0;
    for (int p = 0; p < 3; p++) {
        char name[32];
        make_cloud(&part, sizes[p]);
        /* piece p: particles [first, first + size) of the whole */
        memcpy(part.points, whole.points + 3 * first,
               3 * sizes[p] * sizeof(double));
        for (int k = 0; k < part.nfields; k++) {
            size_t e = (size_t)part.fields[k].ncomp
                     * vtu_type_size(part.fields[k].type);
            memcpy(part.fields[k].data, (char *)whole.fields[k].data
                   + e * first, e * sizes[p]);
        }
        snprintf(name, sizeof name, "piece_%d.vtu", p);
        path_in(path, sizeof path, name);
        assert_int_equal(vtu_write(path, &part, p == 1 ? 0 : 1), SIM_OK);
        first += sizes[p];
        vtu_cloud_free(&part);
    }
    path_in(path, sizeof path, "whole.pvtu");
    assert_int_equal(pvtu_write(path, &whole, 3, "piece_%d.vtu"), SIM_OK);
    assert_int_equal(vtu_read(path, &r), SIM_OK);
    assert_same_cloud(&whole, &r);
    vtu_cloud_free(&r);
    /* four pieces named, the fourth missing */
    assert_int_equal(pvtu_write(path, &whole, 4, "piece_%d.vtu"), SIM_OK);
    assert_int_equal(vtu_read(path, &r), SIM_ERR_IO);
    assert_non_null(strstr(sim_error_message(), "piece_3.vtu"));
    /* a piece with an array less */
    make_cloud(&part, 2);
    part.nfields--;
    path_in(path, sizeof path, "piece_1.vtu");
    assert_int_equal(vtu_write(path, &part, 1), SIM_OK);
    part.nfields++;
    vtu_cloud_free(&part);
    path_in(path, sizeof path, "whole.pvtu");
    assert_int_equal(pvtu_write(path, &whole, 3, "piece_%d.vtu"), SIM_OK);
    assert_int_equal(vtu_read(path, &r), SIM_ERR_IO);
    assert_non_null(strstr(sim_error_message(), "piece piece_1.vtu has 4 "
                                                "arrays"));
    /* no pieces */
    assert_int_equal(pvtu_write(path, &whole, 0, "piece_%d.vtu"), SIM_OK);
    assert_int_equal(vtu_read(path, &r), SIM_ERR_IO);
    assert_non_null(strstr(sim_error_message(), "no Piece"));
    vtu_cloud_free(&whole);
    assert_int_equal(count_tmp(), 0);
}
static void test_round_trip_ascii(void **state) { (void)state; round_trip(0); }

/* The binary payload follows doc/libraries.md §3: no line breaks inside the
 * base64 and a separately padded UInt64 header; cells are vertices. */
static void test_binary_layout(void **state)
{
    struct vtu_cloud c;
    char path[128], *text;
    (void)state;
    make_cloud(&c, 1);
    path_in(path, sizeof path, "layout.vtu");
    assert_int_equal(vtu_write(path, &c, 1), SIM_OK);
    text = slurp(path, NULL);
    /* One point, UInt8 flag 0: header b64(1 as UInt64) + b64(0x00). */
    assert_non_null(strstr(text, "format=\"binary\">AQAAAAAAAAA=AA==<"));
    assert_non_null(strstr(text, "header_type=\"UInt64\""));
    assert_non_null(strstr(text, "Name=\"types\" format=\"binary\">"
                                 "AQAAAAAAAAA=AQ==<"));
    assert_non_null(strstr(text, "Name=\"TimeValue\""));
    free(text);
    vtu_cloud_free(&c);

    make_cloud(&c, 1000);
    assert_int_equal(vtu_write(path, &c, 1), SIM_OK);
    text = slurp(path, NULL);
    for (char *s = strstr(text, "format=\"binary\">"); s;
         s = strstr(s + 1, "format=\"binary\">")) {
        char *end = strchr(s, '<');
        assert_null(memchr(s, '\n', (size_t)(end - s)));
    }
    free(text);
    vtu_cloud_free(&c);
}

/* ascii text is formatted by several threads: the bytes must not depend
 * on how many (a block of 65536 values spans several slices). */
static void test_ascii_threads(void **state)
{
    struct vtu_cloud c;
    char path[128], *one, *three;
    size_t n1, n3;
    (void)state;
    make_cloud(&c, 70001);
    path_in(path, sizeof path, "threads.vtu");
    omp_set_num_threads(1);
    assert_int_equal(vtu_write(path, &c, 0), SIM_OK);
    one = slurp(path, &n1);
    omp_set_num_threads(3);
    assert_int_equal(vtu_write(path, &c, 0), SIM_OK);
    three = slurp(path, &n3);
    assert_int_equal(n1, n3);
    assert_memory_equal(one, three, n1);
    free(one);
    free(three);
    vtu_cloud_free(&c);
}

/* A file another writer could produce: UInt32 header encoded with the data
 * as one stream and broken into lines, Float32 points, ascii ints. */
static void test_foreign_variants(void **state)
{
    unsigned char raw[4 + 2 * 3 * 4];
    char b64[64], path[128], text[1024];
    struct vtu_cloud c;
    const struct vtu_field *f;
    float pts[6] = { 1.5f, -2.0f, 0.25f, 3.0f, 4.0f, 1e-3f };
    uint32_t nb = sizeof pts;
    (void)state;
    memcpy(raw, &nb, 4);
    memcpy(raw + 4, pts, sizeof pts);
    b64_encode(raw, sizeof raw, b64);
    snprintf(text, sizeof text,
             "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
             "version=\"0.1\" byte_order=\"LittleEndian\">\n"
             "<UnstructuredGrid><Piece NumberOfPoints=\"2\" "
             "NumberOfCells=\"0\"><PointData>\n<DataArray type=\"Int32\" "
             "Name=\"type\" format=\"ascii\">\n  7\n -3 </DataArray>\n"
             "</PointData><Points><DataArray type=\"Float32\" "
             "NumberOfComponents=\"3\" format=\"binary\">\n%.16s\n%s\n"
             "</DataArray></Points></Piece></UnstructuredGrid></VTKFile>\n",
             b64, b64 + 16);
    path_in(path, sizeof path, "foreign.vtu");
    spit(path, text, strlen(text));
    assert_int_equal(vtu_read(path, &c), SIM_OK);
    assert_int_equal(c.n, 2);
    for (int i = 0; i < 6; i++)
        assert_true(c.points[i] == (double)pts[i]);
    assert_true(c.time == 0.0);
    assert_int_equal(vtu_require(&c, path, "type", VTU_INT32, 1, &f), SIM_OK);
    assert_int_equal(((int32_t *)f->data)[0], 7);
    assert_int_equal(((int32_t *)f->data)[1], -3);
    assert_int_equal(vtu_require(&c, path, "type", VTU_FLOAT64, 1, &f),
                     SIM_ERR_IO);
    assert_non_null(strstr(sim_error_message(), "is Int32, expected Float64"));
    assert_int_equal(vtu_require(&c, path, "type", -1, 3, &f), SIM_ERR_IO);
    assert_int_equal(vtu_require(&c, path, "nope", -1, 0, &f), SIM_ERR_IO);
    assert_null(f);
    vtu_cloud_free(&c);
}

/* ---- bad files -------------------------------------------------------------- */

/* Write a good binary or ascii file, apply edit(), expect SIM_ERR_IO
 * mentioning the file and `what`. */
static void expect_bad(int binary, void (*edit)(char *, size_t *),
                       const char *what)
{
    struct vtu_cloud c, r;
    char path[128], *text;
    size_t len;
    make_cloud(&c, 5);
    path_in(path, sizeof path, "bad.vtu");
    assert_int_equal(vtu_write(path, &c, binary), SIM_OK);
    vtu_cloud_free(&c);
    text = slurp(path, &len);
    edit(text, &len);
    spit(path, text, len);
    free(text);
    r.n = 99;
    assert_int_equal(vtu_read(path, &r), SIM_ERR_IO);
    if (!strstr(sim_error_message(), path) ||
        !strstr(sim_error_message(), what))
        fail_msg("message '%s' lacks '%s'", sim_error_message(), what);
    assert_int_equal(r.n, 0);
    assert_null(r.points);
    assert_null(r.fields);
}

static void cut_half(char *t, size_t *len) { (void)t; *len /= 2; }
static void cut_tail(char *t, size_t *len) { (void)t; *len -= 20; }
static void bad_char(char *t, size_t *len)
{
    (void)len;
    char *s = strstr(t, "Name=\"velocity\"");
    s = strchr(s, '>') + 20;
    *s = '!';
}
static void drop_chars(char *t, size_t *len)
{
    /* Remove 4 base64 characters: still valid base64, but short. */
    char *s = strchr(strstr(t, "Name=\"velocity\""), '>') + 17;
    memmove(s, s + 4, *len - (size_t)(s + 4 - t));
    *len -= 4;
}
static void more_points(char *t, size_t *len)
{
    (void)len;
    char *s = strstr(t, "NumberOfPoints=\"5\"");
    s[16] = '6';
}
static void no_points(char *t, size_t *len)
{
    char *a = strstr(t, "<Points>"), *b = strstr(t, "</Points>") + 9;
    memmove(a, b, *len - (size_t)(b - t));
    *len -= (size_t)(b - a);
}
static void ascii_drop_value(char *t, size_t *len)
{
    /* The pressure of the last point: "-1\n" -> "\n" (5 values -> 4). */
    char *s = strchr(strstr(t, "Name=\"pressure\""), '>') + 1;
    char *e = strstr(s, "</DataArray>");
    while (e[-1] == '\n' || e[-1] == ' ' || e[-1] == '\t')
        e--;
    char *b = e;
    while (b[-1] != ' ' && b[-1] != '\n')
        b--;
    memmove(b, e, *len - (size_t)(e - t));
    *len -= (size_t)(e - b);
}
static void ascii_garbage(char *t, size_t *len)
{
    (void)len;
    char *s = strchr(strstr(t, "Name=\"type\""), '>') + 2;
    *s = 'x';
}
static void ascii_overflow(char *t, size_t *len)
{
    (void)len;
    char *s = strchr(strstr(t, "Name=\"flag\""), '>') + 2;
    memcpy(s, "999", 3); /* first value was "0 " then "37": now > 255 */
}

static void test_truncated(void **state)
{
    (void)state;
    expect_bad(1, cut_half, "not valid XML");
    expect_bad(1, cut_tail, "not valid XML");
    expect_bad(0, cut_half, "not valid XML");
}

static void test_corrupted(void **state)
{
    (void)state;
    expect_bad(1, bad_char, "invalid base64 character '!'");
    expect_bad(1, drop_chars, "bytes but");
    expect_bad(1, more_points, "NumberOfPoints");
    expect_bad(0, more_points, "values where");
    expect_bad(1, no_points, "missing Points");
    expect_bad(0, ascii_drop_value, "4 values where 5 were expected");
    expect_bad(0, ascii_garbage, "is not a valid Int32");
    expect_bad(0, ascii_overflow, "is not a valid UInt8");
}

/* Entity expansion is refused outright: no DOCTYPE in our files. */
static void test_doctype_refused(void **state)
{
    static const char lol[] =
        "<?xml version=\"1.0\"?>\n<!DOCTYPE l [ <!ENTITY a \"aaaaaaaa\">"
        "<!ENTITY b \"&a;&a;&a;&a;&a;&a;&a;&a;\"> ]>\n<VTKFile type=\""
        "UnstructuredGrid\"><UnstructuredGrid><Piece NumberOfPoints=\"1\">"
        "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" "
        "format=\"ascii\">&b;</DataArray></Points></Piece>"
        "</UnstructuredGrid></VTKFile>\n";
    struct vtu_cloud r;
    char path[128];
    (void)state;
    path_in(path, sizeof path, "lol.vtu");
    spit(path, lol, strlen(lol));
    assert_int_equal(vtu_read(path, &r), SIM_ERR_IO);
    assert_non_null(strstr(sim_error_message(), "<!DOCTYPE>"));
    assert_int_equal(pvd_add(path, 0, "x.vtu"), SIM_ERR_IO);
}

static void test_missing_file(void **state)
{
    struct vtu_cloud r;
    char path[128];
    (void)state;
    path_in(path, sizeof path, "absent.vtu");
    assert_int_equal(vtu_read(path, &r), SIM_ERR_IO);
    assert_non_null(strstr(sim_error_message(), "cannot open"));
}

/* A failed write leaves neither a temporary nor a damaged target. */
static void test_failed_write_cleans_up(void **state)
{
    struct vtu_cloud c;
    char path[128];
    (void)state;
    make_cloud(&c, 10);
    path_in(path, sizeof path, "adir");
    assert_int_equal(mkdir(path, 0700), 0);
    assert_int_equal(vtu_write(path, &c, 1), SIM_ERR_IO); /* rename fails */
    assert_int_equal(count_tmp(), 0);
    path_in(path, sizeof path, "nodir/x.vtu");
    assert_int_equal(vtu_write(path, &c, 0), SIM_ERR_IO);
    assert_int_equal(count_tmp(), 0);
    /* Invalid clouds are refused before any file is created. */
    c.fields[1].ncomp = 0;
    path_in(path, sizeof path, "never.vtu");
    assert_int_equal(vtu_write(path, &c, 1), SIM_ERR_INTERNAL);
    assert_int_equal(access(path, F_OK), -1);
    c.fields[1].ncomp = 3;
    strcpy(c.fields[1].name, "pressure");
    assert_int_equal(vtu_write(path, &c, 1), SIM_ERR_INTERNAL);
    assert_int_equal(access(path, F_OK), -1);
    assert_int_equal(count_tmp(), 0);
    vtu_cloud_free(&c);
}

static void test_add_field_checks(void **state)
{
    struct vtu_cloud c = { 0 };
    void *d;
    (void)state;
    c.n = 4;
    assert_int_equal(vtu_cloud_add_field(&c, "a", VTU_INT32, 1, &d), SIM_OK);
    assert_int_equal(((int32_t *)d)[3], 0);
    assert_int_equal(vtu_cloud_add_field(&c, "a", VTU_INT32, 1, &d),
                     SIM_ERR_INTERNAL);
    assert_int_equal(vtu_cloud_add_field(&c, "b", VTU_INT32, 10, &d),
                     SIM_ERR_INTERNAL);
    assert_int_equal(vtu_cloud_add_field(
                         &c, "a_name_that_is_far_too_long_for_the_sixty_"
                             "four_byte_name_buffer_xx", VTU_UINT8, 1, &d),
                     SIM_ERR_INTERNAL);
    assert_int_equal(c.nfields, 1);
    vtu_cloud_free(&c);
    assert_int_equal(c.nfields, 0);
}

/* ---- pvd -------------------------------------------------------------------- */

/* Timesteps and files of a .pvd in file order. */
static int pvd_list(const char *path, double *t, char files[][32], int max)
{
    char *text = slurp(path, NULL), *s = text;
    int n = 0;
    while ((s = strstr(s, "<DataSet")) && n < max) {
        char *ts = strstr(s, "timestep=\""), *fs = strstr(s, "file=\"");
        t[n] = strtod(ts + 10, NULL);
        sscanf(fs + 6, "%31[^\"]", files[n]);
        n++;
        s++;
    }
    free(text);
    return n;
}

static void test_pvd(void **state)
{
    char path[128], files[8][32];
    double t[8];
    (void)state;
    path_in(path, sizeof path, "fluid.pvd");
    assert_int_equal(pvd_truncate(path, 1.0), SIM_OK); /* absent: no-op */
    assert_int_equal(access(path, F_OK), -1);
    assert_int_equal(pvd_add(path, 0.2, "0.2/fluid.vtu"), SIM_OK);
    assert_int_equal(pvd_add(path, 0.0, "0/fluid.vtu"), SIM_OK);
    assert_int_equal(pvd_add(path, 0.3, "0.3/fluid.vtu"), SIM_OK);
    assert_int_equal(pvd_add(path, 0.1, "0.1/fluid.vtu"), SIM_OK);
    assert_int_equal(pvd_list(path, t, files, 8), 4);
    assert_true(t[0] == 0.0 && t[1] == 0.1 && t[2] == 0.2 && t[3] == 0.3);
    assert_string_equal(files[1], "0.1/fluid.vtu");
    /* Same time (to round-off): replaced, not duplicated. */
    assert_int_equal(pvd_add(path, 0.1 + 0.2, "again.vtu"), SIM_OK);
    assert_int_equal(pvd_list(path, t, files, 8), 4);
    assert_string_equal(files[3], "again.vtu");
    assert_int_equal(pvd_truncate(path, 0.1), SIM_OK);
    assert_int_equal(pvd_list(path, t, files, 8), 2);
    assert_true(t[0] == 0.0 && t[1] == 0.1);
    /* Special characters survive as attribute escapes. */
    assert_int_equal(pvd_add(path, 5.0, "a&b<\"c\".vtu"), SIM_OK);
    assert_int_equal(pvd_add(path, 6.0, "d.vtu"), SIM_OK);
    assert_int_equal(pvd_list(path, t, files, 8), 4);
    assert_true(t[2] == 5.0 && t[3] == 6.0);
    assert_string_equal(files[3], "d.vtu");
    assert_int_equal(pvd_truncate(path, 0.0), SIM_OK);
    assert_int_equal(pvd_list(path, t, files, 8), 1);
    assert_int_equal(count_tmp(), 0);
}

static void test_pvd_corrupted(void **state)
{
    static const char *const bad[] = {
        "<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"0\" "
        "file=\"a.vtu\"/>",                                   /* truncated */
        "<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"x\" "
        "file=\"a.vtu\"/></Collection></VTKFile>",            /* time      */
        "<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"1\"/>"
        "</Collection></VTKFile>",                            /* no file   */
        "<VTKFile type=\"UnstructuredGrid\"><Collection/></VTKFile>",
        "",
    };
    char path[128], *after;
    (void)state;
    path_in(path, sizeof path, "bad.pvd");
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        spit(path, bad[i], strlen(bad[i]));
        assert_int_equal(pvd_add(path, 1.0, "b.vtu"), SIM_ERR_IO);
        assert_non_null(strstr(sim_error_message(), path));
        assert_int_equal(pvd_truncate(path, 0.5), SIM_ERR_IO);
        after = slurp(path, NULL);
        assert_string_equal(after, bad[i]); /* untouched */
        free(after);
    }
    assert_int_equal(count_tmp(), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_base64_vectors),
        cmocka_unit_test(test_base64_all_bytes),
        cmocka_unit_test(test_round_trip_binary),
        cmocka_unit_test(test_round_trip_ascii),
        cmocka_unit_test(test_binary_layout),
        cmocka_unit_test(test_ascii_threads),
        cmocka_unit_test(test_foreign_variants),
        cmocka_unit_test(test_truncated),
        cmocka_unit_test(test_corrupted),
        cmocka_unit_test(test_doctype_refused),
        cmocka_unit_test(test_missing_file),
        cmocka_unit_test(test_failed_write_cleans_up),
        cmocka_unit_test(test_add_field_checks),
        cmocka_unit_test(test_pvtu),
        cmocka_unit_test(test_pvd),
        cmocka_unit_test(test_pvd_corrupted),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
