/*
 * wall.h — analytic walls for DEM grains: planes, boxes (grains inside: a
 * tank; grains outside: an obstacle) and finite cylinders (inside or
 * outside). A wall belongs to a named patch, which accumulates the contact
 * force it receives (the "load of solids on the obstacle", METHODS.md A.9).
 *
 * A box-inside wall is expanded into its six planes at set-up so that a
 * grain in a corner has one contact (and one tangential history) per face.
 * Every other wall gives at most one contact per grain (closest point on a
 * convex solid).
 *
 * TODO(geometry): the geometry primitives of src/particles/geometry.h were
 * not available when this was written; these few closest-point functions
 * stand in for them and should call them once they exist.
 */
#ifndef MPSDEM_DEM_WALL_H
#define MPSDEM_DEM_WALL_H

enum dem_wall_kind {
    DEM_WALL_PLANE,        /* p: point on plane, u: unit normal into the domain */
    DEM_WALL_BOX_OUTSIDE,  /* lo, hi: corners; grains stay outside            */
    DEM_WALL_CYL_OUTSIDE,  /* p: axis start, u: unit axis, len, radius        */
    DEM_WALL_CYL_INSIDE    /* same, grains stay inside the (infinite) tube    */
};

struct dem_wall {
    enum dem_wall_kind kind;
    double p[3], u[3];
    double lo[3], hi[3];
    double len, radius;
    int patch;             /* index into the patch names                    */
};

/* Contact of a sphere (centre x, radius r) with w. Returns 1 and sets the
 * unit normal n (grain -> wall) and the overlap delta > 0 when touching,
 * else 0. */
int wall_contact(const struct dem_wall *w, const double x[3], double r,
                 double n[3], double *delta);

/* Signed distance from x to the wall surface, positive on the grain side. */
double wall_distance(const struct dem_wall *w, const double x[3]);

/* Append the six inward planes of the box [lo, hi] (a tank) to walls;
 * returns the new count. walls must have room for six more. */
int wall_add_box_inside(struct dem_wall *walls, int nwalls, const double lo[3],
                        const double hi[3], int patch);

#endif
