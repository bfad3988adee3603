/*
 * dem_forces.c — one force evaluation: contact forces and moments of all
 * grain pairs and grain-wall contacts, gravity, external and drag forces,
 * turned into accelerations (doc/theory.md A.6, eqs. 17-18):
 *
 *   m_k dv_k/dt = sum_l F^C_kl + m_k g + F^ext_k + F^d_k(v_k)
 *   I_k dw_k/dt = sum_l (R_k n_kl x F^t_kl + M^r_kl),   I_k = (2/5) m_k R_k^2
 *
 * Pairs come from the half neighbour list, so each contact is computed once
 * and its force applied to both grains with opposite signs; with several
 * OpenMP threads every thread accumulates into its own buffer (allocated
 * once) and the buffers are summed per grain afterwards, so the result does
 * not depend on a race. Wall contacts belong to one grain and need no
 * buffer; the force a wall receives is summed per patch.
 *
 * The tangential springs come from the stored histories (extended by
 * tau v^t, Verlet) or, for ARKode, from its state (d->spring_in), whose
 * rates it then writes (doc/theory.md A.6):
 *
 *   d delta^t/dt = v^t - n (delta^t . dn/dt),  dn/dt = (I - n n) dv/|dx|
 *
 * for a pair in contact (dv = v_l - v_k, dx = x_l - x_k), v^t for a wall
 * contact, 0 for a slot out of contact; with the slip phases and their
 * switching functions of dem.h (slip_mode, slip_g).
 */
#include <math.h>
#include <omp.h>
#include <string.h>

#include "core/error.h"
#include "dem/contact/contact_fused.h"
#include "dem/dem.h"
#include "dem/dem_forces_fast.h"

