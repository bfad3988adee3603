/*
 * surface_pressure.c — Dirichlet value of the free-surface particles
 * (`freeSurface { pressure extrapolated; }` in mpsSchemes; the paper's
 * default, doc/theory.md A.4, is P = 0 at the surface particle itself).
 *
 * A surface particle stands for the water within dp/2 of its centre: the
 * surface where p = 0 lies dp/2 outside it, along the outward normal n.
 * Imposing p = 0 at the centre moves the surface down by dp/2 and, with a
 * first-order consistent gradient (pressureGradient corrected), lowers the
 * whole hydrostatic field by rho g dp/2 (24.5 Pa for dp = 5 mm: an L2 error
 * of 4 % in the 0.1 m tank). The value at the centre is instead taken from
 * p = 0 on the surface and the pressure gradient there (the interface
 * Dirichlet condition of the ghost-fluid method, Gibou et al. 2002,
 * J. Comput. Phys. 176, 205, eq. 8, to first order):
 *
 *   p_s = -(dp/2) n . <grad p>_s,   n = -F_s/|F_s|   (eq. 15)
 *   <grad p>_s = C_s sum_j (p_j - p_s) r_sj w_sj / (|r_sj|^2 eps_j)
 *
 * with the corrected gradient (src/particles/operators/gradient_corrected.c)
 * of the neighbours' pressure of the previous step. p_s appears on both sides; it is solved
 * for, p_s = a / (1 + b) with a = -(dp/2) n.C sum p_j r w/r^2 and
 * b = -(dp/2) n.C sum r w/r^2, because the explicit update (p_s of the last
 * step on the right) amplifies itself by |b| per step, and |b| exceeds 1
 * for a splash particle with a close neighbour (it blew up a dam break).
 * The value is then limited to [0, max_j p_j] (fluid neighbours): a
 * particle in free fall (grad p = 0) keeps p = 0, still water gets
 * rho g dp/2, and the surface never carries more than the water below it.
 * A particle without a regular moment matrix, or with 1 + b < 1/2, keeps 0.
 */
#include <math.h>

#include "core/error.h"
#include "mps/mps.h"
#include "mps/mps_impl.h"
#include "particles/operators/gradient_corrected.h"

static double surface_value(const struct mps_solver *s,
                            const struct pop_weights *Wn,
                            const struct pop_weights *Wg, int i)
{
    const struct mps_particles *P = &s->P;
    const struct neighbour_list *nl = &s->nl;
    const double *ie = P->inv_eps, *xi = P->x + 3 * i;
    double m[9] = { 0 }, v[3] = { 0 }, S[3] = { 0 }, F[3] = { 0 };
    double pmax = 0;
    const int64_t k0 = nl->start[i], k1 = nl->start[i + 1];
    const double *rr = neighbour_row_r(nl, i, k0, k1);
    const double *wn = pop_weights_row(Wn, k0, rr, k1 - k0);
    const double *wg = pop_weights_row(Wg, k0, rr, k1 - k0);
    for (int64_t k = k0; k < k1; k++) {
        int j = nl->j[k];
        double r = rr[k - k0];
        if (r == 0)
            continue;
        double d[3] = { P->x[3 * j] - xi[0], P->x[3 * j + 1] - xi[1],
                        P->x[3 * j + 2] - xi[2] };
        double e = ie ? ie[j] : 1.0;
        if (wn[k - k0] > 0)
            for (int q = 0; q < 3; q++)
                F[q] += wn[k - k0] * e * d[q] / r;
        if (wg[k - k0] == 0)
            continue;
        double a = wg[k - k0] * e / (r * r);
        if (P->type[j] == MPS_FLUID && P->fs[j] != MPS_SURFACE)
            pmax = fmax(pmax, P->p[j]);
        for (int q = 0; q < 3; q++) {
            v[q] += a * P->p[j] * d[q];
            S[q] += a * d[q];
            for (int t = 0; t < 3; t++)
                m[3 * q + t] += a * d[q] * d[t];
        }
    }
    double fm = sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]), cv[3], cs[3];
    if (!(fm > 0) || !pop_moment_solve(P->dim, m, v, cv)
        || !pop_moment_solve(P->dim, m, S, cs))
        return 0;
    double a = 0, b = 0, half = 0.5 * s->dp;
    for (int q = 0; q < 3; q++) {     /* n = -F/|F| */
        a += half * cv[q] * F[q] / fm;
        b += half * cs[q] * F[q] / fm;
    }
    if (!(1 + b >= 0.5))
        return 0;
    return fmin(fmax(0.0, a / (1 + b)), pmax);
}

int mps_surface_pressure(struct mps_solver *s)
{
    struct mps_particles *P = &s->P;
    const struct pop_weights Wn = mps_w(s, MPS_W_N), Wg = mps_w(s, MPS_W_G);
    /* In index order, one particle after the other: a surface particle's
     * fit reads the pressure of its surface neighbours, which this loop
     * sets. Run in parallel, that read raced with the writes, and two runs
     * of the same case on two threads differed (from the 5th step of the
     * Kleefsman tank, test/cases/neighbourDistances.sh under load); in
     * order, every thread count gives what one thread always gave. The
     * surface particles are a few per cent of the fluid. */
    if (!s->S.fs_simultaneous) {
        for (int i = 0; i < P->n; i++)
            if (P->type[i] == MPS_FLUID && P->fs[i] == MPS_SURFACE)
                P->p[i] = surface_value(s, &Wn, &Wg, i);
        return SIM_OK;
    }
    /* `sweep simultaneous`: every value from the last step's, so the
     * order does not matter and a distributed run, which fits its own
     * particles and then gives the ghosts their owners' values, repeats
     * one process to round-off. s->div is free until the PPE's source. */
    const int n = mps_own(s);
    double *v = s->div;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; i++)
        if (P->type[i] == MPS_FLUID && P->fs[i] == MPS_SURFACE)
            v[i] = surface_value(s, &Wn, &Wg, i);
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; i++)
        if (P->type[i] == MPS_FLUID && P->fs[i] == MPS_SURFACE)
            P->p[i] = v[i];
    return mps_halo_refresh(s, P->p, sizeof *P->p);
}
