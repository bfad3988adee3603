/*
 * mlpg_solver.c — the MLPG_R projection step (doc/theory.md M.8; Pan 2022
 * thesis sect. 4.1, eqs. 4.5-4.9, 4.22-4.24; algorithm of mlpg_solver.h):
 *
 *   1. neighbour list (Lagrangian nodes: every step; fixed: once)
 *   2. u* = u + dt (nu lap u + g [- u.grad u]) on fluid and wall nodes (C-06)
 *   3. rows of mlpg.h with g_s = (rho/dt) n_s.(u*_K - U_K) (S-2); the pinned
 *      node p = pRefValue
 *   4. solve; u = u* - (dt/rho) grad p (SFDI) on fluid nodes, U on walls
 *   5. Lagrangian: r += u dt (eq. 4.9), or with positionUpdate secondOrder
 *      r += u dt + (dt^2/2) (u.grad) u, u = u^{n+1}, SFDI gradient: the
 *      Taylor expansion of the flow map to second order. For div u = 0
 *      the area map of eq. 4.9, det(I + dt grad u) = 1 + dt^2 det grad u,
 *      shrinks the water by dt^2 |grad u|^2 per step where the flow is
 *      irrotational; the second-order term cancels that dt^2 part
 *      (doc/theory.md M0-26, M0-27)
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/app.h"
#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "linsolve/csr.h"
#include "mlpg/mlpg_solver.h"
#include "particles/operators/operators.h"
#include "particles/operators/surface_quadrant.h"
#include "particles/operators/wet_walls.h"

#define PI 3.141592653589793

static const int DIM_RHO[7] = { 1, -3, 0, 0, 0, 0, 0 };
static const int DIM_NU[7] = { 0, 2, -1, 0, 0, 0, 0 };

static const struct model_head nodes_fixed = {
    "fixed", "Eulerian nodes with advection (doc/theory.md M0-14)" };
static const struct model_head nodes_lagr = {
    "lagrangian", "Pan 2022 eq. 4.9" };
static const struct model_head *const nodes_table[] = {
    &nodes_fixed, &nodes_lagr, NULL };

static const struct model_head fs_none = { "none", "closed domain" };
static const struct model_head fs_quad = {
    "quadrantColumn", "Ma and Zhou 2009; Pan 2022 eqs. 5.32-5.33" };
static const struct model_head *const fs_table[] = { &fs_none, &fs_quad,
                                                     NULL };

static const struct model_head slip_no = { "noSlip", "Pan 2022 sect. 4.3" };
static const struct model_head slip_free = { "freeSlip",
                                             "Pan 2022 sect. 4.3.4" };
static const struct model_head *const slip_table[] = { &slip_no, &slip_free,
                                                       NULL };

static const struct model_head shift_none = { "none", "nodes move with "
                                              "the flow only" };
static const struct model_head shift_lind = { "lind2012",
    "Lind, Xu, Stansby & Rogers 2012 JCP 231 eqs. 20-24" };
static const struct model_head *const shift_table[] = { &shift_none,
                                                        &shift_lind, NULL };

static const struct model_head move_end = { "endVelocity",
    "Pan 2022 eq. 4.9: r += u^{n+1} dt" };
static const struct model_head move_second = { "secondOrder",
    "r += u dt + (dt^2/2) (u.grad) u (doc/theory.md M0-27)" };
static const struct model_head *const move_table[] = { &move_end,
                                                       &move_second, NULL };

static const struct model_head self_mls = { "approximant", "Pan 2022 eq. 4.23" };
static const struct model_head self_nodal = { "nodal", "doc/theory.md M0-03" };
static const struct model_head *const self_table[] = {
    &self_mls, &self_nodal, NULL };

const struct model_choice mlpg_solver_choices[] = {
    { "system/mlpgSchemes", "wallScheme",
      (const void *const *)mlpg_wall_schemes },
    { "system/mlpgSchemes", "nodes", (const void *const *)nodes_table },
    { "system/mlpgSchemes", "selfTerm", (const void *const *)self_table },
    { "system/mlpgSchemes", "freeSurface", (const void *const *)fs_table },
    { "system/mlpgSchemes", "wallCondition",
      (const void *const *)slip_table },
    { "system/mlpgSchemes", "shifting", (const void *const *)shift_table },
    { "system/mlpgSchemes", "positionUpdate",
      (const void *const *)move_table },
    { NULL, NULL, NULL }
};

int mlpg_rows_read(const struct dict *d, int *self_nodal, double *support,
                   double *radius)
{
    TRY(model_select_index(d, "selfTerm", "MLPG self term",
                           (const void *const *)self_table, "approximant",
                           self_nodal));
    TRY(dict_get_scalar_or(d, "supportRadius", 1.85, support));
    TRY(dict_range(d, "supportRadius", *support, 1.2, 3, 0));
    TRY(dict_get_scalar_or(d, "subdomainRadius", 0.8, radius));
    return dict_range(d, "subdomainRadius", *radius, 0.1, 1, 0);
}

int mlpg_settings_read(const struct dict *transport,
                       const struct dict *schemes,
                       const struct dict *solution, struct mlpg_settings *S)
{
    TRY(dict_get_scalar_dim(transport, "rho", DIM_RHO, &S->rho));
    TRY(dict_range(transport, "rho", S->rho, 0, 1e6, 1));
    TRY(dict_get_scalar_dim(transport, "nu", DIM_NU, &S->nu));
    TRY(dict_range(transport, "nu", S->nu, 0, 1e3, 0));
    TRY(model_select(schemes, "wallScheme", "wall scheme",
                     (const void *const *)mlpg_wall_schemes, "improved",
                     (const void **)&S->wall));
    TRY(model_select_index(schemes, "nodes", "MLPG nodes",
                           (const void *const *)nodes_table, "lagrangian",
                           &S->nodes));
    TRY(mlpg_rows_read(schemes, &S->self_nodal, &S->support, &S->radius));
    TRY(model_select_index(schemes, "shifting", "node shifting",
                           (const void *const *)shift_table, "none",
                           &S->shift));
    TRY(model_select_index(schemes, "positionUpdate", "position update",
                           (const void *const *)move_table, "endVelocity",
                           &S->move));
    const struct dict *coeffs = NULL;
    S->shift_coeff = 0.01;
    if (S->shift == MLPG_SHIFT_LIND2012)
        TRY(dict_find_dict(schemes, "lind2012Coeffs", &coeffs));
    if (coeffs) {
        TRY(dict_get_scalar_or(coeffs, "coefficient", S->shift_coeff,
                               &S->shift_coeff));
        TRY(dict_range(coeffs, "coefficient", S->shift_coeff, 0, 1, 1));
    }
    TRY(model_select_index(schemes, "freeSurface", "free-surface detector",
                           (const void *const *)fs_table, "none",
                           &S->free_surface));
    TRY(model_select_index(schemes, "wallCondition", "wall condition",
                           (const void *const *)slip_table, "noSlip",
                           &S->free_slip));
    /* a closed domain needs a pressure level; a free surface or an
     * outlet (fixedPressure) gives one */
    int open = S->free_surface || dict_has(solution, "fixedPressure");
    S->has_pref = !open || dict_has(solution, "pRefPoint");
    if (S->has_pref) {
        if (!dict_has(solution, "pRefPoint"))
            return dict_error(solution, NULL, SIM_ERR_DICT, "pRefPoint: "
                              "required in a closed domain (freeSurface "
                              "none, no fixedPressure): the pressure is "
                              "fixed at the node nearest to it");
        TRY(dict_get_vector(solution, "pRefPoint", 3, S->pref_point));
        TRY(dict_get_scalar_or(solution, "pRefValue", 0, &S->pref_value));
    }
    return SIM_OK;
}

