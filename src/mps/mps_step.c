/*
 * mps_step.c — one MPS time step m -> m+1 (Xie et al. 2025; doc/theory.md
 * A.10 steps 1 and 7-11 with eps = 1, no grains):
 *
 *   1. neighbour search (cells of the largest r_e; CSR list; renumbering)
 *      [coupled, optional: water content traded towards a uniform phi/eps,
 *      volume_exchange.c]
 *      [soil particles: the solid model's friction and drag, and the
 *      drag's reaction on the water, as accelerations added in step 7;
 *      the soil's own viscosity, or the viscoplastic soil's implicit one
 *      after step 7; rho_0/rho_i in the PPE and the correction
 *      (soil/soil_step.c, doc/theory.md K)]
 *   7. prediction    u* = u^m + dt (nu <lap u^m> + g + f_ext)     eq. (10)
 *      [optional collision model on u*; optional predictor r* = r + dt u*
 *      at which the PPE and the gradient are evaluated (Koshizuka 1996)]
 *   8. <n^m> (eq. 7) and free-surface flags (eqs. 14-16)
 *   9. PPE (10)+(12), P = 0 on the free surface               (ppe.c)
 *  10. correction    u^{m+1} = u* - (dt/rho) <grad P^{m+1}>       eq. (8)
 *  11. r^{m+1} = r^m + dt u^{m+1}   [optional shifting]
 *
 * Wall and dummy particles keep their velocity: 0 (fixed, no-slip walls,
 * A.9), or that of their patch's prescribed motion, set with the removal
 * of removed patches before step 1 and followed by the move after step 11
 * (walls.c). The coupling hooks inv_eps and f_ext are used when non-NULL.
 */
#include <math.h>
#include <omp.h>
#include <string.h>

#include "core/error.h"
#include "mps/mps.h"
#include "mps/mps_impl.h"
#include "mps/operators.h"
#include "mps/soil/soil.h"
#include "mps/soil/soil_step.h"
#include "mps/stabiliser/stabiliser.h"

static void predict(struct mps_solver *s, double dt)
{
    struct mps_particles *P = &s->P;
    const struct mps_settings *S = &s->S;
    for (int i = 0; i < P->n; i++)
        s->rows_fluid[i] = P->type[i] == MPS_FLUID;
    const struct pop_weights Wl = mps_w(s, MPS_W_L);
    mps_laplacian(&s->nl, &Wl, P->dim, s->Ll.n0, s->Ll.lambda, 3, P->u,
                  P->inv_eps, s->rows_fluid, s->lap);
    const double *fe = P->f_ext;
    const double *sa = s->soil ? s->soil->acc : NULL;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++) {
        const double nu = sa ? mps_soil_viscosity(s, i) : S->nu;
        for (int q = 0; q < 3; q++) {
            double a = 0;
            if (P->type[i] == MPS_FLUID) {
                a = nu * s->lap[3 * i + q] + S->g[q]
                  + (fe ? fe[3 * i + q] : 0.0);
                if (sa)
                    a += sa[3 * i + q];
            }
            s->ustar[3 * i + q] = P->u[3 * i + q] + dt * a;
        }
    }
    if (P->dim == 2)
        for (int i = 0; i < P->n; i++)
            s->ustar[3 * i + 2] = 0;
}

/* Koshizuka and Oka (1996) predictor: move fluid particles to
 * r* = r + dt u* and re-measure every pair of the list there, so that the
 * number density of the PPE source sees the compression the explicit step
 * would cause. */
static int predict_positions(struct mps_solver *s, double dt, double sign)
{
    struct mps_particles *P = &s->P;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++)
        if (P->type[i] == MPS_FLUID)
            for (int q = 0; q < 3; q++)
                P->x[3 * i + q] += sign * dt * s->ustar[3 * i + q];
    if (sign < 0)
        return SIM_OK;
    TRY(neighbour_update(&s->nl, P->x));   /* from the candidates (skin) */
    return mps_weights(s);
}

static void density(struct mps_solver *s)
{
    struct mps_particles *P = &s->P;
    const struct neighbour_list in = neighbour_inner(&s->nl);
    const struct pop_weights Wn = mps_w(s, MPS_W_N);
    mps_number_density(&in, &Wn, P->inv_eps, NULL, P->nd);
    const double inv_n0 = 1.0 / s->Ln.n0;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++)
        P->nd[i] *= inv_n0;
    mps_free_surface(s);
}

/* <grad P>_i of the fluid rows into s->grad, with the selected form */
static void pressure_gradient(struct mps_solver *s)
{
    struct mps_particles *P = &s->P;
    const struct neighbour_list in = neighbour_inner(&s->nl);
    const struct pop_weights Wg = mps_w(s, MPS_W_G);
    if (s->S.gradient == MPS_GRAD_CORRECTED)
        mps_gradient_corrected(&in, &Wg, P->dim, s->Lg.n0, P->x, P->p,
                               P->inv_eps, s->rows_fluid, s->grad);
    else if (s->S.gradient == MPS_GRAD_PMIN)
        mps_gradient_pmin(&in, &Wg, P->dim, s->Lg.n0, P->x, P->p,
                          P->inv_eps, s->rows_fluid, s->grad);
    else
        mps_gradient(&in, &Wg, P->dim, s->Lg.n0, P->x, P->p,
                     P->inv_eps, s->rows_fluid, s->grad);
}

