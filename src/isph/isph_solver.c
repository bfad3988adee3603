/*
 * isph_solver.c — the two-phase ISPH step (isph_solver.h; Pan 2022 thesis
 * eqs. 5.5-5.13, 5.19-5.31, 5.40-5.48; doc/theory.md S.3).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/app.h"
#include "core/dict.h"
#include "core/error.h"
#include "coupling/drag/drag.h"
#include "isph/isph_solver.h"
#include "linsolve/csr.h"
#include "particles/operators/collision.h"
#include "particles/operators/surface_quadrant.h"
#include "particles/operators/wet_walls.h"

static const int DIM_RHO[7] = { 1, -3, 0, 0, 0, 0, 0 };
static const int DIM_NU[7] = { 0, 2, -1, 0, 0, 0, 0 };
static const int DIM_LEN[7] = { 0, 1, 0, 0, 0, 0, 0 };

static const struct model_head norm_ti = { "traceInverse",
    "2 tr(Gamma^-1)/n, Pan 2022 eq. 5.36 as printed" };
static const struct model_head norm_it = { "inverseTrace",
    "2n/tr(Gamma), doc/theory.md S0-03" };
static const struct model_head *const norm_table[] = { &norm_ti, &norm_it,
                                                       NULL };
static const struct model_head flux_adv = { "advective",
    "-(u_s - u_f).grad alpha_s, Pan 2022 eq. 5.41 as printed" };
static const struct model_head flux_con = { "conservative",
    "-div(alpha_s (u_s - u_f)), doc/theory.md S0-09" };
static const struct model_head flux_up = { "upwind",
    "pairwise upwind divergence, conservative and positive, doc S0-09" };
static const struct model_head flux_muscl = { "muscl",
    "upwind with the upstream gradient to the pair's midpoint, limited, "
    "doc S0-09" };
static const struct model_head *const flux_table[] = { &flux_adv, &flux_con,
                                                       &flux_up, &flux_muscl,
                                                       NULL };
static const struct model_head drag_ex = { "explicit",
    "gamma (u_s - u_f)^n, Pan 2022 eqs. 5.19, 5.27" };
static const struct model_head drag_si = { "semiImplicit",
    "backward-Euler relative velocity, doc/theory.md S0-07" };
static const struct model_head *const drag_step_table[] = { &drag_ex, &drag_si,
                                                       NULL };
static const struct model_head wall_neu = { "neumann",
    "one layer, n.grad p = (rho/dt) n.(u* - U), Pan 2022 eq. 5.31" };
static const struct model_head wall_dum = { "dummyLayers",
    "wall and dummy layers, pressure extrapolated (Adami 2012), doc S0-13" };
static const struct model_head *const wall_table[] = { &wall_neu, &wall_dum,
                                                       NULL };
static const struct model_head surf_q = { "quadrant",
    "occupied quadrants and columns, Pan 2022 eqs. 5.32-5.33" };
static const struct model_head surf_d = { "positionDivergence",
    "quadrant, or div r < 1.6 (Lee et al. 2008), doc/theory.md S0-14" };
static const struct model_head *const surface_table[] = { &surf_q, &surf_d,
                                                          NULL };
static const struct model_head shift_none = { "none",
    "particles move with the water (Pan 2022)" };
static const struct model_head shift_lind = { "lind2012",
    "Fickian shifting, Lind et al. 2012 eqs. 20-24, doc/theory.md S0-15" };
static const struct model_head *const shift_table[] = { &shift_none,
                                                        &shift_lind, NULL };
static const struct model_head coll_none = { "none",
    "no collision model (Pan 2022)" };
static const struct model_head coll_lee = { "lee2011",
    "Lee et al. 2011 collisions on u*, doc/theory.md S0-16" };
static const struct model_head *const collision_table[] = { &coll_none,
                                                            &coll_lee, NULL };
static const struct model_head smooth_none = { "none",
    "velocities as updated (Pan 2022)" };
static const struct model_head smooth_shep = { "shepard",
    "u <- (1 - eps) u + eps <u>, kernel mean, doc/theory.md S0-18" };
static const struct model_head smooth_bih = { "biharmonic",
    "u <- u - eps (I - S)^2 u, S the kernel mean, doc/theory.md S0-18" };
static const struct model_head *const smoothing_table[] = { &smooth_none,
                                                            &smooth_shep,
                                                            &smooth_bih,
                                                            NULL };
static const struct model_head region_all = { "all",
    "every water particle" };
static const struct model_head region_fs = { "freeSurface",
    "the free-surface particles and those with one in reach, doc S0-18" };
static const struct model_head *const region_table[] = { &region_all,
                                                         &region_fs, NULL };
const struct model_choice isph_solver_choices[] = {
    { "system/isphSchemes", "kernel", (const void *const *)isph_kernels },
    { "system/isphSchemes", "laplacian", (const void *const *)norm_table },
    { "system/isphSchemes", "sedimentFlux", (const void *const *)flux_table },
    { "system/isphSchemes", "drag", (const void *const *)drag_step_table },
    { "system/isphSchemes", "wall", (const void *const *)wall_table },
    { "system/isphSchemes", "freeSurface", (const void *const *)surface_table },
    { "system/isphSchemes", "shifting", (const void *const *)shift_table },
    { "system/isphSchemes", "collision",
      (const void *const *)collision_table },
    { "system/isphSchemes", "velocitySmoothing",
      (const void *const *)smoothing_table },
    { "system/isphSchemes", "velocitySmoothingRegion",
      (const void *const *)region_table },
    { NULL, NULL, NULL },
};

int isph_settings_read(const struct dict *transport,
                       const struct dict *sediment, const struct dict *schemes,
                       struct isph_settings *S)
{
    double hf;
    TRY(dict_get_scalar_dim(transport, "rho", DIM_RHO, &S->rho_f));
    TRY(dict_range(transport, "rho", S->rho_f, 0, 1e6, 1));
    TRY(dict_get_scalar_dim(transport, "nu", DIM_NU, &S->nu_f));
    TRY(dict_range(transport, "nu", S->nu_f, 0, 1e3, 0));
    TRY(dict_get_scalar_dim(sediment, "rho", DIM_RHO, &S->rho_s));
    TRY(dict_range(sediment, "rho", S->rho_s, 0, 1e6, 1));
    TRY(dict_get_scalar_dim(sediment, "d", DIM_LEN, &S->d_s));
    TRY(dict_range(sediment, "d", S->d_s, 0, 1, 1));
    TRY(dict_get_scalar_or(sediment, "alphaMax", 0.606, &S->alpha_sm));
    TRY(dict_range(sediment, "alphaMax", S->alpha_sm, 0, 1, 1));
    TRY(model_select(schemes, "kernel", "SPH kernel",
                     (const void *const *)isph_kernels, "wendlandC2",
                     (const void **)&S->kernel));
    TRY(dict_get_scalar_or(schemes, "smoothingLength", 1.3, &hf));
    TRY(dict_range(schemes, "smoothingLength", hf, 1, 2, 0));
    S->h = hf; /* in dl until the caller knows dl */
    TRY(model_select_index(schemes, "laplacian", "Laplacian normalisation",
                           (const void *const *)norm_table, "traceInverse",
                           &S->norm));
    TRY(dict_get_scalar_or(schemes, "lesCoefficient", 0.1, &S->cs));
    TRY(dict_range(schemes, "lesCoefficient", S->cs, 0, 1, 0));
    TRY(dict_get_scalar_or(schemes, "lesExponent", 1, &S->les_n));
    TRY(dict_range(schemes, "lesExponent", S->les_n, 0, 10, 0));
    TRY(model_select_index(schemes, "sedimentFlux", "sediment flux",
                           (const void *const *)flux_table, "advective",
                           &S->flux));
    TRY(model_select_index(schemes, "drag", "drag integration",
                           (const void *const *)drag_step_table, "explicit",
                           &S->drag));
    TRY(model_select_index(schemes, "wall", "wall scheme",
                           (const void *const *)wall_table, "neumann",
                           &S->wall));
    TRY(model_select_index(schemes, "freeSurface", "free-surface detector",
                           (const void *const *)surface_table, "quadrant",
                           &S->surface));
    TRY(model_select_index(schemes, "shifting", "particle shifting",
                           (const void *const *)shift_table, "none",
                           &S->shift));
    TRY(dict_get_scalar_or(schemes, "shiftingCoefficient", 0.25,
                           &S->shift_coeff));
    TRY(dict_range(schemes, "shiftingCoefficient", S->shift_coeff, 0, 10, 0));
    TRY(dict_get_bool_or(schemes, "clipNegativePressure", 0,
                         &S->clip_negative));
    TRY(model_select_index(schemes, "collision", "collision model",
                           (const void *const *)collision_table, "none",
                           &S->collision));
    TRY(dict_get_scalar_or(schemes, "collisionDistance", 0.5,
                           &S->collision_ratio));
    TRY(dict_range(schemes, "collisionDistance", S->collision_ratio, 0, 1,
                   1));
    TRY(dict_get_scalar_or(schemes, "collisionRestitution", 0.2,
                           &S->collision_e));
    TRY(dict_range(schemes, "collisionRestitution", S->collision_e, 0, 1, 0));
    TRY(model_select_index(schemes, "velocitySmoothing", "velocity smoothing",
                           (const void *const *)smoothing_table, "none",
                           &S->smoothing));
    TRY(dict_get_scalar_or(schemes, "velocitySmoothingCoefficient", 0.2,
                           &S->smoothing_eps));
    TRY(dict_range(schemes, "velocitySmoothingCoefficient",
                   S->smoothing_eps, 0, 1, 0));
    TRY(model_select_index(schemes, "velocitySmoothingRegion",
                           "velocity smoothing region",
                           (const void *const *)region_table, "all",
                           &S->smoothing_surface));
    TRY(dict_get_scalar_or(schemes, "volumeRelaxation", 0, &S->volume_beta));
    return dict_range(schemes, "volumeRelaxation", S->volume_beta, 0, 1, 0);
}

