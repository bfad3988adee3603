/*
 * dem_forces_fast.c — the force evaluation of dem_forces (dem_forces.c)
 * on one thread for the fused default law (contact_fused.h) with the
 * springs taken from the stored histories: the Verlet hot path. It
 * computes what the general path computes, operation for operation, and
 * adds every contribution to a grain in the same order (pairs in list
 * order, then walls in candidate order), so the results are the same to
 * the bit (test/bench/bitIdentical.sh on tutorials/demSolid), but
 *   - pairs in contact are collected in blocks of BLK (a scalar pass over
 *     the list tests the overlap and clears the springs of ended
 *     contacts), the law is evaluated on a block as vectors, and a scalar
 *     pass adds the results in list order;
 *   - wall candidates likewise, block by block as the grains reach them;
 *   - force and torque of a grain sit side by side in the buffer (6
 *     doubles), so a neighbour's update touches one cache line;
 *   - the half list only pairs i with j > i, so once row i is added
 *     nothing more is added to grain i nor read from it: its walls, its
 *     accelerations, the closing half kick (d->kick) and the clearing of
 *     its buffer entries are done right then, without a finish pass over
 *     all grains.
 * Bits: sqrt, division and the arithmetic are correctly rounded lane by
 * lane; no floating-point contraction is on (-std=c17 implies
 * -ffp-contract=off; with FMA contraction the scalar and vector code
 * could round differently); the law's branches become selects between
 * values computed both ways. The file is compiled with -fno-math-errno
 * -fno-trapping-math (Makefile), which only drop errno and exception
 * flags, so that sqrt and the selects vectorise.
 * The multi-threaded path (per-thread buffers, reduction, finish) and the
 * ARKode paths (springs as state, slip phases) stay in dem_forces.c.
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
           && !d->slip_g && !d->slip_fn && contact_law_is_fused(&d->law);
}

/* Pairs (and wall candidates) per block: 64 fill a few AVX registers
 * many times over and keep a block in L1. */
#define BLK 64

struct blk {
    /* gathered */
    double dx[3][BLK], d2[BLK], rs[BLK], chi[BLK], mstar[BLK];
    double dv[3][BLK], sw[3][BLK], h[3][BLK];
    /* evaluated: force on i, n x F^t, new spring, normal stiffness */
    double f[3][BLK], tc[3][BLK], hn[3][BLK], kn[BLK];
};

/* The law (contact_eval_fused) on one lane: normal n, overlap delta,
 * relative velocity vr (with the rotation), chi, m*, spring h; out: the
 * force on the first body f, n x F^t tc, the new spring u, kn. */
struct lane {
    double f[3], tc[3], u[3], kn;
};

