/*
 * fo_front.c — front of the granular pack: the largest position along a
 * direction of a grain that touches the pack (has at least minContacts
 * contacts with grains or walls), so that a grain bouncing ahead in the
 * air does not count. Its x, plus its radius, is the runout of a column
 * collapse (A.12.2-4: "sediment front").
 * Columns: time, front position [m] (x.direction + R of the leading
 * grain), its id, grains counted.
 * Keys: direction (1 0 0);  minContacts 1;
 */
#include <math.h>
#include <stdlib.h>

#include "core/dict.h"
#include "core/error.h"
#include "dem/dem.h"
#include "dem/functionObjects/dem_fo.h"

struct front {
    double dir[3];
    long min_contacts;
    int *cnt;
    size_t cap;
};

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
    TRY(dict_get_label_or(dd, "minContacts", 1, &fr->min_contacts));
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    struct front *fr = data;
    (void)s;
    fprintf(f, "# front of the pack along (%g %g %g) [m]\n"
               "# time front id counted\n", fr->dir[0], fr->dir[1],
            fr->dir[2]);
    return SIM_OK;
}

static int execute(void *data, const struct fo_scene *s, FILE *f)
{
    struct front *fr = data;
    const struct dem *d = s->solver;
    if (d->n > fr->cap) {
        int *c = sim_realloc(fr->cnt, d->n * sizeof *c);
        if (!c)
            return SIM_ERR_NOMEM;
        fr->cnt = c, fr->cap = d->n;
    }
    dem_fo_contact_counts(d, fr->cnt);
    double best = -INFINITY;
    long long id = -1;
    size_t counted = 0;
    for (size_t i = 0; i < d->n; i++) {
        if (fr->cnt[i] < fr->min_contacts)
            continue;
        counted++;
        double x = d->x[3 * i] * fr->dir[0] + d->x[3 * i + 1] * fr->dir[1]
                   + d->x[3 * i + 2] * fr->dir[2] + d->r[i];
        if (x > best)
            best = x, id = (long long)d->id[i];
    }
    if (counted)
        fprintf(f, "%.9g %.9g %lld %zu\n", s->time, best, id, counted);
    else
        fprintf(f, "%.9g nan -1 0\n", s->time);
    return SIM_OK;
}

static void destroy(void *data)
{
    struct front *fr = data;
    if (fr)
        free(fr->cnt);
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
