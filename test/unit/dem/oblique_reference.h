/*
 * oblique_reference.h — reference solution of an oblique sphere-wall
 * impact for test_integrators.c, independent of dem_forces and of ARKode:
 * the same contact law (Hertz, dashpot eta = 2 zeta sqrt(k m), spring
 * with the Coulomb cone on the stick force and on the spring's force,
 * doc/theory.md A.6, A0-22, A0-24) written out for one sphere on the
 * plane z = 0 without gravity, integrated by the classical fixed-step
 * Runge-Kutta method with every discontinuity located:
 *
 *   delta = R - z,  vn = -v_z,  u = v_x - R w_y   (tangential slip speed)
 *   F^n = chi delta^1.5 + eta^n vn,  kt = ratio_t chi delta^0.5,
 *   L = mu |F^n|
 *   stick:  F^t = -kt s - eta^t u,  ds/dt = u
 *   slip:   F^t = -L sigma,         s = sigma L/kt   (sigma = +-1)
 *   m dv_z/dt = F^n,  m dv_x/dt = F^t,  I dw_y/dt = -R F^t.
 *
 * Stick becomes slip where max(|kt s + eta^t u|, kt |s|/sqrt(CONE))
 * reaches L; slip becomes stick where both |L sigma + eta^t u| <= L and
 * D <= 0, with D the rate of kt |s| - L along the stick flow from the
 * spring at the limit, here in closed form (eta^n grows as delta^(1/4),
 * dv_z/dt = F^n/m):
 *
 *   D = L vn/(2 delta) + kt sigma u
 *       - mu sgn(F^n) (kn vn + eta^n vn^2/(4 delta) - eta^n F^n/m).
 *
 * Events (a switch, a sign change of F^n, the end of the contact) are
 * located by bisection on the length of the Runge-Kutta step that
 * crosses them (to 1e-15 of the step), the phase decided again there
 * (where F^n changes sign the limit, and the spring at it, are 0: the
 * next phase starts from a zero spring, as a contact does);
 * the start of the contact is exact (free flight). Near both ends of the
 * contact, where the dashpot grows as delta^(1/4), the steps shrink with
 * the overlap; the caller checks the result against a halved step.
 */
#ifndef OBLIQUE_REFERENCE_H
#define OBLIQUE_REFERENCE_H

#include <math.h>
#include <string.h>

#include "dem/contact/contact.h"

struct oref {
    double m, inertia, r, chi, ratio_t, zeta, mu;
    int *resets;         /* counts the springs' jumps (oref_decide)   */
};

struct oref_out {
    double vt, w;        /* v_x and w_y after the contact             */
    int switches;        /* phase changes                             */
    int fn_signs;        /* sign changes of F^n                       */
    int resets;          /* slips of zero length (oref_decide)        */
};

/* y = (z, v_z, v_x, w_y, s) */
struct oref_eval {
    double delta, vn, u, fn, L, kt, kn, eta_n, eta_t, ft;
};

static void oref_law(const struct oref *p, const double *y, int slip,
                     int sigma, struct oref_eval *e)
{
    e->delta = p->r - y[0];
    e->vn = -y[1];
    e->u = y[2] - p->r * y[3];
    double sd = sqrt(fmax(e->delta, 0));
    e->kn = 1.5 * p->chi * sd;
    e->kt = p->ratio_t * p->chi * sd;
    e->eta_n = 2 * p->zeta * sqrt(e->kn * p->m);
    e->eta_t = 2 * p->zeta * sqrt(e->kt * p->m);
    e->fn = p->chi * e->delta * sd + e->eta_n * e->vn;
    e->L = p->mu * fabs(e->fn);
    e->ft = slip ? -e->L * sigma : -e->kt * y[4] - e->eta_t * e->u;
}

static void oref_rhs(const struct oref *p, const double *y, int slip,
                     int sigma, double *dy)
{
    struct oref_eval e;
    oref_law(p, y, slip, sigma, &e);
    dy[0] = y[1];
    dy[1] = e.fn / p->m;
    dy[2] = e.ft / p->m;
    dy[3] = -p->r * e.ft / p->inertia;
    dy[4] = slip ? 0.0 : e.u;
}

