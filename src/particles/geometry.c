/*
 * geometry.c — signed distance, normal and closest point of the analytic
 * solids of geometry.h.
 *
 * Box: with q_i = max(lo_i - x_i, x_i - hi_i) (positive beyond a face),
 *   d = |max(q, 0)|            outside,   d = max_i q_i   inside.
 * Finite cylinder (start p, unit axis a, length L, radius R), in the
 * meridian half-plane: t = (x - p).a, rho = |x - p - t a|,
 *   q = (rho - R, max(-t, t - L)), then the same formula as the box in 2-D.
 * Sphere: d = |x - c| - R.  Half-space: d = (x - p).n.
 * These are the exact Euclidean distances (the usual box/cylinder signed
 * distance functions); normals are computed from the same q so that they
 * stay defined on the surface itself, where x - closest(x) vanishes.
 */
#include "particles/geometry.h"

#include <math.h>
#include <string.h>

#include "core/error.h"

const char *const geom_shape_names[] = { "box", "cylinder", "sphere",
                                         "plane", NULL };

/* Relative tolerance for "equally close" faces. */
#define TIE 1e-12

static double dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double norm(const double a[3]) { return sqrt(dot(a, a)); }

/* v = x - p, in the plane z = 0 for 2-D. */
static void rel(const struct geom *g, const double x[3], const double p[3],
                double v[3])
{
    v[0] = x[0] - p[0];
    v[1] = x[1] - p[1];
    v[2] = g->dim == 2 ? 0.0 : x[2] - p[2];
}

static void copy_in(int dim, const double in[3], double out[3])
{
    out[0] = in[0];
    out[1] = in[1];
    out[2] = dim == 2 ? 0.0 : in[2];
}

static int check_dim(int dim)
{
    if (dim != 2 && dim != 3)
        return sim_error(SIM_ERR_INPUT, "dimension %d is not 2 or 3", dim);
    return SIM_OK;
}

/* ---- constructors ----------------------------------------------------------- */

int geom_box(struct geom *g, int dim, const double min[3], const double max[3])
{
    TRY(check_dim(dim));
    memset(g, 0, sizeof *g);
    g->shape = GEOM_BOX;
    g->dim = dim;
    copy_in(dim, min, g->lo);
    copy_in(dim, max, g->hi);
    for (int i = 0; i < dim; i++)
        if (!(g->hi[i] > g->lo[i]) || !isfinite(g->hi[i] - g->lo[i]))
            return sim_error(SIM_ERR_INPUT, "box max (%g) must exceed min "
                             "(%g) in %c", g->hi[i], g->lo[i], "xyz"[i]);
    return SIM_OK;
}

int geom_sphere(struct geom *g, int dim, const double centre[3], double r)
{
    TRY(check_dim(dim));
    memset(g, 0, sizeof *g);
    g->shape = GEOM_SPHERE;
    g->dim = dim;
    copy_in(dim, centre, g->p);
    g->radius = r;
    if (!(r > 0) || !isfinite(r) || !isfinite(norm(g->p)))
        return sim_error(SIM_ERR_INPUT, "radius %g must be positive", r);
    return SIM_OK;
}

int geom_cylinder(struct geom *g, int dim, const double p1[3],
                  const double p2[3], double r)
{
    double a[3] = { p2[0] - p1[0], p2[1] - p1[1], p2[2] - p1[2] }, len;

    TRY(check_dim(dim));
    memset(g, 0, sizeof *g);
    if (!(r > 0) || !isfinite(r))
        return sim_error(SIM_ERR_INPUT, "radius %g must be positive", r);
    len = norm(a);
    if (!(len > 0) || !isfinite(len))
        return sim_error(SIM_ERR_INPUT, "the two axis points coincide");
    if (dim == 2 && fabs(a[2]) > TIE * len) {
        /* Along z the cross-section with the plane is a circle. */
        if (hypot(a[0], a[1]) > TIE * len)
            return sim_error(SIM_ERR_INPUT, "in 2-D a cylinder's axis must "
                             "lie in the x-y plane or along z");
        return geom_sphere(g, dim, p1, r);
    }
    g->shape = GEOM_CYLINDER;
    g->dim = dim;
    copy_in(dim, p1, g->p);
    if (dim == 2)
        a[2] = 0.0;
    for (int i = 0; i < 3; i++)
        g->axis[i] = a[i] / len;
    g->length = len;
    g->radius = r;
    return SIM_OK;
}

