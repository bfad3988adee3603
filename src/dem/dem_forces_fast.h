/*
 * dem_forces_fast.h — dem_forces' one-thread path for the fused default
 * law with stored springs (dem_forces_fast.c); internal to src/dem.
 */
#ifndef MPSDEM_DEM_DEM_FORCES_FAST_H
#define MPSDEM_DEM_DEM_FORCES_FAST_H

#include "dem/dem.h"

/* Non-zero when dem_forces may take the fast path on nth threads: one
 * thread, no ARKode spring state or slip phases, the fused law. */
int dem_forces_fast_ok(const struct dem *d, int nth);

/* dem_forces after dem_walls_at, with its buffers reserved (d->tbuf all
 * zero, at least 6n doubles): same results to the bit. */
int dem_forces_fast(struct dem *d, const double *x, const double *v,
                    const double *w, double tau, int commit, double *acc,
                    double *alpha);

#endif