int mlpg_fields_alloc(struct mlpg_solver *s, int n)
{
    struct store *st = &s->st;
    store_init(st, "field of the MLPG cloud");
    TRY(store_add(st, "position", "[m]", VTU_FLOAT64, 3,
                  STORE_POINTS, &s->x));
    TRY(store_add(st, "velocity", "[m/s]", VTU_FLOAT64, 3, STORE_WRITE,
                  &s->u));
    TRY(store_add(st, "pressure", "[Pa]", VTU_FLOAT64, 1, STORE_WRITE,
                  &s->p));
    TRY(store_add(st, "type", "0 fluid, 1 wall", VTU_INT32, 1, STORE_WRITE,
                  &s->type));
    TRY(store_add(st, "patch", "wall region, -1 fluid", VTU_INT32, 1,
                  STORE_WRITE, &s->patch));
    TRY(store_add(st, "id", "persistent", VTU_INT64, 1, STORE_WRITE,
                  &s->id));
    TRY(store_add(st, "normal", "wall: unit, into the solid", VTU_FLOAT64,
                  3, STORE_WRITE, &s->normal));
    TRY(store_add(st, "pressureFixed", "1: p given (free surface, wall "
                  "above the water, reference node)", VTU_UINT8, 1,
                  STORE_WRITE, &s->dirichlet));
    TRY(store_add(st, "wallArea", "wall: the length it stands for [m]",
                  VTU_FLOAT64, 1, STORE_WRITE, &s->wall_area));
    TRY(store_add(st, "viscousTraction", "wall: viscous stress of the "
                  "fluid on it [Pa]", VTU_FLOAT64, 3, STORE_WRITE,
                  &s->traction));
    TRY(store_resize(st, (size_t)n));
    s->n = n;
    return SIM_OK;
}