int geom_halfspace(struct geom *g, int dim, const double point[3],
                   const double normal[3])
{
    double len;

    TRY(check_dim(dim));
    memset(g, 0, sizeof *g);
    g->shape = GEOM_HALFSPACE;
    g->dim = dim;
    copy_in(dim, point, g->p);
    copy_in(dim, normal, g->axis);
    len = norm(g->axis);
    if (!(len > 0) || !isfinite(len))
        return sim_error(SIM_ERR_INPUT, "plane normal is zero%s",
                         dim == 2 ? " in the x-y plane" : "");
    for (int i = 0; i < 3; i++)
        g->axis[i] /= len;
    return SIM_OK;
}

/* ---- box -------------------------------------------------------------------- */

/* q_i and the sign of the nearer face along each axis. */
static void box_q(const struct geom *g, const double x[3], double q[3],
                  double s[3])
{
    for (int i = 0; i < 3; i++) {
        double below = g->lo[i] - x[i], above = x[i] - g->hi[i];
        if (i >= g->dim) {
            q[i] = -HUGE_VAL;
            s[i] = 0.0;
            continue;
        }
        q[i] = below > above ? below : above;
        s[i] = below > above ? -1.0 : 1.0;
    }
}

static double box_distance(const struct geom *g, const double x[3])
{
    double q[3], s[3], out = 0.0, in = -HUGE_VAL;
    box_q(g, x, q, s);
    for (int i = 0; i < g->dim; i++) {
        if (q[i] > 0)
            out += q[i] * q[i];
        in = fmax(in, q[i]);
    }
    return out > 0 ? sqrt(out) : in;
}

static void box_normal(const struct geom *g, const double x[3], double n[3])
{
    double q[3], s[3], d = box_distance(g, x), tol;
    box_q(g, x, q, s);
    tol = TIE * (g->hi[0] - g->lo[0] + g->hi[1] - g->lo[1] +
                 (g->dim == 3 ? g->hi[2] - g->lo[2] : 0));
    for (int i = 0; i < 3; i++) {
        if (d > 0)
            n[i] = q[i] > 0 ? s[i] * q[i] : 0.0;
        else
            n[i] = q[i] >= d - tol ? s[i] : 0.0;
    }
    d = norm(n);
    for (int i = 0; i < 3; i++)
        n[i] /= d;
}

static void box_closest(const struct geom *g, const double x[3], double c[3])
{
    double q[3], s[3];
    int imax = 0;
    box_q(g, x, q, s);
    for (int i = 0; i < 3; i++) {
        c[i] = i < g->dim ? fmin(fmax(x[i], g->lo[i]), g->hi[i]) : 0.0;
        if (i < g->dim && q[i] > q[imax])
            imax = i;
    }
    if (q[imax] <= 0) /* inside: onto the nearest face */
        c[imax] = s[imax] > 0 ? g->hi[imax] : g->lo[imax];
}

/* ---- cylinder --------------------------------------------------------------- */

struct cyl_frame {
    double t, rho, dr, da; /* axial coordinate, radius, q components */
    double er[3];          /* unit radial direction                  */
    double sa;             /* -1 nearer the start cap, +1 the end    */
};

static void cyl_frame(const struct geom *g, const double x[3],
                      struct cyl_frame *f)
{
    double v[3];
    rel(g, x, g->p, v);
    f->t = dot(v, g->axis);
    for (int i = 0; i < 3; i++)
        f->er[i] = v[i] - f->t * g->axis[i];
    f->rho = norm(f->er);
    if (f->rho > 0) {
        for (int i = 0; i < 3; i++)
            f->er[i] /= f->rho;
    } else { /* on the axis: any direction perpendicular to it */
        const double *a = g->axis;
        double e[3] = { -a[1], a[0], 0.0 };
        if (g->dim == 3 && fabs(a[2]) > 0.9) {
            e[0] = 0.0; e[1] = -a[2]; e[2] = a[1];
        }
        double l = norm(e);
        for (int i = 0; i < 3; i++)
            f->er[i] = e[i] / l;
    }
    f->dr = f->rho - g->radius;
    f->sa = -f->t > f->t - g->length ? -1.0 : 1.0;
    f->da = f->sa < 0 ? -f->t : f->t - g->length;
}

static double cyl_distance(const struct geom *g, const double x[3])
{
    struct cyl_frame f;
    cyl_frame(g, x, &f);
    if (f.dr > 0 || f.da > 0)
        return hypot(fmax(f.dr, 0.0), fmax(f.da, 0.0));
    return fmax(f.dr, f.da);
}