static inline void cross3(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* Relative velocity terms of a contact with normal n (k -> l); vl, wl and
 * rl are zero for a wall. */
static inline void fill_kinematics(struct contact_geom *g, const double *vk,
                                   const double *wk, double rk,
                                   const double *vl, const double *wl,
                                   double rl)
{
    double s[3], rw[3], vr[3];
    for (int a = 0; a < 3; a++)
        s[a] = rk * wk[a] + (wl ? rl * wl[a] : 0.0);
    cross3(s, g->n, rw);
    for (int a = 0; a < 3; a++)
        vr[a] = vk[a] - (vl ? vl[a] : 0.0) + rw[a];
    g->vn = vr[0] * g->n[0] + vr[1] * g->n[1] + vr[2] * g->n[2];
    for (int a = 0; a < 3; a++) {
        g->vt[a] = vr[a] - g->vn * g->n[a];
        g->wrel[a] = wk[a] - (wl ? wl[a] : 0.0);
    }
}

/* d(delta^t)/dt of a pair spring s carried with the contact: the
 * tangential relative velocity, plus the turn of the normal that keeps s
 * in the tangent plane with its length (s.n = 0 stays 0):
 *   ds/dt = v^t - n (s . dn/dt),  dn/dt = (I - n n)(v_l - v_k)/|x_l - x_k|.
 * inv = 1/|x_l - x_k|. */
static inline void spring_rate_pair(const struct contact_geom *g,
                                    const double *s, double inv,
                                    const double *vk, const double *vl,
                                    double *rate)
{
    double dv[3], dvn = 0;
    for (int a = 0; a < 3; a++) {
        dv[a] = vl[a] - vk[a];
        dvn += dv[a] * g->n[a];
    }
    double sdn = 0;
    for (int a = 0; a < 3; a++)
        sdn += s[a] * (dv[a] - dvn * g->n[a]) * inv;
    for (int a = 0; a < 3; a++)
        rate[a] = g->vt[a] - g->n[a] * sdn;
}

/* Slip phases (arkode, dem.h slip_mode; doc/theory.md A0-24): a contact
 * found sliding at the last committing evaluation slides for the whole
 * step (its end is an event the integrator locates); the law is then
 * given a spring of 1 m along s^, far beyond the slider's reach
 * (kt x 1 m >> mu F^n for any overlap << 1 m), so that it returns the
 * sliding force -mu |F^n| s^ and the spring at the limit whatever the
 * state's length. */
static inline const double *slip_spring(const struct dem *d, size_t slot,
                                        const double *hs, double *buf)
{
    if (!d->slip_mode || !d->slip_mode[slot])
        return hs;
    double s2 = hs[0] * hs[0] + hs[1] * hs[1] + hs[2] * hs[2];
    if (!(s2 > 0))
        return hs;
    double k = 1.0 / sqrt(s2);
    for (int a = 0; a < 3; a++)
        buf[a] = k * hs[a];
    return buf;
}

/* The state's spring on the tangent plane with its length, as the law
 * rotates it (tangential_coulomb.c). */
static inline void tangent_spring(const double *n, const double *h,
                                  double *s)
{
    double hn = h[0] * n[0] + h[1] * n[1] + h[2] * n[2];
    double h2 = h[0] * h[0] + h[1] * h[1] + h[2] * h[2];
    double s2 = h2 - hn * hn;
    double k = hn != 0 && s2 > 0 ? sqrt(h2 / s2) : 1.0;
    for (int a = 0; a < 3; a++)
        s[a] = k * (h[a] - hn * n[a]);
}

/* Switching functions (dem.h slip_g), F^n (slip_fn) and, on a committing
 * evaluation, the phase found there. In stick the cone of
 * tangential_coulomb.c with the uncapped stick force,
 *   g = 1 - max(|kt s + eta^t v^t|, kt |s|/sqrt(CONTACT_SPRING_CONE))/F_max
 * (F_max = mu |F^n|; g <= 0 exactly where the law slides, so the start of
 * slip is a zero from above); in slip the first of the two conditions
 * that keep it sliding, the stick force from the spring at the limit
 * outside the cone,
 *   g = (|F_max s^ + eta^t v^t| - F_max)/F_max,
 * the second (the spring would leave the cone) is added by
 * dem_slip_rates, which needs the accelerations. */
static inline void slip_after(struct dem *d, size_t slot, const double *n,
                              const double *hs,
                              const struct contact_result *res,
                              const double *vt, int commit)
{
    if (d->slip_fn)
        d->slip_fn[slot] = res->fn;
    int upd = commit && d->slip_mode;
    if (!d->slip_g && !upd)
        return;
    int mode = d->slip_mode && d->slip_mode[slot];
    double fmax = d->law.c.mu * fabs(res->fn);
    double s[3], q[3], e = res->eta_t;
    tangent_spring(n, hs, s);
    double sl = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]), g;
    if (mode) {
        double k = sl > 0 ? fmax / sl : 0.0;
        for (int a = 0; a < 3; a++)
            q[a] = k * s[a] + e * vt[a];
        double ql = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
        g = fmax > 0 ? (ql - fmax) / fmax : (ql > 0 ? 1.0 : -1.0);
    } else {
        for (int a = 0; a < 3; a++)
            q[a] = res->kt * s[a] + e * vt[a];
        double ql = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
        double fe = res->kt * sl / sqrt(CONTACT_SPRING_CONE);
        g = fmax > 0 ? 1.0 - (ql > fe ? ql : fe) / fmax : 1.0;
    }
    if (d->slip_g)
        d->slip_g[slot] = g;
    if (upd)   /* dem_slip_rates may still keep a slipping slot sliding */
        d->slip_mode[slot] = fmax > 0 && (mode ? g > 0 : g <= 0);
}

/* A slot out of contact: no slip phase; its switching function is
 * HUGE_VAL (the integrator treats the end of a contact as an event, so
 * that a slip phase just before it is not hidden in the step). */
static inline void slip_open(struct dem *d, size_t slot, int commit)
{
    if (d->slip_g)
        d->slip_g[slot] = HUGE_VAL;
    if (d->slip_fn)
        d->slip_fn[slot] = 0;
    if (commit && d->slip_mode)
        d->slip_mode[slot] = 0;
}

/* The accumulation buffers are kept all zero between evaluations: every
 * value is cleared where it is last read (reduction, finish), which saves
 * a separate clearing pass over 6n doubles per evaluation. */
static int reserve_buffers(struct dem *d, int nth)
{
    size_t need = (size_t)nth * (6 * d->n + 3 * DEM_MAX_PATCHES);
    if (need > d->tbuf_cap) {
        double *b = sim_realloc(d->tbuf, need * sizeof *b);
        if (!b)
            return SIM_ERR_NOMEM;
        memset(b, 0, need * sizeof *b);
        d->tbuf = b;
        d->tbuf_cap = need;
    }
    return SIM_OK;
}

