/*
 * fuzz_vtu.c — libFuzzer target for the VTU/PVD reader (src/io).
 *
 * Any input must either be read or fail with SIM_ERR_IO (or NOMEM), never
 * crash, hang or leak. What is read is written back in binary and in
 * ascii and read again: both must give the same cloud, bit for bit. The
 * same bytes are also offered to pvd_add as an existing collection, which
 * must either refuse it or leave a collection that reads back.
 * Build and run with test/fuzz/run_vtu.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/error.h"
#include "io/vtu.h"

static char in_path[64], out_path[64], pvd_path[64];

static void same(const struct vtu_cloud *a, const struct vtu_cloud *b)
{
    static const size_t sz[] = { 8, 8, 4, 1 };
    if (a->n != b->n || a->nfields != b->nfields ||
        memcmp(&a->time, &b->time, sizeof a->time) ||
        (a->n && memcmp(a->points, b->points, 24 * a->n)))
        abort();
    for (int i = 0; i < a->nfields; i++) {
        const struct vtu_field *f = &a->fields[i], *g = &b->fields[i];
        if (strcmp(f->name, g->name) || f->type != g->type ||
            f->ncomp != g->ncomp ||
            (a->n && memcmp(f->data, g->data,
                            a->n * (size_t)f->ncomp * sz[f->type])))
            abort();
    }
}

static void spit(const char *path, const uint8_t *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(data, 1, size, f) != size)
        abort();
    fclose(f);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct vtu_cloud c, r;
    int rc;

    if (!in_path[0]) {
        snprintf(in_path, sizeof in_path, "/tmp/fuzz_vtu_in.%ld.vtu",
                 (long)getpid());
        snprintf(out_path, sizeof out_path, "/tmp/fuzz_vtu_out.%ld.vtu",
                 (long)getpid());
        snprintf(pvd_path, sizeof pvd_path, "/tmp/fuzz_vtu.%ld.pvd",
                 (long)getpid());
    }
    spit(in_path, data, size);
    rc = vtu_read(in_path, &c);
    if (rc == SIM_OK) {
        for (int binary = 0; binary < 2; binary++) {
            if (vtu_write(out_path, &c, binary) != SIM_OK)
                abort();
            if (vtu_read(out_path, &r) != SIM_OK)
                abort();
            same(&c, &r);
            vtu_cloud_free(&r);
        }
        vtu_cloud_free(&c);
    } else if (rc != SIM_ERR_IO && rc != SIM_ERR_NOMEM) {
        abort();
    } else if (c.n || c.points || c.fields) {
        abort(); /* a failed read leaves an empty cloud */
    }
    spit(pvd_path, data, size);
    rc = pvd_add(pvd_path, 1.5, "x.vtu");
    if (rc == SIM_OK && pvd_truncate(pvd_path, 2.0) != SIM_OK)
        abort(); /* what pvd_add wrote must read back */
    else if (rc != SIM_OK && rc != SIM_ERR_IO)
        abort();
    sim_error_clear();
    unlink(in_path);
    unlink(out_path);
    unlink(pvd_path);
    return 0;
}
