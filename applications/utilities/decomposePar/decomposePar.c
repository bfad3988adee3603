/*
 * decomposePar — the domain decomposition of an mpsFluid case for a
 * distributed run, as OpenFOAM's decomposePar: system/decomposeParDict
 * gives the number of subdomains and the method; the start cloud
 * (<startTime>/fluid.vtu, written by genParticles) is cut by recursive
 * coordinate bisection (particles/decompose.h) and the report gives, per
 * subdomain, its particles, their weight, its halo (the particles of other
 * subdomains within the neighbour-list radius of mpsFluid's settings,
 * which a distributed run receives every step) and its neighbours (one
 * message each way per exchange), then the totals.
 *
 *   decomposePar [-case DIR] -dry-run [-time T] [-subdomains N]
 *
 * Only the dry run exists: `mpirun -np N mpsFluid -parallel` cuts the
 * start cloud itself (the same bisection, the same dictionary), so there
 * are no processor directories to write; without -dry-run the program
 * says so. -subdomains overrides numberOfSubdomains (a scaling table
 * runs it for several N on one case).
 *
 * system/decomposeParDict: particles/decompose.h (maxImbalance is read
 * and checked, and used only by the distributed run).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/app.h"
#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "core/select.h"
#include "io/vtu.h"
#include "mps/mps.h"
#include "particles/decompose.h"
#include "particles/lattice.h"

struct settings {
    long nparts;
    int balance_all;
    int dim;
    double dp, rc;
};

static int read_settings(const struct app *a, const char *subdomains,
                         struct settings *s)
{
    struct dict *dec = NULL, *pat = NULL, *tr = NULL, *sch = NULL;
    struct decompose_settings ds;
    int rc = app_read_dict(a, "system/decomposeParDict", &dec);
    if (!rc) rc = decompose_settings_read(dec, &ds);
    if (!rc) {
        s->nparts = ds.nparts;
        s->balance_all = ds.balance_all;
    }
    if (!rc && subdomains) {
        char *end;
        s->nparts = strtol(subdomains, &end, 10);
        if (*end || end == subdomains)
            rc = sim_error(SIM_ERR_INPUT, "-subdomains '%s': not a whole "
                           "number", subdomains);
    }
    if (!rc && !(s->nparts >= 1 && s->nparts <= 1000000))
        rc = sim_error(SIM_ERR_INPUT, "-subdomains %ld: must be in [1, "
                       "1000000]", s->nparts);
    /* the lattice (genParticles) and the list radius (mpsFluid's
     * settings: the same reading as the solver's) */
    if (!rc) rc = app_read_dict(a, "constant/particlePatches", &pat);
    if (!rc) rc = lattice_read_patches(pat, &s->dim, &s->dp);
    if (!rc) rc = app_read_dict(a, "constant/transportProperties", &tr);
    if (!rc) rc = app_read_dict(a, "system/mpsSchemes", &sch);
    struct mps_settings S;
    if (!rc) rc = mps_settings_read(tr, NULL, sch, NULL, &S);
    if (!rc)
        s->rc = mps_list_radius(&S, s->dp);
    dict_free(dec);
    dict_free(pat);
    dict_free(tr);
    dict_free(sch);
    return rc;
}

