/*
 * generate.c — turn the regions of particleDict into particles.
 *
 * MPS particles (fluid, wall, dummy) live on one lattice of spacing dp
 * for the whole case, anchored by default half a spacing inside the first
 * tank's lower corner, so that a box whose sides are multiples of dp holds
 * exactly (L/dp) particles per direction and its walls lie halfway between
 * the last fluid row and the first wall row (the fluid volume is N dp^3).
 *
 * Each lattice site belongs to the last region (in file order) that
 * claims it; grains claim nothing:
 *   fluid     sites strictly inside the shape (and inside a tank, if any);
 *   wall      sites inside the shape or on its surface: the first dp of
 *             depth is the wall layer (type 1), the next layers-1 are dummy
 *             (type 2), deeper sites are left empty;
 *   tankWall  sites outside the shape or on its surface, the same layers
 *             counted outwards (distance in the max-norm for a box, so that
 *             corners are filled square), except beyond an open face.
 * An unbounded wall (a half-space) claims only sites inside a tank or its
 * wall layers.
 * The normal of a wall or dummy particle is the unit normal of its
 * region's surface pointing from the fluid into the solid.
 *
 * Grains are placed on their own lattice per region, anchored a radius
 * (plus the jitter amplitude) inside the region's lower corner, and kept
 * when the whole grain lies inside the region; or at random (randomPack.c);
 * or where a file puts them (fileGrains.c).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "genParticles.h"

#define TOL 1e-9 /* in units of the spacing */

/* Signed depth of x beyond the tank's surface (> 0 outside) in the
 * max-norm for a box; *open set when x is on or beyond an open face. */
static double tank_depth(const struct region *r, const double x[3], int dim,
                         double tol, int *open)
{
    double depth = -HUGE_VAL;
    *open = 0;
    if (r->g.shape != GEOM_BOX)
        return geom_distance(&r->g, x);
    for (int i = 0; i < dim; i++) {
        double below = r->g.lo[i] - x[i], above = x[i] - r->g.hi[i];
        if ((r->open >> (2 * i) & 1) && below > -tol)
            *open = 1;
        if ((r->open >> (2 * i + 1) & 1) && above > -tol)
            *open = 1;
        depth = fmax(depth, fmax(below, above));
    }
    return depth;
}

static int in_a_tank(const struct gen_case *c, const double x[3], int *any)
{
    double tol = TOL * c->dp;
    *any = 0;
    for (int i = 0; i < c->nregions; i++)
        if (c->r[i].type == REGION_TANK_WALL) {
            *any = 1;
            if (geom_distance(&c->r[i].g, x) < -tol)
                return 1;
        }
    return 0;
}

/* An unbounded solid (a sloping floor) stops at the tanks' outer wall
 * layers, so that it adds nothing outside the container. */
static int in_a_tank_band(const struct gen_case *c, const double x[3])
{
    double tol = TOL * c->dp;
    int any = 0, open;
    for (int i = 0; i < c->nregions; i++)
        if (c->r[i].type == REGION_TANK_WALL) {
            any = 1;
            if (tank_depth(&c->r[i], x, c->dim, tol, &open) <
                    c->layers * c->dp - tol && !open)
                return 1;
        }
    return !any;
}

/* Owner region and particle type of site x; 0 when the site holds no
 * particle. */
static int classify(const struct gen_case *c, const double x[3], int *type,
                    int *region)
{
    double tol = TOL * c->dp, depth = 0;
    int layer, open, any;

    for (int i = c->nregions - 1; i >= 0; i--) {
        const struct region *r = &c->r[i];
        if (x[0] < r->clo[0] || x[0] > r->chi[0] || x[1] < r->clo[1] ||
            x[1] > r->chi[1] || x[2] < r->clo[2] || x[2] > r->chi[2])
            continue; /* cheap rejection before any distance */
        switch (r->type) {
        case REGION_GRAINS:
            continue;
        case REGION_FLUID:
        case REGION_SOIL:
            if (geom_distance(&r->g, x) >= -tol)
                continue;
            if (!in_a_tank(c, x, &any) && any)
                continue;
            *type = TYPE_FLUID;
            *region = i;
            return 1;
        case REGION_WALL:
            if (!r->bounded && !in_a_tank_band(c, x))
                continue;
            depth = -geom_distance(&r->g, x);
            break;
        case REGION_TANK_WALL:
            depth = tank_depth(r, x, c->dim, tol, &open);
            if (open)
                continue;
            break;
        }
        if (depth <= -tol)
            continue;
        layer = (int)floor(fmax(depth, 0.0) / c->dp + TOL);
        *region = i;
        *type = layer == 0 ? TYPE_WALL : TYPE_DUMMY;
        return layer < c->layers;
    }
    return 0;
}

