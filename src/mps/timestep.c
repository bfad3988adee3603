/*
 * timestep.c — time-step limits, pre-run stability checks and the NaN
 * guard of the MPS solver; the limits themselves are shared
 * (src/particles/operators/checks.c):
 *
 *   Courant (A.8 eq. 37):   dt <= C dp / |u|_max     (fluid particles)
 *   acceleration:           dt <= C sqrt(dp / |g|)   (the first steps, when
 *                                                     u is still ~0)
 *   viscous diffusion [P]:  dt <= 0.2 dp^2 / nu      (explicit Laplacian)
 *
 * Before the run, a fixed dt is checked against the free-fall speed of the
 * fluid column, u_ff = sqrt(2 |g| H) with H the fluid's vertical extent:
 * Courant > 1 or the viscous limit exceeded is an error, Courant > maxCo a
 * warning. Radii below 2 dp are refused (the free-surface and gradient
 * operators need the second lattice shell), and wall particles with fewer
 * wall/dummy layers behind them than the largest r_e needs are reported.
 */
#include <math.h>
#include <stdio.h>

#include "core/error.h"
#include "core/log.h"
#include "mps/mps.h"
#include "mps/soil/soil.h"
#include "particles/operators/checks.h"

static double gnorm(const struct mps_settings *S)
{
    return sqrt(S->g[0] * S->g[0] + S->g[1] * S->g[1] + S->g[2] * S->g[2]);
}

/* The largest viscosity of the phases: a liquid soil's may exceed the
 * water's (doc/theory.md K0-09). */
static double nu_max(const struct mps_settings *S)
{
    if (S->soil && S->soil->model == SOIL_MODEL_LIQUID && S->soil->nu > S->nu)
        return S->soil->nu;
    return S->nu;
}

double mps_max_fluid_speed(const struct mps_solver *s)
{
    /* the own particles, over the ranks: a ghost's velocity in the step
     * is its row's, not its owner's (mps_halo.c) */
    double u = pop_max_norm3(mps_own(s), s->P.u, s->P.type, MPS_FLUID);
    return s->halo ? pop_halo_reduce1(s->halo, u, POP_MAX) : u;
}

double mps_propose_dt(const struct mps_solver *s, double max_co)
{
    return pop_stable_dt(s->dp, nu_max(&s->S), mps_max_fluid_speed(s),
                         gnorm(&s->S), max_co);
}

static double fluid_height(const struct mps_particles *P)
{
    int v = P->dim - 1;
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < P->n; i++)
        if (P->type[i] == MPS_FLUID) {
            lo = fmin(lo, P->x[3 * i + v]);
            hi = fmax(hi, P->x[3 * i + v]);
        }
    return hi > lo ? hi - lo : 0;
}

/* Wall particles whose wall+dummy layers behind them (along the normal)
 * are thinner than ceil(r_e/dp) - 1 layers (on the list of the start,
 * where every wall particle has its row). Along a diagonal normal the
 * lattice points behind a particle are sqrt(2) or sqrt(3) dp apart, so at
 * a tank corner the next layer can lie beyond r_e although every layer
 * the kernel reaches is there: the wall is full when the next point along
 * the line (depth + the spacing of the points on it) is outside r_e. */
int mps_thin_walls(const struct mps_solver *s)
{
    const struct mps_particles *P = &s->P;
    const struct neighbour_list *nl = &s->nl;
    int need = (int)ceil(s->re_max / s->dp - 1e-9) - 1, bad = 0;
#pragma omp parallel for reduction(+ : bad)
    for (int i = 0; i < P->n; i++) {
        if (P->type[i] != MPS_WALL)
            continue;
        const double *n = P->normal + 3 * i;
        double depth = 0, step = INFINITY;
        for (int64_t k = nl->start[i]; k < nl->start[i + 1]; k++) {
            int j = nl->j[k];
            if (P->type[j] == MPS_FLUID)
                continue;
            double d[3], a = 0, b = 0;
            for (int q = 0; q < 3; q++) {
                d[q] = P->x[3 * j + q] - P->x[3 * i + q];
                a += d[q] * n[q];
            }
            for (int q = 0; q < 3; q++)
                b += pow(d[q] - a * n[q], 2);
            if (b < 0.25 * s->dp * s->dp && a > 0) {
                depth = fmax(depth, a);
                step = fmin(step, a);
            }
        }
        bad += depth < (need - 0.5) * s->dp
               && !(depth > 0 && depth + step > s->re_max);
    }
    return bad;
}

int mps_check_setup(const struct mps_solver *s, double dt, int adjustable,
                    double max_co)
{
    const struct mps_settings *S = &s->S;
    const double radii[3] = { S->re_n, S->re_grad, S->re_lap };
    const char *names[3] = { "numberDensity", "gradient", "laplacian" };
    for (int k = 0; k < 3; k++)
        if (radii[k] < 2.0)
            return sim_error(SIM_ERR_INPUT, "system/mpsSchemes: r_e of the "
                             "%s operator is %g dp; the lattice needs at "
                             "least 2 dp (2.1 is the usual choice)",
                             names[k], radii[k]);
    double H = fluid_height(&s->P), g = gnorm(S);
    double uff = sqrt(2 * g * H);
    log_info("Stability: fluid height %g m, free-fall speed %g m/s, "
             "viscous limit dt <= %g s", H, uff,
             0.2 * s->dp * s->dp / nu_max(S));
    if (!adjustable) {
        double co = uff * dt / s->dp, dtv = 0.2 * s->dp * s->dp / nu_max(S);
        log_info("Stability: deltaT %g s gives Courant number %.3g at the "
                 "free-fall speed", dt, co);
        if (dt > dtv)
            return sim_error(SIM_ERR_INPUT, "system/controlDict: deltaT %g s "
                             "exceeds the viscous limit 0.2 dp^2/nu = %g s",
                             dt, dtv);
        if (co > 1.0)
            return sim_error(SIM_ERR_INPUT, "system/controlDict: deltaT %g s "
                             "gives a Courant number %.3g > 1 at the "
                             "free-fall speed %.3g m/s of the %.3g m fluid "
                             "column; use deltaT <= %.3g s or adjustTimeStep "
                             "yes", dt, co, uff, H, max_co * s->dp / uff);
        if (co > max_co)
            log_warn("deltaT %g s gives a Courant number %.3g > maxCo %g at "
                     "the free-fall speed", dt, co, max_co);
    }
    int bad = s->n_thin_walls;
    if (bad)
        log_warn("%d wall particle(s) have fewer than %d wall/dummy layers "
                 "behind them: the number density near them is too low "
                 "for r_e = %g m (add dummy layers in system/particleDict)",
                 bad, (int)ceil(s->re_max / s->dp - 1e-9) - 1, s->re_max);
    return SIM_OK;
}

int mps_check_finite(const struct mps_solver *s)
{
    const struct mps_particles *P = &s->P;
    const char *field;
    int bad = pop_first_nonfinite(P->n, P->p, P->u, P->x, &field);
    if (bad < 0)
        return SIM_OK;
    static const char *tn[] = { "fluid", "wall", "dummy" };
    int t = P->type[bad];
    return sim_error(SIM_ERR_NUMERIC, "step %ld: non-finite %s at particle "
                     "id %lld (%s, index %d) near (%g %g %g)", s->step, field,
                     (long long)P->id[bad], t >= 0 && t <= 2 ? tn[t] : "?",
                     bad, P->x[3 * bad], P->x[3 * bad + 1], P->x[3 * bad + 2]);
}