static void cyl_normal(const struct geom *g, const double x[3], double n[3])
{
    struct cyl_frame f;
    double wr, wa, l;
    cyl_frame(g, x, &f);
    if (f.dr > 0 || f.da > 0) {
        wr = fmax(f.dr, 0.0);
        wa = fmax(f.da, 0.0);
    } else {
        double tol = TIE * (g->length + g->radius), m = fmax(f.dr, f.da);
        wr = f.dr >= m - tol;
        wa = f.da >= m - tol;
    }
    for (int i = 0; i < 3; i++)
        n[i] = wr * f.er[i] + wa * f.sa * g->axis[i];
    l = norm(n);
    for (int i = 0; i < 3; i++)
        n[i] /= l;
}

static void cyl_closest(const struct geom *g, const double x[3], double c[3])
{
    struct cyl_frame f;
    double t, rho;
    cyl_frame(g, x, &f);
    if (f.dr > 0 || f.da > 0) {
        t = fmin(fmax(f.t, 0.0), g->length);
        rho = fmin(f.rho, g->radius);
    } else if (f.dr >= f.da) {
        t = f.t;
        rho = g->radius;
    } else {
        t = f.sa < 0 ? 0.0 : g->length;
        rho = f.rho;
    }
    for (int i = 0; i < 3; i++)
        c[i] = g->p[i] + t * g->axis[i] + rho * f.er[i];
}

/* ---- dispatch --------------------------------------------------------------- */

double geom_distance(const struct geom *g, const double x[3])
{
    double v[3];
    switch (g->shape) {
    case GEOM_BOX:
        return box_distance(g, x);
    case GEOM_CYLINDER:
        return cyl_distance(g, x);
    case GEOM_SPHERE:
        rel(g, x, g->p, v);
        return norm(v) - g->radius;
    default:
        rel(g, x, g->p, v);
        return dot(v, g->axis);
    }
}

void geom_normal(const struct geom *g, const double x[3], double n[3])
{
    double v[3], r;
    switch (g->shape) {
    case GEOM_BOX:
        box_normal(g, x, n);
        return;
    case GEOM_CYLINDER:
        cyl_normal(g, x, n);
        return;
    case GEOM_SPHERE:
        rel(g, x, g->p, v);
        r = norm(v);
        if (r == 0) { /* the centre: every direction is as good */
            v[0] = 1.0;
            r = 1.0;
        }
        for (int i = 0; i < 3; i++)
            n[i] = v[i] / r;
        return;
    default:
        memcpy(n, g->axis, sizeof g->axis);
        return;
    }
}

void geom_closest(const struct geom *g, const double x[3], double c[3])
{
    double n[3], d;
    switch (g->shape) {
    case GEOM_BOX:
        box_closest(g, x, c);
        return;
    case GEOM_CYLINDER:
        cyl_closest(g, x, c);
        return;
    case GEOM_SPHERE:
        geom_normal(g, x, n);
        for (int i = 0; i < 3; i++)
            c[i] = g->p[i] + g->radius * n[i];
        return;
    default:
        d = geom_distance(g, x);
        for (int i = 0; i < 3; i++)
            c[i] = (i < g->dim ? x[i] : 0.0) - d * g->axis[i];
        return;
    }
}

int geom_bbox(const struct geom *g, double lo[3], double hi[3])
{
    int bounded = 1;
    for (int i = 0; i < 3; i++) {
        const double *a = g->axis;
        double e;
        switch (g->shape) {
        case GEOM_BOX:
            lo[i] = g->lo[i];
            hi[i] = g->hi[i];
            break;
        case GEOM_SPHERE:
            lo[i] = g->p[i] - g->radius;
            hi[i] = g->p[i] + g->radius;
            break;
        case GEOM_CYLINDER:
            /* The end discs reach R sqrt(1 - a_i^2) beyond the axis. */
            e = g->radius * sqrt(fmax(0.0, 1.0 - a[i] * a[i]));
            lo[i] = fmin(g->p[i], g->p[i] + g->length * a[i]) - e;
            hi[i] = fmax(g->p[i], g->p[i] + g->length * a[i]) + e;
            break;
        default: {
            /* Bounded along i only if the plane is normal to axis i. */
            int only = 1;
            for (int k = 0; k < g->dim; k++)
                only &= k == i || a[k] == 0.0;
            lo[i] = only && a[i] < 0 ? g->p[i] : -HUGE_VAL;
            hi[i] = only && a[i] > 0 ? g->p[i] : HUGE_VAL;
            break;
        }
        }
        if (i >= g->dim)
            lo[i] = hi[i] = 0.0;
        else if (!isfinite(lo[i]) || !isfinite(hi[i]))
            bounded = 0;
    }
    return bounded;
}