/* Wall sectors (doc M0-07): a wall node whose normal differs by more
 * than 30 degrees from every wall node within 1.5 dl, and from at least
 * two of them, is a container corner with sector pi - (angle between its
 * neighbours' normals); every other wall node is straight (pi). */
static void wall_sectors(struct mlpg_solver *s)
{
    const struct neighbour_list *nl = &s->nl;
    const double cos30 = cos(PI / 6), reach = 1.5 * s->S.dl;
    for (int i = 0; i < s->n; i++) {
        for (int q = 0; q < 3; q++)
            s->nin[3 * i + q] = -s->normal[3 * i + q];
        if (s->type[i] != MLPG_WALL) {
            s->sector[i] = 2 * PI;
            continue;
        }
        const double *ni = s->normal + 3 * i;
        int differ = 0, similar = 0, a = -1, b = -1;
        for (int64_t k = nl->start[i]; k < nl->start[i + 1]; k++) {
            int j = nl->j[k];
            if (s->type[j] != MLPG_WALL || nl->r[k] > reach)
                continue;
            const double *nj = s->normal + 3 * j;
            double c = ni[0] * nj[0] + ni[1] * nj[1];
            if (c >= cos30) {
                similar++;
            } else {
                differ++;
                if (a < 0)
                    a = j;
                else if (b < 0)
                    b = j;
            }
        }
        s->sector[i] = PI;
        if (!similar && differ >= 2) {
            const double *na = s->normal + 3 * a, *nb = s->normal + 3 * b;
            s->sector[i] = PI - acos(fmax(-1, fmin(1, na[0] * nb[0]
                                                      + na[1] * nb[1])));
        }
    }
}

static int build_list(struct mlpg_solver *s)
{
    double t0 = app_wall_time();
    const double rc = (s->S.support + s->S.radius) * s->S.dl * 1.001;
    TRY(cells_build(&s->grid, 2, s->x, s->n, rc / 2, NULL, NULL));
    if (s->grid.n_outside)
        return sim_error(SIM_ERR_NUMERIC, "%d MLPG nodes have a non-finite "
                         "position", s->grid.n_outside);
    TRY(neighbour_build(&s->nl, &s->grid, s->x, rc));
    mlpg_radii(&s->c, s->R);
    s->t.builds++;
    s->t.neighbours += app_wall_time() - t0;
    return SIM_OK;
}