static inline __attribute__((always_inline)) struct lane
law_lane(double n0, double n1, double n2, double delta, double vr0,
         double vr1, double vr2, double chi, double mstar, double h0,
         double h1, double h2, double tau, double zeta2, double tn,
         double ratio_t, double mu)
{
        struct lane o;
        double vn = vr0 * n0 + vr1 * n1 + vr2 * n2;
        double vt0 = vr0 - vn * n0, vt1 = vr1 - vn * n1, vt2 = vr2 - vn * n2;
        double sd = sqrt(delta);
        double chisd = chi * sd;
        double kn = 1.5 * chisd, kt = ratio_t * chisd;
        double eta_n = zeta2 * sqrt(kn * mstar);
        double eta_t = eta_n * tn;
        double fn = chisd * delta + eta_n * vn;
        double hn = h0 * n0 + h1 * n1 + h2 * n2;
        double t0 = h0 - hn * n0, t1 = h1 - hn * n1, t2 = h2 - hn * n2;
        double hh = h0 * h0 + h1 * h1 + h2 * h2;
        double ss = hh - hn * hn;
        double scale = sqrt(hh / ss);
        int rot = (hn != 0) & (ss > 0);
        double r0 = t0 * scale, r1 = t1 * scale, r2 = t2 * scale;
        t0 = rot ? r0 : t0;
        t1 = rot ? r1 : t1;
        t2 = rot ? r2 : t2;
        t0 += tau * vt0;
        t1 += tau * vt1;
        t2 += tau * vt2;
        double f0 = -kt * t0 - eta_t * vt0;
        double f1 = -kt * t1 - eta_t * vt1;
        double f2 = -kt * t2 - eta_t * vt2;
        double fmax = mu * fabs(fn);
        double ff = f0 * f0 + f1 * f1 + f2 * f2;
        double ts = t0 * t0 + t1 * t1 + t2 * t2;
        /* the cone of tangential_coulomb.c: total and elastic force */
        int slide = (ff > fmax * fmax)
                    | (kt * kt * ts > CONTACT_SPRING_CONE * fmax * fmax);
        double sl = sqrt(ts);
        double fl = sqrt(ff);
        int along = (sl > 0) & (kt > 0);
        /* sliding along the spring */
        double a0 = -fmax * t0 / sl, a1 = -fmax * t1 / sl;
        double a2 = -fmax * t2 / sl;
        double sc = fmax / (kt * sl);
        /* sliding without a spring */
        double sf = fmax / fl;
        double b0 = f0 * sf, b1 = f1 * sf, b2 = f2 * sf;
        double c0 = t0 * sc, c1 = t1 * sc, c2 = t2 * sc;
        double g0 = slide ? (along ? a0 : b0) : f0;
        double g1 = slide ? (along ? a1 : b1) : f1;
        double g2 = slide ? (along ? a2 : b2) : f2;
        o.u[0] = slide ? (along ? c0 : 0.0) : t0;
        o.u[1] = slide ? (along ? c1 : 0.0) : t1;
        o.u[2] = slide ? (along ? c2 : 0.0) : t2;
        o.f[0] = -fn * n0 + g0;
        o.f[1] = -fn * n1 + g1;
        o.f[2] = -fn * n2 + g2;
        o.tc[0] = n1 * g2 - n2 * g1;
        o.tc[1] = n2 * g0 - n0 * g2;
        o.tc[2] = n0 * g1 - n1 * g0;
        o.kn = kn;
        return o;
}

/* Lane k of a block's results (the same layout in pair and wall blocks). */
static inline __attribute__((always_inline)) void
lane_store(struct lane o, int k, double (*f)[BLK], double (*tc)[BLK],
           double (*hn)[BLK], double *kn)
{
    for (int a = 0; a < 3; a++) {
        hn[a][k] = o.u[a];
        f[a][k] = o.f[a];
        tc[a][k] = o.tc[a];
    }
    kn[k] = o.kn;
}

static void blk_eval(struct blk *restrict b, int m, double tau,
                     const struct contact_coeffs *restrict c)
{
    const double zeta2 = 2.0 * c->zeta, tn = c->hertz_tn;
    const double ratio_t = c->ratio_t, mu = c->mu;
    #pragma omp simd
    for (int k = 0; k < m; k++) {
        double dx = b->dx[0][k], dy = b->dx[1][k], dz = b->dx[2][k];
        double d2 = b->d2[k], rs = b->rs[k];
        double dist = sqrt(d2), inv = 1.0 / dist;
        double n0 = dx * inv, n1 = dy * inv, n2 = dz * inv;
        double delta = rs - dist;
        /* kinematics (fill_kinematics) */
        double s0 = b->sw[0][k], s1 = b->sw[1][k], s2_ = b->sw[2][k];
        double rw0 = s1 * n2 - s2_ * n1;
        double rw1 = s2_ * n0 - s0 * n2;
        double rw2 = s0 * n1 - s1 * n0;
        double vr0 = b->dv[0][k] + rw0, vr1 = b->dv[1][k] + rw1;
        double vr2 = b->dv[2][k] + rw2;
        double h0 = b->h[0][k], h1 = b->h[1][k], h2 = b->h[2][k];
        struct lane o = law_lane(n0, n1, n2, delta, vr0, vr1, vr2,
                                 b->chi[k], b->mstar[k], h0, h1, h2, tau,
                                 zeta2, tn, ratio_t, mu);
        lane_store(o, k, b->f, b->tc, b->hn, b->kn);
    }
}

/* Wall candidates in blocks too: geometry (wall_contact_inline) by a
 * scalar pass, the law as vectors. */
