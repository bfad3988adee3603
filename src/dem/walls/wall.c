/*
 * wall.c — closest points on the analytic wall primitives (see wall.h).
 */
#include "dem/walls/wall.h"

#include <math.h>

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double clampd(double v, double lo, double hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

/* Closest point cp on the solid box to x; returns the distance (negative
 * inside: depth below the nearest face, with cp on that face). */
static double box_closest(const struct dem_wall *w, const double x[3],
                          double cp[3])
{
    int inside = 1;
    for (int a = 0; a < 3; a++) {
        cp[a] = clampd(x[a], w->lo[a], w->hi[a]);
        if (cp[a] != x[a])
            inside = 0;
    }
    if (!inside) {
        double d[3] = {x[0] - cp[0], x[1] - cp[1], x[2] - cp[2]};
        return sqrt(dot3(d, d));
    }
    double best = INFINITY;
    int ba = 0;
    double bv = 0;
    for (int a = 0; a < 3; a++) {
        double dl = x[a] - w->lo[a], dh = w->hi[a] - x[a];
        if (dl < best) { best = dl; ba = a; bv = w->lo[a]; }
        if (dh < best) { best = dh; ba = a; bv = w->hi[a]; }
    }
    cp[0] = x[0], cp[1] = x[1], cp[2] = x[2];
    cp[ba] = bv;
    return -best;
}

/* Distance along the axis t and the radial vector of x from the axis. */
static void cyl_coords(const struct dem_wall *w, const double x[3], double *t,
                       double rv[3])
{
    double d[3] = {x[0] - w->p[0], x[1] - w->p[1], x[2] - w->p[2]};
    *t = dot3(d, w->u);
    for (int a = 0; a < 3; a++)
        rv[a] = d[a] - *t * w->u[a];
}

static double cyl_out_closest(const struct dem_wall *w, const double x[3],
                              double cp[3])
{
    double t, rv[3];
    cyl_coords(w, x, &t, rv);
    double rr = sqrt(dot3(rv, rv));
    double tc = clampd(t, 0, w->len);
    double rc = fmin(rr, w->radius);
    if (tc == t && rc == rr) {     /* inside: nearest of side and caps */
        double ds = w->radius - rr, d0 = t, d1 = w->len - t;
        if (ds <= d0 && ds <= d1 && rr > 0)
            rc = w->radius;
        else
            tc = d0 < d1 ? 0 : w->len;
    }
    for (int a = 0; a < 3; a++)
        cp[a] = w->p[a] + tc * w->u[a] + (rr > 0 ? rc * rv[a] / rr : 0);
    double d[3] = {x[0] - cp[0], x[1] - cp[1], x[2] - cp[2]};
    double dist = sqrt(dot3(d, d));
    return (tc == t && rr <= w->radius) ? -dist : dist;
}

double wall_distance(const struct dem_wall *w, const double x[3])
{
    double cp[3], t, rv[3];
    switch (w->kind) {
    case DEM_WALL_PLANE: {
        double d[3] = {x[0] - w->p[0], x[1] - w->p[1], x[2] - w->p[2]};
        return dot3(d, w->u);
    }
    case DEM_WALL_BOX_OUTSIDE:
        return box_closest(w, x, cp);
    case DEM_WALL_CYL_OUTSIDE:
        return cyl_out_closest(w, x, cp);
    case DEM_WALL_CYL_INSIDE:
        cyl_coords(w, x, &t, rv);
        return w->radius - sqrt(dot3(rv, rv));
    }
    return INFINITY;
}

int wall_contact(const struct dem_wall *w, const double x[3], double r,
                 double n[3], double *delta)
{
    double cp[3], dist, t, rv[3];
    switch (w->kind) {
    case DEM_WALL_PLANE: {
        double d[3] = {x[0] - w->p[0], x[1] - w->p[1], x[2] - w->p[2]};
        dist = dot3(d, w->u);
        if (dist >= r)
            return 0;
        for (int a = 0; a < 3; a++)
            n[a] = -w->u[a];
        *delta = r - dist;
        return 1;
    }
    case DEM_WALL_CYL_INSIDE: {
        cyl_coords(w, x, &t, rv);
        double rr = sqrt(dot3(rv, rv));
        dist = w->radius - rr;
        if (dist >= r || rr == 0)
            return 0;
        for (int a = 0; a < 3; a++)
            n[a] = rv[a] / rr;
        *delta = r - dist;
        return 1;
    }
    case DEM_WALL_BOX_OUTSIDE:
        dist = box_closest(w, x, cp);
        break;
    case DEM_WALL_CYL_OUTSIDE:
        dist = cyl_out_closest(w, x, cp);
        break;
    default:
        return 0;
    }
    if (dist >= r)
        return 0;
    /* Normal from the centre towards the closest surface point; a centre
     * inside the solid flips it so that the grain is pushed out. */
    double d[3] = {cp[0] - x[0], cp[1] - x[1], cp[2] - x[2]};
    double dl = sqrt(dot3(d, d));
    if (dl == 0)
        return 0;
    double s = dist < 0 ? -1.0 : 1.0;
    for (int a = 0; a < 3; a++)
        n[a] = s * d[a] / dl;
    *delta = r - dist;
    return 1;
}

int wall_add_box_inside(struct dem_wall *walls, int nwalls, const double lo[3],
                        const double hi[3], int patch)
{
    for (int a = 0; a < 3; a++)
        for (int side = 0; side < 2; side++) {
            struct dem_wall *w = &walls[nwalls++];
            *w = (struct dem_wall){.kind = DEM_WALL_PLANE, .patch = patch};
            w->p[a] = side ? hi[a] : lo[a];
            w->u[a] = side ? -1.0 : 1.0;
        }
    return nwalls;
}