int isph_fields_alloc(struct isph_solver *s, int n)
{
    struct store *st = &s->st;
    store_init(st, "field of the ISPH cloud");
    TRY(store_add(st, "position", "[m]", VTU_FLOAT64, 3, STORE_POINTS,
                  &s->x));
    TRY(store_add(st, "velocity", "water [m/s]", VTU_FLOAT64, 3,
                  STORE_WRITE, &s->u));
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
    TRY(store_add(st, "alpha.sediment", "sediment volume fraction",
                  VTU_FLOAT64, 1, STORE_WRITE, &s->alpha));
    TRY(store_add(st, "U.sediment", "sediment velocity [m/s]", VTU_FLOAT64,
                  3, STORE_WRITE, &s->us));
    TRY(store_add(st, "volume", "V = m_f/(alpha_f rho_f) (5.34) [m^2]",
                  VTU_FLOAT64, 1, STORE_WRITE, &s->V));
    TRY(store_add(st, "nut", "eddy viscosity (5.9) [m^2/s]", VTU_FLOAT64,
                  1, STORE_WRITE, &s->nut));
    TRY(store_add(st, "freeSurface", "1: p = 0", VTU_UINT8, 1, STORE_WRITE,
                  &s->fs));
    TRY(store_resize(st, (size_t)n));
    s->n = n;
    return SIM_OK;
}

