/* couplingPhysicsBench.c — cost of the coupling physics per fluid step
 * (src/coupling: pairs, porosity, interpolation, reaction, drag), on the
 * two-phase dam break layout of Xie et al. 2025 (doc/theory.md A.12.2,
 * A0-17): a 0.05 x 0.1 x 0.1 m water column on the lattice dp, and the
 * 7425 Table 1 beads (15 x 33 x 15, d = 2.7 mm) at its bottom;
 * r_e,s = 4.1 dp (A0-13).
 *
 * One fluid step of the sequential scheme (A.10) costs: 2 pair builds and
 * 2 porosity evaluations (steps 2 and 5), 1 interpolation (step 3),
 * 1 reaction (step 6), and N_sub = 100 drag + Model B force evaluations on
 * the DEM side (step 4). Each phase is timed as the minimum over repeats
 * (wall clock), the robust statistic on a shared machine.
 *
 * A second table gives the momentum balance of Model B on the same block
 * for a uniform drag: the published reaction (fluid side
 * sum_i V_i f_A,i/eps_i) against what the grains feel (sum_k F_k/eps_k),
 * for r_e,s = 4.1, 3.0, 2.1 dp, and the conservativeReaction option.
 *
 * Usage: couplingPhysicsBench [repeats]   (default 10) */
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "coupling/drag/drag.h"
#include "coupling/interp.h"
#include "coupling/models.h"
#include "coupling/pairs.h"
#include "coupling/porosity.h"
#include "coupling/reaction.h"

enum { NG = 7425 };

static double best(double a, double b) { return a < b ? a : b; }

static void run(double dp, int R)
{
    const double d = 2.7e-3, re = 4.1 * dp, g[3] = { 0, 0, -9.81 };
    int nx = (int)(0.05 / dp), ny = (int)(0.1 / dp), nz = (int)(0.1 / dp);
    int np = nx * ny * nz, n = 0;
    double *xp = malloc(3 * sizeof(double) * np), *u = calloc(3 * np, 8);
    double *eps = malloc(8 * (size_t)np), *fA = malloc(24 * (size_t)np);
    for (int i = 0; i < nx; i++)
        for (int j = 0; j < ny; j++)
            for (int k = 0; k < nz; k++, n++) {
                xp[3 * n] = (i + 0.5) * dp;
                xp[3 * n + 1] = (j + 0.5) * dp;
                xp[3 * n + 2] = (k + 0.5) * dp;
                u[3 * n] = 0.01 * sin(n);
            }
    static double xg[3 * NG], V[NG], dg[NG], ek[NG], uk[3 * NG], gk[3 * NG];
    static double vg[3 * NG], F[3 * NG], Fi[3 * NG];
    static uint8_t wet[NG];
    int ng = 0;
    for (int i = 0; i < 15; i++)
        for (int j = 0; j < 33; j++)
            for (int k = 0; k < 15; k++, ng++) {
                xg[3 * ng] = 0.0047 + i * d;
                xg[3 * ng + 1] = 0.00545 + j * d;
                xg[3 * ng + 2] = dp + d / 2 + k * d;
                V[ng] = M_PI * d * d * d / 6;
                dg[ng] = d;
                vg[3 * ng + 2] = -0.01;
            }
    struct coupling_pairs P = { 0 };
    struct coupling_grain_fields G = { ek, uk, gk, wet };
    const struct drag_fluid w = { 1000, 1e-3 };
    double tb = 1e30, tp = 1e30, ti = 1e30, tr = 1e30, td = 1e30, t;
    double ts = 1e30, tu = 1e30;
    const double skin = 0.3 * dp;
    struct coupling_pairs Q = { 0 };
    int searched;
    long nclamp = 0;
    coupling_pairs_build(&P, 3, re, NG, xg, np, xp);
    for (int r = 0; r < R; r++) {
        t = omp_get_wtime();
        coupling_pairs_build(&P, 3, re, NG, xg, np, xp);
        tb = best(tb, omp_get_wtime() - t);
        t = omp_get_wtime();
        coupling_pairs_invalidate(&Q);   /* a search with the skin */
        coupling_pairs_update(&Q, 3, re, skin, NG, xg, np, xp, &searched);
        ts = best(ts, omp_get_wtime() - t);
        t = omp_get_wtime();
        coupling_pairs_update(&Q, 3, re, skin, NG, xg, np, xp, &searched);
        tu = best(tu, omp_get_wtime() - t);
        if (searched)
            fprintf(stderr, "unexpected search\n");
        t = omp_get_wtime();
        coupling_porosity(&P, V, 0.3, eps, NULL, &nclamp);
        tp = best(tp, omp_get_wtime() - t);
        t = omp_get_wtime();
        coupling_interp_grains(&P, NULL, eps, u, NULL, &G);
        ti = best(ti, omp_get_wtime() - t);
        t = omp_get_wtime();
        for (int s = 0; s < 100; s++) {
            drag_ergun_wen_yu.force_all(&w, NG, ek, dg, V, uk, vg, F);
            coupling_grain_force(COUPLING_MODEL_B, NG, F, ek, NULL, V, 1000,
                                 g, wet, Fi);
        }
        td = best(td, omp_get_wtime() - t);
        t = omp_get_wtime();
        coupling_reaction(&P, NULL, F, dp * dp * dp, NULL, fA, NULL);
        tr = best(tr, omp_get_wtime() - t);
    }
    double total = 2 * tb + 2 * tp + ti + tr + td;
    double total_u = 2 * tu + 2 * tp + ti + tr + td;
    printf("%7.4f %8d %6d %9lld %8.2f %8.2f %8.2f %8.2f %8.2f %8.2f %9.2f "
           "%8.1f %8.1f %7.0fx\n", dp, np, NG, (long long)P.npair, 1e3 * tb,
           1e3 * ts, 1e3 * tu, 1e3 * tp, 1e3 * ti, 1e3 * tr, 1e3 * td,
           1e3 * total, 1e3 * total_u, 3.25 / total);
    coupling_pairs_free(&P);
    coupling_pairs_free(&Q);
    free(xp);
    free(u);
    free(eps);
    free(fA);
}

