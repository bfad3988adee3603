/*
 * wall.h — analytic walls for DEM grains, built on the geometry primitives
 * of src/particles/geometry.h (the same solids genParticles uses for the
 * fluid's walls), so that fluid and grains see one geometry.
 *
 * A wall is a solid and a side: grains stay outside it (an obstacle, a
 * half-space floor) or inside it (a cylindrical tank). A box tank is
 * expanded at set-up into its six half-spaces so that a grain in a corner
 * has one contact, and one tangential history, per face. Every other wall
 * gives at most one contact per grain (closest surface point). A wall
 * belongs to a named patch, which sums the contact force it receives
 * (doc/theory.md A.9, "load of solids on a structure").
 *
 * A wall may move (a rigid translation prescribed by its region's motion,
 * particles/motion/motion.h) or be removed at a time: g is then the solid
 * at the time of the last wall_place, g0 the solid at t = 0, vel the
 * wall's velocity that the contact's relative velocity subtracts, and a
 * removed wall touches nothing and is infinitely far.
 */
#ifndef MPSDEM_DEM_WALL_H
#define MPSDEM_DEM_WALL_H

#include "particles/geometry.h"
#include "particles/motion/motion.h"

struct dem_wall {
    struct geom g;
    int inside;   /* 1: grains inside the solid (a tank), 0: outside */
    int patch;    /* index into the patch names                      */
    int motion;   /* index into the dem's motions, -1: fixed, stays  */
    int removed;  /* 1 after its removeAt                            */
    double vel[3];/* velocity at the last wall_place [m/s]           */
    struct geom g0; /* the solid at t = 0                            */
};

/* Put w where motion m has it at time t (position, velocity, removal). */
void wall_place(struct dem_wall *w, const struct wall_motion *m, double t);

/* Contact of a sphere (centre x, radius r) with w. Returns 1 and sets the
 * unit normal n (grain -> wall) and the overlap delta > 0 when touching,
 * else 0. */
int wall_contact(const struct dem_wall *w, const double x[3], double r,
                 double n[3], double *delta);

/* wall_contact with the common case (a 3-D half-space: floors, tank
 * faces) inlined into the force loop. */
static inline int wall_contact_inline(const struct dem_wall *w,
                                      const double x[3], double r,
                                      double n[3], double *delta)
{
    if (w->g.shape != GEOM_HALFSPACE || w->g.dim != 3 || w->inside
        || w->removed)
        return wall_contact(w, x, r, n, delta);
    const double *u = w->g.axis, *p = w->g.p;
    double dist = (x[0] - p[0]) * u[0] + (x[1] - p[1]) * u[1]
                  + (x[2] - p[2]) * u[2];
    if (dist >= r)
        return 0;
    n[0] = -u[0], n[1] = -u[1], n[2] = -u[2];
    *delta = r - dist;
    return 1;
}

/* Distance from x to the wall surface, positive on the grain side
 * (INFINITY for a removed wall). */
double wall_distance(const struct dem_wall *w, const double x[3]);

/* Append the 2*dim faces of the box tank [lo, hi] (grains inside) as
 * half-spaces to walls, counting them in *nwalls (room for six needed). */
int wall_add_box_inside(struct dem_wall *walls, int *nwalls, int dim,
                        const double lo[3], const double hi[3], int patch);

/* A half-space wall through point p with the unit normal u pointing to the
 * grains (a floor: u = (0 0 1)). */
int wall_plane(struct dem_wall *w, int dim, const double p[3],
               const double u[3], int patch);

#endif
