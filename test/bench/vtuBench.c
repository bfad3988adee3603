/*
 * vtuBench.c — time to write and read a fluid-like particle file (the
 * fields genParticles writes: type, patch, velocity, pressure, normal, id)
 * in binary and ascii, and the file size. Prints one table.
 *   vtuBench [N ...]      (default 10000 100000 1000000 points)
 * Files go to $TMPDIR (default /tmp) and are removed.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "core/error.h"
#include "io/vtu.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void fill(struct vtu_cloud *c, size_t n)
{
    double *v, *p, *nr;
    int32_t *ty, *pa;
    int64_t *id;
    c->n = n;
    c->points = malloc(3 * n * sizeof(double));
    vtu_cloud_add_field(c, "type", VTU_INT32, 1, (void **)&ty);
    vtu_cloud_add_field(c, "patch", VTU_INT32, 1, (void **)&pa);
    vtu_cloud_add_field(c, "velocity", VTU_FLOAT64, 3, (void **)&v);
    vtu_cloud_add_field(c, "pressure", VTU_FLOAT64, 1, (void **)&p);
    vtu_cloud_add_field(c, "normal", VTU_FLOAT64, 3, (void **)&nr);
    vtu_cloud_add_field(c, "id", VTU_INT64, 1, (void **)&id);
    for (size_t i = 0; i < n; i++) {
        for (int d = 0; d < 3; d++) {
            c->points[3 * i + d] = 0.0027 * (double)((i >> (10 * d)) & 1023);
            v[3 * i + d] = sin((double)(i + (size_t)d));
        }
        p[i] = 9810.0 * cos((double)i);
        ty[i] = (int32_t)(i % 3);
        pa[i] = (int32_t)(i % 5) - 1;
        id[i] = (int64_t)i;
    }
}

int main(int argc, char **argv)
{
    static const size_t def[] = { 10000, 100000, 1000000 };
    const char *tmp = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
    char path[4096];
    int nn = argc > 1 ? argc - 1 : 3;

    snprintf(path, sizeof path, "%s/vtuBench.%ld.vtu", tmp, (long)getpid());
    printf("# vtu write/read, fields type patch velocity pressure normal id\n");
    printf("# %10s %7s %10s %10s %10s %10s %12s\n", "points", "format",
           "write_s", "read_s", "MB", "B/point", "Mpoints/s_w");
    for (int k = 0; k < nn; k++) {
        size_t n = argc > 1 ? (size_t)atof(argv[k + 1]) : def[k];
        struct vtu_cloud c = { 0 }, r;
        fill(&c, n);
        for (int binary = 1; binary >= 0; binary--) {
            struct stat st;
            double t0 = now(), t1, t2;
            if (vtu_write(path, &c, binary) != SIM_OK) {
                fprintf(stderr, "%s\n", sim_error_message());
                return 1;
            }
            t1 = now();
            if (vtu_read(path, &r) != SIM_OK) {
                fprintf(stderr, "%s\n", sim_error_message());
                return 1;
            }
            t2 = now();
            stat(path, &st);
            printf("  %10zu %7s %10.4f %10.4f %10.2f %10.1f %12.2f\n", n,
                   binary ? "binary" : "ascii", t1 - t0, t2 - t1,
                   (double)st.st_size / 1e6, (double)st.st_size / (double)n,
                   (double)n / (t1 - t0) / 1e6);
            vtu_cloud_free(&r);
        }
        vtu_cloud_free(&c);
    }
    unlink(path);
    return 0;
}