static int accept_site(const double x[3], void *ctx)
{
    int type, region;
    return classify(ctx, x, &type, &region);
}

int gen_check_memory(const struct gen_case *c)
{
    /* Bytes per particle while generating and writing: position,
     * velocity, normal (3 x 8 each), pressure 8, type/patch/region 12. */
    const double per_mps = 92, per_grain = 3 * 24 + 8 + 4;
    double sites = 0, grains = 0, bytes, phys;
    int any_mps = 0;

    for (int i = 0; i < c->nregions; i++) {
        const struct region *r = &c->r[i];
        double lo[3], hi[3], v = 1;
        if (r->type != REGION_GRAINS) {
            any_mps = 1;
            continue;
        }
        if (r->layout == GRAINS_FILE) {
            grains += (double)r->fn;
            continue;
        }
        if (r->layout == GRAINS_RANDOM) { /* at most, all of the smallest */
            double d = r->dist.min;
            grains += r->solid_fraction * gen_region_volume(r) /
                      (c->dim == 2 ? M_PI * d * d / 4 : M_PI * d * d * d / 6)
                      + 1;
            continue;
        }
        geom_bbox(&r->g, lo, hi);
        for (int d = 0; d < c->dim; d++)
            v *= (hi[d] - lo[d]) / r->spacing + 2;
        grains += v * (r->lattice == LATTICE_HEXAGONAL ? sqrt(2.0) : 1.0);
    }
    if (any_mps) {
        sites = 1;
        for (int d = 0; d < c->dim; d++)
            sites *= (c->hi[d] - c->lo[d]) / c->dp + 3;
    }
    bytes = sites * per_mps + grains * per_grain;
    phys = (double)sysconf(_SC_PHYS_PAGES) * (double)sysconf(_SC_PAGESIZE);
    if (bytes > phys || sites > 2147483647.0 || grains > 2147483647.0)
        return dict_error(c->d, "dp", SIM_ERR_DICT, "this case would need "
                          "about %.3g bytes (%.3g fluid lattice sites, %.3g "
                          "grain sites), more than the %.3g bytes of memory "
                          "of this machine (or over 2^31 particles): "
                          "increase dp or the grain spacing, or shrink the "
                          "regions", bytes, sites, grains, phys);
    log_info("Memory estimate: %.3g MB for at most %.3g lattice sites and "
             "%.3g grains (%.3g MB available)", bytes / 1e6, sites, grains,
             phys / 1e6);
    return SIM_OK;
}

static int alloc_mps(const struct gen_case *c, struct mps_cloud *m)
{
    size_t n = m->n ? m->n : 1;
    for (int i = 0; i < c->nregions; i++)
        if (c->r[i].type == REGION_SOIL && !m->phase) {
            m->phase = sim_calloc(n, sizeof *m->phase);
            if (!m->phase)
                return SIM_ERR_NOMEM;
        }
    m->u = sim_calloc(3 * n, sizeof *m->u);
    m->normal = sim_calloc(3 * n, sizeof *m->normal);
    m->p = sim_calloc(n, sizeof *m->p);
    m->type = sim_calloc(n, sizeof *m->type);
    m->patch = sim_calloc(n, sizeof *m->patch);
    m->region = sim_calloc(n, sizeof *m->region);
    if (!m->u || !m->normal || !m->p || !m->type || !m->patch || !m->region)
        return SIM_ERR_NOMEM;
    return SIM_OK;
}

static void fill_mps_fields(const struct gen_case *c, struct mps_cloud *m)
{
#pragma omp parallel for
    for (size_t k = 0; k < m->n; k++) {
        const double *x = m->x + 3 * k;
        int type = TYPE_FLUID, i = 0;
        classify(c, x, &type, &i);
        const struct region *r = &c->r[i];
        m->type[k] = type;
        m->region[k] = i;
        m->patch[k] = type == TYPE_FLUID ? -1 : i;
        if (m->phase)
            m->phase[k] = type == TYPE_FLUID && r->type == REGION_SOIL;
        memcpy(m->u + 3 * k, r->velocity, sizeof r->velocity);
        if (type != TYPE_FLUID) {
            double *n = m->normal + 3 * k;
            geom_normal(&r->g, x, n);
            if (r->type == REGION_WALL) /* fluid is outside an obstacle */
                for (int d = 0; d < 3; d++)
                    n[d] = -n[d];
        }
    }
}