/* Laplacian and SFDI coefficients of every node, per candidate. */
static int node_coefficients(struct mlpg_solver *s)
{
    s->coef_start = sim_realloc(s->coef_start,
                                (size_t)(s->n + 1) * sizeof *s->coef_start);
    if (!s->coef_start)
        return SIM_ERR_NOMEM;
    s->coef_start[0] = 0;
    for (int i = 0; i < s->n; i++)
        s->coef_start[i + 1] = s->coef_start[i]
                             + mlpg_candidates(&s->c, i, NULL);
    size_t ne = (size_t)s->coef_start[s->n];
    s->lap = sim_realloc(s->lap, ne * sizeof *s->lap);
    s->sfdi = sim_realloc(s->sfdi, ne * sizeof *s->sfdi);
    s->cand = sim_realloc(s->cand, ne * sizeof *s->cand);
    if (!s->lap || !s->sfdi || !s->cand)
        return SIM_ERR_NOMEM;
    if (s->S.nodes == MLPG_NODES_FIXED) { /* the arc weights, once */
        s->dw_start = sim_realloc(s->dw_start, (size_t)(s->n + 1)
                                                   * sizeof *s->dw_start);
        if (!s->dw_start)
            return SIM_ERR_NOMEM;
        s->dw_start[0] = 0;
        for (int i = 0; i < s->n; i++)
            s->dw_start[i + 1] = s->dw_start[i]
                + (s->coef_start[i + 1] - s->coef_start[i])
                  * mlpg_domain_points(&s->c, i);
        s->dw = sim_realloc(s->dw, (size_t)s->dw_start[s->n] * sizeof *s->dw);
        if (!s->dw)
            return SIM_ERR_NOMEM;
    }
    int rc = SIM_OK;
    for (int i = 0; i < s->n && rc == SIM_OK; i++) {
        int64_t e = s->coef_start[i];
        int32_t *cand = s->cand + e;
        int m = mlpg_candidates(&s->c, i, cand);
        if (s->dw && !s->dirichlet[i])
            rc = mlpg_domain_weights(&s->c, i, cand, m,
                                     s->dw + s->dw_start[i]);
        if (rc != SIM_OK)
            break;
        rc = mlpg_fit2_coeffs(&s->c, i, cand, m, s->nl.rc,
                              MLPG_FIT2_LAPLACIAN, s->lap + e);
        if (rc == SIM_OK)
            rc = mlpg_sfdi(&s->c, i, cand, m, s->sfdi + e);
        if (rc != SIM_OK && s->type[i] == MLPG_WALL) {
            /* a wall node above the water, whose neighbours lie on its
             * wall: no viscous term and no gradient (doc M0-23) */
            sim_error_clear();
            rc = SIM_OK;
            for (int k = 0; k < m; k++)
                s->lap[e + k] = s->sfdi[e + k][0] = s->sfdi[e + k][1] = 0;
        }
    }
    return rc;
}

/* The nodes whose pressure is given: wall nodes above the water and the
 * free surface (p = 0, doc M0-22, M0-23), fixedPressure boxes, the
 * reference node; and the dry wall nodes left out of every row. */
