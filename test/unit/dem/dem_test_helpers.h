/*
 * dem_test_helpers.h — small set-up helpers shared by the DEM tests (header
 * only: every test file is its own executable).
 */
#ifndef DEM_TEST_HELPERS_H
#define DEM_TEST_HELPERS_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "dem/dem.h"
#include "dem/integrators/integrator.h"

/* Table 1 glass beads (doc/theory.md A.11). */
#define T1_E 1.0e8
#define T1_NU 0.2
#define T1_RHO 2500.0
#define T1_MU 0.2
#define T1_E_REST 0.9
#define T1_R 0.00135

static inline int th_law(struct dem *d, const struct contact_normal_ops *n,
                         const struct contact_damping_ops *dm,
                         const struct contact_tangential_ops *t,
                         const struct contact_rolling_ops *r, double mu,
                         double e)
{
    d->law.normal = n;
    d->law.damping = dm;
    d->law.tangential = t;
    d->law.rolling = r;
    d->law.c.E = T1_E;
    d->law.c.nu = T1_NU;
    d->law.c.rho = T1_RHO;
    d->law.c.mu = mu;
    d->law.c.e = e;
    return contact_law_init(&d->law);
}

/* n grains of radius T1_R at rest at the origin; the caller places them. */
static inline int th_grains(struct dem *d, size_t n)
{
    int rc = dem_resize(d, n);
    for (size_t i = 0; i < n; i++) {
        d->r[i] = T1_R;
        d->id[i] = (int64_t)i;
    }
    return rc;
}

static inline void th_floor(struct dem *d)
{
    const double p[3] = {0, 0, 0}, u[3] = {0, 0, 1};
    d->walls = malloc(sizeof *d->walls);
    wall_plane(&d->walls[0], 3, p, u, 0);
    d->nwalls = 1;
    d->npatches = 1;
    strcpy(d->patch_names[0], "floor");
}

static inline struct dem_integrator_params th_params(void)
{
    struct dem_integrator_params p = {
        .dt = 0, .dt_fraction = 0.1, .rtol = 1e-6, .atol_x = 1e-9,
        .atol_v = 1e-6, .atol_w = 1e-3, .safety = 0.5,
        .table = "ARKODE_DORMAND_PRINCE_7_4_5", .max_steps = 10000000};
    return p;
}

#endif