static int report(const struct settings *s, const struct vtu_cloud *c,
                  const char *file)
{
    const struct vtu_field *type;
    TRY(vtu_require(c, file, "type", VTU_INT32, 1, &type));
    const int32_t *ty = type->data;
    const int n = (int)c->n;
    double *w = malloc((size_t)(n > 0 ? n : 1) * sizeof *w);
    int32_t *part = malloc((size_t)(n > 0 ? n : 1) * sizeof *part);
    struct decompose_part *out = calloc((size_t)s->nparts, sizeof *out);
    int rc = w && part && out ? SIM_OK : SIM_ERR_NOMEM;
    long fluid = 0;
    for (int i = 0; i < n && !rc; i++) {
        w[i] = s->balance_all || ty[i] == 0 ? 1.0 : 0.0;
        fluid += ty[i] == 0;
    }
    double t0 = app_wall_time();
    if (!rc) rc = decompose_rcb(s->dim, c->points, w, n, (int)s->nparts,
                                part);
    double t1 = app_wall_time();
    if (!rc) rc = decompose_halo(s->dim, c->points, w, n, part,
                                 (int)s->nparts, s->rc, out);
    double t2 = app_wall_time();
    if (!rc) {
        log_info("Decomposing %s: %d particles (%ld fluid), %ld subdomains, "
                 "balance %s, halo radius %g m (%g dp: the list radius of "
                 "system/mpsSchemes)", file, n, fluid, s->nparts,
                 s->balance_all ? "all" : "fluid", s->rc, s->rc / s->dp);
        log_info("\n%10s %10s %10s %10s %10s", "subdomain", "particles",
                 "weight", "halo", "neighbours");
        long hsum = 0, hmax = 0, pmax = 0, nbmax = 0, nbsum = 0;
        double wmax = 0, wsum = 0, hrel = 0;
        for (long p = 0; p < s->nparts; p++) {
            const struct decompose_part *q = &out[p];
            if (s->nparts <= 64)
                log_info("%10ld %10ld %10.0f %10ld %10d", p, q->owned,
                         q->weight, q->halo, q->neighbours);
            hsum += q->halo;
            hmax = q->halo > hmax ? q->halo : hmax;
            if (q->owned > 0)
                hrel = fmax(hrel, (double)q->halo / (double)q->owned);
            pmax = q->owned > pmax ? q->owned : pmax;
            wmax = fmax(wmax, q->weight);
            wsum += q->weight;
            nbsum += q->neighbours;
            nbmax = q->neighbours > nbmax ? q->neighbours : nbmax;
        }
        double mean = wsum / (double)s->nparts;
        log_info("\nmax particles per subdomain   %ld (mean %.0f)", pmax,
                 (double)n / (double)s->nparts);
        log_info("max weight per subdomain      %.0f (mean %.0f, imbalance "
                 "%.3f)", wmax, mean, mean > 0 ? wmax / mean : 0.0);
        log_info("halo particles                %ld in total, %ld at most; "
                 "at most %.3f of a subdomain's own particles", hsum, hmax,
                 hrel);
        log_info("neighbour subdomains          %.2f on average, %ld at "
                 "most: %ld messages per exchange", (double)nbsum
                 / (double)s->nparts, nbmax, nbsum);
        log_info("time                          %.3g s bisection, %.3g s "
                 "halo", t1 - t0, t2 - t1);
        log_info("\nDry run: nothing written (mpirun -np %ld mpsFluid "
                 "-parallel cuts the start cloud itself, the same way)",
                 s->nparts);
    }
    free(w);
    free(part);
    free(out);
    return rc;
}

int main(int argc, char **argv)
{
    struct app app;
    const char *dry = NULL, *time_dir = NULL, *subdomains = NULL;
    const struct app_option opts[] = {
        { "-dry-run", 0, NULL, "report the decomposition, write nothing",
          &dry },
        { "-time", 1, "T", "decompose the cloud of time T (default 0)",
          &time_dir },
        { "-subdomains", 1, "N", "override numberOfSubdomains", &subdomains },
        { NULL, 0, NULL, NULL, NULL },
    };
    app_init(&app, "decomposePar", "domain decomposition report of an "
             "mpsFluid case", argc, argv, opts, 0);
    if (!dry) {
        sim_error(SIM_ERR_INPUT, "decomposePar writes no processor "
                  "directories: `mpirun -np N mpsFluid -parallel` cuts the "
                  "start cloud itself; run `decomposePar -dry-run` for the "
                  "report");
        app_fatal(&app, SIM_ERR_INPUT);
    }
    struct settings s = { 0 };
    int rc = read_settings(&app, subdomains, &s);
    if (rc)
        app_fatal(&app, rc);
    char rel[512], path[4096];
    snprintf(rel, sizeof rel, "%s/fluid.vtu", time_dir ? time_dir : "0");
    struct vtu_cloud c;
    rc = vtu_read(app_path(&app, rel, path, sizeof path), &c);
    if (!rc)
        rc = vtu_check_finite(&c, rel);
    if (!rc)
        rc = report(&s, &c, rel);
    vtu_cloud_free(&c);
    if (rc)
        app_fatal(&app, rc);
    return app_end(&app);
}
