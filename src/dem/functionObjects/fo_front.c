/*
 * fo_front.c — front of the granular pack: the largest position along a
 * direction of a grain that belongs to the pack, i.e. to the largest
 * cluster of grains connected by grain-grain contacts (surfaces closer
 * than `tolerance` times the smaller radius, so that neighbours that just
 * touch in a packing count), so that grains that
 * bounced or rolled ahead on their own do not count. The leading grain's
 * position plus its radius is the runout of a column collapse (A.12.2-4:
 * "sediment front"). The clusters are found by union-find over the
 * contacts of the neighbour list.
 * Columns: time, front position [m] (x.direction + R of the leading
 * grain), its id, grains in the pack.
 * Keys: direction (1 0 0);  tolerance 0.05;  (fraction of the smaller
 * radius; gaps beyond the neighbour skin are never seen)
 */
#include <math.h>
#include <stdlib.h>

#include "core/dict.h"
#include "core/error.h"
#include "dem/dem.h"
#include "dem/functionObjects/dem_fo.h"

struct front {
    double dir[3];
    double tol;
    size_t *parent, *size;
    size_t cap;
};

static size_t find(size_t *parent, size_t i)
{
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];   /* path halving */
        i = parent[i];
    }
    return i;
}

static void unite(struct front *fr, size_t a, size_t b)
{
    a = find(fr->parent, a);
    b = find(fr->parent, b);
    if (a == b)
        return;
    if (fr->size[a] < fr->size[b]) {
        size_t t = a;
        a = b, b = t;
    }
    fr->parent[b] = a;
    fr->size[a] += fr->size[b];
}

/* Root of the largest cluster of touching grains. */
static size_t largest_cluster(struct front *fr, const struct dem *d)
{
    for (size_t i = 0; i < d->n; i++)
        fr->parent[i] = i, fr->size[i] = 1;
    for (size_t i = 0; i < d->n; i++)
        for (size_t p = d->nl.start[i]; p < d->nl.start[i + 1]; p++) {
            size_t j = d->nl.j[p];
            double d2 = 0;
            for (int a = 0; a < 3; a++) {
                double dx = d->x[3 * j + a] - d->x[3 * i + a];
                d2 += dx * dx;
            }
            double rs = d->r[i] + d->r[j]
                        + fr->tol * (d->r[i] < d->r[j] ? d->r[i] : d->r[j]);
            if (d2 < rs * rs)
                unite(fr, i, j);
        }
    size_t best = 0;
    for (size_t i = 0; i < d->n; i++)
        if (fr->parent[i] == i && fr->size[i] > fr->size[best])
            best = i;
    return best;
}

static int create(const struct dict *dd, const struct fo_scene *s,
                  void **data)
{
    (void)s;
    struct front *fr = sim_calloc(1, sizeof *fr);
    if (!fr)
        return SIM_ERR_NOMEM;
    *data = fr;
    const double def[3] = {1, 0, 0};
    TRY(dict_get_vector_or(dd, "direction", 3, def, fr->dir));
    double l = sqrt(fr->dir[0] * fr->dir[0] + fr->dir[1] * fr->dir[1]
                    + fr->dir[2] * fr->dir[2]);
    if (!(l > 0))
        return dict_error(dd, "direction", SIM_ERR_DICT,
                          "direction must not be zero");
    for (int a = 0; a < 3; a++)
        fr->dir[a] /= l;
    TRY(dict_get_scalar_or(dd, "tolerance", 0.05, &fr->tol));
    if (!(fr->tol >= 0 && fr->tol < 1))
        return dict_error(dd, "tolerance", SIM_ERR_DICT,
                          "tolerance %g must be in [0, 1)", fr->tol);
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    struct front *fr = data;
    (void)s;
    fprintf(f, "# front of the pack along (%g %g %g) [m]\n"
               "# time front id packGrains\n", fr->dir[0], fr->dir[1],
            fr->dir[2]);
    return SIM_OK;
}

static int execute(void *data, const struct fo_scene *s, FILE *f)
{
    struct front *fr = data;
    const struct dem *d = s->solver;
    if (d->n == 0) {
        fprintf(f, "%.9g nan -1 0\n", s->time);
        return SIM_OK;
    }
    if (d->n > fr->cap) {
        size_t *p = sim_realloc(fr->parent, d->n * sizeof *p);
        if (!p)
            return SIM_ERR_NOMEM;
        fr->parent = p;
        size_t *z = sim_realloc(fr->size, d->n * sizeof *z);
        if (!z)
            return SIM_ERR_NOMEM;
        fr->size = z, fr->cap = d->n;
    }
    size_t root = largest_cluster(fr, d);
    double best = -INFINITY;
    long long id = -1;
    size_t counted = 0;
    for (size_t i = 0; i < d->n; i++) {
        if (find(fr->parent, i) != root)
            continue;
        counted++;
        double x = d->x[3 * i] * fr->dir[0] + d->x[3 * i + 1] * fr->dir[1]
                   + d->x[3 * i + 2] * fr->dir[2] + d->r[i];
        if (x > best)
            best = x, id = (long long)d->id[i];
    }
    fprintf(f, "%.9g %.9g %lld %zu\n", s->time, best, id, counted);
    return SIM_OK;
}

static void destroy(void *data)
{
    struct front *fr = data;
    if (fr) {
        free(fr->parent);
        free(fr->size);
    }
    free(fr);
}

const struct fo_ops dem_fo_front = {
    .name = "front",
    .reference = "",
    .file = "",
    .create = create,
    .header = header,
    .execute = execute,
    .destroy = destroy,
};
