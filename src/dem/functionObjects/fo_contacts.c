/*
 * fo_contacts.c — contact statistics: number of grain-grain and grain-wall
 * contacts and the largest overlap, absolute and relative to the smaller
 * radius (E2-02 maximum overlap; a check that the stiffness is adequate).
 * Columns: time, contacts, wallContacts, maxOverlap [m], maxOverlap/R.
 * Keys: none beyond the schedule.
 */
#include <math.h>

#include "core/error.h"
#include "dem/dem.h"
#include "dem/functionObjects/dem_fo.h"

static int create(const struct dict *d, const struct fo_scene *s, void **data)
{
    (void)d, (void)s;
    *data = NULL;
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    (void)data, (void)s;
    fprintf(f, "# contact statistics\n"
               "# time contacts wallContacts maxOverlap maxOverlapRel\n");
    return SIM_OK;
}

static int execute(void *data, const struct fo_scene *s, FILE *f)
{
    (void)data;
    const struct dem *d = s->solver;
    long nc = 0, nw = 0;
    double dmax = 0, rmax = 0;
    for (size_t i = 0; i < d->n; i++) {
        for (size_t p = d->nl.start[i]; p < d->nl.start[i + 1]; p++) {
            size_t j = d->nl.j[p];
            double d2 = 0;
            for (int a = 0; a < 3; a++) {
                double dx = d->x[3 * j + a] - d->x[3 * i + a];
                d2 += dx * dx;
            }
            double delta = d->r[i] + d->r[j] - sqrt(d2);
            if (delta <= 0)
                continue;
            nc++;
            dmax = fmax(dmax, delta);
            rmax = fmax(rmax, delta / fmin(d->r[i], d->r[j]));
        }
        for (int w = 0; w < d->nwalls; w++) {
            double delta = d->r[i] - wall_distance(&d->walls[w], &d->x[3 * i]);
            if (delta <= 0)
                continue;
            nw++;
            dmax = fmax(dmax, delta);
            rmax = fmax(rmax, delta / d->r[i]);
        }
    }
    fprintf(f, "%.9g %ld %ld %.9g %.9g\n", s->time, nc, nw, dmax, rmax);
    return SIM_OK;
}

static void destroy(void *data)
{
    (void)data;
}

const struct fo_ops dem_fo_contacts = {
    .name = "contacts",
    .reference = "E2-02",
    .file = "",
    .create = create,
    .header = header,
    .execute = execute,
    .destroy = destroy,
};
