/*
 * particleDict.c — read system/particleDict into a struct gen_case and
 * check it, so that every input error is reported, with its file and
 * line, before anything is generated or written (particleDict.reference
 * documents every key).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/app.h"
#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "genParticles.h"
#include "particles/motion/motion.h"

const char *const region_type_names[] = { "tankWall", "wall", "fluid",
                                          "grains", "soil", NULL };
const char *const region_shape_names[] = { "box", "cylinder", "sphere",
                                           "plane", "file", NULL };
/* the lattice kinds, then random (randomPack.c) */
static const char *const grain_lattice_names[] = { "cubic", "hexagonal",
                                                   "random", NULL };
enum { LATTICE_WORD_RANDOM = 2 };
static const char *const face_names[] = { "xmin", "xmax", "ymin", "ymax",
                                          "zmin", "zmax", NULL };
static const char *const format_names[] = { "ascii", "binary", NULL };
static const int dims_length[7] = { 0, 1, 0, 0, 0, 0, 0 };
static const double zero3[3] = { 0, 0, 0 };

/* Re-issue the message of a failed geometry constructor at `key`. */
static int shape_error(const struct region *r, const char *key)
{
    char msg[512];
    snprintf(msg, sizeof msg, "%s", sim_error_message());
    return dict_error(r->d, key, SIM_ERR_DICT, "region '%s': %s", r->name,
                      msg);
}

static int read_shape(const struct gen_case *c, struct region *r)
{
    const struct dict *d = r->d;
    double a[3], b[3], rad = 0;
    int shape;

    TRY(dict_get_word(d, "shape", region_shape_names, &shape));
    r->shape = shape;
    if (shape == SHAPE_FILE) { /* the grains' box, once they are read */
        if (r->type != REGION_GRAINS)
            return dict_error(d, "shape", SIM_ERR_DICT, "region '%s': shape "
                              "file is for grains regions (type grains)",
                              r->name);
        return SIM_OK;
    }
    switch ((enum geom_shape)shape) {
    case GEOM_BOX:
        TRY(dict_get_vector(d, "min", 3, a));
        TRY(dict_get_vector(d, "max", 3, b));
        if (geom_box(&r->g, c->dim, a, b))
            return shape_error(r, "max");
        break;
    case GEOM_CYLINDER:
        TRY(dict_get_vector(d, "point1", 3, a));
        TRY(dict_get_vector(d, "point2", 3, b));
        TRY(dict_get_scalar_dim(d, "radius", dims_length, &rad));
        if (geom_cylinder(&r->g, c->dim, a, b, rad))
            return shape_error(r, rad > 0 ? "point2" : "radius");
        break;
    case GEOM_SPHERE:
        TRY(dict_get_vector(d, "centre", 3, a));
        TRY(dict_get_scalar_dim(d, "radius", dims_length, &rad));
        if (geom_sphere(&r->g, c->dim, a, rad))
            return shape_error(r, "radius");
        break;
    case GEOM_HALFSPACE:
        TRY(dict_get_vector(d, "point", 3, a));
        TRY(dict_get_vector(d, "normal", 3, b));
        if (geom_halfspace(&r->g, c->dim, a, b))
            return shape_error(r, "normal");
        break;
    }
    return SIM_OK;
}

/* open (zmax ...); of a tank: faces without walls. */
static int read_open(const struct gen_case *c, struct region *r)
{
    const struct dict_value *list;

    if (!dict_has(r->d, "open"))
        return SIM_OK;
    TRY(dict_get_list(r->d, "open", &list));
    if (r->g.shape != GEOM_BOX)
        return dict_error(r->d, "open", SIM_ERR_DICT, "region '%s': open "
                          "faces need shape box", r->name);
    for (int i = 0; i < dict_value_len(list); i++) {
        const struct dict_value *v = dict_value_at(list, i);
        const char *w;
        int f;
        TRY(dict_value_get_word(v, &w));
        for (f = 0; face_names[f] && strcmp(face_names[f], w); f++)
            ;
        if (!face_names[f] || f >= 2 * c->dim)
            return dict_value_error(v, SIM_ERR_DICT, "unknown face '%s'; "
                                    "valid: xmin xmax ymin ymax%s", w,
                                    c->dim == 3 ? " zmin zmax" : "");
        r->open |= 1u << f;
    }
    return SIM_OK;
}

