/*
 * geometry.h — analytic solids shared by particle generation (genParticles)
 * and the DEM's walls: box, finite cylinder (any axis), sphere and
 * half-space.
 *
 * Conventions. The signed distance is negative inside the solid, zero on
 * its surface and positive outside; it is the Euclidean distance to the
 * surface (exact for every shape, including at box edges and corners).
 * The normal at x is the unit outward normal of the surface at the point
 * closest to x (the gradient of the signed distance where it exists; where
 * several surface points are equally close, e.g. at a box corner seen from
 * inside, the normalised sum of their normals).
 *
 * 2-D (dim = 2): everything lives in the plane z = 0 and the z components
 * of the inputs are ignored: a box is the rectangle [min, max] in x-y, a
 * sphere is a circle, a half-space's normal is projected on x-y, and a
 * cylinder must have its axis either in the x-y plane (a rectangle of
 * width 2 radius) or along z (a circle).
 *
 * Units: metres throughout.
 */
#ifndef MPSDEM_PARTICLES_GEOMETRY_H
#define MPSDEM_PARTICLES_GEOMETRY_H

enum geom_shape { GEOM_BOX, GEOM_CYLINDER, GEOM_SPHERE, GEOM_HALFSPACE };

/* Names as used in dictionaries ("box" "cylinder" "sphere" "plane"),
 * indexed by enum geom_shape, NULL terminated. */
extern const char *const geom_shape_names[];

struct geom {
    enum geom_shape shape;
    int dim;              /* 2 or 3                                     */
    double lo[3], hi[3];  /* box corners                                */
    double p[3];          /* sphere centre; cylinder axis start;        */
                          /* half-space: a point on its plane           */
    double axis[3];       /* cylinder: unit axis; half-space: unit      */
                          /* outward normal                             */
    double length;        /* cylinder: axis length                      */
    double radius;        /* sphere, cylinder                           */
};

/* Constructors; they validate (positive sizes, non-degenerate axis and
 * normal) and return SIM_ERR_INPUT with a message saying what is wrong,
 * so that a caller can prefix the dictionary location. */
int geom_box(struct geom *g, int dim, const double min[3], const double max[3]);
int geom_sphere(struct geom *g, int dim, const double centre[3], double r);
int geom_cylinder(struct geom *g, int dim, const double p1[3],
                  const double p2[3], double r);
/* Solid = the side of the plane through `point` opposite to `normal`. */
int geom_halfspace(struct geom *g, int dim, const double point[3],
                   const double normal[3]);

double geom_distance(const struct geom *g, const double x[3]);
static inline int geom_inside(const struct geom *g, const double x[3])
{
    return geom_distance(g, x) <= 0.0;
}
void geom_normal(const struct geom *g, const double x[3], double n[3]);
void geom_closest(const struct geom *g, const double x[3], double c[3]);

/* Axis-aligned bounding box; unbounded directions get -/+HUGE_VAL. In
 * 2-D, lo[2] = hi[2] = 0. Returns 1 when bounded in every used direction. */
int geom_bbox(const struct geom *g, double lo[3], double hi[3]);

#endif
