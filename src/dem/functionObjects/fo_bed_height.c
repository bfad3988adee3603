/*
 * fo_bed_height.c — height of the granular bed: the top (x.up + R) of the
 * highest grain that rests on the bed (at least minContacts contacts), and
 * the mean top of the grains within one diameter of it (a smoother
 * surface measure), optionally only over a horizontal window.
 * Columns: time, bed top [m], mean top of the surface layer [m], grains in
 * that layer.
 * Keys: up (0 0 1);  minContacts 2;  min (x y z) / max (x y z) optional
 * window on the other coordinates.
 */
#include <math.h>
#include <stdlib.h>

#include "core/dict.h"
#include "core/error.h"
#include "dem/dem.h"
#include "dem/functionObjects/dem_fo.h"

struct bed {
    double up[3], lo[3], hi[3];
    long min_contacts;
    int *cnt;
    size_t cap;
};

static int create(const struct dict *dd, const struct fo_scene *s,
                  void **data)
{
    (void)s;
    struct bed *b = sim_calloc(1, sizeof *b);
    if (!b)
        return SIM_ERR_NOMEM;
    *data = b;
    const double up[3] = {0, 0, 1}, lo[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    const double hi[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
    TRY(dict_get_vector_or(dd, "up", 3, up, b->up));
    double l = sqrt(b->up[0] * b->up[0] + b->up[1] * b->up[1]
                    + b->up[2] * b->up[2]);
    if (!(l > 0))
        return dict_error(dd, "up", SIM_ERR_DICT, "up must not be zero");
    for (int a = 0; a < 3; a++)
        b->up[a] /= l;
    TRY(dict_get_vector_or(dd, "min", 3, lo, b->lo));
    TRY(dict_get_vector_or(dd, "max", 3, hi, b->hi));
    TRY(dict_get_label_or(dd, "minContacts", 2, &b->min_contacts));
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    (void)data, (void)s;
    fprintf(f, "# bed height [m]\n# time top meanSurface surfaceGrains\n");
    return SIM_OK;
}

static int in_window(const struct bed *b, const double *x)
{
    for (int a = 0; a < 3; a++)
        if (x[a] < b->lo[a] || x[a] > b->hi[a])
            return 0;
    return 1;
}

static int execute(void *data, const struct fo_scene *s, FILE *f)
{
    struct bed *b = data;
    const struct dem *d = s->solver;
    if (d->n > b->cap) {
        int *c = sim_realloc(b->cnt, d->n * sizeof *c);
        if (!c)
            return SIM_ERR_NOMEM;
        b->cnt = c, b->cap = d->n;
    }
    dem_fo_contact_counts(d, b->cnt);
    double top = -INFINITY;
    for (size_t i = 0; i < d->n; i++)
        if (b->cnt[i] >= b->min_contacts && in_window(b, &d->x[3 * i]))
            top = fmax(top, d->x[3 * i] * b->up[0] + d->x[3 * i + 1] * b->up[1]
                                + d->x[3 * i + 2] * b->up[2] + d->r[i]);
    double sum = 0;
    long m = 0;
    for (size_t i = 0; i < d->n && isfinite(top); i++) {
        if (b->cnt[i] < b->min_contacts || !in_window(b, &d->x[3 * i]))
            continue;
        double h = d->x[3 * i] * b->up[0] + d->x[3 * i + 1] * b->up[1]
                   + d->x[3 * i + 2] * b->up[2] + d->r[i];
        if (h > top - 2 * d->r[i])
            sum += h, m++;
    }
    if (m)
        fprintf(f, "%.9g %.9g %.9g %ld\n", s->time, top, sum / m, m);
    else
        fprintf(f, "%.9g nan nan 0\n", s->time);
    return SIM_OK;
}

static void destroy(void *data)
{
    struct bed *b = data;
    if (b)
        free(b->cnt);
    free(b);
}

const struct fo_ops dem_fo_bed_height = {
    .name = "bedHeight",
    .reference = "",
    .file = "",
    .create = create,
    .header = header,
    .execute = execute,
    .destroy = destroy,
};