/* V = m_f/(alpha_f rho_f) (5.34). */
static double volume(const struct isph_solver *s, int i)
{
    return s->m[i] / ((1 - s->alpha[i]) * s->S.rho_f);
}

static int build_list(struct isph_solver *s)
{
    double t0 = app_wall_time();
    const double rc = s->S.kernel->support * s->S.h * 1.001;
    TRY(cells_build(&s->grid, 2, s->x, s->n, rc / 2, NULL, NULL));
    if (s->grid.n_outside)
        return sim_error(SIM_ERR_NUMERIC, "%d ISPH particles have a "
                         "non-finite position", s->grid.n_outside);
    TRY(neighbour_build(&s->nl, &s->grid, s->x, rc));
    s->t.neighbours += app_wall_time() - t0;
    return SIM_OK;
}

/* V (5.34), dry walls (V = 0, inactive), corrections at the current
 * positions. A wall particle is wet by mlpgFluid's rule (M0-23,
 * pop_wet_walls; doc/theory.md S0-06): above the water its support holds
 * only water below it and its Neumann row loses its diagonal. */
static int prepare(struct isph_solver *s)
{
    pop_wet_walls(&s->nl, s->x, s->type, s->normal, s->S.g, 1,
                  s->S.kernel->support * s->S.h, s->S.dl, s->rows);
    for (int i = 0; i < s->n; i++) {
        if (s->type[i] == ISPH_DUMMY) /* wet with its wall particle */
            s->rows[i] = s->anchor[i] >= 0 && s->rows[s->anchor[i]];
        s->V[i] = s->rows[i] ? volume(s, i) : 0;
    }
    TRY(isph_corrections(&s->cl));
    for (int i = 0; i < s->n; i++) /* an isolated wall particle is dry */
        if (s->isolated[i] && s->type[i] != ISPH_FLUID)
            s->rows[i] = 0, s->V[i] = 0;
    return SIM_OK;
}

/* Two sums of a particle inside the square lattice of spacing dl at V =
 * dl^2: the kernel sum sum_b V_b W_ab, itself included (theta_ref of
 * S0-19), and div r = sum_b V_b (x_b - x_a).grad W_ab (2 for a kernel
 * integrated exactly; 1.948 for Wendland C2 at h = 1.3 dl). */
static void lattice_sums(const struct isph_settings *S, double *theta,
                         double *divr)
{
    const double reach = S->kernel->support * S->h, V = S->dl * S->dl;
    const int m = (int)ceil(reach / S->dl);
    *theta = *divr = 0;
    for (int i = -m; i <= m; i++)
        for (int j = -m; j <= m; j++) {
            double r = S->dl * hypot(i, j);
            if (r >= reach)
                continue;
            *theta += V * S->kernel->w(r, S->h);
            *divr -= V * S->kernel->dw(r, S->h) * r;
        }
}

int isph_solver_init(struct isph_solver *s, const struct isph_settings *S,
                     struct linsolve *ls)
{
    s->S = *S;
    s->ls = ls;
    size_t n = (size_t)s->n;
#define ALLOC(p, k) (s->p = sim_calloc((k) * n, sizeof *s->p))
    if (!ALLOC(x0, 3) || !ALLOC(ustar, 3) || !ALLOC(m, 1) || !ALLOC(L, 4)
        || !ALLOC(c, 1) || !ALLOC(Sv, 2) || !ALLOC(b, 1)
        || !ALLOC(dalpha_f, 1) || !ALLOC(anew, 1) || !ALLOC(gu, 4)
        || !ALLOC(gus, 4)
        || !ALLOC(aflux, 1) || !ALLOC(aw, 2) || !ALLOC(gp, 2) || !ALLOC(w, 2)
        || !ALLOC(divu, 1) || !ALLOC(Tf, 3) || !ALLOC(Ts, 3)
        || !ALLOC(acc_f, 2) || !ALLOC(acc_s, 2) || !ALLOC(gamma, 1)
        || !ALLOC(rows, 1) || !ALLOC(isolated, 1) || !ALLOC(anchor, 1)
        || !ALLOC(divr, 1) || !ALLOC(theta, 1) || !ALLOC(truncated, 1))
        return SIM_ERR_NOMEM;
#undef ALLOC
    for (int i = 0; i < s->n; i++)
        if (s->type[i] == ISPH_DUMMY && S->wall != ISPH_WALL_DUMMY)
            return sim_error(SIM_ERR_INPUT, "particle %d is a dummy "
                             "particle: they go with wall dummyLayers", i);
    for (int i = 0; i < s->n; i++) {
        if (s->type[i] != ISPH_FLUID) { /* walls: pure water at rest */
            s->alpha[i] = 0;
            memset(s->u + 3 * i, 0, 3 * sizeof(double));
            memset(s->us + 3 * i, 0, 3 * sizeof(double));
        }
        if (!(s->alpha[i] >= 0 && s->alpha[i] <= S->alpha_sm))
            return sim_error(SIM_ERR_INPUT, "particle %d: alpha.sediment "
                             "%g outside [0, alphaMax = %g]", i, s->alpha[i],
                             S->alpha_sm);
        /* m_f from the volume the particle stands for (dl^2 at the start) */
        double V = s->V[i] > 0 ? s->V[i] : S->dl * S->dl;
        s->m[i] = V * (1 - s->alpha[i]) * S->rho_f;
        /* dalpha_f = 0 (calloc): the first step has alpha_f^-1 = alpha_f^0 */
    }
    s->cl = (struct isph_cloud){ .n = s->n, .x = s->x, .V = s->V,
                                 .nl = &s->nl, .kernel = S->kernel,
                                 .active = s->rows, .h = S->h,
                                 .norm = S->norm, .L = s->L, .c = s->c,
                                 .S = s->Sv, .isolated = s->isolated,
                                 .divr = S->surface == ISPH_SURFACE_DIVERGENCE
                                       ? s->divr : NULL,
                                 .theta = S->volume_beta > 0 ? s->theta
                                                             : NULL };
    double divr0;
    lattice_sums(S, &s->theta_ref, &divr0);
    s->flux_scale = 2 / divr0;
    TRY(build_list(s));
    isph_find_anchors(s);
    return prepare(s);
}

