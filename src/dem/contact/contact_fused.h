/*
 * contact_fused.h — the default law (normal hertz, damping restitution,
 * tangential coulomb, rolling none, twisting none, any
 * tangentialStiffness) and its variants with the dashpots xie2025 and
 * tsuji, written out in one inline function for the force loop
 * (doc/design.md C4: per-pair calls through four function pointers cost
 * about a tenth of the DEM step). The three dashpots are all
 * eta = 2 zeta sqrt(k m*) with k the tangent stiffness; they differ only in
 * zeta (contact_coeffs.zeta, set by contact_law_init). It computes what
 * contact_eval computes with those sub-models (normal_hertz.c,
 * damping_restitution.c, damping_xie2025.c, damping_tsuji.c,
 * tangential_coulomb.c) up to rounding (eta^t = eta^n sqrt(kt/kn) here);
 * test_contact_laws checks the two against each other on random contacts.
 * Any other combination takes the generic path.
 */
#ifndef MPSDEM_DEM_CONTACT_FUSED_H
#define MPSDEM_DEM_CONTACT_FUSED_H

#include <math.h>

#include "dem/contact/contact.h"

/* Non-zero when law is the combination this file implements. */
static inline int contact_law_is_fused(const struct contact_law *law)
{
    return law->normal == &contact_normal_hertz
           && (law->damping == &contact_damping_restitution
               || law->damping == &contact_damping_xie2025
               || law->damping == &contact_damping_tsuji)
           && law->tangential == &contact_tangential_coulomb
           && law->rolling == &contact_rolling_none
           && (!law->twisting || law->twisting == &contact_twisting_none);
}

/* always inlined: a call per contact costs a sixth of the force loop */
static inline __attribute__((always_inline)) void
contact_eval_fused(const struct contact_law *law,
                   const struct contact_geom *g, const double *h,
                   double tau, double *hnew, struct contact_result *out)
{
    const struct contact_coeffs *c = &law->c;
    double chi = g->chi;
    double sd = sqrt(g->delta);
    double chisd = chi * sd;
    double kn = 1.5 * chisd, kt = c->ratio_t * chisd;
    double eta_n = 2.0 * c->zeta * sqrt(kn * g->mstar);
    double eta_t = eta_n * c->hertz_tn;
    double fn = chisd * g->delta + eta_n * g->vn;
    /* spring: rotate onto the tangent plane keeping its length, extend */
    const double *n = g->n;
    double hn = h[0] * n[0] + h[1] * n[1] + h[2] * n[2];
    double s[3], ft[3];
    for (int a = 0; a < 3; a++)
        s[a] = h[a] - hn * n[a];
    if (hn != 0) {
        double h2 = h[0] * h[0] + h[1] * h[1] + h[2] * h[2];
        double s2 = h2 - hn * hn;
        if (s2 > 0) {
            double scale = sqrt(h2 / s2);
            for (int a = 0; a < 3; a++)
                s[a] *= scale;
        }
    }
    for (int a = 0; a < 3; a++) {
        s[a] += tau * g->vt[a];
        ft[a] = -kt * s[a] - eta_t * g->vt[a];
    }
    double fmax = c->mu * fabs(fn);
    double f2 = ft[0] * ft[0] + ft[1] * ft[1] + ft[2] * ft[2];
    double s2 = s[0] * s[0] + s[1] * s[1] + s[2] * s[2];
    /* the cone of tangential_coulomb.c: total and elastic force */
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
    for (int a = 0; a < 3; a++) {
        hnew[a] = s[a];
        out->ft[a] = ft[a];
        out->mroll[a] = 0;
        out->f[a] = -fn * n[a] + ft[a];
    }
    out->fn = fn;
    out->kn = kn;
    out->kt = kt;
    out->eta_t = eta_t;
}

#endif
