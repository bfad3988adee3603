/*
 * dem_forces_fast.c — the force evaluation of dem_forces (dem_forces.c)
 * on one thread for the fused default law (contact_fused.h) with the
 * springs taken from the stored histories: the Verlet hot path. It
 * computes exactly what the general path computes, operation for
 * operation and in the same order (same bits), but
 *   - the law is inlined and the row's loop carries no test for the
 *     ARKode state (spring_in, spring_rate, slip phases) nor for the
 *     generic law;
 *   - grain i's force and torque are summed in registers over its row
 *     (its pairs in list order, then its walls) on top of what rows
 *     i' < i left in the buffer, and stored once;
 *   - the buffer holds force and torque of a grain side by side
 *     (6 doubles), so a neighbour's update touches one cache line;
 *   - the half list only pairs i with j > i, so after row i nothing is
 *     added to grain i and nothing reads grain i again: its
 *     accelerations, the closing half kick (d->kick) and the clearing of
 *     its buffer entries are done right there, without a finish pass
 *     over all grains.
 * The multi-threaded path (per-thread buffers, reduction, finish) and the
 * ARKode paths stay in dem_forces.c.
 */
#include <math.h>
#include <string.h>

#include "core/error.h"
#include "dem/contact/contact_fused.h"
#include "dem/dem.h"
#include "dem/dem_forces_fast.h"

int dem_forces_fast_ok(const struct dem *d, int nth)
{
    return nth == 1 && !d->spring_in && !d->spring_rate && !d->slip_mode
           && !d->slip_g && contact_law_is_fused(&d->law);
}