static int read_grains(const struct gen_case *c, struct region *r)
{
    const struct dict *d = r->d;
    int lat;
    double lo[3], hi[3], gap;

    if (r->shape == SHAPE_FILE) {
        r->layout = GRAINS_FILE;
        TRY(gen_file_read(c, r));
        return dict_get_vector_or(d, "omega", 3, zero3, r->omega);
    }
    /* a random packing may take its diameters from a distribution */
    if (dict_has(d, "diameter")) {
        TRY(dict_get_scalar_dim(d, "diameter", dims_length, &r->diameter));
        if (!(r->diameter > 0) || !isfinite(r->diameter))
            return dict_error(d, "diameter", SIM_ERR_DICT, "diameter must be "
                              "positive");
    }
    TRY(dict_get_word_or(d, "lattice", grain_lattice_names, LATTICE_CUBIC,
                         &lat));
    if (lat == LATTICE_WORD_RANDOM) {
        r->layout = GRAINS_RANDOM;
        TRY(gen_random_read(c, r));
        return dict_get_vector_or(d, "omega", 3, zero3, r->omega);
    }
    if (dict_has(d, "diameterDistribution"))
        return dict_error(d, "diameterDistribution", SIM_ERR_DICT, "region "
                          "'%s': a diameter distribution needs lattice "
                          "random (a lattice has one spacing)", r->name);
    if (!dict_has(d, "diameter")) /* "missing keyword 'diameter'" */
        TRY(dict_get_scalar_dim(d, "diameter", dims_length, &r->diameter));
    r->layout = GRAINS_LATTICE;
    r->lattice = (enum lattice_kind)lat;
    TRY(dict_get_scalar_dim_or(d, "spacing", dims_length, r->diameter,
                               &r->spacing));
    if (!(r->spacing >= r->diameter * (1 - 1e-12)) || !isfinite(r->spacing))
        return dict_error(d, "spacing", SIM_ERR_DICT, "spacing %g is smaller "
                          "than the diameter %g: grains would overlap",
                          r->spacing, r->diameter);
    TRY(dict_get_scalar_or(d, "jitter", 0.0, &r->jitter));
    gap = r->spacing - r->diameter;
    if (!(r->jitter >= 0) || 2 * r->jitter * r->spacing > gap * (1 + 1e-9))
        return dict_error(d, "jitter", SIM_ERR_DICT, "jitter must be between "
                          "0 and %g (= (spacing - diameter)/(2 spacing)), so "
                          "that grains cannot overlap", gap / (2 * r->spacing));
    TRY(dict_get_label_or(d, "seed", 1, &r->seed));
    TRY(dict_get_vector_or(d, "omega", 3, zero3, r->omega));
    if (!geom_bbox(&r->g, lo, hi))
        return dict_error(d, "shape", SIM_ERR_DICT, "grains need a bounded "
                          "shape (box, cylinder or sphere)");
    return SIM_OK;
}

