/*
 * grainVolume.c — `grainVolume exclude;` in a fluid region: leave out the
 * water the grains displace, so that a coupled run starts at rest.
 *
 * With the fluid lattice filling the pores (`fill`, the default, which is
 * what Xie et al. 2025 §3.1 appear to do: METHODS.md A0-16) every particle
 * inside a packed bed has the porosity-weighted number density (eq. 7,
 * sum of w/eps_j) of about n0/eps, twice n0 in a simple-cubic bed: the PPE
 * source (12)/(13) reads that as a compression of 100 % and, at dt = 1e-4
 * s, answers with a pressure of order 1e5 Pa in the first step, which
 * throws the water out of the bed and over the walls. The physical state
 * is the one where the pores hold the fluid: eps/dp^d particles per unit
 * volume, i.e. <n>_i ~ n0 everywhere.
 *
 * So each fluid site of such a region is kept with the probability eps_i,
 * the porosity the coupled solver will compute there (eqs. 29-31 with the
 * kernel radius r_e,s and the clamp porosityMin of system/couplingDict).
 * The choice is deterministic, by error diffusion along the Morton
 * (Z-order) curve of the lattice indices: the running sum of eps over the
 * visited sites decides, so that any run of consecutive sites keeps the
 * number its porosity asks for to within one, and the kept sites spread
 * over all three directions (a raster order would remove whole columns).
 * Wall and dummy particles are never removed (walls are not porous).
 */
#include <math.h>
#include <stdint.h>
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

static const char *const grain_volume_names[] = { "fill", "exclude", NULL };

/* Interleave the low 21 bits of three indices (Morton order). */
static uint64_t spread3(uint64_t v)
{
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
}

struct site { uint64_t key; size_t k; };

static int by_key(const void *a, const void *b)
{
    const struct site *p = a, *q = b;
    return (p->key > q->key) - (p->key < q->key);
}

/* Porosity at every MPS site from the grains, as the coupled run sees it. */
static int site_porosity(const struct app *a, const struct gen_case *c,
                         const struct mps_cloud *m, const struct dem_cloud *g,
                         const struct region *asker, double *eps)
{
    struct coupling_settings cs;
    struct coupling_pairs pairs;
    struct dict *cd;
    char path[4096];
    double *Vg;
    int rc;

    if (access(app_path(a, "system/couplingDict", path, sizeof path), R_OK))
        return dict_error(asker->d, "grainVolume", SIM_ERR_DICT,
                          "region '%s': grainVolume exclude needs "
                          "system/couplingDict (its kernelRadius and "
                          "porosityMin define the porosity)", asker->name);
    TRY(app_read_dict(a, "system/couplingDict", &cd));
    rc = coupling_settings_read(cd, &cs);
    dict_free(cd);
    TRY(rc);
    Vg = sim_malloc((g->n ? g->n : 1) * sizeof *Vg);
    if (!Vg)
        return SIM_ERR_NOMEM;
    /* 2-D: a sphere's volume spread over the unit depth dp, as the coupled
     * solver does (couple_fluid.c). */
    for (size_t k = 0; k < g->n; k++) {
        double r = g->radius[k], V = 4.0 / 3.0 * M_PI * r * r * r;
        Vg[k] = c->dim == 3 ? V : V / c->dp;
    }
    memset(&pairs, 0, sizeof pairs);
    rc = coupling_pairs_build(&pairs, c->dim, cs.radius * c->dp, (int)g->n,
                              g->x, (int)m->n, m->x);
    if (rc == SIM_OK)
        rc = coupling_porosity(&pairs, Vg, cs.eps_min, eps, NULL, NULL);
    coupling_pairs_free(&pairs);
    free(Vg);
    return rc;
}

/* Error diffusion along the Morton curve over the sites with keep[k] set
 * on entry; clears keep[k] of the sites left out. */
