/*
 * dem_case_io.c — walls from system/particleDict, grains from and to
 * dem.vtu, contact histories for restart, and the start-up overlap check
 * (dem_case.h).
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "dem/dem_case.h"
#include "io/vtu.h"

#define MAX_WALLS 256

static const char *const face_words[] = {"xmin", "xmax", "ymin", "ymax",
                                         "zmin", "zmax", NULL};

static int read_shape(const struct dict *r, int dim, struct geom *g)
{
    double a[3], b[3], rad;
    int shape;
    TRY(dict_get_word(r, "shape", geom_shape_names, &shape));
    int rc = SIM_OK;
    switch ((enum geom_shape)shape) {
    case GEOM_BOX:
        TRY(dict_get_vector(r, "min", 3, a));
        TRY(dict_get_vector(r, "max", 3, b));
        rc = geom_box(g, dim, a, b);
        break;
    case GEOM_CYLINDER:
        TRY(dict_get_vector(r, "point1", 3, a));
        TRY(dict_get_vector(r, "point2", 3, b));
        TRY(dict_get_scalar(r, "radius", &rad));
        rc = geom_cylinder(g, dim, a, b, rad);
        break;
    case GEOM_SPHERE:
        TRY(dict_get_vector(r, "centre", 3, a));
        TRY(dict_get_scalar(r, "radius", &rad));
        rc = geom_sphere(g, dim, a, rad);
        break;
    case GEOM_HALFSPACE:
        TRY(dict_get_vector(r, "point", 3, a));
        TRY(dict_get_vector(r, "normal", 3, b));
        rc = geom_halfspace(g, dim, a, b);
        break;
    }
    if (rc != SIM_OK) {
        char msg[512];
        snprintf(msg, sizeof msg, "%s", sim_error_message());
        return dict_error(r, "shape", SIM_ERR_DICT, "%s", msg);
    }
    return SIM_OK;
}

/* Open faces of a tank box: bit 2*axis + side. */
static int read_open(const struct dict *r, unsigned *open)
{
    *open = 0;
    if (!dict_has(r, "open"))
        return SIM_OK;
    const struct dict_value *l;
    TRY(dict_get_list(r, "open", &l));
    for (int i = 0; i < dict_value_len(l); i++) {
        const char *w;
        TRY(dict_value_get_word(dict_value_at(l, i), &w));
        for (int f = 0; face_words[f]; f++)
            if (strcmp(face_words[f], w) == 0)
                *open |= 1u << f;
    }
    return SIM_OK;
}

/* A wall of solid g; motion: index of its motion, or -1. */
static void add_solid(struct dem *d, const struct geom *g, int inside,
                      int patch, int motion)
{
    struct dem_wall *w = &d->walls[d->nwalls++];
    memset(w, 0, sizeof *w);
    w->g = w->g0 = *g;
    w->inside = inside, w->patch = patch, w->motion = motion;
}

static int add_tank(struct dem *d, const struct dict *r, int dim,
                    const struct geom *g, int patch, int motion)
{
    unsigned open;
    TRY(read_open(r, &open));
    if (g->shape != GEOM_BOX) {
        add_solid(d, g, 1, patch, motion);
        return SIM_OK;
    }
    for (int a = 0; a < dim; a++)
        for (int side = 0; side < 2; side++) {
            if (open >> (2 * a + side) & 1)
                continue;
            double p[3] = {0, 0, 0}, u[3] = {0, 0, 0};
            p[a] = side ? g->hi[a] : g->lo[a];
            u[a] = side ? -1.0 : 1.0;
            TRY(wall_plane(&d->walls[d->nwalls], dim, p, u, patch));
            d->walls[d->nwalls++].motion = motion;
        }
    if (!d->have_domain) {
        /* a grain beyond the tank by two diameters has tunnelled out */
        for (int a = 0; a < 3; a++) {
            d->dom_lo[a] = g->lo[a] - 4 * d->rmax;
            d->dom_hi[a] = g->hi[a] + 4 * d->rmax;
        }
        if (dim == 2)
            d->dom_lo[2] = -1, d->dom_hi[2] = 1;
        d->have_domain = 1;
    }
    return SIM_OK;
}