static int read_region(const struct gen_case *c, struct region *r)
{
    const struct dict *d = r->d;
    int type;

    double lo[3], hi[3];

    TRY(dict_get_word(d, "type", region_type_names, &type));
    r->type = (enum region_type)type;
    TRY(read_shape(c, r));
    r->bounded = geom_bbox(&r->g, lo, hi);
    TRY(dict_get_vector_or(d, "velocity", 3, zero3, r->velocity));
    if (c->dim == 2)
        r->velocity[2] = 0;
    /* A wall moves by its motion only (which the solvers read too):
     * refuse a velocity they would ignore. */
    int is_wall = r->type == REGION_TANK_WALL || r->type == REGION_WALL;
    if (is_wall && (r->velocity[0] != 0 || r->velocity[1] != 0
                    || r->velocity[2] != 0))
        return dict_error(d, "velocity", SIM_ERR_DICT, "region '%s': a "
                          "wall's velocity is not read; a moving wall "
                          "needs motion { type translation; velocity "
                          "(...); }", r->name);
    /* checked here so that a bad motion stops before anything is
     * written; the solvers read it again */
    struct wall_motion m;
    TRY(wall_motion_read(d, is_wall, c->dim, c->app->case_abs, &m));
    wall_motion_free(&m);
    switch (r->type) {
    case REGION_TANK_WALL:
        TRY(read_open(c, r));
        break;
    case REGION_FLUID:
    case REGION_SOIL:
        TRY(dict_get_bool_or(d, "hydrostaticPressure", 0, &r->hydrostatic));
        /* the lattice fraction dp/4 keeps particles at least dp/2 apart
         * and inside the walls (the first site is dp/2 from a wall) */
        TRY(dict_get_scalar_or(d, "jitter", 0.0, &r->jitter));
        if (!(r->jitter >= 0 && r->jitter <= 0.25))
            return dict_error(d, "jitter", SIM_ERR_DICT, "jitter of a fluid "
                              "region must be between 0 and 0.25 (a "
                              "fraction of dp), got %g", r->jitter);
        TRY(dict_get_label_or(d, "seed", 1, &r->seed));
        r->has_surface = dict_has(d, "surfaceHeight");
        if (r->has_surface)
            TRY(dict_get_scalar_dim(d, "surfaceHeight", dims_length,
                                    &r->surface));
        break;
    case REGION_GRAINS:
        TRY(read_grains(c, r));
        break;
    case REGION_WALL:
        TRY(dict_get_bool_or(d, "surfaceNodes", 0, &r->surface_nodes));
        TRY(dict_get_scalar_or(d, "surfaceClearance", 0.5, &r->clearance));
        if (r->surface_nodes && !(c->dim == 2 && r->g.shape == GEOM_SPHERE))
            return dict_error(d, "surfaceNodes", SIM_ERR_DICT, "region "
                              "'%s': surfaceNodes is for a circle (2-D: "
                              "shape sphere, or cylinder along z)", r->name);
        if (r->surface_nodes)
            TRY(dict_range(d, "surfaceClearance", r->clearance, 0, 2, 0));
        break;
    }
    return SIM_OK;
}

/* A region's name is located by its list item, or by its key in the
 * dictionary form. */
struct name_at {
    const struct dict_value *item;
    const struct dict *parent;
};

static int name_error(const struct name_at *at, const char *name,
                      const char *what)
{
    if (at->item)
        return dict_value_error(at->item, SIM_ERR_DICT, "region '%s' %s",
                                name, what);
    return dict_error(at->parent, name, SIM_ERR_DICT, "region '%s' %s", name,
                      what);
}

static int add_region(struct gen_case *c, const char *name,
                      const struct dict *d, const struct name_at *at)
{
    struct region *r;

    if (strlen(name) >= sizeof r->name)
        return name_error(at, name, "has too long a name (63 characters "
                          "at most)");
    for (int i = 0; i < c->nregions; i++)
        if (strcmp(c->r[i].name, name) == 0)
            return name_error(at, name, "is defined twice");
    r = sim_realloc(c->r, (size_t)(c->nregions + 1) * sizeof *r);
    if (!r)
        return SIM_ERR_NOMEM;
    c->r = r;
    r = &c->r[c->nregions++];
    memset(r, 0, sizeof *r);
    strcpy(r->name, name);
    r->d = d;
    return read_region(c, r);
}

/* regions ( name { ... } ... );  or  regions { name { ... } ... } */
static int read_regions(struct gen_case *c)
{
    const struct dict_value *list;

    if (dict_is_dict(c->d, "regions")) {
        const struct dict *rd;
        TRY(dict_get_dict(c->d, "regions", &rd));
        for (int i = 0; i < dict_size(rd); i++) {
            const char *key = dict_key_at(rd, i);
            const struct dict *sub;
            if (!dict_is_dict(rd, key))
                return dict_error(rd, key, SIM_ERR_DICT, "'%s' is not a "
                                  "region { ... }", key);
            struct name_at at = { NULL, rd };
            TRY(dict_get_dict(rd, key, &sub));
            TRY(add_region(c, key, sub, &at));
        }
    } else {
        TRY(dict_get_list(c->d, "regions", &list));
        for (int i = 0; i < dict_value_len(list); i += 2) {
            const struct dict_value *nv = dict_value_at(list, i), *dv;
            const char *name;
            TRY(dict_value_get_word(nv, &name));
            dv = i + 1 < dict_value_len(list) ? dict_value_at(list, i + 1)
                                              : NULL;
            if (!dv || dict_value_kind(dv) != DICT_DICT)
                return dict_value_error(nv, SIM_ERR_DICT, "region '%s' needs "
                                        "a { ... } after its name", name);
            struct name_at at = { nv, NULL };
            TRY(add_region(c, name, dict_value_dict(dv), &at));
        }
    }
    if (c->nregions == 0)
        return dict_error(c->d, "regions", SIM_ERR_DICT, "no regions");
    return SIM_OK;
}