static int choose_sites(const struct gen_case *c, const struct mps_cloud *m,
                        const double *eps, uint8_t *keep)
{
    size_t ns = 0;
    for (size_t k = 0; k < m->n; k++)
        ns += keep[k];
    struct site *s = sim_malloc((ns ? ns : 1) * sizeof *s);
    if (!s)
        return SIM_ERR_NOMEM;
    double lo[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL };
    for (size_t k = 0; k < m->n; k++)
        for (int d = 0; d < 3 && keep[k]; d++)
            lo[d] = fmin(lo[d], m->x[3 * k + d]);
    ns = 0;
    for (size_t k = 0; k < m->n; k++) {
        if (!keep[k])
            continue;
        uint64_t key = 0;
        for (int d = 0; d < c->dim; d++) {
            uint64_t i = (uint64_t)llround((m->x[3 * k + d] - lo[d]) / c->dp);
            key |= spread3(i) << d;
        }
        s[ns].key = key;
        s[ns++].k = k;
    }
    qsort(s, ns, sizeof *s, by_key);
    double acc = 0.0;
    for (size_t q = 0; q < ns; q++) {
        acc += eps[s[q].k];
        if (acc >= 0.5)
            acc -= 1.0;
        else
            keep[s[q].k] = 0;
    }
    free(s);
    return SIM_OK;
}

static void compact(struct mps_cloud *m, const uint8_t *keep)
{
    size_t n = 0;
    for (size_t k = 0; k < m->n; k++) {
        if (!keep[k])
            continue;
        memmove(m->x + 3 * n, m->x + 3 * k, 3 * sizeof *m->x);
        memmove(m->u + 3 * n, m->u + 3 * k, 3 * sizeof *m->u);
        memmove(m->normal + 3 * n, m->normal + 3 * k, 3 * sizeof *m->normal);
        m->p[n] = m->p[k];
        m->type[n] = m->type[k];
        m->patch[n] = m->patch[k];
        m->region[n] = m->region[k];
        n++;
    }
    m->n = n;
}

struct region_use {
    int mode;         /* index in grain_volume_names */
    size_t removed;   /* fluid sites left out        */
    double solid;     /* sum of 1 - eps over them    */
};

int gen_exclude_grains(const struct app *a, struct gen_case *c,
                       struct mps_cloud *m, const struct dem_cloud *g)
{
    struct region_use *u = sim_calloc((size_t)c->nregions, sizeof *u);
    const struct region *asker = NULL;
    uint8_t *keep = NULL;
    double *eps = NULL;
    int rc = SIM_OK;

    if (!u)
        return SIM_ERR_NOMEM;
    for (int i = 0; i < c->nregions; i++) {
        if (c->r[i].type != REGION_FLUID)
            continue;
        TRY_GOTO(rc, dict_get_word_or(c->r[i].d, "grainVolume",
                                      grain_volume_names, 0, &u[i].mode),
                 out);
        if (u[i].mode && !asker)
            asker = &c->r[i];
    }
    if (!asker || g->n == 0 || m->n == 0)
        goto out;
    keep = sim_malloc(m->n);
    eps = sim_malloc(m->n * sizeof *eps);
    if (!keep || !eps) {
        rc = SIM_ERR_NOMEM;
        goto out;
    }
    TRY_GOTO(rc, site_porosity(a, c, m, g, asker, eps), out);
    for (size_t k = 0; k < m->n; k++)
        keep[k] = m->type[k] == TYPE_FLUID && u[m->region[k]].mode;
    TRY_GOTO(rc, choose_sites(c, m, eps, keep), out);
    for (size_t k = 0; k < m->n; k++) {
        int i = m->region[k];
        if (m->type[k] != TYPE_FLUID || !u[i].mode) {
            keep[k] = 1;
            continue;
        }
        u[i].solid += 1.0 - eps[k];
        if (!keep[k]) {
            u[i].removed++;
            c->r[i].count[0]--;
        }
    }
    compact(m, keep);
    for (int i = 0; i < c->nregions; i++)
        if (u[i].mode)
            log_info("Region %s: grainVolume exclude: %zu fluid particles "
                     "left out where the grains are (grain volume %.1f "
                     "dp^%d by eq. 31)", c->r[i].name, u[i].removed,
                     u[i].solid, c->dim);
out:
    free(u);
    free(keep);
    free(eps);
    return rc;
}
