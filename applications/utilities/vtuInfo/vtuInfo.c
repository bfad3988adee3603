/*
 * vtuInfo — what a .vtu particle file holds (checkMesh-like): point count,
 * time, bounds, and per field its type, components, range and mean; for
 * integer fields with few distinct values, how many points take each.
 * Scripts and tests read its output; every line is "key value...".
 *
 *   vtuInfo [-case DIR] [-dump] FILE...      (FILE relative to the case)
 *
 * -dump prints, instead, one line per point: x y z and every component of
 * every field, after a "# x y z name_0 ..." header (for awk).
 */
#include <inttypes.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/app.h"
#include "core/error.h"
#include "io/vtu.h"

static const char *const type_names[] = { "Float64", "Int64", "Int32",
                                          "UInt8" };

static double value(const struct vtu_field *f, size_t i)
{
    switch (f->type) {
    case VTU_FLOAT64: return ((const double *)f->data)[i];
    case VTU_INT64:   return (double)((const int64_t *)f->data)[i];
    case VTU_INT32:   return ((const int32_t *)f->data)[i];
    default:          return ((const uint8_t *)f->data)[i];
    }
}

/* "counts v:n v:n ..." when an integer field has at most 32 values. */
static void print_counts(const struct vtu_field *f, size_t n)
{
    double v[32];
    size_t cnt[32];
    int nv = 0;

    for (size_t i = 0; i < n; i++) {
        double x = value(f, i);
        int k;
        for (k = 0; k < nv && v[k] != x; k++)
            ;
        if (k == nv) {
            if (nv == 32)
                return;
            v[nv] = x;
            cnt[nv++] = 0;
        }
        cnt[k]++;
    }
    printf("counts %s", f->name);
    for (int k = 0; k < nv; k++)
        printf(" %.0f:%zu", v[k], cnt[k]);
    printf("\n");
}

static void print_field(const struct vtu_field *f, size_t n)
{
    printf("field %s %s %d\n", f->name, type_names[f->type], f->ncomp);
    for (int c = 0; c < f->ncomp; c++) {
        double lo = HUGE_VAL, hi = -HUGE_VAL, sum = 0;
        for (size_t i = 0; i < n; i++) {
            double x = value(f, i * (size_t)f->ncomp + (size_t)c);
            lo = fmin(lo, x);
            hi = fmax(hi, x);
            sum += x;
        }
        printf("range %s %d %.10g %.10g %.10g\n", f->name, c, n ? lo : 0,
               n ? hi : 0, n ? sum / (double)n : 0);
    }
    if (f->type != VTU_FLOAT64 && f->ncomp == 1)
        print_counts(f, n);
}

static void dump(const struct vtu_cloud *c)
{
    printf("# x y z");
    for (int k = 0; k < c->nfields; k++)
        for (int j = 0; j < c->fields[k].ncomp; j++)
            printf(c->fields[k].ncomp > 1 ? " %s_%d" : " %s",
                   c->fields[k].name, j);
    printf("\n");
    for (size_t i = 0; i < c->n; i++) {
        printf("%.17g %.17g %.17g", c->points[3 * i], c->points[3 * i + 1],
               c->points[3 * i + 2]);
        for (int k = 0; k < c->nfields; k++) {
            const struct vtu_field *f = &c->fields[k];
            for (int j = 0; j < f->ncomp; j++)
                printf(" %.17g", value(f, i * (size_t)f->ncomp + (size_t)j));
        }
        printf("\n");
    }
}

static int info(const struct app *a, const char *rel, int dump_points)
{
    struct vtu_cloud c;
    char path[4096];
    double lo[3] = { 0, 0, 0 }, hi[3] = { 0, 0, 0 };

    TRY(vtu_read(app_path(a, rel, path, sizeof path), &c));
    if (dump_points) {
        dump(&c);
        vtu_cloud_free(&c);
        return SIM_OK;
    }
    for (size_t i = 0; i < c.n; i++)
        for (int d = 0; d < 3; d++) {
            double x = c.points[3 * i + d];
            lo[d] = i ? fmin(lo[d], x) : x;
            hi[d] = i ? fmax(hi[d], x) : x;
        }
    printf("file %s\npoints %zu\ntime %.17g\n", path, c.n, c.time);
    printf("bounds %.10g %.10g %.10g %.10g %.10g %.10g\n", lo[0], lo[1],
           lo[2], hi[0], hi[1], hi[2]);
    for (int k = 0; k < c.nfields; k++)
        print_field(&c.fields[k], c.n);
    vtu_cloud_free(&c);
    return SIM_OK;
}

int main(int argc, char **argv)
{
    struct app app;
    const char *dump_flag = NULL;
    const struct app_option opts[] = {
        { "-dump", 0, NULL, "print every point as a table", &dump_flag },
        { NULL, 0, NULL, NULL, NULL },
    };

    app_init(&app, "vtuInfo", "print what .vtu particle files hold", argc,
             argv, opts, 1);
    if (app.nargs < 1) {
        sim_error(SIM_ERR_INPUT, "no file given (usage: vtuInfo [-case DIR] "
                  "FILE...)");
        app_fatal(&app, SIM_ERR_INPUT);
    }
    for (int i = 0; i < app.nargs; i++) {
        int rc = info(&app, app.args[i], dump_flag != NULL);
        if (rc != SIM_OK)
            app_fatal(&app, rc);
    }
    return app_end(&app);
}