/* Pair contacts of grain i into f/t (force, torque buffers of 3n). */
static void pair_row(struct dem *d, size_t i, const double *x, const double *v,
                     const double *w, double tau, int commit, double *f,
                     double *t, long *nc, double *om2)
{
    int fused = contact_law_is_fused(&d->law);
    for (size_t p = d->nl.start[i]; p < d->nl.start[i + 1]; p++) {
        size_t j = d->nl.j[p];
        struct contact_geom g;
        double dx[3], d2 = 0;
        for (int a = 0; a < 3; a++) {
            dx[a] = x[3 * j + a] - x[3 * i + a];
            d2 += dx[a] * dx[a];
        }
        double rs = d->r[i] + d->r[j];
        if (d2 >= rs * rs) {
            double *h = &d->hist[3 * p];
            if (commit && (h[0] != 0 || h[1] != 0 || h[2] != 0))
                h[0] = h[1] = h[2] = 0;   /* the contact ended */
            if (d->spring_rate)
                memset(&d->spring_rate[3 * p], 0, 3 * sizeof(double));
            slip_open(d, p, commit);
            continue;
        }
        /* divisions dominate the geometry: one reciprocal each */
        double dist = sqrt(d2), inv = 1.0 / dist;
        for (int a = 0; a < 3; a++)
            g.n[a] = dx[a] * inv;
        g.delta = rs - dist;
        g.rstar = fused ? 0.0 : d->r[i] * d->r[j] / rs;
        g.chi = d->pair_c[2 * p];
        g.mstar = d->pair_c[2 * p + 1];
        double sum_inv_m = d->inv_m[i] + d->inv_m[j];
        fill_kinematics(&g, &v[3 * i], &w[3 * i], d->r[i], &v[3 * j],
                        &w[3 * j], d->r[j]);
        struct contact_result res;
        double hn[3];
        const double *hs = d->spring_in ? &d->spring_in[3 * p]
                                        : &d->hist[3 * p];
        double sb[3];
        const double *hl = slip_spring(d, p, hs, sb);
        if (fused)
            contact_eval_fused(&d->law, &g, hl, tau, hn, &res);
        else
            contact_eval(&d->law, &g, hl, tau, hn, &res);
        if (commit)
            memcpy(&d->hist[3 * p], hn, sizeof hn);
        if (d->spring_rate)
            spring_rate_pair(&g, hs, inv, &v[3 * i], &v[3 * j],
                             &d->spring_rate[3 * p]);
        slip_after(d, p, g.n, hs, &res, g.vt, commit);
        double tc[3];
        cross3(g.n, res.ft, tc);
        for (int a = 0; a < 3; a++) {
            f[3 * i + a] += res.f[a];
            f[3 * j + a] -= res.f[a];
            t[3 * i + a] += d->r[i] * tc[a] + res.mroll[a];
            t[3 * j + a] += d->r[j] * tc[a] - res.mroll[a];
        }
        (*nc)++;
        double w2 = res.kn * sum_inv_m;
        *om2 = w2 > *om2 ? w2 : *om2;
    }
}

