/*
 * walls.c — wall and dummy particles (doc/theory.md A.9, after Koshizuka et
 * al. 1998 and MLParticle-SJTU practice):
 *
 *   - wall particles (one layer) are unknowns of the PPE, have the wall
 *     velocity (0: fixed walls) and are never free surface;
 *   - dummy particles (ceil(r_e/dp) - 1 layers behind) only complete the
 *     number density and the neighbour sums; their pressure is that of the
 *     nearest wall particle (A.9 default; `dummyPressure zero;` gives the
 *     Koshizuka original p = 0), so that the (p_i + p_j) gradient (eq. 8)
 *     holds the fluid off the wall;
 *   - `dummyPressure extrapolated;` instead sets, after the PPE, the
 *     pressure of every wall and dummy particle with fluid neighbours
 *     (gradient radius) from them, as in Adami, Hu and Adams (2012,
 *     J. Comput. Phys. 231, 7057, eq. 27, fixed wall):
 *       p_w = sum_f (p_f + rho g.(r_w - r_f)) w_wf / sum_f w_wf
 *     (the PPE still solves the wall rows: they keep the fluid from
 *     entering the wall; only the gradient and the loads see p_w). A
 *     hydrostatic field then stays linear across the wall, so that a
 *     first-order consistent gradient (pressureGradient corrected) feels
 *     no wall force in still water, and a wall particle beside the free
 *     surface carries the surface pressure instead of the 0 of a dry or
 *     the suction of a half-empty PPE row. Dummies out of reach of the
 *     fluid take their partner's value plus rho g.(r_dummy - r_wall);
 *   - the load on a patch is F = sum_i p_i dp^(d-1) n_i over its wall
 *     particles, n_i the unit normal from the fluid into the solid
 *     (A.9 [P]); in 2-D it is per unit depth [N/m]. Known bias: the wall
 *     layer lies dp/2 inside the solid, so its pressure exceeds that of
 *     the face by rho g dp/2, and edge/corner particles (diagonal normals)
 *     add about 0.7 dp of width per edge: on the 20 dp floor of the 2-D
 *     test tank the load is 10 % above the water weight (test_step.c);
 *   - a patch with a prescribed motion (settings wall_motion) moves
 *     rigidly: its wall and dummy particles carry the velocity of the
 *     step, (d(t + dt) - d(t))/dt, so that the viscous term sees the
 *     wall's no-slip velocity and the PPE's div u* its motion, and are
 *     moved by d(t + dt) - d(t) (positions exact to round-off); a patch
 *     past its removeAt is deleted at the start of the step, dummies of
 *     other patches that leaned on it lose their partner (pressure 0).
 *     While such patches exist, a dummy's partner is searched in its own
 *     patch only: a gate's dummy must not take the pressure of the floor
 *     it leaves behind.
 * The partner search and the extrapolation are the shared ones
 * (src/particles/operators/walls.c); this file says which particles use
 * them and when.
 */
#include <math.h>
#include <string.h>

#include "core/error.h"
#include "core/log.h"
#include "mps/mps.h"
#include "mps/mps_impl.h"
#include "particles/operators/walls.h"

/* Patch k moves or is removed at some time. */
static int patch_dynamic(const struct mps_solver *s, int k)
{
    const struct mps_settings *S = &s->S;
    if (k < 0 || k >= S->n_wall_motion || !S->wall_motion)
        return 0;
    const struct wall_motion *m = &S->wall_motion[k];
    return wall_motion_moves(m) || isfinite(m->remove_at);
}

/* A dummy of a moving or removed patch leans on its own patch only. */
static int same_patch_if_dynamic(const void *ctx, int i, int j)
{
    const struct mps_solver *s = ctx;
    const struct mps_particles *P = &s->P;
    return !(P->patch[j] != P->patch[i] && s->walls_move
             && (patch_dynamic(s, P->patch[i])
                 || patch_dynamic(s, P->patch[j])));
}

int mps_find_partners(struct mps_solver *s)
{
    struct mps_particles *P = &s->P;
    int orphans = pop_wall_partners(&s->nl, P->n, P->type, MPS_DUMMY,
                                    MPS_WALL, P->id, 1e-9 * s->dp,
                                    same_patch_if_dynamic, s, P->partner);
    if (orphans)
        log_warn("%d dummy particle(s) have no wall particle within r_e = "
                 "%g m; their pressure stays 0", orphans, s->re_max);
    return SIM_OK;
}

/* Adami et al. (2012) eq. (27) on the gradient radius. */
static int extrapolate(const struct mps_solver *s,
                       const struct pop_weights *Wg, int i, double *p)
{
    const struct mps_particles *P = &s->P;
    return pop_wall_extrapolate(&s->nl, Wg, P->x, P->p, P->type,
                                MPS_FLUID, s->S.rho, s->S.g, i, p);
}

