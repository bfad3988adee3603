/*
 * dem_fo.c — registry of the DEM function objects and the contact count
 * they share.
 */
#include "dem/functionObjects/dem_fo.h"

#include <math.h>
#include <string.h>

#include "dem/dem.h"

const struct fo_ops *const dem_fo_table[] = {
    &dem_fo_kinetic_energy, &dem_fo_wall_forces, &dem_fo_front,
    &dem_fo_bed_height, &dem_fo_grain_state, &dem_fo_contacts, NULL};

void dem_fo_contact_counts(const struct dem *d, int *cnt)
{
    memset(cnt, 0, d->n * sizeof *cnt);
    for (size_t i = 0; i < d->n; i++) {
        for (size_t p = d->nl.start[i]; p < d->nl.start[i + 1]; p++) {
            size_t j = d->nl.j[p];
            double d2 = 0;
            for (int a = 0; a < 3; a++) {
                double dx = d->x[3 * j + a] - d->x[3 * i + a];
                d2 += dx * dx;
            }
            double rs = d->r[i] + d->r[j];
            if (d2 < rs * rs)
                cnt[i]++, cnt[j]++;
        }
        for (int w = 0; w < d->nwalls; w++)
            if (wall_distance(&d->walls[w], &d->x[3 * i]) < d->r[i])
                cnt[i]++;
    }
}