struct wblk {
    double n[3][BLK], delta[BLK], vr[3][BLK], chi[BLK], mstar[BLK];
    double h[3][BLK];
    double f[3][BLK], tc[3][BLK], hn[3][BLK], kn[BLK];
    int on[BLK];
};

static void wblk_eval(struct wblk *restrict b, int m, double tau,
                      const struct contact_coeffs *restrict c)
{
    const double zeta2 = 2.0 * c->zeta, tn = c->hertz_tn;
    const double ratio_t = c->ratio_t, mu = c->mu;
    #pragma omp simd
    for (int k = 0; k < m; k++) {
        struct lane o = law_lane(b->n[0][k], b->n[1][k], b->n[2][k],
                                 b->delta[k], b->vr[0][k], b->vr[1][k],
                                 b->vr[2][k], b->chi[k], b->mstar[k],
                                 b->h[0][k], b->h[1][k], b->h[2][k], tau,
                                 zeta2, tn, ratio_t, mu);
        lane_store(o, k, b->f, b->tc, b->hn, b->kn);
    }
}

struct fast {
    struct dem *d;
    const double *x, *v, *w, *fext, *fd;
    double *acc, *alpha, *ft6, *pf;
    double tau, kick;
    int commit, drag;
    size_t q, nq;   /* wall candidates (use_wlist): the next, their count */
    struct wblk *wb;   /* evaluated candidates wq0 .. wq0 + wm - 1 */
    size_t wq0;
    int wm;
    long nwc;
    double om2;
};

/* Wall contact of grain i with wall wl (wall_row, dem_forces.c), added to
 * its sums fti. */
