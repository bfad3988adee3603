/*
 * tangential_coulomb.c — tangential spring-dashpot with a Coulomb slider,
 * doc/theory.md A.6 eqs. (20), (22), (24) and A0-24:
 *
 *   delta^t(t) = P_n delta^t_0 |delta^t_0|/|P_n delta^t_0| + (t - t_0) v^t
 *   F^t        = -kt delta^t - eta^t v^t    if |F^t| <= mu |F^n| and
 *                                              kt |delta^t| <= mu |F^n|
 *              = -mu |F^n| delta^t/|delta^t|            otherwise (slider)
 *
 * The cone bounds the spring's force as well as the total (A0-24): with
 * the total alone, a spring at the limit whose dashpot pulls inward
 * (unloading, s^.v^t < 0) is held outside the cone by the dashpot until
 * the total reaches the limit, is reset, and again: a sawtooth with a
 * step-size dependent phase instead of the slip the spring's own motion
 * asks for. Where eta^t = 0 both tests are one.
 *
 * delta^t_0 is the spring stored at the last accepted time t_0 (history per
 * contact pair, kept across neighbour rebuilds by the neighbour list); P_n
 * projects it onto the current tangent plane and the magnitude is kept
 * (the rotation of A.6 [P]). On slip the spring is rescaled to
 * |delta^t| = mu |F^n|/kt (A0-11, the form of Xie et al. 2025: slip along
 * -delta^t). When the spring is still zero the slider acts along the trial
 * force instead.
 * Reference: Cundall and Strack (1979); Xie et al. (2025) eqs. (20), (22).
 */
#include <math.h>

#include "dem/contact/contact.h"

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void rotate_spring(const double *n, const double h[3], double s[3])
{
    double hn = dot3(h, n);
    for (int a = 0; a < 3; a++)
        s[a] = h[a] - hn * n[a];
    if (hn == 0)   /* already in the tangent plane (or zero): nothing to keep */
        return;
    double h2 = dot3(h, h);
    double s2 = h2 - hn * hn;
    if (s2 > 0) {
        double scale = sqrt(h2 / s2);
        for (int a = 0; a < 3; a++)
            s[a] *= scale;
    }
}

static void eval_coulomb(const struct contact_coeffs *c,
                         const struct contact_geom *g, double fn, double kt,
                         double eta_t, const double h[3], double tau,
                         double hnew[3], double ft[3])
{
    double s[3];
    rotate_spring(g->n, h, s);
    for (int a = 0; a < 3; a++) {
        s[a] += tau * g->vt[a];
        ft[a] = -kt * s[a] - eta_t * g->vt[a];
    }
    double fmax = c->mu * fabs(fn);
    double f2 = dot3(ft, ft), s2 = dot3(s, s);
    if (f2 > fmax * fmax
        || kt * kt * s2 > CONTACT_SPRING_CONE * fmax * fmax) {
        double sl = sqrt(s2);
        double fl = sqrt(f2);
        if (sl > 0 && kt > 0) {
            for (int a = 0; a < 3; a++) {
                ft[a] = -fmax * s[a] / sl;
                s[a] *= fmax / (kt * sl);
            }
        } else {
            for (int a = 0; a < 3; a++) {
                ft[a] *= fmax / fl;
                s[a] = 0;
            }
        }
    }
    for (int a = 0; a < 3; a++)
        hnew[a] = s[a];
}

const struct contact_tangential_ops contact_tangential_coulomb = {
    .name = "coulomb",
    .reference = "Cundall and Strack 1979; Xie et al. 2025 eqs. 20, 22, 24",
    .history = 3,
    .eval = eval_coulomb,
};