/* Every region gave particles: an empty one is a mistake in the input. */
static int check_counts(const struct gen_case *c, int grains)
{
    for (int i = 0; i < c->nregions; i++) {
        const struct region *r = &c->r[i];
        size_t n = r->count[0] + r->count[1] + r->count[2] + r->count[3];
        if ((r->type == REGION_GRAINS) != grains || n > 0)
            continue;
        return dict_error(r->d, "shape", SIM_ERR_DICT, "region '%s' gives "
                          "no particles (smaller than the spacing %g, or "
                          "carved away by the regions after it)", r->name,
                          r->type == REGION_GRAINS ? r->spacing : c->dp);
    }
    return SIM_OK;
}

/* The box of the sites each region may claim: its bounding box, grown by
 * the wall layers for a tank (and a little for round-off). */
static void claim_boxes(struct gen_case *c)
{
    for (int i = 0; i < c->nregions; i++) {
        struct region *r = &c->r[i];
        double grow = 1e-6 * c->dp;
        if (r->type == REGION_TANK_WALL)
            grow += c->layers * c->dp;
        geom_bbox(&r->g, r->clo, r->chi);
        for (int d = 0; d < 3; d++) {
            r->clo[d] -= grow;
            r->chi[d] += grow;
        }
    }
}

/* `jitter` of a fluid region: its fluid particles shifted by up to
 * +-jitter dp per coordinate (lattice_jitter, the grains' generator, over
 * the region's particles in lattice order: same seed, same cloud). The
 * free-surface height stays the lattice's (r->top). */
static int jitter_fluid(const struct gen_case *c, struct mps_cloud *m)
{
    for (int i = 0; i < c->nregions; i++) {
        const struct region *r = &c->r[i];
        if ((r->type != REGION_FLUID && r->type != REGION_SOIL) || !(r->jitter > 0))
            continue;
        size_t n = 0;
        double *x = sim_calloc(3 * (r->count[TYPE_FLUID] + 1), sizeof *x);
        if (!x)
            return SIM_ERR_NOMEM;
        for (size_t k = 0; k < m->n; k++)
            if (m->region[k] == i && m->type[k] == TYPE_FLUID)
                memcpy(x + 3 * n++, m->x + 3 * k, 3 * sizeof *x);
        lattice_jitter(x, n, c->dim, r->jitter * c->dp, (uint64_t)r->seed);
        n = 0;
        for (size_t k = 0; k < m->n; k++)
            if (m->region[k] == i && m->type[k] == TYPE_FLUID)
                memcpy(m->x + 3 * k, x + 3 * n++, 3 * sizeof *x);
        free(x);
    }
    return SIM_OK;
}

int gen_mps(struct gen_case *c, struct mps_cloud *m)
{
    struct lattice l = { LATTICE_CUBIC, c->dim,
                         { c->origin[0], c->origin[1], c->origin[2] }, c->dp };
    int any = 0;

    memset(m, 0, sizeof *m);
    for (int i = 0; i < c->nregions; i++)
        any |= c->r[i].type != REGION_GRAINS;
    if (!any)
        return SIM_OK;
    claim_boxes(c);
    TRY(lattice_fill(&l, c->lo, c->hi, accept_site, c, &m->x, &m->n));
    TRY(alloc_mps(c, m));
    fill_mps_fields(c, m);
    for (int i = 0; i < c->nregions; i++)
        c->r[i].top = -HUGE_VAL;
    for (size_t k = 0; k < m->n; k++) {
        struct region *r = &c->r[m->region[k]];
        r->count[m->type[k]]++;
        if (m->type[k] == TYPE_FLUID)
            r->top = fmax(r->top, m->x[3 * k + c->vertical] + 0.5 * c->dp);
    }
    TRY(jitter_fluid(c, m));
    TRY(gen_surface_nodes(c, m));
    return check_counts(c, 0);
}

/* A grain centre is kept when the whole grain (and its jitter) fits. */
struct grain_fit {
    const struct geom *g;
    double limit; /* largest signed distance of a kept centre [m] */
};

static int grain_fits(const double x[3], void *ctx)
{
    const struct grain_fit *f = ctx;
    return geom_distance(f->g, x) <= f->limit;
}

/* Grain centres of a lattice region; radii all the same. */
static int lattice_grains(const struct gen_case *c, const struct region *r,
                          double **x, double **radius, size_t *n)
{
    double rad = 0.5 * r->diameter, amp = r->jitter * r->spacing;
    double lo[3], hi[3];
    struct lattice l = { r->lattice, c->dim, { 0, 0, 0 }, r->spacing };
    struct grain_fit fit = { &r->g, -(rad + amp) + TOL * r->spacing };

    geom_bbox(&r->g, lo, hi);
    for (int d = 0; d < c->dim; d++)
        l.origin[d] = lo[d] + rad + amp;
    TRY(lattice_fill(&l, lo, hi, grain_fits, &fit, x, n));
    lattice_jitter(*x, *n, c->dim, amp, (uint64_t)r->seed);
    *radius = sim_malloc((*n ? *n : 1) * sizeof **radius);
    if (!*radius) {
        free(*x);
        return SIM_ERR_NOMEM;
    }
    for (size_t k = 0; k < *n; k++)
        (*radius)[k] = rad;
    return SIM_OK;
}