/* dt/rho_i of eq. (8) for fluid particle i: dt/rho_0, times 1/eps_i
 * (Model B, eq. 5) and rho_0/rho_i (soil) */
static double correction_factor(const struct mps_solver *s, int i, double dt)
{
    const double *cs = s->P.corr_scale;
    const double *rr = s->soil ? s->soil->ratio : NULL;
    double c = dt / s->S.rho;
    if (cs)
        c *= cs[i];
    if (rr)
        c *= rr[i];
    return c;
}

static void correct(struct mps_solver *s, double dt)
{
    struct mps_particles *P = &s->P;
    pressure_gradient(s);
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++) {
        const double c = correction_factor(s, i, dt);
        for (int q = 0; q < 3; q++)
            P->u[3 * i + q] = P->type[i] == MPS_FLUID
                            ? s->ustar[3 * i + q] - c * s->grad[3 * i + q]
                            : P->u[3 * i + q];
    }
}

/* The viscoplastic soil's implicit viscous step (soil/soil_step.c) in
 * incremental form (doc/theory.md K0-14): on u* less the correction of the
 * last step's pressure, which is added back after. Without it the stiff
 * viscosity ties the soil to the walls within the step and carries its
 * weight there, before the PPE sees it: a resting layer lost 73 % of its
 * hydrostatic pressure and its friction with it. s->lap is free after the
 * prediction. */
static int soil_viscous(struct mps_solver *s, double dt)
{
    if (!mps_soil_implicit_wanted(s))
        return SIM_OK;
    struct mps_particles *P = &s->P;
    double *v = s->lap;
    pressure_gradient(s);
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++) {
        const double c = P->type[i] == MPS_FLUID ? correction_factor(s, i, dt)
                                                 : 0.0;
        for (int q = 0; q < 3; q++)
            v[3 * i + q] = s->ustar[3 * i + q] - c * s->grad[3 * i + q];
    }
    TRY(mps_soil_implicit(s, dt, v));
    const uint8_t *role = s->soil->role;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++)
        if (role[i] == SOIL_SOIL) {
            const double c = correction_factor(s, i, dt);
            for (int q = 0; q < P->dim; q++)
                s->ustar[3 * i + q] = v[3 * i + q] + c * s->grad[3 * i + q];
        }
    return SIM_OK;
}

static void move(struct mps_solver *s, double dt)
{
    struct mps_particles *P = &s->P;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++)
        if (P->type[i] == MPS_FLUID)
            for (int q = 0; q < 3; q++)
                P->x[3 * i + q] += dt * P->u[3 * i + q];
    mps_walls_move(s);
}

int mps_step(struct mps_solver *s, double dt)
{
    double t0 = omp_get_wtime();
    TRY(mps_check_finite(s));     /* state handed in from outside */
    s->dt_last = dt;
    TRY(mps_walls_begin_step(s, dt));
    TRY(mps_halo_prepare(s));
    TRY(mps_neighbours(s));
    double t1 = omp_get_wtime();
    TRY(mps_volume_exchange(s, dt));
    if (s->soil) {
        mps_soil_begin(s);
        TRY(mps_soil_forces(s));
    }
    predict(s, dt);
    TRY(soil_viscous(s, dt));
    TRY(mps_halo_refresh(s, s->ustar, 3 * sizeof *s->ustar));
    if (s->S.collision != &mps_stabiliser_none) {
        TRY(s->S.collision->apply(s, dt));
        TRY(mps_halo_refresh(s, s->ustar, 3 * sizeof *s->ustar));
    }
    if (s->S.predictor)
        TRY(predict_positions(s, dt, 1.0));
    density(s);
    TRY(mps_halo_refresh(s, s->P.nd, sizeof *s->P.nd));
    TRY(mps_halo_refresh(s, s->P.fs, sizeof *s->P.fs));
    double t2 = omp_get_wtime();
    TRY(mps_ppe_solve(s, dt));
    double t3 = omp_get_wtime();
    if (s->S.clip_negative)
        for (int i = 0; i < s->P.n; i++)
            s->P.p[i] = fmax(s->P.p[i], 0.0);
    TRY(mps_dummy_pressure(s));
    TRY(mps_halo_refresh(s, s->P.p, sizeof *s->P.p));
    correct(s, dt);
    if (s->S.predictor)
        predict_positions(s, dt, -1.0);   /* back to r^m, then r^m + dt u */
    move(s, dt);
    if (s->S.shifting != &mps_stabiliser_none)   /* it reads r_j */
        TRY(mps_halo_refresh(s, s->P.x, 3 * sizeof *s->P.x));
    TRY(s->S.shifting->apply(s, dt));
    if (s->soil)
        mps_soil_end(s, dt);
    /* a ghost's row misses neighbours beyond the halo: the ghosts leave
     * the step at their owners' positions and velocities, which the
     * coupling reads between steps and the next step's rows */
    TRY(mps_halo_refresh(s, s->P.x, 3 * sizeof *s->P.x));
    TRY(mps_halo_refresh(s, s->P.u, 3 * sizeof *s->P.u));
    double t4 = omp_get_wtime();
    s->t.neighbours += t1 - t0;
    s->t.explicit_ += t2 - t1;
    s->t.correction += t4 - t3;
    s->t.steps++;
    s->step++;
    s->time += dt;
    return mps_check_finite(s);
}