int mps_dummy_pressure(struct mps_solver *s)
{
    struct mps_particles *P = &s->P;
    const int mode = s->S.dummy_pressure;
    const double rho = s->S.rho, *g = s->S.g;
    const struct pop_weights Wg = mps_w(s, MPS_W_G);
    if (mode == MPS_DUMMY_P_EXTRAPOLATED) {
        /* wall particles first: deep dummies fall back on their partner */
#pragma omp parallel for schedule(static)
        for (int i = 0; i < P->n; i++)
            if (P->type[i] == MPS_WALL && !extrapolate(s, &Wg, i, &P->p[i]))
                P->p[i] = 0;
        /* a dummy's partner may be a ghost */
        TRY(mps_halo_refresh(s, P->p, sizeof *P->p));
    }
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++) {
        if (P->type[i] != MPS_DUMMY)
            continue;
        int w = P->partner[i];
        if (mode == MPS_DUMMY_P_EXTRAPOLATED
            && extrapolate(s, &Wg, i, &P->p[i]))
            continue;
        if (mode == MPS_DUMMY_P_ZERO || w < 0) {
            P->p[i] = 0;
            continue;
        }
        double p = P->p[w];
        /* a dry partner (no water near) gives 0, not a suction */
        if (mode == MPS_DUMMY_P_EXTRAPOLATED && p > 0)
            for (int q = 0; q < 3; q++)
                p += rho * g[q] * (P->x[3 * i + q] - P->x[3 * w + q]);
        P->p[i] = p;
    }
    return SIM_OK;
}

void mps_wall_forces(const struct mps_solver *s, int npatch, double *force)
{
    const struct mps_particles *P = &s->P;
    double area = P->dim == 3 ? s->dp * s->dp : s->dp;
    memset(force, 0, sizeof *force * 3 * (size_t)npatch);
    const int n = mps_own(s);
    for (int i = 0; i < n; i++) {
        int k = P->patch[i];
        if (P->type[i] != MPS_WALL || k < 0 || k >= npatch)
            continue;
        for (int q = 0; q < 3; q++)
            force[3 * k + q] += P->p[i] * area * P->normal[3 * i + q];
    }
}

/* Delete the particles of patches removed by time t; *gone: how many. */
static int remove_patches(struct mps_solver *s, double t, int *gone_out)
{
    struct mps_particles *P = &s->P;
    const struct wall_motion *wm = s->S.wall_motion;
    int m = 0;
    for (int i = 0; i < P->n; i++) {
        int k = P->patch[i];
        if (P->type[i] == MPS_FLUID || k < 0 || k >= s->S.n_wall_motion
            || !wall_motion_removed(&wm[k], t))
            s->perm[m++] = i;
    }
    int gone = P->n - m;
    *gone_out = gone;
    if (gone) {
        s->rebuild = 1;   /* the list and the grid index the old set */
        return mps_particles_permute(s, s->perm, m);
    }
    return SIM_OK;
}

int mps_walls_begin_step(struct mps_solver *s, double dt)
{
    struct mps_particles *P = &s->P;
    const struct wall_motion *wm = s->S.wall_motion;
    const int np = s->S.n_wall_motion;
    if (!s->walls_move)
        return SIM_OK;
    const double t = s->time;
    int gone;
    TRY(remove_patches(s, t, &gone));
    if (gone)
        log_info("    t = %g s: %d wall/dummy particle(s) of removed "
                 "patches deleted", t, gone);
    for (int k = 0; k < np; k++) {
        double d0[3], d1[3];
        wall_motion_displacement(&wm[k], t, d0);
        wall_motion_displacement(&wm[k], t + dt, d1);
        for (int q = 0; q < 3; q++)
            s->wall_dx[3 * k + q] = d1[q] - d0[q];
    }
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++) {
        int k = P->patch[i];
        if (P->type[i] == MPS_FLUID || k < 0 || k >= np
            || !wall_motion_moves(&wm[k]))
            continue;
        for (int q = 0; q < 3; q++)
            P->u[3 * i + q] = s->wall_dx[3 * k + q] / dt;
    }
    return SIM_OK;
}

void mps_walls_move(struct mps_solver *s)
{
    struct mps_particles *P = &s->P;
    const int np = s->S.n_wall_motion;
    if (!s->walls_move)
        return;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++) {
        int k = P->patch[i];
        if (P->type[i] == MPS_FLUID || k < 0 || k >= np
            || !wall_motion_moves(&s->S.wall_motion[k]))
            continue;
        for (int q = 0; q < 3; q++)
            P->x[3 * i + q] += s->wall_dx[3 * k + q];
    }
}