/* Wall contacts of grain i; pf: per-patch force received by the walls. */
static void wall_row(struct dem *d, size_t i, const double *x, const double *v,
                     const double *w, double tau, int commit, double *f,
                     double *t, double *pf, long *nc, double *om2)
{
    int fused = contact_law_is_fused(&d->law);
    size_t wk = 3 * d->nl.npairs;   /* wall springs follow the pairs' */
    size_t q0 = d->use_wlist ? d->wstart[i] : 0;
    size_t q1 = d->use_wlist ? d->wstart[i + 1] : (size_t)d->nwalls;
    for (size_t q = q0; q < q1; q++) {
        int wl = d->use_wlist ? d->wlist[q] : (int)q;
        size_t hk = 3 * (i * (size_t)d->nwalls + (size_t)wl);
        struct contact_geom g;
        if (!wall_contact_inline(&d->walls[wl], &x[3 * i], d->r[i], g.n,
                                 &g.delta)) {
            double *h = &d->whist[hk];
            if (commit && (h[0] != 0 || h[1] != 0 || h[2] != 0))
                h[0] = h[1] = h[2] = 0;
            if (d->spring_rate)
                memset(&d->spring_rate[wk + hk], 0, 3 * sizeof(double));
            slip_open(d, (wk + hk) / 3, commit);
            continue;
        }
        g.rstar = d->r[i];
        g.mstar = d->m[i];
        g.chi = d->wall_chi[i];
        /* a wall in rigid translation: its velocity is that of the
         * contact point */
        fill_kinematics(&g, &v[3 * i], &w[3 * i], d->r[i],
                        d->walls[wl].vel, NULL, 0);
        struct contact_result res;
        double hn[3];
        const double *hs = d->spring_in ? &d->spring_in[wk + hk]
                                        : &d->whist[hk];
        double sb[3];
        const double *hl = slip_spring(d, (wk + hk) / 3, hs, sb);
        if (fused)
            contact_eval_fused(&d->law, &g, hl, tau, hn, &res);
        else
            contact_eval(&d->law, &g, hl, tau, hn, &res);
        if (commit)
            memcpy(&d->whist[hk], hn, sizeof hn);
        if (d->spring_rate)   /* a fixed wall: its normal turns only with
                                 the grain's motion on a curved wall, left
                                 to the projection at accepted steps */
            memcpy(&d->spring_rate[wk + hk], g.vt, sizeof g.vt);
        slip_after(d, (wk + hk) / 3, g.n, hs, &res, g.vt, commit);
        double tc[3];
        cross3(g.n, res.ft, tc);
        int pa = d->walls[wl].patch;
        for (int a = 0; a < 3; a++) {
            f[3 * i + a] += res.f[a];
            t[3 * i + a] += d->r[i] * tc[a] + res.mroll[a];
            pf[3 * pa + a] -= res.f[a];
        }
        (*nc)++;
        double w2 = res.kn * d->inv_m[i];
        *om2 = w2 > *om2 ? w2 : *om2;
    }
}

/* Gravity, external force and drag; contact sums in f, t. */
static int finish(struct dem *d, const double *v, double *f, double *t,
                  double *acc, double *alpha)
{
    struct dem_coupling *c = &d->cpl;
    if (c->drag && c->uf && c->eps) {
        int rc = c->drag(c->drag_ctx, d->n, d->r, v, c->uf, c->eps, c->fd);
        if (rc != SIM_OK) {
            memset(d->tbuf, 0, d->tbuf_cap * sizeof *d->tbuf);
            return rc;
        }
    }
    int drag = c->drag && c->uf && c->eps;
    double kick = d->kick;
    #pragma omp parallel for schedule(static) if (d->n > DEM_OMP_MIN)
    for (size_t i = 0; i < d->n; i++)
        for (int a = 0; a < 3; a++) {
            size_t k = 3 * i + a;
            double fk = f[k] + (c->fext ? c->fext[k] : 0.0)
                        + (drag ? c->fd[k] : 0.0);
            acc[k] = fk * d->inv_m[i] + d->gravity[a];
            alpha[k] = t[k] * d->inv_i[i];
            f[k] = t[k] = 0;
            if (kick != 0) {   /* Verlet's closing half kick, same pass */
                d->v[k] += kick * acc[k];
                d->w[k] += kick * alpha[k];
            }
        }
    return SIM_OK;
}

static int n_small(const struct dem *d)
{
    return d->n <= d->omp_min;
}

