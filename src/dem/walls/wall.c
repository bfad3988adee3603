/*
 * wall.c — sphere-wall contact geometry from the signed distance and normal
 * of the geometry primitives (see wall.h).
 */
#include "dem/walls/wall.h"

#include "core/error.h"

double wall_distance(const struct dem_wall *w, const double x[3])
{
    double s = geom_distance(&w->g, x);
    return w->inside ? -s : s;
}

int wall_contact(const struct dem_wall *w, const double x[3], double r,
                 double n[3], double *delta)
{
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
    w->inside = 0;
    w->patch = patch;
    /* geom_halfspace's normal is the solid's outward normal: the grains'
     * side is where u points, so the solid lies on -u and its outward
     * normal is u. */
    return geom_halfspace(&w->g, dim, p, u);
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