static int dirichlet_nodes(struct mlpg_solver *s)
{
    memset(s->dirichlet, 0, (size_t)s->n);
    memset(s->exclude, 0, (size_t)s->n);
    memset(s->surface, 0, (size_t)s->n);
    /* dry wall nodes, no fluid node within the MLS support: p = 0, outside
     * the system (doc M0-23) */
    const struct neighbour_list *nl = &s->nl;
    const double *g = s->S.g, gn = hypot(g[0], g[1]);
    const double up[2] = { gn > 0 ? -g[0] / gn : 0, gn > 0 ? -g[1] / gn : 0 };
    /* wet: water within the MLS support; with a free surface and gravity
     * not all of it lower than the node by more than half a spacing,
     * unless the wall faces down (a roof) */
    pop_wet_walls(nl, s->x, s->type, s->normal, g, s->S.free_surface,
                  s->c.rs, s->S.dl, s->exclude);
    for (int i = 0; i < s->n; i++)
        s->dirichlet[i] = s->exclude[i] = !s->exclude[i];
    uint8_t *given = s->dirichlet;
    /* a wet wall node whose row cannot be made (the MLS support of a point
     * of its half disc holds only its own wall: it stands above the
     * water) is dry too */
    int maxlen = 1;
    for (int i = 0; i < s->n; i++)
        if ((int)(nl->start[i + 1] - nl->start[i]) + 1 > maxlen)
            maxlen = (int)(nl->start[i + 1] - nl->start[i]) + 1;
    double *buf = sim_malloc((size_t)maxlen * (6 * sizeof(double)
                                               + sizeof(int32_t)));
    if (!buf)
        return SIM_ERR_NOMEM;
    for (int i = 0; i < s->n; i++) {
        if (s->type[i] != MLPG_WALL || given[i])
            continue;
        int32_t *cand = (int32_t *)(buf + 6 * maxlen);
        int m = mlpg_candidates(&s->c, i, cand);
        if (s->S.wall->row(&s->c, i, cand, m, buf, buf + maxlen) != SIM_OK
            || mlpg_domain_weights(&s->c, i, cand, m, buf + maxlen)
                   != SIM_OK) {
            sim_error_clear();
            given[i] = s->exclude[i] = 1;
        }
    }
    free(buf);
    if (s->S.free_surface) {
        uint8_t *flag = s->fsflag, *counts = s->fsflag + s->n;
        for (int i = 0; i < s->n; i++) {
            flag[i] = s->type[i] == MLPG_FLUID; /* the rows to flag */
            counts[i] = flag[i] || !given[i];     /* and the neighbours */
        }
        pop_surface_quadrant(&s->nl, s->x, 2.5 * s->S.dl, 0.4 * s->S.dl,
                             flag, counts, NULL, flag);
        for (int i = 0; i < s->n; i++)
            if (s->type[i] == MLPG_FLUID)
                given[i] = s->surface[i] = flag[i];
        /* a wet wall node at the waterline: nothing counted in the
         * 90-degree sector above it (its other sectors are the wall's) nor
         * higher than itself by 0.05 dl within 2.5 dl (water that has
         * risen along the wall puts the node back in the system). It
         * stands at the water's edge: p = 0 and, like a dry node, in no
         * other node's row, so that the surface nodes beside it do not
         * take its p = 0 below the water level for a suction towards the
         * wall (doc M0-22) */
        for (int i = 0; gn > 0 && i < s->n; i++) {
            if (s->type[i] != MLPG_WALL || given[i])
                continue;
            int above = 0;
            for (int64_t k = nl->start[i]; k < nl->start[i + 1]; k++) {
                int j = nl->j[k];
                double dx = s->x[3 * j] - s->x[3 * i];
                double dy = s->x[3 * j + 1] - s->x[3 * i + 1];
                double h = up[0] * dx + up[1] * dy;
                if (counts[j] && nl->r[k] < 2.5 * s->S.dl
                    && (h > fabs(-up[1] * dx + up[0] * dy)
                        || h > 0.05 * s->S.dl)) {
                    above = 1;
                    break;
                }
            }
            given[i] = s->exclude[i] = !above;
        }
    }
    s->n_surface = 0;
    for (int i = 0; i < s->n; i++) {
        s->n_surface += s->surface[i];
        s->pgiven[i] = 0;
    }
    for (int f = 0; f < s->nfixed_p; f++) {
        const struct mlpg_fixed_pressure *F = &s->fixed_p[f];
        for (int i = 0; i < s->n; i++) {
            if (s->type[i] == MLPG_FLUID
                && mlpg_in_box(s->x + 3 * i, F->lo, F->hi)) {
                s->dirichlet[i] = 1;
                s->pgiven[i] = F->value;
            }
        }
    }
    if (s->pin >= 0) {
        s->dirichlet[s->pin] = 1;
        s->pgiven[s->pin] = s->S.pref_value;
    }
    return SIM_OK;
}

static void neumann(void *ctx, int i, int nseg, const double n[2][2],
                    double g[2])
{
    const struct mlpg_solver *s = ctx;
    const double rho_dt = s->S.rho / s->last_dt;
    double du[2] = { s->ustar[3 * i] - s->wallU[3 * i],
                     s->ustar[3 * i + 1] - s->wallU[3 * i + 1] };
    for (int k = 0; k < nseg; k++)
        g[k] = rho_dt * (n[k][0] * du[0] + n[k][1] * du[1]);
}

