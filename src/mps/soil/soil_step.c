/*
 * soil_step.c — soil particles in the MPS step (doc/theory.md K.2, K0-01):
 * the fluid solver's particles with phase 1 are soil, of density rho_s.
 *
 *   solid model (eq. 9):  Du/Dt = -(1/rho_s) grad P + (F_f + F_d)/rho_s + g
 *       no viscous term; F_f from soil_friction (eqs. 10-14, with the
 *       column weights of eq. 13), F_d from soil_drag (K.1), whose
 *       reaction accelerates the water (dragReaction yes)
 *   liquid model:         Du/Dt = -(1/rho_s) grad P + nu_s lap u + g
 *       a second fluid with its own viscosity
 *
 * Both models make the PPE a multi-density one, div((1/rho) grad P) =
 * (1/dt) div u* (times rho_0, the water's density, so that a case
 * without soil has the single-density matrix): every pair term of the
 * Laplacian carries the harmonic mean 2 r_i r_j/(r_i + r_j) of
 * r = rho_0/rho (1 for water and walls), and the correction of particle i
 * is -(dt/rho_0) r_i grad P. The acceleration of the last step, which the
 * friction (10) reads, is (u^{m+1} - u^m)/dt of every particle less the
 * friction's own F_f/rho (K0-10; `frictionLoad total` keeps it); it is a
 * field of fluid.vtu, so that a restart goes on with it.
 *
 * Not yet multi-density: the wall and dummy pressure extrapolated from
 * the fluid (walls.c, dummyPressure extrapolated) uses the water's density
 * beside soil too (each neighbour's own density was tried, 2026-11-27:
 * E5-02 L2 0.125 instead of 0.021 in soilLayerStill, not kept). The
 * collision model weighs each pair by the densities (s->soil->rho).
 */
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "mps/mps.h"
#include "mps/soil/soil.h"
#include "mps/soil/soil_step.h"

int mps_soil_init(struct mps_solver *s)
{
    if (!s->S.soil || !s->P.phase)
        return SIM_OK;
    struct mps_soil *m = sim_calloc(1, sizeof *m);
    if (!m)
        return SIM_ERR_NOMEM;
    s->soil = m;
    size_t c = (size_t)s->P.cap;
    m->role = sim_calloc(c, 1);
    m->ratio = sim_calloc(c, sizeof *m->ratio);
    m->rho = sim_calloc(c, sizeof *m->rho);
    m->p_h = sim_calloc(c, sizeof *m->p_h);
    m->S = sim_calloc(c, sizeof *m->S);
    m->F = sim_calloc(3 * c, sizeof *m->F);
    m->Fd = sim_calloc(3 * c, sizeof *m->Fd);
    m->acc = sim_calloc(3 * c, sizeof *m->acc);
    m->u_old = sim_calloc(3 * c, sizeof *m->u_old);
    if (!m->role || !m->ratio || !m->rho || !m->p_h || !m->S || !m->F
        || !m->Fd || !m->acc || !m->u_old)
        return SIM_ERR_NOMEM;
    return SIM_OK;
}

void mps_soil_free(struct mps_solver *s)
{
    struct mps_soil *m = s->soil;
    if (!m)
        return;
    free(m->role); free(m->ratio); free(m->rho); free(m->p_h); free(m->S);
    free(m->F); free(m->Fd); free(m->acc); free(m->u_old);
    free(m);
    s->soil = NULL;
}

void mps_soil_begin(struct mps_solver *s)
{
    struct mps_soil *m = s->soil;
    const struct mps_particles *P = &s->P;
    const double rho0 = s->S.rho, rho_s = s->S.soil->rho;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++) {
        int soil = P->type[i] == MPS_FLUID && P->phase[i] == 1;
        m->role[i] = P->type[i] == MPS_FLUID ? (soil ? SOIL_SOIL : SOIL_FLUID)
                   : P->type[i] == MPS_WALL ? SOIL_WALL : SOIL_OTHER;
        m->rho[i] = soil ? rho_s : rho0;
        m->ratio[i] = soil ? rho0 / rho_s : 1.0;
        for (int q = 0; q < 3; q++)
            m->u_old[3 * i + q] = P->u[3 * i + q];
    }
}

int mps_soil_forces(struct mps_solver *s)
{
    struct mps_soil *m = s->soil;
    const struct mps_particles *P = &s->P;
    const struct soil_props *sp = s->S.soil;
    memset(m->acc, 0, 3 * (size_t)P->n * sizeof *m->acc);
    if (sp->model != SOIL_MODEL_SOLID)
        return SIM_OK;
    const double gz = -s->S.g[P->dim == 2 ? 1 : 2];
    TRY(soil_column_weight(P->n, P->dim, P->x, m->role, m->rho, gz,
                           sp->column_half_width * s->dp, m->p_h));
    const struct soil_friction_params fp = {
        .mu = sp->mu, .kernel_weight = sp->kernel_weight, .cap = sp->cap,
        .dt = s->dt_last, .n0 = s->Ln.n0 };
    soil_friction(&fp, P->dim, &s->nl, s->w_n, P->x, P->u, P->accel, m->rho,
                  m->p_h, m->role, m->F);
    const struct soil_drag_params dp = {
        .cd = sp->cd, .rho_f = s->S.rho, .l0 = s->dp, .n0 = s->Ln.n0 };
    soil_drag(&dp, &s->nl, s->w_n, P->u, m->role, m->Fd,
              sp->drag_reaction ? m->acc : NULL, m->S);
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++)
        if (m->role[i] == SOIL_SOIL)
            for (int q = 0; q < 3; q++)
                m->acc[3 * i + q] = (m->F[3 * i + q] + m->Fd[3 * i + q])
                                  / m->rho[i];
    return SIM_OK;
}

double mps_soil_viscosity(const struct mps_solver *s, int i)
{
    if (s->P.phase[i] != 1)
        return s->S.nu;
    return s->S.soil->model == SOIL_MODEL_LIQUID ? s->S.soil->nu : 0.0;
}

void mps_soil_end(struct mps_solver *s, double dt)
{
    struct mps_soil *m = s->soil;
    struct mps_particles *P = &s->P;
    /* K0-10: the friction's own part is not a normal load; fed back, it
     * makes a loop of gain ~2 mu (> 1 for sand) */
    const int total = s->S.soil->model != SOIL_MODEL_SOLID
                   || s->S.soil->load_total;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++)
        for (int q = 0; q < 3; q++)
            P->accel[3 * i + q] = (P->u[3 * i + q] - m->u_old[3 * i + q]) / dt
                                - (total ? 0.0 : m->F[3 * i + q] / m->rho[i]);
}
