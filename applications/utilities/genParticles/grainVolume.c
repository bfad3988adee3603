/*
 * grainVolume.c — `grainVolume scale;` in a fluid region: the water the
 * grains displace is taken out of the particles' volumes, so that a
 * coupled run starts at rest.
 *
 * With the fluid lattice filling the pores (`fill`, what Xie et al. 2025
 * §3.1 appear to do: doc/theory.md A0-16) every particle
 * inside a packed bed has the porosity-weighted number density (eq. 7,
 * sum of w/eps_j) of about n0/eps, twice n0 in a simple-cubic bed: the PPE
 * source (12)/(13) reads that as a compression of 100 % and, at dt = 1e-4
 * s, answers with a pressure of order 1e5 Pa in the first step, which
 * throws the water out of the bed and over the walls.
 *
 * With `scale` the lattice stays whole and each fluid particle holds the
 * fluid volume phi_i dp^d, phi_i = eps_i the porosity the coupled solver
 * will compute at its site (eqs. 29-31 with the kernel radius r_e,s and
 * the clamp porosityMin of system/couplingDict), written as the field
 * volumeFraction of 0/fluid.vtu. The coupling then weighs every neighbour
 * by phi_j/eps_j instead of 1/eps_j (couple_fluid.c), so that <n>_i = n0
 * at t = 0, and the total fluid volume sum phi_i dp^d is the water's.
 * (Removing a fraction 1 - eps of the sites instead leaves an irregular
 * cloud whose <n>_i scatter by ~10 %, biased by a few per cent in places:
 * the density term of the PPE turns that into pressure errors of the
 * order of the hydrostatic pressure in the first step.)
 * Wall and dummy particles keep phi = 1 (walls are not porous).
 *
 * Default (issue 23): `scale` in a case with system/couplingDict, the
 * one that starts a coupled run at rest; `fill` in a case without one,
 * where no porosity is defined and nothing would be scaled.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/app.h"
#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "coupling/models.h"
#include "coupling/pairs.h"
#include "coupling/porosity.h"
#include "genParticles.h"

static const char *const grain_volume_names[] = { "fill", "scale", NULL };

/* Porosity at every MPS site from the grains, as the coupled run sees it. */
static int site_porosity(const struct app *a, const struct gen_case *c,
                         const struct mps_cloud *m, const struct dem_cloud *g,
                         const struct region *asker, double *eps)
{
    struct coupling_settings cs;
    struct coupling_pairs pairs;
    struct dict *cd;
    double *Vg;
    int rc;

    TRY(app_read_dict_optional(a, "system/couplingDict", &cd));
    if (!cd)
        return dict_error(asker->d, "grainVolume", SIM_ERR_DICT,
                          "region '%s': grainVolume scale needs "
                          "system/couplingDict (its kernelRadius and "
                          "porosityMin define the porosity)", asker->name);
    rc = coupling_settings_read(cd, &cs);
    dict_free(cd);
    TRY(rc);
    Vg = sim_malloc((g->n ? g->n : 1) * sizeof *Vg);
    if (!Vg)
        return SIM_ERR_NOMEM;
    for (size_t k = 0; k < g->n; k++)
        Vg[k] = coupling_grain_measure(c->dim, g->radius[k], c->dp);
    memset(&pairs, 0, sizeof pairs);
    rc = coupling_pairs_build(&pairs, c->dim, cs.radius * c->dp, (int)g->n,
                              g->x, (int)m->n, m->x);
    if (rc == SIM_OK)
        rc = coupling_porosity(&pairs, Vg, cs.eps_min, eps, NULL, NULL);
    coupling_pairs_free(&pairs);
    free(Vg);
    return rc;
}

int gen_grain_volume(const struct app *a, struct gen_case *c,
                     struct mps_cloud *m, const struct dem_cloud *g)
{
    int *scale = sim_calloc((size_t)c->nregions, sizeof *scale);
    double *solid = sim_calloc((size_t)c->nregions, sizeof *solid);
    const struct region *asker = NULL;
    int rc = SIM_OK;

    if (!scale || !solid) {
        rc = SIM_ERR_NOMEM;
        goto out;
    }
    char path[4096];
    int coupled = !access(app_path(a, "system/couplingDict", path,
                                   sizeof path), R_OK);
    for (int i = 0; i < c->nregions; i++) {
        if (c->r[i].type != REGION_FLUID)
            continue;
        TRY_GOTO(rc, dict_get_word_or(c->r[i].d, "grainVolume",
                                      grain_volume_names, coupled,
                                      &scale[i]),
                 out);
        if (scale[i] && !asker)
            asker = &c->r[i];
    }
    if (!asker || g->n == 0 || m->n == 0)
        goto out;
    m->phi = sim_malloc(m->n * sizeof *m->phi);
    if (!m->phi) {
        rc = SIM_ERR_NOMEM;
        goto out;
    }
    TRY_GOTO(rc, site_porosity(a, c, m, g, asker, m->phi), out);
    for (size_t k = 0; k < m->n; k++) {
        int i = m->region[k];
        if (m->type[k] == TYPE_FLUID && scale[i])
            solid[i] += 1.0 - m->phi[k];
        else
            m->phi[k] = 1.0;
    }
    for (int i = 0; i < c->nregions; i++)
        if (scale[i])
            log_info("Region %s: grainVolume scale: the particles' volume "
                     "fractions take out %.1f dp^%d where the grains are "
                     "(eq. 31)", c->r[i].name, solid[i], c->dim);
out:
    free(scale);
    free(solid);
    return rc;
}