int mlpg_solver_init(struct mlpg_solver *s, const struct mlpg_settings *S,
                     struct linsolve *ls)
{
    s->S = *S;
    s->ls = ls;
    size_t n = (size_t)s->n;
    s->ustar = sim_calloc(3 * n, sizeof *s->ustar);
    s->nin = sim_calloc(3 * n, sizeof *s->nin);
    s->pgiven = sim_calloc(n, sizeof *s->pgiven);
    s->wallU = sim_calloc(3 * n, sizeof *s->wallU);
    s->sector = sim_calloc(n, sizeof *s->sector);
    s->R = sim_calloc(n, sizeof *s->R);
    s->b = sim_calloc(n, sizeof *s->b);
    s->fsflag = sim_calloc(2 * n, 1);
    s->exclude = sim_calloc(n, 1);
    s->surface = sim_calloc(n, 1);
    if (!s->surface || !s->ustar || !s->nin || !s->pgiven || !s->wallU || !s->sector
        || !s->R || !s->b || !s->fsflag || !s->exclude)
        return SIM_ERR_NOMEM;
    int moving = 0;
    for (int g = 0; g < s->ngroups; g++)
        moving |= wall_motion_moves(&s->groups[g].motion);
    if (moving && S->nodes == MLPG_NODES_FIXED)
        return sim_error(SIM_ERR_INPUT, "system/mlpgSchemes: nodes fixed, "
                         "but a wall group of system/mlpgSolution has a "
                         "motion: moving walls need nodes lagrangian");
    if (S->shift != MLPG_SHIFT_NONE && S->nodes == MLPG_NODES_FIXED)
        return sim_error(SIM_ERR_INPUT, "system/mlpgSchemes: shifting with "
                         "nodes fixed: only Lagrangian nodes are shifted "
                         "(shifting none, or nodes lagrangian)");
    if (S->shift != MLPG_SHIFT_NONE) {
        struct pop_lattice lat;
        TRY(pop_lattice_constants(mlpg_weight, 2, S->dl,
                                  S->support * S->dl, &lat));
        s->shift_n0 = lat.n0;
    }
    if (moving) {
        s->x0 = sim_malloc(3 * n * sizeof *s->x0);
        if (!s->x0)
            return SIM_ERR_NOMEM;
    }
    for (int i = 0; i < s->n; i++) {
        int g = s->group ? s->group[i] : -1;
        if (s->type[i] != MLPG_WALL || g < 0)
            continue;
        const struct wall_motion *m = &s->groups[g].motion;
        if (wall_motion_moves(m)) { /* the cloud is at the start time */
            double d[3];
            wall_motion_displacement(m, s->time, d);
            wall_motion_velocity(m, s->time, s->wallU + 3 * i);
            for (int q = 0; q < 3; q++)
                s->x0[3 * i + q] = s->x[3 * i + q] - d[q];
        } else {
            memcpy(s->wallU + 3 * i, s->groups[g].U, 3 * sizeof(double));
        }
        memcpy(s->u + 3 * i, s->wallU + 3 * i, 3 * sizeof(double));
    }
    s->c = (struct mlpg_cloud){
        .n = s->n, .dl = S->dl, .rs = S->support * S->dl,
        .R0 = S->radius * S->dl, .x = s->x, .type = s->type,
        .normal = s->nin, .sector = s->sector, .R = s->R,
        .dirichlet = s->dirichlet, .exclude = s->exclude, .nl = &s->nl,
        .self_nodal = S->self_nodal,
    };
    TRY(build_list(s));
    wall_sectors(s);
    int ncorner = 0;
    for (int i = 0; i < s->n; i++)
        ncorner += s->type[i] == MLPG_WALL && s->sector[i] < PI - 1e-6;
    /* the reference node */
    double best = HUGE_VAL;
    s->pin = -1;
    for (int i = 0; S->has_pref && i < s->n; i++) {
        double d = hypot(s->x[3 * i] - S->pref_point[0],
                         s->x[3 * i + 1] - S->pref_point[1]);
        if (d < best) {
            best = d;
            s->pin = i;
        }
    }
    if (S->has_pref && best > 2 * S->dl)
        return sim_error(SIM_ERR_INPUT, "system/mlpgSolution: pRefPoint "
                         "(%g %g) is %g m from the nearest node (more than "
                         "2 dl): put it inside the domain",
                         S->pref_point[0], S->pref_point[1], best);
    log_info("MLPG cloud: %d nodes, %d corner nodes", s->n, ncorner);
    if (s->pin >= 0)
        log_info("Pressure reference: node %d at (%g %g)", s->pin,
                 s->x[3 * s->pin], s->x[3 * s->pin + 1]);
    return SIM_OK;
}