/* wallLayers auto | N: wall layer plus dummy layers. */
static int read_layers(struct gen_case *c, double kernel_radius_hint)
{
    const struct dict_value *v;
    double kr;
    long n;

    if (dict_has(c->d, "wallLayers")) {
        TRY(dict_get_value(c->d, "wallLayers", &v));
        if (dict_value_len(v) == 1 &&
            dict_value_kind(dict_value_at(v, 0)) == DICT_NUMBER) {
            TRY(dict_get_label(c->d, "wallLayers", &n));
            if (n < 1 || n > 100)
                return dict_error(c->d, "wallLayers", SIM_ERR_DICT,
                                  "wallLayers %ld is not in 1..100 (or auto)",
                                  n);
            c->layers = (int)n;
            return SIM_OK;
        }
        if (dict_value_len(v) != 1 ||
            strcmp(dict_value_text(dict_value_at(v, 0)), "auto") != 0)
            return dict_error(c->d, "wallLayers", SIM_ERR_DICT, "wallLayers "
                              "must be auto or a whole number");
    }
    TRY(dict_get_scalar_or(c->d, "kernelRadius", kernel_radius_hint, &kr));
    if (!(kr > 0))
        return dict_error(c->d, "wallLayers", SIM_ERR_DICT, "wallLayers auto "
                          "needs the largest kernel radius: give "
                          "'kernelRadius 2.1;' (in units of dp) here, or "
                          "set the radii in system/mpsSchemes");
    if (kr > 100)
        return dict_error(c->d, "kernelRadius", SIM_ERR_DICT, "kernelRadius "
                          "%g (in units of dp) is not plausible", kr);
    /* A radius raised in system/mpsSchemes and not here would leave the
     * walls' kernel support short of dummies: mpsFluid only finds out at
     * its start, after the case has been generated. */
    if (kr < kernel_radius_hint - 1e-9) {
        char where[512];
        log_warn("%s: kernelRadius %g is smaller than the largest r_e %g of "
                 "system/mpsSchemes: wallLayers auto makes %d layer(s), too "
                 "few for r_e %g (set kernelRadius %g, or remove it)",
                 dict_where(c->d, "kernelRadius", where, sizeof where), kr,
                 kernel_radius_hint, (int)ceil(kr - 1e-9), kernel_radius_hint,
                 kernel_radius_hint);
    }
    /* One wall layer and ceil(re/dp) - 1 dummy layers (doc/theory.md A.9). */
    c->layers = (int)ceil(kr - 1e-9);
    return SIM_OK;
}

static int inside_box(int dim, const double lo[3], const double hi[3],
                      const double tlo[3], const double thi[3], double tol)
{
    for (int i = 0; i < dim; i++)
        if (lo[i] < tlo[i] - tol || hi[i] > thi[i] + tol)
            return 0;
    return 1;
}

/* Every bounded region other than a tank lies inside some tank. */
static int check_in_tank(const struct gen_case *c)
{
    const struct region *tank = NULL;
    for (int t = 0; t < c->nregions && !tank; t++)
        if (c->r[t].type == REGION_TANK_WALL)
            tank = &c->r[t];
    if (!tank)
        return SIM_OK;
    for (int i = 0; i < c->nregions; i++) {
        const struct region *r = &c->r[i];
        double lo[3], hi[3], tlo[3], thi[3];
        int ok = 0;
        if (r->type == REGION_TANK_WALL || r->shape == SHAPE_FILE ||
            !geom_bbox(&r->g, lo, hi))
            continue; /* a file's grains are checked one by one */
        for (int t = 0; t < c->nregions && !ok; t++)
            if (c->r[t].type == REGION_TANK_WALL) {
                geom_bbox(&c->r[t].g, tlo, thi);
                ok = inside_box(c->dim, lo, hi, tlo, thi, 1e-9 * c->dp);
            }
        if (!ok) {
            geom_bbox(&tank->g, tlo, thi);
            return dict_error(r->d, "shape", SIM_ERR_DICT, "region '%s' "
                              "(%g %g %g)..(%g %g %g) is not inside the tank "
                              "'%s' (%g %g %g)..(%g %g %g)", r->name, lo[0],
                              lo[1], lo[2], hi[0], hi[1], hi[2], tank->name,
                              tlo[0], tlo[1], tlo[2], thi[0], thi[1], thi[2]);
        }
    }
    return SIM_OK;
}

