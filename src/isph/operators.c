/*
 * operators.c — the corrected SPH gradient and Laplacian of Schwaiger
 * (2008) as the thesis's ch. 5 writes them (Pan 2022, eqs. 5.35-5.38,
 * 5.40, 5.44; doc/theory.md S.2, S0-02, S0-03); definitions in isph.h.
 */
#include <math.h>

#include "core/error.h"
#include "isph/isph.h"
#include "particles/neighbour.h"

void isph_kernel_gradient(const struct isph_cloud *c, int a, int b,
                          double r, double dx[2], double gw[2])
{
    dx[0] = c->x[3 * b] - c->x[3 * a];
    dx[1] = c->x[3 * b + 1] - c->x[3 * a + 1];
    double d = r > 0 ? c->kernel->dw(r, c->h) / r : 0;
    gw[0] = -d * dx[0];
    gw[1] = -d * dx[1];
}

int isph_corrections(struct isph_cloud *c)
{
    const struct neighbour_list *nl = c->nl;
    const double reach = c->kernel->support * c->h;
    int bad = -1;
    long isolated = 0;
#pragma omp parallel for schedule(static) reduction(+ : isolated)
    for (int a = 0; a < c->n; a++) {
        double Li[4] = { 0 }, G[4] = { 0 }, S[2] = { 0 }, dr = 0, th = 0;
        if (c->isolated)
            c->isolated[a] = 0;
        if (c->active && !c->active[a])
            continue;
        for (int64_t k = nl->start[a]; k < nl->start[a + 1]; k++) {
            int b = nl->j[k];
            double r = nl->r[k], dx[2], gw[2];
            if (b == a || !(r > 0) || r >= reach)
                continue;
            isph_kernel_gradient(c, a, b, r, dx, gw);
            double V = c->V[b], F = (dx[0] * gw[0] + dx[1] * gw[1]) / (r * r);
            if (c->divr)
                dr -= V * c->kernel->dw(r, c->h) * r;
            if (c->theta)
                th += V * c->kernel->w(r, c->h);
            for (int p = 0; p < 2; p++) {
                S[p] += V * gw[p];
                for (int q = 0; q < 2; q++) {
                    Li[2 * p + q] += V * gw[p] * dx[q];
                    G[2 * p + q] += V * F * dx[p] * dx[q];
                }
            }
        }
        if (c->divr)
            c->divr[a] = dr;
        if (c->theta)
            c->theta[a] = th + c->V[a] * c->kernel->w(0, c->h);
        double det = Li[0] * Li[3] - Li[1] * Li[2];
        double dg = G[0] * G[3] - G[1] * G[2], tr = G[0] + G[3];
        double *L = c->L + 4 * a;
        if (!(fabs(det) > 1e-12 * (Li[0] * Li[0] + Li[3] * Li[3]))
            || !(dg > 0) || !(tr > 0)) {
            if (c->isolated) {
                c->isolated[a] = 1;
                isolated++;
                L[0] = L[1] = L[2] = L[3] = 0;
                c->c[a] = c->S[2 * a] = c->S[2 * a + 1] = 0;
                continue;
            }
#pragma omp critical
            if (bad < 0 || a < bad)
                bad = a;
            continue;
        }
        L[0] = Li[3] / det;
        L[1] = -Li[1] / det;
        L[2] = -Li[2] / det;
        L[3] = Li[0] / det;
        /* tr(Gamma^-1) = tr(Gamma)/det(Gamma) in 2-D */
        c->c[a] = c->norm == ISPH_LAP_TRACE_INVERSE ? 2 * (tr / dg) / 2
                                                    : 2 * 2 / tr;
        c->S[2 * a] = S[0];
        c->S[2 * a + 1] = S[1];
    }
    c->n_isolated = isolated;
    if (bad >= 0)
        return sim_error(SIM_ERR_NUMERIC, "ISPH correction at particle %d "
                         "(%g, %g): its neighbours within %g m do not span "
                         "the plane", bad, c->x[3 * bad], c->x[3 * bad + 1],
                         reach);
    return SIM_OK;
}

void isph_gradient(const struct isph_cloud *c, const double *f, int stride,
                   int a, double g[2])
{
    const struct neighbour_list *nl = c->nl;
    const double reach = c->kernel->support * c->h, *L = c->L + 4 * a;
    double s[2] = { 0, 0 };
    for (int64_t k = nl->start[a]; k < nl->start[a + 1]; k++) {
        int b = nl->j[k];
        double r = nl->r[k], dx[2], gw[2];
        if (b == a || !(r > 0) || r >= reach)
            continue;
        isph_kernel_gradient(c, a, b, r, dx, gw);
        double df = c->V[b] * (f[stride * b] - f[stride * a]);
        s[0] += df * gw[0];
        s[1] += df * gw[1];
    }
    g[0] = L[0] * s[0] + L[1] * s[1];
    g[1] = L[2] * s[0] + L[3] * s[1];
}

void isph_laplacian_row(const struct isph_cloud *c, int a, double *l)
{
    const struct neighbour_list *nl = c->nl;
    const double reach = c->kernel->support * c->h, *L = c->L + 4 * a;
    const double *S = c->S + 2 * a;
    /* grad f_a . S_a = sum_b V_b (f_b - f_a) (L_a grad W_ab) . S_a */
    for (int64_t k = nl->start[a]; k < nl->start[a + 1]; k++) {
        int b = nl->j[k];
        double r = nl->r[k], dx[2], gw[2];
        l[k - nl->start[a]] = 0;
        if (b == a || !(r > 0) || r >= reach)
            continue;
        isph_kernel_gradient(c, a, b, r, dx, gw);
        double F = (dx[0] * gw[0] + dx[1] * gw[1]) / (r * r);
        double Lg[2] = { L[0] * gw[0] + L[1] * gw[1],
                         L[2] * gw[0] + L[3] * gw[1] };
        l[k - nl->start[a]] = c->c[a] * c->V[b]
                            * (F - (Lg[0] * S[0] + Lg[1] * S[1]));
    }
}

double isph_laplacian(const struct isph_cloud *c, const double *f, int a)
{
    const struct neighbour_list *nl = c->nl;
    int m = (int)(nl->start[a + 1] - nl->start[a]);
    double l[m > 0 ? m : 1], s = 0;
    isph_laplacian_row(c, a, l);
    for (int k = 0; k < m; k++)
        s += l[k] * (f[nl->j[nl->start[a] + k]] - f[a]);
    return s;
}
