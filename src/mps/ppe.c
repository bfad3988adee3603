/*
 * ppe.c — the pressure Poisson equation with the mixed source term
 * (Xie et al. 2025 eq. 12, Model A form with eps = 1; doc/theory.md A.4):
 *
 *   <lap P^{m+1}>_i = (1 - gamma) (rho/dt) <div u*>_i
 *                     - gamma (rho/dt^2) (<n^m>_i - n0)/n0
 *
 * with the Laplacian (10) over fluid and wall particles (dummies only fill
 * the number density), the divergence (9) on the gradient radius, and <n^m>
 * at the current positions (A0-05: no predictor position update).
 * Unknowns are the fluid and wall particles that are neither free surface
 * nor dry wall; those carry the Dirichlet value P = 0 and drop out (with
 * `freeSurface { pressure extrapolated; }` surface particles carry the
 * value of surface_pressure.c instead, moved to the right-hand side).
 * We solve A p = b with A = -lap (SPD M-matrix for eps = 1), so
 *   A_ii = c sum_j w_ij/eps_j,  A_ij = -c w_ij/eps_j (j unknown),
 *   c = 2d/(n0 lambda),  b_i = -RHS_i.
 * With porosity the matrix becomes non-symmetric (A.4 [P]); select
 * bicgstab then. `porousLaplacian symmetric` takes the pair weight
 * 2/(eps_i + eps_j) instead of 1/eps_j (doc/theory.md A.4, the optional
 * symmetric variant): A stays SPD and PCG applies, at half the cost per
 * iteration of BiCGSTAB's two products. The two agree where eps varies
 * slowly over r_e. The warm start is the pressure of the previous step.
 * With soil particles (doc/theory.md K0-01) every pair term also carries
 * the harmonic mean 2 r_i r_j/(r_i + r_j) of r = rho_0/rho: the
 * multi-density div((rho_0/rho) grad P) (soil/soil_step.c).
 * Coupling hooks: ppe_scale s_i multiplies the source (Model B: eps_i,
 * eq. 13); with scaled_divergence set the divergence term is
 * <div(s u*)>_i instead and s_i multiplies the density term only (A0-04
 * (b), models.c).
 */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "core/log.h"
#include "linsolve/csr.h"
#include "mps/mps.h"
#include "mps/mps_impl.h"
#include "mps/soil/soil_step.h"
#include "mps/surface_pressure.h"
#include "particles/operators/matrix.h"

/* Number unknowns; rows_ppe marks fluid and wall rows (for div u*). */
static int number_unknowns(struct mps_solver *s)
{
    struct mps_particles *P = &s->P;
    int m = 0;
    for (int i = 0; i < P->n; i++) {
        int inside = P->type[i] != MPS_DUMMY;
        s->rows_ppe[i] = (uint8_t)inside;
        s->unk[i] = (inside && P->fs[i] == MPS_INNER) ? m++ : -1;
    }
    return m;
}

/* Pressure of the rows that drop out: 0 (dry walls; surface particles by
 * default) or the extrapolated surface value (surface_pressure.c). */
static int dirichlet_values(struct mps_solver *s)
{
    struct mps_particles *P = &s->P;
    if (s->S.fs_pressure == MPS_FS_P_EXTRAPOLATED)
        TRY(mps_surface_pressure(s));
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++)
        if (P->type[i] != MPS_DUMMY && s->unk[i] < 0
            && !(P->type[i] == MPS_FLUID && P->fs[i] == MPS_SURFACE
                 && s->S.fs_pressure == MPS_FS_P_EXTRAPOLATED))
            P->p[i] = 0;
    return SIM_OK;
}

static int assemble(struct mps_solver *s, int m)
{
    const struct mps_particles *P = &s->P;
    const struct neighbour_list *nl = &s->nl;
    const struct pop_weights W = mps_w(s, MPS_W_L);
    const double *ie = P->inv_eps;
    const double *rr = s->soil ? s->soil->ratio : NULL; /* rho_0/rho */
    const double c = 2.0 * P->dim / (s->Ll.n0 * s->Ll.lambda);
    const int sym = s->S.porous_symmetric;
    int64_t *rp = s->A.rowptr;
    /* pass 1: row lengths (diagonal + unknown neighbours); dummies are
     * never unknowns, so the pattern needs no type test */
    pop_matrix_rowptr(nl, P->n, &W, s->unk, m, rp);
    TRY(csr_reserve(&s->A, &s->cap_nnz, rp[m]));
    s->A.n = m;
    s->A.nnz = rp[m];
    /* pass 2: values; the diagonal first in each row */
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++) {
        int r = s->unk[i];
        if (r < 0)
            continue;
        int64_t pos = rp[r] + 1;
        double diag = 0, bd = 0;
        const int64_t k0 = nl->start[i], k1 = nl->start[i + 1];
        const double *w = pop_weights_of(&W, nl, i, k0, k1);
        for (int64_t k = k0; k < k1; k++) {
            int j = nl->j[k];
            if (w[k - k0] == 0 || P->type[j] == MPS_DUMMY)
                continue;
            /* inv_eps holds phi/eps: the pair weight 2/(eps_i + eps_j) in
             * those terms is the harmonic mean of the two values */
            double a = c * w[k - k0] * (!ie ? 1.0
                                   : sym ? 2.0 * ie[i] * ie[j] / (ie[i] + ie[j])
                                         : ie[j]);
            if (rr) /* multi-density: harmonic mean of rho_0/rho */
                a *= 2.0 * rr[i] * rr[j] / (rr[i] + rr[j]);
            diag += a;
            if (s->unk[j] >= 0) {
                s->A.col[pos] = s->unk[j];
                s->A.val[pos++] = -a;
            } else {
                bd += a * P->p[j];      /* Dirichlet neighbour */
            }
        }
        s->b[r] = bd;
        s->A.col[rp[r]] = r;
        /* A row with no fluid/wall neighbour cannot happen for an inner
         * particle (n >= beta n0); keep the matrix regular anyway. */
        s->A.val[rp[r]] = diag > 0 ? diag : 1.0;
    }
    return SIM_OK;
}

