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
 *   viscoplastic model:   Du/Dt = -(1/rho_s) grad P + div(2 nu(p, D) D) + g
 *       the Drucker-Prager yield stress as a viscosity, implicit
 *       (soil_viscoplastic.c, K.6)
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
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "linsolve/csr.h"
#include "mps/mps.h"
#include "mps/soil/soil.h"
#include "mps/soil/soil_step.h"
#include "particles/operators/matrix.h"
#include "particles/operators/operators.h"

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
    if (s->S.soil->model != SOIL_MODEL_VISCOPLASTIC)
        return SIM_OK;
    m->nu = sim_calloc(c, sizeof *m->nu);
    m->nu_w = sim_calloc(c, sizeof *m->nu_w);
    m->unk = sim_calloc(c, sizeof *m->unk);
    m->A.rowptr = sim_calloc(c + 1, sizeof *m->A.rowptr);
    m->b = sim_calloc(3 * c, sizeof *m->b);
    m->rhs = sim_calloc(c, sizeof *m->rhs);
    m->sol = sim_calloc(c, sizeof *m->sol);
    if (!m->nu || !m->nu_w || !m->unk || !m->A.rowptr || !m->b || !m->rhs || !m->sol)
        return SIM_ERR_NOMEM;
    /* K0-11: the velocities to 1e-10 of the right-hand side, far below
     * the PPE's error */
    return linsolve_create_named("pcg", "jacobi", 1e-10, 100000, &m->ls);
}

void mps_soil_free(struct mps_solver *s)
{
    struct mps_soil *m = s->soil;
    if (!m)
        return;
    free(m->role); free(m->ratio); free(m->rho); free(m->p_h); free(m->S);
    free(m->F); free(m->Fd); free(m->acc); free(m->u_old);
    free(m->nu); free(m->nu_w); free(m->unk); free(m->A.rowptr); free(m->A.col);
    free(m->A.val); free(m->b); free(m->rhs); free(m->sol);
    if (m->ls)
        linsolve_free(m->ls);
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
    /* the soil's share of the load on a wall particle: that of its fluid
     * neighbours within the number-density radius, by their weights */
    const struct neighbour_list *nl = &s->nl;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++) {
        if (P->type[i] != MPS_WALL) {
            P->soil_frac[i] = m->role[i] == SOIL_SOIL;
            continue;
        }
        double ws = 0, wf = 0;
        for (int64_t k = nl->start[i]; k < nl->start[i + 1]; k++) {
            const int j = nl->j[k];
            if (P->type[j] != MPS_FLUID)
                continue;
            wf += s->w_n[k];
            if (P->phase[j] == 1)
                ws += s->w_n[k];
        }
        P->soil_frac[i] = wf > 0 ? ws / wf : 0.0;
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

/*
 * K0-12: the pressure p' of the yield stress, into m->S. An inner particle
 * has the PPE's pressure of the last step (the mean stress of the
 * incompressible soil). A surface particle has only the Dirichlet value,
 * which is ~0 for every particle of a sheet a few particles thick: its
 * sliding layer would have no strength at all. It takes instead the
 * larger of that value and the infinite-slope normal stress under the
 * soil above it: rho_s |g| d cos(theta_g), d = h cos(theta_z) the depth
 * normal to the surface, h the soil column above along the vertical axis
 * (y in 2-D, z in 3-D; eq. 13's p_h l0 plus half a spacing), theta_g and
 * theta_z the angles of the inward surface vector F (eq. 15) to gravity
 * and to the downward axis. With gravity along the axis that is
 * rho_s |g| h cos^2(theta): a flat top carries the weight of the soil
 * above, a vertical face nothing (its horizontal stress is zero).
 */
static int yield_pressure(struct mps_solver *s)
{
    struct mps_soil *m = s->soil;
    const struct mps_particles *P = &s->P;
    const double *g = s->S.g;
    const double gm = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    TRY(soil_column_weight(P->n, P->dim, P->x, m->role, m->rho, gm,
                           s->S.soil->column_half_width * s->dp, m->p_h));
    const struct neighbour_list in = neighbour_inner(&s->nl);
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++) {
        m->S[i] = P->p[i];
        if (m->role[i] != SOIL_SOIL || P->fs[i] != MPS_SURFACE || gm == 0)
            continue;
        double F[3];
        pop_surface_vector_row(&in, POP_STORED(s->w_n), P->x, P->inv_eps, i,
                               F);
        const double f = sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]);
        double cg = 1.0, cz = 1.0;
        if (f > 0) {
            cg = fmax(0.0, (F[0] * g[0] + F[1] * g[1] + F[2] * g[2])
                           / (f * gm));
            cz = fmax(0.0, -F[P->dim == 2 ? 1 : 2] / f);
        }
        const double h = (m->p_h[i] + 0.5 * m->rho[i] * gm) * s->dp;
        m->S[i] = fmax(P->p[i], h * cz * cg);
    }
    return SIM_OK;
}

int mps_soil_implicit_wanted(const struct mps_solver *s)
{
    return s->soil && s->S.soil->model == SOIL_MODEL_VISCOPLASTIC;
}

const int32_t *mps_soil_unshifted(const struct mps_solver *s)
{
    return mps_soil_implicit_wanted(s) ? s->P.phase : NULL;
}

int mps_soil_implicit(struct mps_solver *s, double dt, double *v)
{
    struct mps_soil *m = s->soil;
    const struct soil_props *sp = s->S.soil;
    const struct mps_particles *P = &s->P;
    const double *g = s->S.g;
    const double gm = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    const struct soil_vp_params vp = {
        .mu = sp->mu, .cohesion = sp->cohesion, .rho = sp->rho,
        .nu_max = sp->nu_max,
        .p_wall = 0.5 * sp->rho * gm * s->dp };
    TRY(yield_pressure(s));
    soil_vp_viscosity(&vp, P->dim, &s->nl, s->w_l, s->Ll.n0, P->x, P->u,
                      m->S, m->role, m->nu, m->nu_w);
    int n = 0;
    for (int i = 0; i < P->n; i++)
        m->unk[i] = m->role[i] == SOIL_SOIL ? n++ : -1;
    if (n == 0)
        return SIM_OK;
    const int64_t nnz = pop_matrix_rowptr(&s->nl, P->n, POP_STORED(s->w_l),
                                          m->unk, n, m->A.rowptr);
    TRY(csr_reserve(&m->A, &m->cap_nnz, nnz));
    m->A.n = n;
    m->A.nnz = nnz;
    const double c_dt = dt * 2.0 * P->dim / (s->Ll.n0 * s->Ll.lambda);
    soil_vp_system(&s->nl, s->w_l, c_dt, s->S.nu, m->nu, m->nu_w, m->role,
                   m->unk, v, P->normal, m->A.rowptr, m->A.col, m->A.val,
                   m->b);
    for (int q = 0; q < P->dim; q++) {
        for (int i = 0; i < P->n; i++)
            if (m->unk[i] >= 0) {
                m->rhs[m->unk[i]] = m->b[3 * (size_t)m->unk[i] + q];
                m->sol[m->unk[i]] = v[3 * i + q];
            }
        struct linsolve_stats st;
        int rc = linsolve_solve(m->ls, &m->A, m->rhs, m->sol, &st);
        if (rc)
            return sim_error(rc, "step %ld: the soil's implicit viscous step "
                             "(%d unknowns, component %d) failed",
                             s->step, n, q);
        for (int i = 0; i < P->n; i++)
            if (m->unk[i] >= 0)
                v[3 * i + q] = m->sol[m->unk[i]];
    }
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
