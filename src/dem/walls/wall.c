/*
 * wall.c — sphere-wall contact geometry from the signed distance and normal
 * of the geometry primitives (see wall.h).
 */
#include "dem/walls/wall.h"

#include <math.h>
#include <string.h>

#include "core/error.h"

double wall_distance(const struct dem_wall *w, const double x[3])
{
    if (w->removed)
        return INFINITY;
    double s = geom_distance(&w->g, x);
    return w->inside ? -s : s;
}

int wall_contact(const struct dem_wall *w, const double x[3], double r,
                 double n[3], double *delta)
{
    if (w->removed)
        return 0;
    if (w->g.shape == GEOM_HALFSPACE && w->g.dim == 3 && !w->inside) {
        /* the common case (floors, tank faces) without the general call */
        const double *u = w->g.axis, *p = w->g.p;
        double dist = (x[0] - p[0]) * u[0] + (x[1] - p[1]) * u[1]
                      + (x[2] - p[2]) * u[2];
        if (dist >= r)
            return 0;
        n[0] = -u[0], n[1] = -u[1], n[2] = -u[2];
        *delta = r - dist;
        return 1;
    }
    double dist = wall_distance(w, x);
    if (dist >= r)
        return 0;
    /* geom_normal is the solid's outward normal at the closest point: it
     * points away from a grain outside the solid and towards the wall for
     * a grain inside a tank. A centre that crossed the surface keeps the
     * normal that pushes it back. */
    geom_normal(&w->g, x, n);
    if (!w->inside)
        n[0] = -n[0], n[1] = -n[1], n[2] = -n[2];
    *delta = r - dist;
    return 1;
}

int wall_plane(struct dem_wall *w, int dim, const double p[3],
               const double u[3], int patch)
{
    memset(w, 0, sizeof *w);
    w->patch = patch;
    w->motion = -1;
    /* geom_halfspace's normal is the solid's outward normal: the grains'
     * side is where u points, so the solid lies on -u and its outward
     * normal is u. */
    TRY(geom_halfspace(&w->g, dim, p, u));
    w->g0 = w->g;
    return SIM_OK;
}

void wall_place(struct dem_wall *w, const struct wall_motion *m, double t)
{
    double d[3];
    w->removed = wall_motion_removed(m, t);
    wall_motion_displacement(m, t, d);
    wall_motion_velocity(m, t, w->vel);
    w->g = w->g0;
    /* a rigid translation moves every point the solid is defined by */
    for (int a = 0; a < 3; a++) {
        w->g.lo[a] += d[a];
        w->g.hi[a] += d[a];
        w->g.p[a] += d[a];
    }
}

int wall_add_box_inside(struct dem_wall *walls, int *nwalls, int dim,
                        const double lo[3], const double hi[3], int patch)
{
    for (int a = 0; a < dim; a++)
        for (int side = 0; side < 2; side++) {
            double p[3] = {0, 0, 0}, u[3] = {0, 0, 0};
            p[a] = side ? hi[a] : lo[a];
            u[a] = side ? -1.0 : 1.0;
            TRY(wall_plane(&walls[*nwalls], dim, p, u, patch));
            (*nwalls)++;
        }
    return SIM_OK;
}