static int add_region(struct dem *d, const char *name, const struct dict *r,
                      int dim, const char *case_dir)
{
    int patch = d->npatches;
    if (patch >= DEM_MAX_PATCHES || d->nwalls + 6 > MAX_WALLS)
        return dict_error(r, NULL, SIM_ERR_DICT, "too many regions (%d at "
                          "most)", DEM_MAX_PATCHES);
    snprintf(d->patch_names[patch], sizeof d->patch_names[patch], "%s", name);
    d->npatches++;
    const char *type;
    TRY(dict_get_string(r, "type", &type));
    int is_wall = !strcmp(type, "tankWall") || !strcmp(type, "wall");
    struct wall_motion *m = &d->motions[patch];
    TRY(wall_motion_read(r, is_wall, dim, case_dir, m));
    if (!is_wall)
        return SIM_OK;  /* fluid and grains regions make no walls */
    int motion = wall_motion_moves(m) || isfinite(m->remove_at) ? patch : -1;
    if (wall_motion_moves(m))
        log_info("Wall %s moves (motion %s)", name, m->ops->name);
    if (isfinite(m->remove_at))
        log_info("Wall %s is removed at t = %g s", name, m->remove_at);
    struct geom g;
    TRY(read_shape(r, dim, &g));
    if (strcmp(type, "tankWall") == 0)
        return add_tank(d, r, dim, &g, patch, motion);
    add_solid(d, &g, 0, patch, motion);
    return SIM_OK;
}

int dem_read_walls(const struct dict *pd, const char *case_dir,
                   struct dem *d, int *dim)
{
    long dl;
    TRY(dict_get_label_or(pd, "dimension", 3, &dl));
    *dim = (int)dl;
    free(d->walls);
    d->walls = sim_calloc(MAX_WALLS, sizeof *d->walls);
    if (!d->walls)
        return SIM_ERR_NOMEM;
    if (d->motions)
        for (int k = 0; k < DEM_MAX_PATCHES; k++)
            wall_motion_free(&d->motions[k]);
    free(d->motions);
    d->motions = sim_calloc(DEM_MAX_PATCHES, sizeof *d->motions);
    if (!d->motions)
        return SIM_ERR_NOMEM;
    for (int k = 0; k < DEM_MAX_PATCHES; k++)
        wall_motion_init(&d->motions[k]);
    d->nwalls = 0;
    d->npatches = 0;
    if (dict_is_dict(pd, "regions")) {
        const struct dict *rd;
        TRY(dict_get_dict(pd, "regions", &rd));
        for (int i = 0; i < dict_size(rd); i++) {
            const struct dict *r;
            TRY(dict_get_dict(rd, dict_key_at(rd, i), &r));
            TRY(add_region(d, dict_key_at(rd, i), r, *dim, case_dir));
        }
        return SIM_OK;
    }
    const struct dict_value *l;
    TRY(dict_get_list(pd, "regions", &l));
    for (int i = 0; i + 1 < dict_value_len(l); i += 2) {
        const char *name;
        TRY(dict_value_get_word(dict_value_at(l, i), &name));
        const struct dict_value *v = dict_value_at(l, i + 1);
        if (dict_value_kind(v) != DICT_DICT)
            return dict_value_error(v, SIM_ERR_DICT, "region '%s' needs "
                                    "a { ... }", name);
        TRY(add_region(d, name, dict_value_dict(v), *dim, case_dir));
    }
    return SIM_OK;
}

int dem_read_grains(const char *path, struct dem *d)
{
    struct vtu_cloud c;
    memset(&c, 0, sizeof c);
    TRY(vtu_read(path, &c));
    const struct vtu_field *fr, *fv, *fw, *fg, *fi;
    int rc = vtu_check_finite(&c, path);
    if (!rc) rc = vtu_require(&c, path, "radius", VTU_FLOAT64, 1, &fr);
    if (!rc) rc = vtu_require(&c, path, "velocity", VTU_FLOAT64, 3, &fv);
    if (!rc) rc = vtu_require(&c, path, "omega", VTU_FLOAT64, 3, &fw);
    if (!rc) rc = vtu_require(&c, path, "group", VTU_INT32, 1, &fg);
    if (!rc) rc = vtu_require(&c, path, "id", VTU_INT64, 1, &fi);
    if (!rc) rc = dem_resize(d, c.n);
    if (rc) {
        vtu_cloud_free(&c);
        return rc;
    }
    memcpy(d->x, c.points, 3 * c.n * sizeof(double));
    memcpy(d->v, fv->data, 3 * c.n * sizeof(double));
    memcpy(d->w, fw->data, 3 * c.n * sizeof(double));
    memcpy(d->r, fr->data, c.n * sizeof(double));
    memcpy(d->group, fg->data, c.n * sizeof(int32_t));
    memcpy(d->id, fi->data, c.n * sizeof(int64_t));
    for (size_t i = 0; i < c.n; i++)
        if (!(d->r[i] > 0) || !isfinite(d->x[3 * i] + d->x[3 * i + 1]
                                        + d->x[3 * i + 2])) {
            rc = sim_error(SIM_ERR_INPUT, "%s: grain %zu (id %lld) has "
                           "radius %g or a non-finite position", path, i,
                           (long long)d->id[i], d->r[i]);
            break;
        }
    vtu_cloud_free(&c);
    return rc;
}

int dem_write_grains(const char *path, const struct dem *d, int binary)
{
    struct vtu_field f[STORE_MAX_FIELDS];
    struct vtu_cloud c;
    store_cloud(&d->st, d->t, f, &c);
    return vtu_write(path, &c, binary);
}