/* k_f = gamma alpha_s/(alpha_f rho_f): the drag's acceleration of a
 * particle's water is k_f w (5.19), w = u_s - u_f of the step (S0-07). */
static double drag_rate(const struct isph_solver *s, int a)
{
    return s->gamma[a] * s->alpha[a] / ((1 - s->alpha[a]) * s->S.rho_f);
}

/* nu_s^0 (5.7), capped at 0.95 alpha_sm (D-02). */
static double nu_s0(const struct isph_settings *S, double as)
{
    if (as <= 0)
        return 0;
    double a = fmin(as, 0.95 * S->alpha_sm);
    double q = cbrt(S->alpha_sm / a) - 1;
    return 1.2 * S->rho_f / S->rho_s * S->nu_f / (q * q);
}

/* div(alpha_s w)_a, w = u_s - u_f, as the symmetric SPH divergence sum_b
 * V_b 2 (alpha_s w)_ab . grad_a W_ab over the water neighbours, with the
 * pair's flux (alpha_s w)_ab = alpha_s,up (w_a + w_b)/2 taken from the
 * upstream particle (S0-09): the pair terms are antisymmetric (what a
 * loses b gains: sum alpha_s V is kept while V is) and alpha_s stays >= 0
 * while dt sum_b 2 V_b |w.grad W| <= 1. Walls take no sediment. The sum
 * is divided by div r_0/2 of the start lattice (lattice_sums): for a
 * linear flux the sum is div(alpha_s w) times sum_b V_b dx (x) grad W =
 * (div r/2) I, 0.974 I for Wendland C2 at h = 1.3 dl, and undivided the
 * suspension of the batch settling test sank 2.6 % slow. */
static double upwind_flux(const struct isph_solver *s, int a,
                          const double wa[2])
{
    const double reach = s->S.kernel->support * s->S.h;
    double sum = 0;
    for (int64_t k = s->nl.start[a]; k < s->nl.start[a + 1]; k++) {
        int b = s->nl.j[k];
        double r = s->nl.r[k];
        if (b == a || !(r > 0) || r >= reach || !(s->V[b] > 0)
            || s->type[b] != ISPH_FLUID)
            continue;
        double dx[2], gw[2];
        isph_kernel_gradient(&s->cl, a, b, r, dx, gw);
        double f = 0.5 * ((wa[0] + s->us[3 * b] - s->u[3 * b]) * gw[0]
                          + (wa[1] + s->us[3 * b + 1] - s->u[3 * b + 1])
                            * gw[1]);
        int up = f > 0 ? a : b;
        double al = s->alpha[up];
        if (s->S.flux == ISPH_FLUX_MUSCL) {
            /* the upstream value at the pair's midpoint, dx = x_b - x_a,
             * kept between the pair's values and below twice the
             * upstream value, so that an empty particle sends nothing
             * (the same from both sides) */
            const double *g = s->aw + 2 * up, h = up == a ? 0.5 : -0.5;
            al += h * (g[0] * dx[0] + g[1] * dx[1]);
            al = fmin(fmax(al, fmin(s->alpha[a], s->alpha[b])),
                      fmin(fmax(s->alpha[a], s->alpha[b]), 2 * s->alpha[up]));
        }
        sum += 2 * s->V[b] * al * f;
    }
    return s->flux_scale * sum;
}

/* alpha_s^(n+1) (5.28) into anew: every term is at level n. Returns the
 * number of particles clipped to [0, alpha_sm]. */
static long new_alpha(struct isph_solver *s, double dt)
{
    const struct isph_settings *S = &s->S;
    long clipped = 0;
#pragma omp parallel for schedule(static) reduction(+ : clipped)
    for (int a = 0; a < s->n; a++) {
        double as = s->alpha[a], na;
        if (s->type[a] != ISPH_FLUID) {
            s->anew[a] = as;
            continue;
        }
        if (S->flux >= ISPH_FLUX_UPWIND) {
            /* the sediment volume sv = alpha_s V of a particle whose water
             * volume m_f/rho_f is its own: d sv/dt = -V div(alpha_s w)
             * (div u_f drops out); alpha_s = sv/(sv + m_f/rho_f) */
            double sv = s->V[a] * (as - dt * s->aflux[a]);
            double water = s->m[a] / S->rho_f;
            na = sv / (fmax(sv, 0) + water); /* < 0: clipped, counted */
        } else {
            na = as + dt * (-as * s->divu[a] - s->aflux[a]);
        }
        if (na < 0 || na > S->alpha_sm) {
            clipped++;
            na = fmin(fmax(na, 0), S->alpha_sm);
        }
        s->anew[a] = na;
    }
    return clipped;
}