/* The box the MPS lattice is scanned over, and the lattice origin. */
static int mps_box(struct gen_case *c)
{
    const struct region *unbounded = NULL, *first = NULL;
    int any = 0;

    for (int d = 0; d < 3; d++) {
        c->lo[d] = HUGE_VAL;
        c->hi[d] = -HUGE_VAL;
    }
    for (int i = 0; i < c->nregions; i++) {
        const struct region *r = &c->r[i];
        double lo[3], hi[3], grow;
        if (r->type == REGION_GRAINS)
            continue;
        any = 1;
        if (!geom_bbox(&r->g, lo, hi)) {
            unbounded = unbounded ? unbounded : r;
            continue;
        }
        if (!first || (r->type == REGION_TANK_WALL &&
                       first->type != REGION_TANK_WALL))
            first = r;
        grow = r->type == REGION_TANK_WALL ? (c->layers + 1) * c->dp : c->dp;
        for (int d = 0; d < c->dim; d++) {
            c->lo[d] = fmin(c->lo[d], lo[d] - grow);
            c->hi[d] = fmax(c->hi[d], hi[d] + grow);
        }
    }
    if (c->dim == 2)
        c->lo[2] = c->hi[2] = 0;
    if (any && !first)
        return dict_error(unbounded->d, "shape", SIM_ERR_DICT, "region '%s' "
                          "is unbounded and no bounded region (a tank) "
                          "limits it", unbounded->name);
    if (first && !dict_has(c->d, "origin")) {
        double lo[3], hi[3];
        geom_bbox(&first->g, lo, hi);
        for (int d = 0; d < 3; d++)
            c->origin[d] = d < c->dim ? lo[d] + 0.5 * c->dp : 0.0;
    }
    return SIM_OK;
}

int gen_read(struct gen_case *c, const struct app *a, const struct dict *d,
             const char *path, double kernel_radius_hint, int binary_default)
{
    long dim;
    int fmt;

    memset(c, 0, sizeof *c);
    c->app = a;
    c->d = d;
    c->dict_path = path;
    TRY(dict_get_label_or(d, "dimension", 3, &dim));
    if (dim != 2 && dim != 3)
        return dict_error(d, "dimension", SIM_ERR_DICT, "dimension %ld is "
                          "not 2 or 3", dim);
    c->dim = (int)dim;
    c->vertical = c->dim - 1;
    TRY(dict_get_scalar_dim(d, "dp", dims_length, &c->dp));
    if (!(c->dp > 0) || !isfinite(c->dp))
        return dict_error(d, "dp", SIM_ERR_DICT, "dp must be a positive "
                          "length [m], not %g", c->dp);
    TRY(dict_get_word_or(d, "writeFormat", format_names, binary_default != 0,
                         &fmt));
    c->binary = fmt == 1;
    TRY(read_layers(c, kernel_radius_hint));
    TRY(dict_get_vector_or(d, "origin", 3, zero3, c->origin));
    if (c->dim == 2)
        c->origin[2] = 0;
    TRY(read_regions(c));
    for (int i = 0; i < c->nregions; i++)
        if (c->r[i].shape == SHAPE_FILE)
            TRY(gen_file_check(c, &c->r[i]));
    TRY(check_in_tank(c));
    TRY(mps_box(c));
    return SIM_OK;
}

void gen_case_free(struct gen_case *c)
{
    for (int i = 0; i < c->nregions; i++) {
        free(c->r[i].file);
        free(c->r[i].fx);
        free(c->r[i].fr);
        free(c->r[i].fline);
    }
    free(c->r);
    c->r = NULL;
    c->nregions = 0;
}