/* Grains of region r (centres, radii) appended to m. */
static int gen_grains(const struct gen_case *c, struct region *r,
                      struct dem_cloud *m)
{
    double *x = NULL, *rad = NULL, *nx, *nr;
    size_t n = 0;

    switch (r->layout) {
    case GRAINS_LATTICE:
        TRY(lattice_grains(c, r, &x, &rad, &n));
        break;
    case GRAINS_RANDOM:
        TRY(gen_random_pack(c, r, &x, &rad, &n));
        break;
    case GRAINS_FILE:
        x = r->fx;
        rad = r->fr;
        n = r->fn;
        break;
    }
    nx = sim_realloc(m->x, 3 * (m->n + n + 1) * sizeof *nx);
    if (nx)
        m->x = nx;
    nr = nx ? sim_realloc(m->radius, (m->n + n + 1) * sizeof *nr) : NULL;
    if (nr)
        m->radius = nr;
    if (nx && nr) {
        memcpy(m->x + 3 * m->n, x, 3 * n * sizeof *x);
        memcpy(m->radius + m->n, rad, n * sizeof *rad);
    }
    if (r->layout != GRAINS_FILE) { /* the region keeps a file's */
        free(x);
        free(rad);
    }
    if (!nx || !nr)
        return SIM_ERR_NOMEM;
    r->count[3] = n;
    m->n += n;
    return SIM_OK;
}

int gen_dem(struct gen_case *c, struct dem_cloud *m)
{
    size_t k = 0, n;

    memset(m, 0, sizeof *m);
    for (int i = 0; i < c->nregions; i++)
        if (c->r[i].type == REGION_GRAINS)
            TRY(gen_grains(c, &c->r[i], m));
    TRY(check_counts(c, 1));
    n = m->n ? m->n : 1;
    if (!m->radius)
        m->radius = sim_calloc(n, sizeof *m->radius);
    m->u = sim_calloc(3 * n, sizeof *m->u);
    m->omega = sim_calloc(3 * n, sizeof *m->omega);
    m->group = sim_calloc(n, sizeof *m->group);
    if (!m->radius || !m->u || !m->omega || !m->group)
        return SIM_ERR_NOMEM;
    for (int i = 0; i < c->nregions; i++) {
        const struct region *r = &c->r[i];
        if (r->type != REGION_GRAINS)
            continue;
        for (size_t j = 0; j < r->count[3]; j++, k++) {
            memcpy(m->u + 3 * k, r->velocity, sizeof r->velocity);
            memcpy(m->omega + 3 * k, r->omega, sizeof r->omega);
            m->group[k] = i;
        }
    }
    return SIM_OK;
}

/* p = rho |g| (h - z) for the fluid of regions that ask for it, with h the
 * region's surfaceHeight or the top of its particles. A soil region is
 * saturated soil under water up to its surfaceHeight h_w (doc/theory.md
 * E5-02): p = rho_soil |g| (top - z) + rho |g| (h_w - top), top the top of
 * its particles, the second term only when h_w > top. */
int gen_hydrostatic(struct gen_case *c, struct mps_cloud *m)
{
    double gv = c->g[c->vertical];

    for (size_t k = 0; k < m->n; k++) {
        const struct region *r = &c->r[m->region[k]];
        if (m->type[k] != TYPE_FLUID || !r->hydrostatic)
            continue;
        double z = m->x[3 * k + c->vertical];
        if (r->type == REGION_SOIL) {
            double water = r->has_surface ? fmax(r->surface - r->top, 0) : 0;
            m->p[k] = -gv * (c->rho_soil * (r->top - z) + c->rho * water);
            continue;
        }
        double h = r->has_surface ? r->surface : r->top;
        m->p[k] = -c->rho * gv * (h - z);
    }
    return SIM_OK;
}

void mps_cloud_free(struct mps_cloud *m)
{
    free(m->x);
    free(m->u);
    free(m->p);
    free(m->normal);
    free(m->type);
    free(m->patch);
    free(m->region);
    free(m->phi);
    free(m->phase);
    memset(m, 0, sizeof *m);
}

void dem_cloud_free(struct dem_cloud *m)
{
    free(m->x);
    free(m->radius);
    free(m->u);
    free(m->omega);
    free(m->group);
    memset(m, 0, sizeof *m);
}