/* Step 1: gradients at r^n, stresses, drag. */
static void gradients(struct isph_solver *s)
{
    const struct isph_settings *S = &s->S;
    const double les = (S->cs * S->dl) * (S->cs * S->dl);
    if (S->flux == ISPH_FLUX_CONSERVATIVE) /* its product, for div below */
        for (int a = 0; a < s->n; a++)
            for (int q = 0; q < 2; q++)
                s->aw[2 * a + q] = s->alpha[a] * (s->us[3 * a + q]
                                                  - s->u[3 * a + q]);
    if (S->flux == ISPH_FLUX_MUSCL) /* grad alpha_s, for the face values */
#pragma omp parallel for schedule(static)
        for (int a = 0; a < s->n; a++) {
            s->aw[2 * a] = s->aw[2 * a + 1] = 0;
            if (s->rows[a] && s->type[a] == ISPH_FLUID)
                isph_gradient(&s->cl, s->alpha, 1, a, s->aw + 2 * a);
        }
#pragma omp parallel for schedule(static)
    for (int a = 0; a < s->n; a++) {
        double *gu = s->gu + 4 * a, *gs = s->gus + 4 * a;
        memset(gu, 0, 4 * sizeof *gu);
        memset(gs, 0, 4 * sizeof *gs);
        s->aflux[a] = s->divu[a] = 0;
        s->gp[2 * a] = s->gp[2 * a + 1] = 0;
        s->nut[a] = s->gamma[a] = 0;
        memset(s->Tf + 3 * a, 0, 3 * sizeof(double));
        memset(s->Ts + 3 * a, 0, 3 * sizeof(double));
        if (!s->rows[a])
            continue;
        for (int q = 0; q < 2; q++) {
            isph_gradient(&s->cl, s->u + q, 3, a, gu + 2 * q);
            isph_gradient(&s->cl, s->us + q, 3, a, gs + 2 * q);
        }
        double rel[2] = { s->us[3 * a] - s->u[3 * a],
                          s->us[3 * a + 1] - s->u[3 * a + 1] }, g0[2], g1[2];
        if (S->flux == ISPH_FLUX_ADVECTIVE) { /* rel . grad alpha_s */
            isph_gradient(&s->cl, s->alpha, 1, a, g0);
            s->aflux[a] = rel[0] * g0[0] + rel[1] * g0[1];
        } else if (S->flux == ISPH_FLUX_CONSERVATIVE) { /* div(alpha_s rel) */
            isph_gradient(&s->cl, s->aw, 2, a, g0);
            isph_gradient(&s->cl, s->aw + 1, 2, a, g1);
            s->aflux[a] = g0[0] + g1[1];
        } else if (s->type[a] == ISPH_FLUID) {
            s->aflux[a] = upwind_flux(s, a, rel);
        }
        if (S->drag == ISPH_DRAG_SEMI_IMPLICIT)
            isph_gradient(&s->cl, s->p, 1, a, s->gp + 2 * a);
        s->divu[a] = gu[0] + gu[3];
        double as = s->alpha[a];
        double damp = pow(fmax(0, 1 - as / S->alpha_sm), S->les_n);
        /* |S| = sqrt(2 S:S), S = (grad u + grad u^T)/2 */
        double sxy = 0.5 * (gu[1] + gu[2]);
        double sf = sqrt(2 * (gu[0] * gu[0] + gu[3] * gu[3] + 2 * sxy * sxy));
        double sxs = 0.5 * (gs[1] + gs[2]);
        double ss = sqrt(2 * (gs[0] * gs[0] + gs[3] * gs[3] + 2 * sxs * sxs));
        double ntf = les * sf * damp, nts = les * ss * damp;
        s->nut[a] = ntf;
        double nf = S->nu_f + ntf, ns = nu_s0(S, as) + nts;
        double *Tf = s->Tf + 3 * a, *Ts = s->Ts + 3 * a;
        Tf[0] = nf * 2 * gu[0];
        Tf[1] = nf * (gu[1] + gu[2]);
        Tf[2] = nf * 2 * gu[3];
        Ts[0] = ns * 2 * gs[0];
        Ts[1] = ns * (gs[1] + gs[2]);
        Ts[2] = ns * 2 * gs[3];
        if (as < ISPH_ALPHA_TRACE) { /* no sediment phase (S0-11) */
            memset(Ts, 0, 3 * sizeof *Ts);
            memset(gs, 0, 4 * sizeof *gs);
        }
        double du = hypot(rel[0], rel[1]);
        /* (5.12)-(5.13) are the Ergun / Wen-Yu law with its switch at
         * alpha_f = 0.8, K of src/coupling/drag (Re -> 0 guarded there) */
        const struct drag_fluid fl = { S->rho_f, S->rho_f * S->nu_f };
        s->gamma[a] = s->type[a] == ISPH_FLUID
                    ? drag_ergun_wen_yu.coeff(&fl, 1 - as, du, S->d_s) : 0;
    }
    /* the divergence of the stress (5.43), fluid and sediment */
    const double reach = S->kernel->support * S->h;
#pragma omp parallel for schedule(static)
    for (int a = 0; a < s->n; a++) {
        double af[2] = { 0, 0 }, asd[2] = { 0, 0 };
        if (s->type[a] == ISPH_FLUID) {
            double fa = 1 - s->alpha[a], sa = s->alpha[a];
            for (int64_t k = s->nl.start[a]; k < s->nl.start[a + 1]; k++) {
                int b = s->nl.j[k];
                double r = s->nl.r[k];
                if (b == a || !(r > 0) || r >= reach || !(s->V[b] > 0))
                    continue;
                double dx[2], gw[2];
                isph_kernel_gradient(&s->cl, a, b, r, dx, gw);
                double fb = 1 - s->alpha[b], sb = s->alpha[b];
                double lf = 1 + 0.5 * log(fb / fa);
                /* D-09: no log factor where a fraction vanishes */
                double ls = sa < ISPH_ALPHA_TRACE || sb < ISPH_ALPHA_TRACE
                          ? 1 : 1 + 0.5 * log(sb / sa);
                const double *Ta = s->Tf + 3 * a, *Tb = s->Tf + 3 * b;
                const double *Sa = s->Ts + 3 * a, *Sb = s->Ts + 3 * b;
                double V = s->V[b];
                af[0] += V * lf * ((Ta[0] + Tb[0]) * gw[0] + (Ta[1] + Tb[1]) * gw[1]);
                af[1] += V * lf * ((Ta[1] + Tb[1]) * gw[0] + (Ta[2] + Tb[2]) * gw[1]);
                asd[0] += V * ls * ((Sa[0] + Sb[0]) * gw[0] + (Sa[1] + Sb[1]) * gw[1]);
                asd[1] += V * ls * ((Sa[1] + Sb[1]) * gw[0] + (Sa[2] + Sb[2]) * gw[1]);
            }
        }
        s->acc_f[2 * a] = af[0];
        s->acc_f[2 * a + 1] = af[1];
        int trace = s->alpha[a] < ISPH_ALPHA_TRACE;
        s->acc_s[2 * a] = trace ? 0 : asd[0];
        s->acc_s[2 * a + 1] = trace ? 0 : asd[1];
    }
}

