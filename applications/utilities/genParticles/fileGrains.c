/*
 * fileGrains.c — a grains region whose grains come from a file:
 *
 *     bed { type grains; shape file; file "constant/bed.csv"; format csv;
 *           scale 1; maxOverlap 0.05; }
 *
 * The format readers (grainFile/) parse; here the region's keys are read,
 * the path is taken relative to the case, lengths are scaled (`scale
 * 0.001` for a file in millimetres), and the grains are checked: radii
 * positive, z = 0 in 2-D, each grain wholly inside a tankWall region (open
 * faces excepted) when the case has one, and no two grains overlapping by
 * more than maxOverlap of the smaller radius (demSolid's initialOverlap
 * measure). Every refusal names the file and the line of the grain.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/app.h"
#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "core/select.h"
#include "genParticles.h"
#include "grainFile/grainFile.h"
#include "particles/cells.h"

/* Re-issue the reader's "file:line: ..." at the region's `file` key. */
static int at_file_key(const struct region *r, int rc)
{
    char msg[1536];
    snprintf(msg, sizeof msg, "%s", sim_error_message());
    if (rc == SIM_ERR_NOMEM)
        return rc;
    return dict_error(r->d, "file", SIM_ERR_DICT, "region '%s': %s", r->name,
                      msg);
}

static int load(const char *path, struct grain_text *t)
{
    FILE *f = fopen(path, "rb");
    long size;
    memset(t, 0, sizeof *t);
    t->path = path;
    if (!f)
        return sim_error(SIM_ERR_IO, "%s: cannot open: %s", path,
                         strerror(errno));
    if (fseek(f, 0, SEEK_END) != 0 || (size = ftell(f)) < 0 ||
        fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        return sim_error(SIM_ERR_IO, "%s: cannot read: %s", path,
                         strerror(errno));
    }
    t->buf = sim_malloc((size_t)size + 1);
    if (!t->buf) {
        fclose(f);
        return SIM_ERR_NOMEM;
    }
    t->len = fread(t->buf, 1, (size_t)size, f);
    t->buf[t->len] = '\0';
    int bad = ferror(f);
    fclose(f);
    if (bad || t->len != (size_t)size)
        return sim_error(SIM_ERR_IO, "%s: read failed", path);
    if (memchr(t->buf, '\0', t->len))
        return sim_error(SIM_ERR_INPUT, "%s: not a text file (it holds NUL "
                         "bytes)", path);
    return SIM_OK;
}

/* The rows, scaled and checked one by one, into the region. */
static int take_rows(const struct gen_case *c, struct region *r,
                     const struct grain_text *t, struct grain_rows *g,
                     double scale)
{
    double lo[3] = { HUGE_VAL, HUGE_VAL, 0 }, hi[3] = { -HUGE_VAL, -HUGE_VAL,
                                                        0 };
    if (g->n == 0)
        return grain_text_error(t, 0, "holds no grains");
    for (size_t k = 0; k < g->n; k++) {
        double *x = g->x + 3 * k;
        if (!(g->r[k] > 0))
            return grain_text_error(t, g->line[k], "radius %g (diameter %g) "
                                    "must be positive", g->r[k], 2 * g->r[k]);
        if (c->dim == 2 && x[2] != 0)
            return grain_text_error(t, g->line[k], "z = %g in a 2-D case: "
                                    "grains lie in the x-y plane (z = 0)",
                                    x[2]);
        g->r[k] *= scale;
        for (int d = 0; d < 3; d++) {
            x[d] *= scale;
            if (d < c->dim) {
                lo[d] = fmin(lo[d], x[d] - g->r[k]);
                hi[d] = fmax(hi[d], x[d] + g->r[k]);
            }
        }
    }
    r->fn = g->n;
    r->fx = g->x;
    r->fr = g->r;
    r->fline = g->line;
    memset(g, 0, sizeof *g);
    /* the region's box is the grains' (claim boxes, the summary) */
    TRY(geom_box(&r->g, c->dim, lo, hi));
    r->bounded = 1;
    return SIM_OK;
}