static inline void wall_one(struct fast *F, size_t i, int wl, double *fti)
{
    struct dem *d = F->d;
    const double *xi = &F->x[3 * i], *vi = &F->v[3 * i], *wi = &F->w[3 * i];
    double ri = d->r[i];
    size_t hk = 3 * (i * (size_t)d->nwalls + (size_t)wl);
    const struct dem_wall *wa = &d->walls[wl];
    struct contact_geom g;
    double *h = &d->whist[hk];
    if (!wall_contact_inline(wa, xi, ri, g.n, &g.delta)) {
        if (F->commit && (h[0] != 0 || h[1] != 0 || h[2] != 0))
            h[0] = h[1] = h[2] = 0;
        return;
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
    contact_eval_fused(&d->law, &g, h, F->tau, hn, &res);
    if (F->commit) {
        h[0] = hn[0];
        h[1] = hn[1];
        h[2] = hn[2];
    }
    double tc[3];
    tc[0] = g.n[1] * res.ft[2] - g.n[2] * res.ft[1];
    tc[1] = g.n[2] * res.ft[0] - g.n[0] * res.ft[2];
    tc[2] = g.n[0] * res.ft[1] - g.n[1] * res.ft[0];
    int pa = wa->patch;
    for (int a = 0; a < 3; a++) {
        fti[a] += res.f[a];
        fti[3 + a] += ri * tc[a] + res.mroll[a];
        F->pf[3 * pa + a] -= res.f[a];
    }
    F->nwc++;
    double w2 = res.kn * d->inv_m[i];
    F->om2 = w2 > F->om2 ? w2 : F->om2;
}

/* Evaluate the wall candidates from q0 on (BLK of them at most): all
 * belong to grains not finished yet. */
static void wall_block(struct fast *F, size_t q0)
{
    struct dem *d = F->d;
    struct wblk *restrict b = F->wb;
    int m = F->nq - q0 < BLK ? (int)(F->nq - q0) : BLK;
    /* the springs are scattered (3 per grain and wall): ask for all of
     * the block's at once */
    for (int k = 0; k < m; k++) {
        size_t q = q0 + (size_t)k;
        __builtin_prefetch(&d->whist[3 * (d->wgrain[q] * (size_t)d->nwalls
                                          + (size_t)d->wlist[q])], 1);
    }
    for (int k = 0; k < m; k++) {
        size_t q = q0 + (size_t)k, i = d->wgrain[q];
        int wl = d->wlist[q];
        const struct dem_wall *wa = &d->walls[wl];
        const double *vi = &F->v[3 * i], *wi = &F->w[3 * i];
        double ri = d->r[i];
        double n[3] = {0, 0, 1}, delta = 0;
        int on = wall_contact_inline(wa, &F->x[3 * i], ri, n, &delta);
        b->on[k] = on;
        if (!on)
            n[0] = 0, n[1] = 0, n[2] = 1, delta = 0;
        /* fill_kinematics of a wall in rigid translation */
        double s[3], rw[3];
        for (int a = 0; a < 3; a++)
            s[a] = ri * wi[a] + 0.0;
        rw[0] = s[1] * n[2] - s[2] * n[1];
        rw[1] = s[2] * n[0] - s[0] * n[2];
        rw[2] = s[0] * n[1] - s[1] * n[0];
        const double *h = &d->whist[3 * (i * (size_t)d->nwalls + (size_t)wl)];
        for (int a = 0; a < 3; a++) {
            b->n[a][k] = n[a];
            b->vr[a][k] = vi[a] - wa->vel[a] + rw[a];
            b->h[a][k] = h[a];
        }
        b->delta[k] = delta;
        b->chi[k] = d->wall_chi[i];
        b->mstar[k] = d->m[i];
    }
    wblk_eval(b, m, F->tau, &d->law.c);
    F->wq0 = q0;
    F->wm = m;
}

/* Wall candidate q (of grain i), evaluated by wall_block, into fti. */
static inline void wall_take(struct fast *F, size_t q, size_t i, double *fti)
{
    struct dem *d = F->d;
    if (q >= F->wq0 + (size_t)F->wm)
        wall_block(F, q);
    const struct wblk *b = F->wb;
    int k = (int)(q - F->wq0), wl = d->wlist[q];
    double *h = &d->whist[3 * (i * (size_t)d->nwalls + (size_t)wl)];
    if (!b->on[k]) {
        if (F->commit && (h[0] != 0 || h[1] != 0 || h[2] != 0))
            h[0] = h[1] = h[2] = 0;
        return;
    }
    if (F->commit)
        for (int a = 0; a < 3; a++)
            h[a] = b->hn[a][k];
    double ri = d->r[i];
    int pa = d->walls[wl].patch;
    for (int a = 0; a < 3; a++) {
        fti[a] += b->f[a][k];
        fti[3 + a] += ri * b->tc[a][k] + 0.0;   /* mroll = 0 */
        F->pf[3 * pa + a] -= b->f[a][k];
    }
    F->nwc++;
    double w2 = b->kn[k] * d->inv_m[i];
    F->om2 = w2 > F->om2 ? w2 : F->om2;
}

/* Walls of grain i, then its accelerations and closing half kick (finish,
 * dem_forces.c). With the wall list, a cursor runs through the
 * candidates (grain by grain) instead of reading wstart for every
 * grain: most grains have none. */
static inline void grain_done(struct fast *F, size_t i)
{
    struct dem *d = F->d;
    double *restrict fti = &F->ft6[6 * i];
    if (d->use_wlist) {
        const uint32_t *wg = d->wgrain;
        while (F->q < F->nq && wg[F->q] == i) {
            wall_take(F, F->q, i, fti);
            F->q++;
        }
    } else {
        for (int wl = 0; wl < d->nwalls; wl++)
            wall_one(F, i, wl, fti);
    }
    const double inv_mi = d->inv_m[i], inv_ii = d->inv_i[i];
    const double *restrict fext = F->fext, *restrict fd = F->fd;
    double *restrict acc = &F->acc[3 * i], *restrict alpha = &F->alpha[3 * i];
    double *restrict vi = &d->v[3 * i], *restrict wi = &d->w[3 * i];
    const double kick = F->kick;
    const int drag = F->drag;
    for (int a = 0; a < 3; a++) {
        size_t k = 3 * i + a;
        double fk = fti[a] + (fext ? fext[k] : 0.0) + (drag ? fd[k] : 0.0);
        double ak = fk * inv_mi + d->gravity[a];
        double alk = fti[3 + a] * inv_ii;
        acc[a] = ak;
        alpha[a] = alk;
        fti[a] = fti[3 + a] = 0;
        if (kick != 0) {
            vi[a] += kick * ak;
            wi[a] += kick * alk;
        }
    }
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
    double pf[3 * DEM_MAX_PATCHES] = {0};
    struct wblk wb;
    struct fast F = {
        .d = d, .x = x, .v = v, .w = w, .fext = c->fext, .fd = c->fd,
        .acc = acc, .alpha = alpha, .ft6 = d->tbuf, .pf = pf, .tau = tau,
        .kick = d->kick, .commit = commit, .drag = drag,
        .nq = d->use_wlist && n ? d->wstart[n] : 0, .wb = &wb,
    };
    const double *restrict r = d->r, *restrict inv_m = d->inv_m;
    const double *restrict pair_c = d->pair_c;
    const uint32_t *restrict nlj = d->nl.j;
    const size_t *restrict start = d->nl.start;
    double *restrict hist = d->hist;
    double *restrict ft6 = d->tbuf;   /* 6 per grain: f, t; all zero
                                         outside this function */
    size_t np = n ? start[n] : 0;
    struct blk b;
    uint32_t bi[BLK], bj[BLK];
    size_t bp[BLK];
    long nc = 0;
    double om2 = 0;
    size_t row = 0;   /* rows below are done */
    size_t p = 0, i = 0;
    while (p < np) {
        /* gather the next BLK pairs in contact; a pair out of contact
         * only has its spring cleared (pair_row) */
        int m = 0;
        for (; p < np && m < BLK; p++) {
            while (start[i + 1] <= p)
                i++;
            size_t j = nlj[p];
            double dx[3], d2 = 0;
            for (int a = 0; a < 3; a++) {
                dx[a] = x[3 * j + a] - x[3 * i + a];
                d2 += dx[a] * dx[a];
            }
            double rs = r[i] + r[j];
            double *h = &hist[3 * p];
            if (d2 >= rs * rs) {
                if (commit && (h[0] != 0 || h[1] != 0 || h[2] != 0))
                    h[0] = h[1] = h[2] = 0;   /* the contact ended */
                continue;
            }
            bi[m] = (uint32_t)i;
            bj[m] = (uint32_t)j;
            bp[m] = p;
            for (int a = 0; a < 3; a++) {
                b.dx[a][m] = dx[a];
                b.dv[a][m] = v[3 * i + a] - v[3 * j + a];
                b.sw[a][m] = r[i] * w[3 * i + a] + r[j] * w[3 * j + a];
                b.h[a][m] = h[a];
            }
            b.d2[m] = d2;
            b.rs[m] = rs;
            b.chi[m] = pair_c[2 * p];
            b.mstar[m] = pair_c[2 * p + 1];
            m++;
        }
        blk_eval(&b, m, tau, &d->law.c);
        /* scatter in list order */
        for (int k = 0; k < m; k++) {
            size_t ik = bi[k], j = bj[k];
            while (row < ik)
                grain_done(&F, row++);
            if (commit)
                for (int a = 0; a < 3; a++)
                    hist[3 * bp[k] + a] = b.hn[a][k];
            double *fti = &ft6[6 * ik], *ftj = &ft6[6 * j];
            double ri = r[ik], rj = r[j];
            for (int a = 0; a < 3; a++) {   /* the moments as pair_row's,
                                               with mroll = 0 */
                fti[a] += b.f[a][k];
                ftj[a] -= b.f[a][k];
                fti[3 + a] += ri * b.tc[a][k] + 0.0;
                ftj[3 + a] += rj * b.tc[a][k] - 0.0;
            }
            nc++;
            double w2 = b.kn[k] * (inv_m[ik] + inv_m[j]);
            om2 = w2 > om2 ? w2 : om2;
        }
    }
    while (row < n)
        grain_done(&F, row++);
    (void)r;
    for (int p = 0; p < 3 * DEM_MAX_PATCHES; p++)
        d->patch_force[p] = 0.0 + pf[p];   /* as the reduction over
                                              threads: -0 becomes 0 */
    d->ncontacts = nc;
    d->nwall_contacts = F.nwc;
    d->omega2_max = om2 > F.om2 ? om2 : F.om2;
    d->stats.fevals++;
    return SIM_OK;
}