/* 1 when a free-surface, isolated or dry particle is within reach of a
 * (a itself included): its support is truncated (`truncated`, set once a
 * step at r*). volumeRelaxation (S0-19) acts only where it is not (there
 * theta is short of theta_ref by the missing part of the support, not by
 * a spacing); velocitySmoothingRegion freeSurface (S0-18) only where it
 * is. */
static int near_surface(const struct isph_solver *s, int a)
{
    const double reach = s->S.kernel->support * s->S.h;
    if (s->fs[a] || s->isolated[a])
        return 1;
    for (int64_t k = s->nl.start[a]; k < s->nl.start[a + 1]; k++) {
        int b = s->nl.j[k];
        if (s->nl.r[k] < reach
            && (s->fs[b] || s->isolated[b] || !(s->V[b] > 0)))
            return 1;
    }
    return 0;
}

/* The pressure equation at r* (rows as in isph_solver.h). */
static int assemble(struct isph_solver *s, double dt)
{
    const struct neighbour_list *nl = &s->nl;
    const double rho = s->S.rho_f, reach = s->S.kernel->support * s->S.h;
    struct csr_matrix *A = &s->A;
    int n = s->n;
    if (!A->rowptr || A->n < n) {
        free(A->rowptr);
        A->rowptr = sim_malloc((size_t)(n + 1) * sizeof *A->rowptr);
        if (!A->rowptr)
            return SIM_ERR_NOMEM;
    }
    A->n = n;
    A->rowptr[0] = 0;
    for (int a = 0; a < n; a++)
        A->rowptr[a + 1] = A->rowptr[a] + 1 + (nl->start[a + 1] - nl->start[a]);
    TRY(csr_reserve(A, &s->capA, A->rowptr[n]));
    A->nnz = A->rowptr[n];
    int bad = -1;
#pragma omp parallel for schedule(dynamic, 64)
    for (int a = 0; a < n; a++) {
        int64_t e = A->rowptr[a], k0 = nl->start[a];
        int m = (int)(nl->start[a + 1] - k0);
        A->col[e] = a;
        for (int k = 0; k < m; k++) {
            A->col[e + 1 + k] = nl->j[k0 + k];
            A->val[e + 1 + k] = 0;
        }
        if (!s->rows[a] || s->fs[a]) {
            A->val[e] = 1; /* free surface, dry wall: p = 0 */
            s->b[a] = 0;
            continue;
        }
        if (s->type[a] != ISPH_FLUID && s->S.wall == ISPH_WALL_DUMMY) {
            /* the water's pressure extrapolated (Adami et al. 2012 eq.
             * 27, U = 0): p_a = sum_f W_af (p_f + rho (g + d_f).(x_a -
             * x_f)) / sum_f W_af over the water f in reach, d_f the
             * drag's acceleration of f's water (the grains' weight that
             * the water's pressure carries) */
            double ws = 0, gr = 0;
            for (int k = 0; k < m; k++) {
                int f = nl->j[k0 + k];
                double r = nl->r[k0 + k];
                if (s->type[f] != ISPH_FLUID || !(s->V[f] > 0) || r >= reach)
                    continue;
                double wk = s->S.kernel->w(r, s->S.h);
                A->val[e + 1 + k] = -wk;
                ws += wk;
                double kf = drag_rate(s, f);
                const double *wf = s->w + 2 * f;
                gr += wk * ((s->S.g[0] + kf * wf[0]) * (s->x[3 * a] - s->x[3 * f])
                            + (s->S.g[1] + kf * wf[1])
                              * (s->x[3 * a + 1] - s->x[3 * f + 1]));
            }
            A->val[e] = 1;
            if (ws > 0) {
                for (int k = 0; k < m; k++)
                    A->val[e + 1 + k] /= ws;
                s->b[a] = rho * gr / ws;
                continue;
            }
            /* a dummy out of the water's reach: its wall particle's p
             * plus hydrostatics (a wall particle there is dry: p = 0) */
            int w = s->anchor[a];
            s->b[a] = 0;
            if (w < 0)
                continue;
            for (int k = 0; k < m; k++)
                if (nl->j[k0 + k] == w) {
                    A->val[e + 1 + k] = -1;
                    break;
                }
            s->b[a] = rho * (s->S.g[0] * (s->x[3 * a] - s->x[3 * w])
                             + s->S.g[1] * (s->x[3 * a + 1] - s->x[3 * w + 1]));
            continue;
        }
        if (s->type[a] == ISPH_FLUID) {
            double l[m > 0 ? m : 1], d = 0, div[2];
            isph_laplacian_row(&s->cl, a, l);
            double g0[2], g1[2];
            isph_gradient(&s->cl, s->ustar, 3, a, g0);
            isph_gradient(&s->cl, s->ustar + 1, 3, a, g1);
            div[0] = g0[0] + g1[1];
            for (int k = 0; k < m; k++) {
                A->val[e + 1 + k] = -l[k];
                d += l[k];
            }
            A->val[e] = d;
            double af = 1 - s->alpha[a];
            div[1] = s->dalpha_f[a] / (af * dt);
            if (s->S.volume_beta > 0 && !s->truncated[a])
                div[1] -= s->S.volume_beta * (s->theta[a] / s->theta_ref - 1)
                        / dt;
            s->b[a] = -(rho / dt) * (div[0] + div[1]);
            continue;
        }
        /* a wet wall: n.grad p = (rho/dt) n.(u* - U), U = 0 (5.31) */
        const double *L = s->L + 4 * a, *nn = s->normal + 3 * a;
        double d = 0;
        for (int k = 0; k < m; k++) {
            int b = nl->j[k0 + k];
            double r = nl->r[k0 + k];
            if (b == a || !(r > 0) || r >= reach || !(s->V[b] > 0))
                continue;
            double dx[2], gw[2];
            isph_kernel_gradient(&s->cl, a, b, r, dx, gw);
            double Lg[2] = { L[0] * gw[0] + L[1] * gw[1],
                             L[2] * gw[0] + L[3] * gw[1] };
            double v = s->V[b] * (nn[0] * Lg[0] + nn[1] * Lg[1]);
            A->val[e + 1 + k] = v;
            d -= v;
        }
        A->val[e] = d;
        s->b[a] = rho / dt * (nn[0] * s->ustar[3 * a]
                              + nn[1] * s->ustar[3 * a + 1]);
        if (!(d > 0)) {
#pragma omp critical
            if (bad < 0 || a < bad)
                bad = a;
        }
    }
    if (bad >= 0)
        return sim_error(SIM_ERR_NUMERIC, "ISPH wall particle %d (%g, %g): "
                         "its Neumann row has a non-positive diagonal (its "
                         "neighbours are not on its fluid side: check the "
                         "normals)", bad, s->x[3 * bad], s->x[3 * bad + 1]);
    return SIM_OK;
}