int gen_file_read(const struct gen_case *c, struct region *r)
{
    const char *name;
    const void *fmt;
    char path[4096];
    double scale;
    struct grain_text t;
    struct grain_rows g = { 0 };
    int rc;

    TRY(dict_get_string(r->d, "file", &name));
    TRY(model_select(r->d, "format", "grain file format",
                     (const void *const *)grain_format_table, NULL, &fmt));
    r->format = fmt;
    TRY(dict_get_scalar_or(r->d, "scale", 1.0, &scale));
    if (!(scale > 0) || !isfinite(scale))
        return dict_error(r->d, "scale", SIM_ERR_DICT, "scale must be "
                          "positive (0.001 for a file in millimetres), not "
                          "%g", scale);
    TRY(dict_get_scalar_or(r->d, "maxOverlap", 0.05, &r->max_overlap));
    if (!(r->max_overlap >= 0 && r->max_overlap < 1))
        return dict_error(r->d, "maxOverlap", SIM_ERR_DICT, "maxOverlap %g "
                          "must be in [0, 1) (a fraction of the smaller "
                          "radius)", r->max_overlap);
    if (!name[0])
        return dict_error(r->d, "file", SIM_ERR_DICT, "region '%s': empty "
                          "file name", r->name);
    if (name[0] == '/')
        snprintf(path, sizeof path, "%s", name);
    else
        app_path(c->app, name, path, sizeof path);
    r->file = strdup(path);
    if (!r->file)
        return SIM_ERR_NOMEM;
    rc = load(r->file, &t);
    if (rc == SIM_OK)
        rc = r->format->read(&t, &g);
    if (rc == SIM_OK)
        rc = take_rows(c, r, &t, &g, scale);
    free(t.buf);
    grain_rows_free(&g);
    if (rc != SIM_OK)
        return at_file_key(r, rc);
    log_info("Region %s: %zu grains from %s (%s%s)", r->name, r->fn, r->file,
             r->format->name, scale != 1 ? ", scaled" : "");
    return SIM_OK;
}

/* Whether grain (x, rad) lies inside tank t, its open faces excepted,
 * overlapping a wall by at most `overlap` of its radius: a bed settled in
 * another run rests on the walls with the small overlaps its contacts
 * carry (demSolid's initialOverlap measures them the same way). */
static int in_tank(const struct region *t, int dim, const double x[3],
                   double rad, double overlap)
{
    double tol = fmax(1e-9, overlap) * rad;
    if (t->g.shape != GEOM_BOX)
        return geom_distance(&t->g, x) <= -rad + tol;
    for (int d = 0; d < dim; d++) {
        if (!(t->open >> (2 * d) & 1) && x[d] - rad < t->g.lo[d] - tol)
            return 0;
        if (!(t->open >> (2 * d + 1) & 1) && x[d] + rad > t->g.hi[d] + tol)
            return 0;
    }
    return 1;
}

static int check_domain(const struct gen_case *c, const struct region *r)
{
    const struct region *tank = NULL;
    int ntanks = 0;
    for (int i = 0; i < c->nregions; i++)
        if (c->r[i].type == REGION_TANK_WALL) {
            tank = tank ? tank : &c->r[i];
            ntanks++;
        }
    if (!tank)
        return SIM_OK; /* no container: no domain to leave */
    for (size_t k = 0; k < r->fn; k++) {
        const double *x = r->fx + 3 * k;
        int ok = 0;
        for (int i = 0; i < c->nregions && !ok; i++)
            ok = c->r[i].type == REGION_TANK_WALL &&
                 in_tank(&c->r[i], c->dim, x, r->fr[k], r->max_overlap);
        if (ok)
            continue;
        if (ntanks > 1)
            return dict_error(r->d, "file", SIM_ERR_DICT, "region '%s': "
                              "%s:%ld: grain at (%g %g %g), radius %g, is "
                              "not inside any tankWall region", r->name,
                              r->file, r->fline[k], x[0], x[1], x[2],
                              r->fr[k]);
        return dict_error(r->d, "file", SIM_ERR_DICT, "region '%s': %s:%ld: "
                          "grain at (%g %g %g), radius %g, is not inside the "
                          "tank '%s' (%g %g %g)..(%g %g %g) (a wall overlap "
                          "up to maxOverlap %g of the radius is accepted)",
                          r->name, r->file, r->fline[k], x[0], x[1], x[2],
                          r->fr[k],
                          tank->name, tank->g.lo[0], tank->g.lo[1],
                          tank->g.lo[2], tank->g.hi[0], tank->g.hi[1],
                          tank->g.hi[2], r->max_overlap);
    }
    return SIM_OK;
}