int dem_forces_fast(struct dem *d, const double *x, const double *v,
                    const double *w, double tau, int commit, double *acc,
                    double *alpha)
{
    size_t n = d->n;
    struct dem_coupling *c = &d->cpl;
    int drag = c->drag && c->uf && c->eps;
    if (drag) {   /* v is not changed by the contact loop before a grain's
                     own row is done: the same drag as after the loop */
        int rc = c->drag(c->drag_ctx, n, d->r, v, c->uf, c->eps, c->fd);
        if (rc != SIM_OK)
            return rc;
    }
    const double *fext = c->fext, *fd = c->fd;
    const double *restrict r = d->r, *restrict inv_m = d->inv_m;
    const double *restrict inv_i = d->inv_i;
    const double *restrict pair_c = d->pair_c;
    const uint32_t *restrict nlj = d->nl.j;
    const size_t *restrict start = d->nl.start;
    double *restrict hist = d->hist, *restrict whist = d->whist;
    double *restrict ft6 = d->tbuf;   /* 6 per grain: f, t; all zero
                                         outside this function */
    const double g0 = d->gravity[0], g1 = d->gravity[1], g2 = d->gravity[2];
    const double kick = d->kick;
    const int nwalls = d->nwalls, use_wlist = d->use_wlist;
    double pf[3 * DEM_MAX_PATCHES] = {0};
    long nc = 0, nwc = 0;
    double om2 = 0;
    for (size_t i = 0; i < n; i++) {
        const double *xi = &x[3 * i], *vi = &v[3 * i], *wi = &w[3 * i];
        const double ri = r[i], inv_mi = inv_m[i];
        double *fti = &ft6[6 * i];
        double fx = fti[0], fy = fti[1], fz = fti[2];
        double tx = fti[3], ty = fti[4], tz = fti[5];
        for (size_t p = start[i]; p < start[i + 1]; p++) {
            size_t j = nlj[p];
            const double *xj = &x[3 * j];
            double dx[3], d2 = 0;
            for (int a = 0; a < 3; a++) {
                dx[a] = xj[a] - xi[a];
                d2 += dx[a] * dx[a];
            }
            double rj = r[j];
            double rs = ri + rj;
            double *h = &hist[3 * p];
            if (d2 >= rs * rs) {
                if (commit && (h[0] != 0 || h[1] != 0 || h[2] != 0))
                    h[0] = h[1] = h[2] = 0;   /* the contact ended */
                continue;
            }
            struct contact_geom g;
            double dist = sqrt(d2), inv = 1.0 / dist;
            for (int a = 0; a < 3; a++)
                g.n[a] = dx[a] * inv;
            g.delta = rs - dist;
            g.rstar = 0.0;
            g.chi = pair_c[2 * p];
            g.mstar = pair_c[2 * p + 1];
            double sum_inv_m = inv_mi + inv_m[j];
            /* fill_kinematics (dem_forces.c) of a pair */
            const double *vj = &v[3 * j], *wj = &w[3 * j];
            double s[3], rw[3], vr[3];
            for (int a = 0; a < 3; a++)
                s[a] = ri * wi[a] + rj * wj[a];
            rw[0] = s[1] * g.n[2] - s[2] * g.n[1];
            rw[1] = s[2] * g.n[0] - s[0] * g.n[2];
            rw[2] = s[0] * g.n[1] - s[1] * g.n[0];
            for (int a = 0; a < 3; a++)
                vr[a] = vi[a] - vj[a] + rw[a];
            g.vn = vr[0] * g.n[0] + vr[1] * g.n[1] + vr[2] * g.n[2];
            for (int a = 0; a < 3; a++)
                g.vt[a] = vr[a] - g.vn * g.n[a];
            struct contact_result res;
            double hn[3];
            contact_eval_fused(&d->law, &g, h, tau, hn, &res);
            if (commit) {
                h[0] = hn[0];
                h[1] = hn[1];
                h[2] = hn[2];
            }
            double tc[3];
            tc[0] = g.n[1] * res.ft[2] - g.n[2] * res.ft[1];
            tc[1] = g.n[2] * res.ft[0] - g.n[0] * res.ft[2];
            tc[2] = g.n[0] * res.ft[1] - g.n[1] * res.ft[0];
            double *ftj = &ft6[6 * j];
            fx += res.f[0];
            fy += res.f[1];
            fz += res.f[2];
            tx += ri * tc[0] + res.mroll[0];
            ty += ri * tc[1] + res.mroll[1];
            tz += ri * tc[2] + res.mroll[2];
            for (int a = 0; a < 3; a++) {
                ftj[a] -= res.f[a];
                ftj[3 + a] += rj * tc[a] - res.mroll[a];
            }
            nc++;
            double w2 = res.kn * sum_inv_m;
            om2 = w2 > om2 ? w2 : om2;
        }
        /* walls (wall_row, dem_forces.c) */
        size_t q0 = use_wlist ? d->wstart[i] : 0;
        size_t q1 = use_wlist ? d->wstart[i + 1] : (size_t)nwalls;
        for (size_t q = q0; q < q1; q++) {
            int wl = use_wlist ? d->wlist[q] : (int)q;
            size_t hk = 3 * (i * (size_t)nwalls + (size_t)wl);
            const struct dem_wall *wa = &d->walls[wl];
            struct contact_geom g;
            double *h = &whist[hk];
            if (!wall_contact_inline(wa, xi, ri, g.n, &g.delta)) {
                if (commit && (h[0] != 0 || h[1] != 0 || h[2] != 0))
                    h[0] = h[1] = h[2] = 0;
                continue;
            }
            g.rstar = ri;
            g.mstar = d->m[i];
            g.chi = d->wall_chi[i];
            const double *vw = wa->vel;
            double s[3], rw[3], vr[3];
            for (int a = 0; a < 3; a++)
                s[a] = ri * wi[a] + 0.0;
            rw[0] = s[1] * g.n[2] - s[2] * g.n[1];
            rw[1] = s[2] * g.n[0] - s[0] * g.n[2];
            rw[2] = s[0] * g.n[1] - s[1] * g.n[0];
            for (int a = 0; a < 3; a++)
                vr[a] = vi[a] - vw[a] + rw[a];
            g.vn = vr[0] * g.n[0] + vr[1] * g.n[1] + vr[2] * g.n[2];
            for (int a = 0; a < 3; a++)
                g.vt[a] = vr[a] - g.vn * g.n[a];
            struct contact_result res;
            double hn[3];
            contact_eval_fused(&d->law, &g, h, tau, hn, &res);
            if (commit) {
                h[0] = hn[0];
                h[1] = hn[1];
                h[2] = hn[2];
            }
            double tc[3];
            tc[0] = g.n[1] * res.ft[2] - g.n[2] * res.ft[1];
            tc[1] = g.n[2] * res.ft[0] - g.n[0] * res.ft[2];
            tc[2] = g.n[0] * res.ft[1] - g.n[1] * res.ft[0];
            int pa = wa->patch;
            fx += res.f[0];
            fy += res.f[1];
            fz += res.f[2];
            tx += ri * tc[0] + res.mroll[0];
            ty += ri * tc[1] + res.mroll[1];
            tz += ri * tc[2] + res.mroll[2];
            for (int a = 0; a < 3; a++)
                pf[3 * pa + a] -= res.f[a];
            nwc++;
            double w2 = res.kn * inv_mi;
            om2 = w2 > om2 ? w2 : om2;
        }
        /* finish (dem_forces.c) for grain i: complete now */
        double fs[3] = {fx, fy, fz}, ts[3] = {tx, ty, tz};
        double gv[3] = {g0, g1, g2};
        double inv_ii = inv_i[i];
        for (int a = 0; a < 3; a++) {
            size_t k = 3 * i + a;
            double fk = fs[a] + (fext ? fext[k] : 0.0)
                        + (drag ? fd[k] : 0.0);
            acc[k] = fk * inv_mi + gv[a];
            alpha[k] = ts[a] * inv_ii;
            fti[a] = fti[3 + a] = 0;
            if (kick != 0) {
                d->v[k] += kick * acc[k];
                d->w[k] += kick * alpha[k];
            }
        }
    }
    for (int p = 0; p < 3 * DEM_MAX_PATCHES; p++)
        d->patch_force[p] = 0.0 + pf[p];   /* as the reduction over
                                              threads: -0 becomes 0 */
    d->ncontacts = nc;
    d->nwall_contacts = nwc;
    d->omega2_max = om2;
    d->stats.fevals++;
    return SIM_OK;
}
