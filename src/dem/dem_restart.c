/*
 * dem_restart.c — contact histories written beside dem.vtu so that a
 * restart continues a run exactly (tangential springs included), and the
 * start-up overlap check (dem_case.h).
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "core/log.h"
#include "dem/dem_case.h"

int dem_write_contacts(const char *path, const struct dem *d)
{
    char tmp[4200];
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    FILE *f = fopen(tmp, "w");
    if (!f)
        return sim_error(SIM_ERR_IO, "%s: cannot create: %s", tmp,
                         strerror(errno));
    fprintf(f, "# demContacts: tangential springs [m] at t = %.17g\n"
               "# h_next %.17g\n"
               "# id_i id_j (or -(wall+1)) hx hy hz\n", d->t, d->h_next);
    for (size_t i = 0; i < d->n; i++) {
        for (size_t p = d->nl.start[i]; p < d->nl.start[i + 1]; p++) {
            const double *h = &d->hist[3 * p];
            if (h[0] != 0 || h[1] != 0 || h[2] != 0)
                fprintf(f, "%lld %lld %.17g %.17g %.17g\n",
                        (long long)d->id[i], (long long)d->id[d->nl.j[p]],
                        h[0], h[1], h[2]);
        }
        for (int w = 0; w < d->nwalls; w++) {
            const double *h = &d->whist[3 * (i * (size_t)d->nwalls + w)];
            if (h[0] != 0 || h[1] != 0 || h[2] != 0)
                fprintf(f, "%lld %d %.17g %.17g %.17g\n", (long long)d->id[i],
                        -(w + 1), h[0], h[1], h[2]);
        }
    }
    int bad = ferror(f);
    if (fclose(f) != 0 || bad || rename(tmp, path) != 0) {
        remove(tmp);
        return sim_error(SIM_ERR_IO, "%s: write failed", path);
    }
    return SIM_OK;
}

struct id_index {
    int64_t id;
    size_t i;
};

static int cmp_id(const void *a, const void *b)
{
    const struct id_index *x = a, *y = b;
    return (x->id > y->id) - (x->id < y->id);
}

static long find_id(const struct id_index *t, size_t n, int64_t id)
{
    struct id_index key = {id, 0};
    const struct id_index *hit = bsearch(&key, t, n, sizeof *t, cmp_id);
    return hit ? (long)hit->i : -1;
}

/* Store spring h for the pair (a, b); the list keeps i < j, and the spring
 * seen from the other grain is -h. */
static int set_pair(struct dem *d, size_t a, size_t b, const double *h)
{
    double s = 1;
    if (a > b) {
        size_t t = a;
        a = b, b = t, s = -1;
    }
    for (size_t p = d->nl.start[a]; p < d->nl.start[a + 1]; p++)
        if (d->nl.j[p] == b) {
            for (int k = 0; k < 3; k++)
                d->hist[3 * p + k] = s * h[k];
            return 1;
        }
    return 0;
}

int dem_read_contacts(const char *path, struct dem *d, int *found)
{
    dem_invalidate_forces(d);
    FILE *f = fopen(path, "r");
    *found = f != NULL;
    if (!f)
        return SIM_OK;
    struct id_index *t = sim_malloc((d->n ? d->n : 1) * sizeof *t);
    if (!t) {
        fclose(f);
        return SIM_ERR_NOMEM;
    }
    for (size_t i = 0; i < d->n; i++)
        t[i] = (struct id_index){d->id[i], i};
    qsort(t, d->n, sizeof *t, cmp_id);
    char line[512];
    long lineno = 0, lost = 0;
    int rc = SIM_OK;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        double hn;
        if (sscanf(line, "# h_next %lg", &hn) == 1)
            d->h_next = hn;
        if (line[0] == '#')
            continue;
        long long a, b;
        double h[3];
        if (sscanf(line, "%lld %lld %lg %lg %lg", &a, &b, &h[0], &h[1],
                   &h[2]) != 5) {
            rc = sim_error(SIM_ERR_IO, "%s:%ld: expected 'id id hx hy hz'",
                           path, lineno);
            break;
        }
        long ia = find_id(t, d->n, a);
        if (ia < 0) {
            lost++;
            continue;
        }
        if (b < 0) {
            long w = -b - 1;
            if (w >= d->nwalls) {
                lost++;
                continue;
            }
            memcpy(&d->whist[3 * ((size_t)ia * d->nwalls + (size_t)w)], h,
                   sizeof h);
            continue;
        }
        long ib = find_id(t, d->n, b);
        if (ib < 0 || !set_pair(d, (size_t)ia, (size_t)ib, h))
            lost++;
    }
    fclose(f);
    free(t);
    if (lost)
        log_warn("%s: %ld contact histories matched no current contact "
                 "pair", path, lost);
    return rc;
}