/* (u.grad) u at node i, SFDI gradient (C.7) on the step's coefficients */
static void advection(const struct mlpg_solver *s, int i, double adv[2])
{
    double gx[2] = { 0, 0 }, gy[2] = { 0, 0 };
    for (int64_t e = s->coef_start[i] + 1; e < s->coef_start[i + 1]; e++) {
        int j = s->cand[e];
        for (int q = 0; q < 2; q++) {
            double du = s->u[3 * j + q] - s->u[3 * i + q];
            gx[q] += s->sfdi[e][0] * du;
            gy[q] += s->sfdi[e][1] * du;
        }
    }
    for (int q = 0; q < 2; q++)
        adv[q] = s->u[3 * i] * gx[q] + s->u[3 * i + 1] * gy[q];
}

int mlpg_step(struct mlpg_solver *s, double dt)
{
    const struct mlpg_settings *S = &s->S;
    const int fixed = S->nodes == MLPG_NODES_FIXED, n = s->n;
    const int second = !fixed && S->move == MLPG_MOVE_SECOND_ORDER;
    double t0 = app_wall_time(), tnew = s->time + dt;
    s->last_dt = dt;
    if (!fixed && s->t.steps > 0) /* Lagrangian: the nodes moved */
        TRY(build_list(s));
    if (!fixed || !s->assembled) {
        TRY(dirichlet_nodes(s));
        TRY(node_coefficients(s));
    }
    /* U^{n+1} of the walls that move (S-2) */
    for (int i = 0; s->x0 && i < n; i++) {
        int g = s->group[i];
        if (g >= 0 && wall_motion_moves(&s->groups[g].motion))
            wall_motion_velocity(&s->groups[g].motion, tnew,
                                 s->wallU + 3 * i);
    }
    /* 2. u* on fluid and wall nodes (doc M0-06) */
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; i++) {
        int64_t e0 = s->coef_start[i], e1 = s->coef_start[i + 1];
        double lap[2] = { 0, 0 }, adv[2] = { 0, 0 };
        for (int64_t e = e0 + 1; e < e1; e++) {
            int j = s->cand[e];
            for (int q = 0; q < 2; q++)
                lap[q] += s->lap[e] * (s->u[3 * j + q] - s->u[3 * i + q]);
        }
        if (fixed) /* the advection of fixed nodes */
            advection(s, i, adv);
        for (int q = 0; q < 2; q++) {
            double a = S->nu * lap[q] + S->g[q] - adv[q];
            s->ustar[3 * i + q] = s->u[3 * i + q] + dt * a;
        }
        s->ustar[3 * i + 2] = 0;
    }
    double t1 = app_wall_time();
    s->t.explicit_ += t1 - t0;
    /* 3. rows */
    struct mlpg_system sys = { .wall = S->wall, .rho_dt = S->rho / dt,
                               .ustar = s->ustar, .neumann = neumann,
                               .ctx = s, .p_given = s->pgiven,
                               .dw = s->dw, .dw_start = s->dw_start };
    if (!fixed || !s->assembled) {
        TRY(mlpg_assemble(&s->c, &sys, &s->A, &s->capA, s->b));
        s->assembled = 1;
    } else {
        TRY(mlpg_rhs(&s->c, &sys, &s->A, s->b));
    }
    double t2 = app_wall_time();
    s->t.assembly += t2 - t1;
    /* 4. solve, correct */
    TRY(linsolve_solve(s->ls, &s->A, s->b, s->p, &s->last));
    s->t.ppe_iters += s->last.iters;
    double t3 = app_wall_time();
    s->t.ppe += t3 - t2;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; i++) {
        const int wall = s->type[i] == MLPG_WALL;
        const int grp = s->group ? s->group[i] : -1;
        const int fs = grp >= 0 && s->groups[grp].free_slip >= 0
                     ? s->groups[grp].free_slip : S->free_slip;
        const int slip = wall && fs && !s->dirichlet[i]
                      && fabs(s->sector[i] - PI) < 1e-6; /* dry: U */
        if (wall) { /* no slip; free slip: below, from the new flow */
            memcpy(s->u + 3 * i, s->wallU + 3 * i, 3 * sizeof(double));
            s->fsflag[i] = slip;
            continue;
        }
        int64_t e0 = s->coef_start[i], e1 = s->coef_start[i + 1];
        double g[2] = { 0, 0 };
        for (int64_t e = e0 + 1; e < e1; e++) {
            double dp = s->p[s->cand[e]] - s->p[i];
            g[0] += s->sfdi[e][0] * dp;
            g[1] += s->sfdi[e][1] * dp;
        }
        for (int q = 0; q < 2; q++)
            s->u[3 * i + q] = s->ustar[3 * i + q] - dt / S->rho * g[q];
        s->u[3 * i + 2] = 0;
    }
    /* free slip (doc M0-16): the wall's normal velocity and the tangential
     * velocity of the water next to the node, the Shepard (weighted)
     * mean of the fluid nodes' new velocities within the MLS support (a
     * one-sided momentum update of the wall node itself, or a linear fit
     * to the wall, is unstable) */
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; i++) {
        if (s->type[i] != MLPG_WALL || !s->fsflag[i])
            continue;
        double uf[2] = { 0, 0 }, sw = 0;
        for (int64_t k = s->nl.start[i]; k < s->nl.start[i + 1]; k++) {
            int j = s->nl.j[k];
            double w = s->type[j] == MLPG_FLUID
                     ? mlpg_weight(s->nl.r[k], s->c.rs) : 0;
            uf[0] += w * s->u[3 * j];
            uf[1] += w * s->u[3 * j + 1];
            sw += w;
        }
        if (!(sw > 0))
            continue; /* no water next to it: the wall's velocity */
        uf[0] /= sw;
        uf[1] /= sw;
        const double *nn = s->nin + 3 * i, *U = s->wallU + 3 * i;
        double un = U[0] * nn[0] + U[1] * nn[1];
        double ut = -uf[0] * nn[1] + uf[1] * nn[0];
        s->u[3 * i] = un * nn[0] - ut * nn[1];
        s->u[3 * i + 1] = un * nn[1] + ut * nn[0];
    }
    /* secondOrder (doc M0-27): (dt^2/2) (u.grad) u^{n+1} of the fluid
     * nodes, SFDI gradient, into ustar (free after the correction) */
    if (second) {
#pragma omp parallel for schedule(static)
        for (int i = 0; i < n; i++) {
            if (s->type[i] == MLPG_WALL)
                continue;
            double adv[2];
            advection(s, i, adv);
            for (int q = 0; q < 2; q++)
                s->ustar[3 * i + q] = 0.5 * dt * dt * adv[q];
        }
    }
    /* 5. Lagrangian nodes move; walls follow their motion (a sliding lid
     * stays: a conveyor) */
    if (!fixed)
        for (int i = 0; i < n; i++) {
            int g = s->group ? s->group[i] : -1;
            if (s->type[i] != MLPG_WALL)
                for (int q = 0; q < 2; q++)
                    s->x[3 * i + q] += s->u[3 * i + q] * dt
                                     + (second ? s->ustar[3 * i + q] : 0.0);
            else if (g >= 0 && wall_motion_moves(&s->groups[g].motion)) {
                double d[3];
                wall_motion_displacement(&s->groups[g].motion, tnew, d);
                for (int q = 0; q < 2; q++)
                    s->x[3 * i + q] = s->x0[3 * i + q] + d[q];
            }
        }
    if (!fixed && S->shift == MLPG_SHIFT_LIND2012)
        mlpg_shift(s);
    for (int i = 0; i < n; i++)
        for (int q = 0; q < 2; q++)
            if (!isfinite(s->u[3 * i + q]) || !isfinite(s->p[i]))
                return sim_error(SIM_ERR_NUMERIC, "MLPG node %d: non-finite "
                                 "velocity or pressure after the step", i);
    s->t.correction += app_wall_time() - t3;
    s->t.steps++;
    s->time += dt;
    return SIM_OK;
}

void mlpg_solver_free(struct mlpg_solver *s)
{
    store_free(&s->st);
    free(s->ustar), free(s->nin), free(s->pgiven), free(s->wallU);
    free(s->x0), free(s->group), free(s->fixed_p);
    for (int g = 0; g < s->ngroups; g++)
        wall_motion_free(&s->groups[g].motion);
    free(s->groups);
    free(s->sector), free(s->R), free(s->b);
    free(s->fsflag), free(s->exclude), free(s->surface), free(s->cand);
    free(s->dw), free(s->dw_start);
    free(s->lap), free(s->sfdi), free(s->coef_start);
    cells_free(&s->grid);
    neighbour_free(&s->nl);
    csr_free(&s->A);
    linsolve_free(s->ls);
    memset(s, 0, sizeof *s);
}