int dem_forces(struct dem *d, double tm, const double *x, const double *v,
               const double *w, double tau, int commit, double *acc,
               double *alpha)
{
    dem_walls_at(d, tm);
    /* Small systems run on one thread: a parallel region costs more than
     * the work (and much more on a loaded machine). */
    int nth = n_small(d) ? 1 : omp_get_max_threads();
    size_t n = d->n, stride = 6 * n + 3 * DEM_MAX_PATCHES;
    TRY(reserve_buffers(d, nth));
    if (dem_forces_fast_ok(d, nth))   /* the Verlet hot path */
        return dem_forces_fast(d, x, v, w, tau, commit, acc, alpha);
    long nc = 0, nwc = 0;
    double om2 = 0;
    int team = 1;
    #pragma omp parallel num_threads(nth) reduction(+ : nc, nwc) \
        reduction(max : om2)
    {
        double *f = d->tbuf + (size_t)omp_get_thread_num() * stride;
        double *t = f + 3 * n, *pf = t + 3 * n;
        #pragma omp single
        team = omp_get_num_threads();
        /* static chunks: the same thread sums the same rows in every call, so
         * results are reproducible for a given thread count */
        #pragma omp for schedule(static, 256) nowait
        for (size_t i = 0; i < n; i++) {
            pair_row(d, i, x, v, w, tau, commit, f, t, &nc, &om2);
            wall_row(d, i, x, v, w, tau, commit, f, t, pf, &nwc, &om2);
        }
        #pragma omp barrier
        if (team > 1) {
            #pragma omp for schedule(static)
            for (size_t k = 0; k < 6 * n; k++)
                for (int th = 1; th < team; th++) {
                    d->tbuf[k] += d->tbuf[(size_t)th * stride + k];
                    d->tbuf[(size_t)th * stride + k] = 0;
                }
        }
    }
    for (int p = 0; p < 3 * DEM_MAX_PATCHES; p++) {
        double s = 0;
        for (int th = 0; th < team; th++) {
            s += d->tbuf[(size_t)th * stride + 6 * n + p];
            d->tbuf[(size_t)th * stride + 6 * n + p] = 0;
        }
        d->patch_force[p] = s;
    }
    d->ncontacts = nc;
    d->nwall_contacts = nwc;
    d->omega2_max = om2;
    d->stats.fevals++;
    return finish(d, v, d->tbuf, d->tbuf + 3 * n, acc, alpha);
}

/* kt |s| - mu |F^n| of a contact of overlap delta and approach speed vn
 * whose spring has length sl: the spring's distance to the cone. */
static double cone_gap(const struct dem *d, struct contact_geom *g,
                       double delta, double vn, double sl)
{
    double fel, kn, kt, eta_n, eta_t;
    g->delta = delta;
    g->vn = vn;
    d->law.normal->eval(&d->law.c, g, &fel, &kn, &kt);
    d->law.damping->eval(&d->law.c, g, kn, kt, &eta_n, &eta_t);
    return kt * sl - d->law.c.mu * fabs(fel + eta_n * vn);
}

/* The second condition of a slip phase (A0-24): D, the rate of
 * kt |s| - mu |F^n| along the stick flow (ds/dt = v^t, x, v moving with
 * v, a) from the spring at the limit, s = (mu |F^n|/kt) s^. D > 0: the
 * spring would leave the cone, the slider keeps sliding although s^.v^t
 * may be < 0 (the limit shrinks faster than the spring unloads). By
 * central differences over +-sig along the flow, sig = 1e-6 of the
 * contact's time scales (min of 1/omega_n and delta/|vn|): truncation
 * ~1e-12, rounding ~1e-10 relative. delta and vn come from the moved
 * positions and velocities, so walls of any shape and pairs whose normal
 * turns are covered alike. */
static double slip_rate(const struct dem *d, const double *xi,
                        const double *vi, const double *ai, double ri,
                        const double *xj, const double *vj,
                        const double *aj, double rj,
                        const struct dem_wall *wall, struct contact_geom *g,
                        const double *s, const double *vt, double fmax,
                        double kt, double kn)
{
    double sl = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    if (!(sl > 0) || !(kt > 0))
        return 0;
    double om = sqrt(kn / g->mstar);
    double sig = 1.0 / om, avn = fabs(g->vn);
    if (avn * sig > g->delta)
        sig = g->delta / avn;
    sig *= 1e-6;
    double gap[2];
    for (int k = 0; k < 2; k++) {
        double h = k ? -sig : sig, x[3], y[3], v[3], n[3], delta;
        for (int a = 0; a < 3; a++) {
            x[a] = xi[a] + h * vi[a];
            v[a] = vi[a] + h * ai[a];
        }
        if (wall) {
            for (int a = 0; a < 3; a++) {
                x[a] -= h * wall->vel[a];
                v[a] -= wall->vel[a];
            }
            if (!wall_contact_inline(wall, x, ri, n, &delta))
                return 0;
        } else {
            double d2 = 0;
            for (int a = 0; a < 3; a++) {
                y[a] = xj[a] + h * vj[a] - x[a];
                v[a] -= vj[a] + h * aj[a];
                d2 += y[a] * y[a];
            }
            double dist = sqrt(d2);
            delta = ri + rj - dist;
            for (int a = 0; a < 3; a++)
                n[a] = y[a] / dist;
        }
        double vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2], s2 = 0;
        for (int a = 0; a < 3; a++) {
            double sa = fmax / (kt * sl) * s[a] + h * vt[a];
            s2 += sa * sa;
        }
        gap[k] = cone_gap(d, g, delta, vn, sqrt(s2));
    }
    return (gap[0] - gap[1]) / (2 * sig) / (fmax * om);
}