/* Worst overlapping pair and count above frac; ij receives the pair. */
static long scan_pairs(struct dem *d, double frac, double *worst,
                       size_t ij[2])
{
    long c = 0;
    *worst = 0;
    for (size_t i = 0; i < d->n; i++)
        for (size_t p = d->nl.start[i]; p < d->nl.start[i + 1]; p++) {
            size_t j = d->nl.j[p];
            double d2 = 0;
            for (int a = 0; a < 3; a++) {
                double dx = d->x[3 * j + a] - d->x[3 * i + a];
                d2 += dx * dx;
            }
            double rel = (d->r[i] + d->r[j] - sqrt(d2))
                         / fmin(d->r[i], d->r[j]);
            if (rel > frac)
                c++;
            if (rel > *worst)
                *worst = rel, ij[0] = i, ij[1] = j;
        }
    return c;
}

/* One relaxation sweep: move each pair apart (and grains out of walls) to
 * the allowed overlap, half each. */
static void relax_sweep(struct dem *d, double frac)
{
    for (size_t i = 0; i < d->n; i++) {
        for (size_t p = d->nl.start[i]; p < d->nl.start[i + 1]; p++) {
            size_t j = d->nl.j[p];
            double dx[3], d2 = 0;
            for (int a = 0; a < 3; a++) {
                dx[a] = d->x[3 * j + a] - d->x[3 * i + a];
                d2 += dx[a] * dx[a];
            }
            double dist = sqrt(d2);
            double target = d->r[i] + d->r[j]
                            - frac * fmin(d->r[i], d->r[j]);
            if (dist >= target || dist == 0)
                continue;
            double s = 0.5 * (target - dist) / dist;
            for (int a = 0; a < 3; a++) {
                d->x[3 * i + a] -= s * dx[a];
                d->x[3 * j + a] += s * dx[a];
            }
        }
        for (int w = 0; w < d->nwalls; w++) {
            double n[3], delta;
            if (!wall_contact(&d->walls[w], &d->x[3 * i], d->r[i], n, &delta))
                continue;
            double excess = delta - frac * d->r[i];
            if (excess > 0)
                for (int a = 0; a < 3; a++)
                    d->x[3 * i + a] -= excess * n[a];
        }
    }
}

int dem_check_initial_overlap(struct dem *d, const struct dem_solution *s,
                              const char *where)
{
    long count;
    double worst;
    dem_overlap_stats(d, s->max_overlap, &count, &worst);
    if (count == 0) {
        log_info("Initial overlap: none above %g of the smaller radius "
                 "(largest %.3g)", s->max_overlap, worst);
        return SIM_OK;
    }
    if (!s->relax_overlap) {
        size_t ij[2] = {0, 0}, gw = 0;
        double wp, ww = 0;
        int w = -1;
        scan_pairs(d, s->max_overlap, &wp, ij);
        /* The worst may be a grain in a wall (a stray grain far outside
         * the tank, x = 1e300): the pair alone named "grains 0 and 0". */
        for (size_t i = 0; i < d->n; i++)
            for (int k = 0; k < d->nwalls; k++) {
                double n[3], delta;
                if (wall_contact(&d->walls[k], &d->x[3 * i], d->r[i], n,
                                 &delta) && delta / d->r[i] > ww)
                    ww = delta / d->r[i], gw = i, w = k;
            }
        char eg[256];
        const double *x = &d->x[3 * gw];
        if (w >= 0 && ww > wp)
            snprintf(eg, sizeof eg, "grain id %lld at (%g %g %g) and wall "
                     "%d of patch %s", (long long)d->id[gw], x[0], x[1],
                     x[2], w, d->patch_names[d->walls[w].patch]);
        else
            snprintf(eg, sizeof eg, "grains id %lld and %lld",
                     (long long)d->id[ij[0]], (long long)d->id[ij[1]]);
        return sim_error(SIM_ERR_INPUT,
                         "%s: %ld contacts overlap by more than %g of the "
                         "smaller radius (largest %.3g, e.g. %s); set "
                         "initialOverlap/action relax in system/demSolution "
                         "to separate them", where, count, s->max_overlap,
                         worst, eg);
    }
    log_info("Initial overlap: %ld contacts above %g (largest %.3g): "
             "relaxing", count, s->max_overlap, worst);
    for (int it = 0; it < 200 && count > 0; it++) {
        relax_sweep(d, 0.5 * s->max_overlap);
        TRY(dem_update_neighbours(d, d->x));
        dem_overlap_stats(d, s->max_overlap, &count, &worst);
    }
    if (count > 0)
        return sim_error(SIM_ERR_INPUT, "%s: %ld contacts still overlap by "
                         "more than %g after 200 relaxation sweeps (largest "
                         "%.3g): the packing is too dense", where, count,
                         s->max_overlap, worst);
    log_info("Initial overlap: relaxed, largest now %.3g", worst);
    return SIM_OK;
}