/* freeSurface positionDivergence (S0-14): a water particle whose div r
 * (2 inside the water in 2-D, about 1 on the surface; isph_corrections
 * sums it) is below 1.6 is on the surface too (after Lee et al. 2008): it
 * catches the thin tongues and stretched layers of a fast flow whose four
 * quadrants the walls and a few neighbours fill. */
static void divergence_surface(struct isph_solver *s)
{
    for (int a = 0; a < s->n; a++)
        if (s->type[a] == ISPH_FLUID && s->rows[a])
            s->fs[a] |= s->divr[a] < ISPH_SURFACE_DIV_R;
}

int isph_step(struct isph_solver *s, double dt)
{
    const struct isph_settings *S = &s->S;
    const int n = s->n, dummies = S->wall == ISPH_WALL_DUMMY;
    double t0 = app_wall_time();
    if (s->t.steps > 0) {
        TRY(build_list(s));
        TRY(prepare(s));
    }
    /* 1-2. at r^n: gradients, stresses, drag; u_f*, r* */
    gradients(s);
    for (int a = 0; a < n; a++) {
        double *us = s->ustar + 3 * a;
        us[2] = 0;
        if (s->type[a] != ISPH_FLUID) { /* walls: U + dt g (5.31) */
            us[0] = dt * S->g[0];
            us[1] = dt * S->g[1];
            continue;
        }
        /* drag -F/(alpha_f rho_f), F = gamma alpha_s (u_f - u_s) */
        double kf = drag_rate(s, a);
        double ks = s->gamma[a] / S->rho_s, *w = s->w + 2 * a;
        const double *gs = s->gus + 4 * a, *gp = s->gp + 2 * a;
        for (int q = 0; q < 2; q++)
            w[q] = s->us[3 * a + q] - s->u[3 * a + q];
        if (S->drag == ISPH_DRAG_SEMI_IMPLICIT) {
            double wq[2];
            for (int q = 0; q < 2; q++) { /* a_s - a_f without the drag */
                double af = s->acc_f[2 * a + q] - gp[q] / S->rho_f;
                double as = s->acc_s[2 * a + q] - gp[q] / S->rho_s
                          - (w[0] * gs[2 * q] + w[1] * gs[2 * q + 1]);
                wq[q] = (w[q] + dt * (as - af)) / (1 + dt * (kf + ks));
            }
            w[0] = wq[0];
            w[1] = wq[1];
        }
        for (int q = 0; q < 2; q++)
            us[q] = s->u[3 * a + q] + dt * (s->acc_f[2 * a + q] + S->g[q]
                                            + kf * w[q]);
    }
    if (S->collision == ISPH_COLLISION_LEE2011) /* x0: work, set below */
        pop_collision(&s->nl, s->x, s->type, NULL, S->collision_ratio * S->dl,
                      S->collision_e, s->ustar, s->x0);
    s->n_clipped += new_alpha(s, dt);
    memcpy(s->x0, s->x, 3 * sizeof(double) * (size_t)n);
    for (int a = 0; a < n; a++)
        if (s->type[a] == ISPH_FLUID)
            for (int q = 0; q < 2; q++)
                s->x[3 * a + q] += dt * s->ustar[3 * a + q];
    double t1 = app_wall_time();
    s->t.explicit_ += t1 - t0;
    /* 3. at r*: corrections, free surface, pressure; theta stays r^n's:
     * the predictor's own change of volume is div u*'s */
    double *theta = s->cl.theta;
    s->cl.theta = NULL;
    TRY(build_list(s));
    int rc = prepare(s);
    s->cl.theta = theta;
    TRY(rc);
    for (int a = 0; a < n; a++)
        s->fs[a] = s->type[a] == ISPH_FLUID;
    /* water and wet walls (and their dummies) count as neighbours */
    pop_surface_quadrant(&s->nl, s->x, 2.5 * S->dl, 0.4 * S->dl, s->fs,
                         s->rows, dummies ? s->normal : NULL, s->fs);
    if (S->surface == ISPH_SURFACE_DIVERGENCE)
        divergence_surface(s);
    s->n_surface = 0;
    for (int a = 0; a < n; a++) {
        s->fs[a] = (s->fs[a] || s->isolated[a]) && s->type[a] == ISPH_FLUID;
        s->n_surface += s->fs[a];
    }
    if (S->volume_beta > 0 || S->smoothing_surface)
#pragma omp parallel for schedule(static)
        for (int a = 0; a < n; a++)
            s->truncated[a] = near_surface(s, a);
    TRY(assemble(s, dt));
    double t2 = app_wall_time();
    TRY(linsolve_solve(s->ls, &s->A, s->b, s->p, &s->last));
    if (S->clip_negative)
        isph_clip_negative(s);
    s->t.ppe_iters += s->last.iters;
    double t3 = app_wall_time();
    s->t.ppe += t3 - t2;
    /* 4-5. u_f^{n+1}, r^{n+1}; u_s^{n+1}, alpha_s^{n+1} */
#pragma omp parallel for schedule(static)
    for (int a = 0; a < n; a++) {
        if (s->type[a] != ISPH_FLUID)
            continue;
        double gp[2], uf[2] = { s->u[3 * a], s->u[3 * a + 1] };
        double *us = s->us + 3 * a, as = s->alpha[a];
        isph_gradient(&s->cl, s->p, 1, a, gp);
        const double *gs = s->gus + 4 * a, *w = s->w + 2 * a;
        double rel[2] = { us[0] - uf[0], us[1] - uf[1] };
        double ks = s->gamma[a] / S->rho_s; /* F/(alpha_s rho_s) = ks (u_f - u_s) */
        for (int q = 0; q < 2; q++) {
            s->u[3 * a + q] = s->ustar[3 * a + q] - dt / S->rho_f * gp[q];
            double adv = rel[0] * gs[2 * q] + rel[1] * gs[2 * q + 1];
            us[q] += dt * (-gp[q] / S->rho_s + s->acc_s[2 * a + q] + S->g[q]
                           - ks * w[q] - adv);
        }
        s->dalpha_f[a] = as - s->anew[a]; /* the next step's (5.24) */
        s->alpha[a] = s->anew[a];
    }
    if (S->smoothing != ISPH_SMOOTHING_NONE)
        isph_smooth_velocities(s);
    /* r^(n+1) once every gradient at r* is taken (5.26) */
    for (int a = 0; a < n; a++)
        if (s->type[a] == ISPH_FLUID)
            for (int q = 0; q < 2; q++)
                s->x[3 * a + q] = s->x0[3 * a + q] + dt * s->u[3 * a + q];
    for (int a = 0; a < n; a++)
        if (s->type[a] == ISPH_FLUID
            && s->V[a] > 0) /* V of the new fraction (5.34) */
            s->V[a] = volume(s, a);
    if (dummies)
        isph_keep_off_walls(s);
    if (S->shift == ISPH_SHIFT_LIND2012)
        isph_shift(s);
    for (int a = 0; a < 3 * n; a++)
        if (!isfinite(s->u[a]) || !isfinite(s->us[a]))
            return sim_error(SIM_ERR_NUMERIC, "ISPH particle %d: non-finite "
                             "velocity after the step", a / 3);
    s->t.correction += app_wall_time() - t3;
    s->t.steps++;
    return SIM_OK;
}

void isph_solver_free(struct isph_solver *s)
{
    store_free(&s->st);
    free(s->x0), free(s->ustar), free(s->m), free(s->L), free(s->c);
    free(s->Sv), free(s->b), free(s->dalpha_f), free(s->anew), free(s->gu);
    free(s->gus), free(s->aflux), free(s->aw), free(s->gp), free(s->w),
        free(s->divu), free(s->Tf), free(s->Ts);
    free(s->acc_f), free(s->acc_s), free(s->gamma), free(s->rows);
    free(s->isolated), free(s->anchor), free(s->divr), free(s->theta);
    free(s->truncated);
    cells_free(&s->grid);
    neighbour_free(&s->nl);
    csr_free(&s->A);
    linsolve_free(s->ls);
    memset(s, 0, sizeof *s);
}