/* Model B exchange on the bead block at dp = 2.7 mm: relative difference
 * between the fluid's momentum rate and -sum_k F_k/eps_k. */
static void model_b_balance(double ratio)
{
    const double dp = 2.7e-3, d = 2.7e-3, Vp = dp * dp * dp, g0[3] = { 0 };
    int nx = (int)(0.05 / dp), ny = (int)(0.1 / dp), nz = (int)(0.1 / dp);
    int np = nx * ny * nz, n = 0;
    double *xp = malloc(24 * (size_t)np), *u = calloc(3 * (size_t)np, 8);
    double *eps = malloc(8 * (size_t)np), *fA = malloc(24 * (size_t)np);
    double *a = malloc(24 * (size_t)np);
    for (int i = 0; i < nx; i++)
        for (int j = 0; j < ny; j++)
            for (int k = 0; k < nz; k++, n++) {
                xp[3 * n] = (i + 0.5) * dp;
                xp[3 * n + 1] = (j + 0.5) * dp;
                xp[3 * n + 2] = (k + 0.5) * dp;
            }
    static double xg[3 * NG], V[NG], F[3 * NG], Fin[3 * NG], ek[NG];
    static double uk[3 * NG];
    static uint8_t wet[NG];
    int ng = 0;
    for (int i = 0; i < 15; i++)
        for (int j = 0; j < 33; j++)
            for (int k = 0; k < 15; k++, ng++) {
                xg[3 * ng] = 0.0047 + i * d;
                xg[3 * ng + 1] = 0.00545 + j * d;
                xg[3 * ng + 2] = dp + d / 2 + k * d;
                V[ng] = M_PI * d * d * d / 6;
                F[3 * ng + 2] = 1e-5;
            }
    struct coupling_pairs P = { 0 };
    struct coupling_grain_fields G = { ek, uk, NULL, wet };
    coupling_pairs_build(&P, 3, ratio * dp, NG, xg, np, xp);
    coupling_porosity(&P, V, 0.3, eps, NULL, NULL);
    coupling_interp_grains(&P, NULL, eps, u, NULL, &G);
    double want = 0, mean_ek = 0, got[2];
    for (int k = 0; k < NG; k++) {
        want -= F[3 * k + 2] / ek[k];
        mean_ek += ek[k] / NG;
    }
    for (int cons = 0; cons <= 1; cons++) {
        coupling_reaction_input(COUPLING_MODEL_B, cons, NG, F, ek, Fin);
        coupling_reaction(&P, NULL, Fin, Vp, NULL, fA, NULL);
        coupling_mps_accel(COUPLING_MODEL_B, cons, np, eps, fA, 1000, g0,
                           NULL, a);
        got[cons] = 0;
        for (int i = 0; i < np; i++)
            got[cons] += 1000 * eps[i] * Vp * a[3 * i + 2];
    }
    printf("%8.1f %9.4f %12.3e %12.3e %+10.3f %+10.1e\n", ratio, mean_ek,
           want, got[0], 100 * (got[0] - want) / want,
           100 * (got[1] - want) / want);
    coupling_pairs_free(&P);
    free(xp);
    free(u);
    free(eps);
    free(fA);
    free(a);
}

int main(int argc, char **argv)
{
    int R = argc > 1 ? atoi(argv[1]) : 10;
    printf("# coupling physics per fluid step, %d threads, best of %d\n",
           omp_get_max_threads(), R);
    printf("# step = 2 pairs + 2 porosity + interp + reaction + 100 x "
           "(drag + Model B force); 'vs paper' = 3.25 s (Table 2, DEM + "
           "coupling, which also includes the DEM contacts)\n");
    printf("# search = pair build; skin = build keeping candidates within "
           "r_e,s + 0.3 dp; refresh = reuse of those candidates (weights "
           "only); step = with 2 searches, step_rf = with 2 refreshes\n");
    printf("#    dp       np     ng     pairs search  skin_sr  refresh   "
           "por_ms interp_ms react_ms drag100_ms  step_ms  step_rf "
           "vs_paper\n");
    const double dps[] = { 0.002, 0.0027, 0.003 };
    for (int i = 0; i < 3; i++)
        run(dps[i], R);
    printf("\n# Model B exchange, 7425 beads, dp = 2.7 mm, uniform drag "
           "1e-5 N: fluid momentum rate vs -sum F/eps_k\n");
    printf("# re_s/dp  mean_eps_k  -sum F/eps_k  fluid_literal  literal_%%  "
           "conservative_%%\n");
    const double ratios[] = { 4.1, 3.0, 2.1 };
    for (int i = 0; i < 3; i++)
        model_b_balance(ratios[i]);
    return 0;
}