static void source(struct mps_solver *s, double dt)
{
    const struct mps_particles *P = &s->P;
    const double g = s->S.gamma, rho = s->S.rho;
    const struct neighbour_list in = neighbour_inner(&s->nl);
    const double *u = s->ustar, *sc = P->ppe_scale;
    const int dw = s->S.scaled_divergence && sc;
    if (dw) {
        /* the prediction is done with lap: s u* goes there */
        double *su = s->lap;
#pragma omp parallel for schedule(static)
        for (int i = 0; i < P->n; i++)
            for (int q = 0; q < 3; q++)
                su[3 * i + q] = sc[i] * s->ustar[3 * i + q];
        u = su;
    }
    const struct pop_weights Wg = mps_w(s, MPS_W_G);
    mps_divergence(&in, &Wg, P->dim, s->Lg.n0, P->x, u, P->inv_eps,
                   s->rows_ppe, s->div);
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++) {
        int r = s->unk[i];
        if (r < 0)
            continue;
        double dn = P->nd[i] - 1.0;
        double sd = sc ? sc[i] : 1.0; /* B: eps_i (13) */
        double rhs = dw ? (1 - g) * rho / dt * s->div[i]
                          - g * rho / (dt * dt) * dn * sd
                        : ((1 - g) * rho / dt * s->div[i]
                           - g * rho / (dt * dt) * dn) * sd;
        s->b[r] -= rhs;
        s->sol[r] = P->p[i];
    }
}

/* A distributed run's solve (mps_halo.c): the own unknowns, numbered
 * first, offset by the ranks before; columns made global. */
static int solve_distributed(struct mps_solver *s, int *m_own)
{
    struct pop_halo *h = s->halo;
    const int own = h->n_own, n = s->P.n;
    int mo = 0;
    for (int i = 0; i < own; i++)
        mo += s->unk[i] >= 0;
    *m_own = mo;
    int64_t total;
    const int64_t row0 = h->ops->exscan(h, mo, &total);
    if (total > INT32_MAX)
        return sim_error(SIM_ERR_INPUT, "PPE: %lld unknowns exceed the "
                         "32-bit column numbers", (long long)total);
    for (int i = 0; i < own; i++)
        s->gunk[i] = s->unk[i] >= 0 ? row0 + s->unk[i] : -1;
    TRY(mps_halo_refresh(s, s->gunk, sizeof *s->gunk));
    for (int i = 0; i < n; i++)
        if (s->unk[i] >= 0)
            s->gcol[s->unk[i]] = (int32_t)s->gunk[i];
    struct csr_matrix A = s->A;
    A.n = mo;
    A.nnz = s->A.rowptr[mo];
    for (int64_t k = 0; k < A.nnz; k++)
        A.col[k] = s->gcol[A.col[k]];
    return h->ops->solve(h, s->ls, &A, row0, total, s->b, s->sol, &s->last);
}

int mps_ppe_solve(struct mps_solver *s, double dt)
{
    struct mps_particles *P = &s->P;
    double t0 = omp_get_wtime();
    int m = number_unknowns(s);
    TRY(dirichlet_values(s));
    TRY(assemble(s, m));
    source(s, dt);
    double t1 = omp_get_wtime();
    s->t.assembly += t1 - t0;
    int rc = SIM_OK;
    if (s->halo)
        rc = solve_distributed(s, &m);   /* collective, even for m = 0 */
    else if (m > 0)
        rc = linsolve_solve(s->ls, &s->A, s->b, s->sol, &s->last);
    else
        memset(&s->last, 0, sizeof s->last);
    s->t.ppe += omp_get_wtime() - t1;
    s->t.ppe_iters += s->last.iters;
    s->t.ppe_setup += s->last.setup_s;
    s->t.ppe_solve += s->last.solve_s;
    s->t.ppe_row_iters += (double)s->last.iters * m;
    s->t.ppe_nnz_iters += (double)s->last.iters * (double)s->A.rowptr[m];
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++)
        if (P->type[i] != MPS_DUMMY)
            if (s->unk[i] >= 0)
                P->p[i] = s->sol[s->unk[i]];
    if (!rc)
        rc = mps_halo_refresh(s, P->p, sizeof *P->p);
    if (rc) {
        char why[512];
        snprintf(why, sizeof why, "%s", sim_error_message());
        return sim_error(rc, "step %ld: the pressure Poisson equation (%d "
                         "unknowns) failed: %s", s->step, m, why);
    }
    return SIM_OK;
}