/* Overlaps through a cell grid of side 2 R_max: every pair in contact is
 * in neighbouring cells. */
static int check_overlaps(const struct gen_case *c, const struct region *r)
{
    struct cell_grid cg = { 0 };
    double rmax = 0, worst = 0;
    size_t ncontact = 0;
    int rc;

    if (r->fn > 2147483647u)
        return dict_error(r->d, "file", SIM_ERR_DICT, "region '%s': more "
                          "than 2^31 grains", r->name);
    for (size_t k = 0; k < r->fn; k++)
        rmax = fmax(rmax, r->fr[k]);
    rc = cells_build(&cg, c->dim, r->fx, (int)r->fn, 2 * rmax, NULL, NULL);
    if (rc != SIM_OK) {
        cells_free(&cg);
        return at_file_key(r, rc);
    }
    for (size_t i = 0; i < r->fn; i++) {
        const double *xi = r->fx + 3 * i;
        int ic[3], lo[3], hi[3];
        size_t bad = r->fn;
        double frac_bad = 0;
        cells_locate(&cg, xi, ic);
        for (int d = 0; d < 3; d++) {
            lo[d] = ic[d] > 0 ? ic[d] - 1 : 0;
            hi[d] = ic[d] + 1 < cg.nc[d] ? ic[d] + 1 : cg.nc[d] - 1;
        }
        for (int z = lo[2]; z <= hi[2]; z++)
            for (int y = lo[1]; y <= hi[1]; y++)
                for (int x = lo[0]; x <= hi[0]; x++) {
                    int64_t cell = x + cg.nc[0] * (y + cg.nc[1] * (int64_t)z);
                    for (int64_t s = cg.start[cell]; s < cg.start[cell + 1];
                         s++) {
                        size_t j = (size_t)cg.order[s];
                        if (j <= i)
                            continue;
                        const double *xj = r->fx + 3 * j;
                        double dx = xi[0] - xj[0], dy = xi[1] - xj[1],
                               dz = xi[2] - xj[2], sum = r->fr[i] + r->fr[j];
                        double dist = sqrt(dx * dx + dy * dy + dz * dz);
                        if (!(dist < sum))
                            continue;
                        double frac = (sum - dist) /
                                      fmin(r->fr[i], r->fr[j]);
                        ncontact++;
                        worst = fmax(worst, frac);
                        if (frac > r->max_overlap && j < bad) {
                            bad = j;
                            frac_bad = frac;
                        }
                    }
                }
        if (bad < r->fn) {
            cells_free(&cg);
            return dict_error(r->d, "file", SIM_ERR_DICT, "region '%s': "
                              "%s:%ld: the grain of this line and that of "
                              "line %ld overlap by %.3g of the smaller "
                              "radius, more than maxOverlap %g", r->name,
                              r->file, r->fline[i], r->fline[bad], frac_bad,
                              r->max_overlap);
        }
    }
    cells_free(&cg);
    if (ncontact)
        log_info("Region %s: %zu pairs of grains overlap, by at most %.3g of "
                 "the smaller radius (maxOverlap %g)", r->name, ncontact,
                 worst, r->max_overlap);
    return SIM_OK;
}

int gen_file_check(const struct gen_case *c, const struct region *r)
{
    TRY(check_domain(c, r));
    return check_overlaps(c, r);
}