static void oref_rk4(const struct oref *p, const double *y, double h,
                     int slip, int sigma, double *out)
{
    double k1[5], k2[5], k3[5], k4[5], t[5];
    oref_rhs(p, y, slip, sigma, k1);
    for (int i = 0; i < 5; i++) t[i] = y[i] + 0.5 * h * k1[i];
    oref_rhs(p, t, slip, sigma, k2);
    for (int i = 0; i < 5; i++) t[i] = y[i] + 0.5 * h * k2[i];
    oref_rhs(p, t, slip, sigma, k3);
    for (int i = 0; i < 5; i++) t[i] = y[i] + h * k3[i];
    oref_rhs(p, t, slip, sigma, k4);
    for (int i = 0; i < 5; i++)
        out[i] = y[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
}

/* The switching function of the phase (positive while it lasts). */
static double oref_g(const struct oref *p, const double *y, int slip,
                     int sigma)
{
    struct oref_eval e;
    oref_law(p, y, slip, sigma, &e);
    if (!(e.L > 0))
        return slip ? 1.0 : -1.0;
    if (!slip) {
        double ftot = fabs(e.kt * y[4] + e.eta_t * e.u);
        double fel = e.kt * fabs(y[4]) / sqrt(CONTACT_SPRING_CONE);
        return 1 - fmax(ftot, fel) / e.L;
    }
    double h = (fabs(e.L * sigma + e.eta_t * e.u) - e.L) / e.L;
    double dfn = e.kn * e.vn + e.eta_n * e.vn * e.vn / (4 * e.delta)
                 - e.eta_n * e.fn / p->m;
    double D = e.L * e.vn / (2 * e.delta) + e.kt * sigma * e.u
               - p->mu * (e.fn > 0 ? 1 : -1) * dfn;
    return fmax(h, D / (e.L * sqrt(e.kn / p->m)));
}

/* The phase at a state where it may change: slip if the stick force or
 * the spring leaves the cone, stick otherwise; a new slip phase slides
 * along the spring (along the stick force while the spring is 0). */
static void oref_decide(const struct oref *p, double *y, int *slip,
                        int *sigma, double t, double *t_reset)
{
    struct oref_eval e;
    if (*slip && oref_g(p, y, 1, *sigma) > 0)
        return;
    if (*slip) {   /* the spring stays at the limit where stick begins */
        oref_law(p, y, 1, *sigma, &e);
        y[4] = *sigma * e.L / e.kt;
    }
    *slip = 0;
    if (oref_g(p, y, 0, 0) <= 0) {
        oref_law(p, y, 0, 0, &e);
        double dir = y[4] != 0 ? y[4] : e.kt * y[4] + e.eta_t * e.u;
        *sigma = dir > 0 ? 1 : -1;
        *slip = 1;
        y[4] = *sigma * e.L / e.kt;
        /* a slip of zero length: the dashpot drove the stick force out
         * of the cone against the spring (L < eta^t |u| < 2 L); the
         * slider's reset put the spring at the limit on its own side,
         * where the stick force is inside again: stick goes on from
         * there (a jump of the spring). These jumps come faster and
         * faster as eta^t |u| nears 2 L, where the slip proper starts:
         * one within 1e-9/omega_n of the last is taken as that point. */
        if (oref_g(p, y, 1, *sigma) <= 0
            && !(t - *t_reset < 1e-9 / sqrt(e.kn / p->m))) {
            *slip = 0;
            *t_reset = t;
            p->resets[0]++;
        }
    }
}

/* Impact at speed 1 m/s, angle theta from the normal; nsteps RK4 steps
 * over the nominal contact time tc. */
static void oblique_reference(const struct oref *p, double theta, double tc,
                              long nsteps, struct oref_out *out)
{
    double y[5] = {p->r, -cos(theta), sin(theta), 0, 0};
    double h = tc / nsteps;
    struct oref_eval e;
    /* at delta -> 0 only the dashpots act: slip from the start where
     * eta^t |u| > mu eta^n vn */
    int slip = sqrt(p->ratio_t / 1.5) * fabs(y[2]) > p->mu * -y[1];
    int sigma = y[2] > 0 ? 1 : -1;
    out->switches = out->fn_signs = out->resets = 0;
    struct oref q = *p;
    q.resets = &out->resets;
    p = &q;
    double t = 0, t_reset = -INFINITY;
    for (long it = 0; it < 100 * nsteps; it++) {
        /* near delta = 0 (both ends) the dashpot grows as delta^(1/4):
         * steps in proportion to the overlap there, at most 100 per
         * overlap's worth of travel (graded down to 1e-4 h) */
        double yn[5], dl = p->r - y[0], vv = fabs(y[1]), he = h;
        if (dl < 100 * vv * h)
            he = h * fmax(1e-4, dl / (100 * vv * h));
        oref_rk4(p, y, he, slip, sigma, yn);
        oref_law(p, y, slip, sigma, &e);
        double fn0 = e.fn, g0 = it ? oref_g(p, y, slip, sigma) : 1.0;
        int ends = !(p->r - yn[0] > 0);
        int flip = 0, cross = 0;
        if (!ends) {
            oref_law(p, yn, slip, sigma, &e);
            flip = fn0 * e.fn < 0;
            cross = g0 > 0 && oref_g(p, yn, slip, sigma) <= 0;
        }
        if (!ends && !flip && !cross) {
            memcpy(y, yn, sizeof y);
            t += he;
            continue;
        }
        /* the earliest event inside the step: bisect its length */
        double lo = 0, hi = he;
        while (hi - lo > 1e-15 * he) {
            double tm = 0.5 * (lo + hi), ym[5];
            oref_rk4(p, y, tm, slip, sigma, ym);
            int ev = !(p->r - ym[0] > 0);
            if (!ev) {
                oref_law(p, ym, slip, sigma, &e);
                ev = fn0 * e.fn < 0
                     || (g0 > 0 && oref_g(p, ym, slip, sigma) <= 0);
            }
            if (ev)
                hi = tm;
            else
                lo = tm;
        }
        double ym[5];
        oref_rk4(p, y, hi, slip, sigma, ym);
        memcpy(y, ym, sizeof y);
        t += hi;
        if (!(p->r - y[0] > 0))
            break;   /* the contact has ended */
        oref_law(p, y, slip, sigma, &e);
        int was = slip;
        if (fn0 * e.fn < 0) {
            /* the limit went through 0 and the spring with it: a new
             * phase as at the start of a contact */
            out->fn_signs++;
            y[4] = 0;
            slip = 0;
        }
        oref_decide(p, y, &slip, &sigma, t, &t_reset);
        out->switches += was != slip;
    }
    out->vt = y[2];
    out->w = y[3];
}

#endif