int dem_slip_rates(struct dem *d, const double *x, const double *v,
                   const double *w, const double *acc, const double *spring,
                   const unsigned char *mode, double *g,
                   unsigned char *mode_next)
{
    size_t wk = 3 * d->nl.npairs;
    for (size_t i = 0; i < d->n; i++) {
        for (size_t p = d->nl.start[i]; p < d->nl.start[i + 1]; p++) {
            if (!mode[p])
                continue;
            size_t j = d->nl.j[p];
            struct contact_geom cg;
            double dx[3], d2 = 0;
            for (int a = 0; a < 3; a++) {
                dx[a] = x[3 * j + a] - x[3 * i + a];
                d2 += dx[a] * dx[a];
            }
            double rs = d->r[i] + d->r[j];
            if (d2 >= rs * rs)
                continue;
            double dist = sqrt(d2);
            for (int a = 0; a < 3; a++)
                cg.n[a] = dx[a] / dist;
            cg.rstar = d->r[i] * d->r[j] / rs;
            cg.chi = d->pair_c[2 * p];
            cg.mstar = d->pair_c[2 * p + 1];
            fill_kinematics(&cg, &v[3 * i], &w[3 * i], d->r[i], &v[3 * j],
                            &w[3 * j], d->r[j]);
            double fel, kn, kt, eta_n, eta_t, s[3];
            cg.delta = rs - dist;
            d->law.normal->eval(&d->law.c, &cg, &fel, &kn, &kt);
            d->law.damping->eval(&d->law.c, &cg, kn, kt, &eta_n, &eta_t);
            double fmax = d->law.c.mu * fabs(fel + eta_n * cg.vn);
            if (!(fmax > 0))
                continue;
            tangent_spring(cg.n, &spring[3 * p], s);
            double vt[3] = {cg.vt[0], cg.vt[1], cg.vt[2]};
            double r = slip_rate(d, &x[3 * i], &v[3 * i], &acc[3 * i],
                                 d->r[i], &x[3 * j], &v[3 * j], &acc[3 * j],
                                 d->r[j], NULL, &cg, s, vt, fmax, kt, kn);
            if (g && r > g[p])
                g[p] = r;
            if (mode_next && r > 0)
                mode_next[p] = 1;
        }
        for (int wl = 0; wl < d->nwalls; wl++) {
            size_t hk = 3 * (i * (size_t)d->nwalls + (size_t)wl);
            size_t slot = (wk + hk) / 3;
            if (!mode[slot])
                continue;
            const struct dem_wall *wall = &d->walls[wl];
            struct contact_geom cg;
            if (!wall_contact_inline(wall, &x[3 * i], d->r[i], cg.n,
                                     &cg.delta))
                continue;
            cg.rstar = d->r[i];
            cg.mstar = d->m[i];
            cg.chi = d->wall_chi[i];
            fill_kinematics(&cg, &v[3 * i], &w[3 * i], d->r[i], wall->vel,
                            NULL, 0);
            double fel, kn, kt, eta_n, eta_t, s[3];
            d->law.normal->eval(&d->law.c, &cg, &fel, &kn, &kt);
            d->law.damping->eval(&d->law.c, &cg, kn, kt, &eta_n, &eta_t);
            double fmax = d->law.c.mu * fabs(fel + eta_n * cg.vn);
            if (!(fmax > 0))
                continue;
            tangent_spring(cg.n, &spring[wk + hk], s);
            double vt[3] = {cg.vt[0], cg.vt[1], cg.vt[2]};
            double r = slip_rate(d, &x[3 * i], &v[3 * i], &acc[3 * i],
                                 d->r[i], NULL, NULL, NULL, 0, wall, &cg, s,
                                 vt, fmax, kt, kn);
            if (g && r > g[slot])
                g[slot] = r;
            if (mode_next && r > 0)
                mode_next[slot] = 1;
        }
    }
    return SIM_OK;
}
