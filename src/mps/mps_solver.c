/* mps_solver.c — creation of the solver state (lattice constants per
 * operator radius, the box, work storage, wall/dummy partners) and the
 * neighbour phase of a step. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "core/log.h"
#include "mps/kernel/kernel.h"
#include "mps/mps.h"
#include "mps/mps_impl.h"
#include "mps/soil/soil_step.h"
#include "mps/stabiliser/stabiliser.h"

void mps_settings_default(struct mps_settings *S)
{
    memset(S, 0, sizeof *S);
    S->rho = 1000;
    S->nu = 1e-6;
    S->g[2] = -9.81;
    S->kernel = &mps_kernel_zhang2014;
    S->re_n = 2.1;
    S->re_grad = 2.1;
    S->re_lap = 3.1;
    S->gamma = 0.01;
    S->beta = 0.8;
    S->alpha = 0.9;
    S->fs_n_max = 0.97;
    S->beta_porous = 0.8;
    S->collision = &mps_stabiliser_none;
    S->shifting = &mps_stabiliser_none;
    S->collision_ratio = 0.5;
    S->collision_restitution = 0.2;
    S->shifting_coeff = 0.01;
    S->renumber_interval = 1;
    S->skin = 0.0;
    S->max_escape_fraction = 0.05;
}

/* Largest operator radius, and the list radius (the cell size). */
static double radius_max(const struct mps_settings *S, double dp)
{
    return dp * fmax(S->re_n, fmax(S->re_grad, S->re_lap));
}

double mps_list_radius(const struct mps_settings *S, double dp)
{
    return radius_max(S, dp) + dp * (S->skin > 0 ? S->skin
                                     : S->predictor ? 0.5 : 0.0);
}

/* Box = bounding box of the start state, widened so that splash has room;
 * the vertical axis gets as much room again above. */
static void box_of(const struct mps_particles *P, double re_max,
                   double lo[3], double hi[3])
{
    int d = P->dim;
    for (int k = 0; k < 3; k++) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    for (int i = 0; i < P->n; i++)
        for (int k = 0; k < d; k++) {
            lo[k] = fmin(lo[k], P->x[3 * i + k]);
            hi[k] = fmax(hi[k], P->x[3 * i + k]);
        }
    for (int k = 0; k < 3; k++) {
        if (k >= d) {
            lo[k] = hi[k] = 0;
            continue;
        }
        double ext = hi[k] - lo[k];
        double m = fmax(4 * re_max, 0.25 * ext);
        lo[k] -= m;
        hi[k] += m + (k == d - 1 ? ext : 0);
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int mps_check_extent(const struct mps_particles *P,
                     const struct mps_settings *S, double dp,
                     const char *origin)
{
    double lo[3], hi[3], h = mps_list_radius(S, dp), cells = 1, worst = 0;
    int axis = 0;
    box_of(P, radius_max(S, dp), lo, hi);
    for (int k = 0; k < P->dim; k++) {
        double m = floor((hi[k] - lo[k]) / h) + 1;
        cells *= m;
        if (m > worst) {
            worst = m;
            axis = k;
        }
    }
    /* the limits of cells_build */
    if (worst <= 1e9 && cells <= 2147483647.0)
        return SIM_OK;
    /* One stray particle (a corrupted or diverged state) is the usual
     * cause: name the one farthest from the median along that axis. */
    double *c = sim_malloc(((size_t)P->n + 1) * sizeof *c);
    if (!c)
        return SIM_ERR_NOMEM;
    for (int i = 0; i < P->n; i++)
        c[i] = P->x[3 * i + axis];
    qsort(c, (size_t)P->n, sizeof *c, cmp_double);
    double med = P->n ? c[P->n / 2] : 0, far = -1;
    free(c);
    int which = 0;
    for (int i = 0; i < P->n; i++)
        if (fabs(P->x[3 * i + axis] - med) > far) {
            far = fabs(P->x[3 * i + axis] - med);
            which = i;
        }
    const double *x = P->x + 3 * which;
    char who[64] = "";
    if (P->id)
        snprintf(who, sizeof who, "id %lld, ", (long long)P->id[which]);
    return sim_error(SIM_ERR_INPUT, "%s: particle (%spoint %d) at "
                     "(%g %g %g) lies %g m from the median of the particles "
                     "along %c: the domain box around them would need %.3g "
                     "neighbour cells of %g m (at most 2^31)",
                     origin ? origin : "the start state", who, which, x[0],
                     x[1], x[2], far, "xyz"[axis], cells, h);
}

/* The per-particle work arrays for P.cap particles (a distributed run's
 * count changes every step); contents are per step, not kept. */
int mps_fit_work(struct mps_solver *s)
{
    const size_t c = (size_t)s->P.cap, had = s->ustar ? (size_t)s->cap_work : 0;
    if (s->ustar && c <= had && (!s->halo || s->gunk))
        return SIM_OK;
    const size_t old = had < c ? had : c;
    /* grown arrays start at zero in their new part, as calloc's did */
#define FIT(a, k) do {                                                     \
        void *t_ = sim_realloc(s->a, (k) * c * sizeof *s->a + 1);          \
        if (!t_)                                                           \
            return SIM_ERR_NOMEM;                                          \
        s->a = t_;                                                         \
        memset(s->a + (k) * old, 0, (k) * (c - old) * sizeof *s->a);       \
    } while (0)
    FIT(ustar, 3); FIT(grad, 3); FIT(lap, 3); FIT(div, 1);
    FIT(rows_fluid, 1); FIT(rows_ppe, 1); FIT(rows_list, 1);
    FIT(perm, 1); FIT(unk, 1); FIT(b, 1); FIT(sol, 1); FIT(x_ref, 3);
    if (s->halo) {
        FIT(gunk, 1);
        FIT(gcol, 1);
    }
#undef FIT
    int64_t *rp = sim_realloc(s->A.rowptr, (c + 1) * sizeof *rp);
    if (!rp)
        return SIM_ERR_NOMEM;
    if (!s->A.rowptr)
        rp[0] = 0;
    s->A.rowptr = rp;
    s->cap_work = (int)c;
    return SIM_OK;
}

static int build_list(struct mps_solver *s);

int mps_solver_init(struct mps_solver *s, struct mps_particles *P,
                    const struct mps_settings *S, double dp,
                    struct linsolve *ls)
{
    memset(s, 0, sizeof *s);
    s->P = *P;
    store_moved(&s->P.st, P, &s->P, sizeof *P);
    memset(P, 0, sizeof *P);
    /* P->n is the caller's word (a test may fill part of the room) */
    TRY(store_resize(&s->P.st, (size_t)s->P.n));
    s->P.cap = (int)s->P.st.cap;
    s->S = *S;
    s->dp = dp;
    s->ls = ls;
    int d = s->P.dim;
    const struct mps_kernel_ops *K = S->kernel;
    TRY(mps_lattice_constants(K, d, dp, S->re_n * dp, &s->Ln));
    TRY(mps_lattice_constants(K, d, dp, S->re_grad * dp, &s->Lg));
    TRY(mps_lattice_constants(K, d, dp, S->re_lap * dp, &s->Ll));
    s->re_max = radius_max(S, dp);
    /* Rows split at the larger of the number-density and gradient radii
     * when the Laplacian's is larger: their operators (and the collision
     * model) then skip the outer pairs, 60-70 % of a row at 2.1 / 3.1 dp. */
    double r_in = dp * fmax(S->re_n, S->re_grad);
    s->nl.r_inner = r_in < s->re_max ? r_in : 0.0;
    s->nl.measure_r = S->measure_r;
    /* With the predictor, pairs are re-measured at r* = r + dt u*: a skin
     * of half a spacing keeps pairs that come into range (a Courant
     * number below 0.25 moves two particles together by < 0.5 dp). */
    s->r_list = mps_list_radius(S, dp);
    log_info("MPS lattice (%d-D, dp = %g m, kernel %s):", d, dp, K->name);
    log_info("    number density r_e = %g dp: n0 = %.6f, %d neighbours, "
             "|F0| = %.4f", S->re_n, s->Ln.n0, s->Ln.nnb, s->Ln.f0);
    log_info("    gradient       r_e = %g dp: n0 = %.6f", S->re_grad, s->Lg.n0);
    log_info("    Laplacian      r_e = %g dp: n0 = %.6f, lambda = %.6f dp^2",
             S->re_lap, s->Ll.n0, s->Ll.lambda / (dp * dp));
    for (int i = 0; i < s->P.n; i++)
        s->n_fluid0 += s->P.type[i] == MPS_FLUID;
    for (int k = 0; k < S->n_wall_motion && S->wall_motion; k++)
        s->walls_move |= wall_motion_moves(&S->wall_motion[k])
                         || isfinite(S->wall_motion[k].remove_at);
    if (s->walls_move) {
        s->wall_dx = sim_calloc(3 * (size_t)S->n_wall_motion,
                                sizeof *s->wall_dx);
        if (!s->wall_dx)
            return SIM_ERR_NOMEM;
    }
    TRY(mps_check_extent(&s->P, S, dp, NULL));
    box_of(&s->P, s->re_max, s->box_lo, s->box_hi);
    TRY(mps_fit_work(s));
    s->setup_rows = 1;
    TRY(mps_neighbours(s));
    /* Partners are searched over the whole list radius (skin included),
     * then the rows go back to the operators' radius. */
    s->nl.rc = s->r_list;
    TRY(neighbour_update(&s->nl, s->P.x));
    TRY(mps_find_partners(s));
    s->nl.rc = s->re_max;
    TRY(neighbour_update(&s->nl, s->P.x));
    s->n_thin_walls = mps_thin_walls(s);
    /* the setup list's rows (every wall and dummy) outnumber those of the
     * run's lists: its storage goes, so that it does not set the peak */
    mps_drop_list(s);
    /* From here on only particles that can see water within the list
     * radius get rows (list_rows); the list is built again on the same
     * grid, order unchanged. */
    s->setup_rows = 0;
    s->dummy_rows = s->S.dummy_pressure == MPS_DUMMY_P_EXTRAPOLATED;
    TRY(build_list(s));
    TRY(mps_soil_init(s));   /* before the weights: it stores them */
    return mps_weights(s);
}

void mps_solver_free(struct mps_solver *s)
{
    mps_particles_free(&s->P);
    cells_free(&s->grid);
    neighbour_free(&s->nl);
    free(s->w_n);
    if (s->w_g != s->w_n)
        free(s->w_g);
    if (s->w_l != s->w_n && s->w_l != s->w_g)
        free(s->w_l);
    free(s->wrow);
    free(s->ustar); free(s->grad); free(s->lap); free(s->div);
    free(s->rows_fluid); free(s->rows_ppe); free(s->rows_list);
    free(s->cell_wet);
    free(s->perm); free(s->unk); free(s->b); free(s->sol);
    free(s->A.rowptr); free(s->A.col); free(s->A.val); free(s->x_ref);
    free(s->gunk); free(s->gcol);
    free(s->wall_dx);
    mps_soil_free(s);
    linsolve_free(s->ls);
    memset(s, 0, sizeof *s);
}

/* Stored weights (the soil model): arrays of the list's size. */
static int grow_weights(struct mps_solver *s)
{
    size_t want = (size_t)s->nl.nnz + 1;
    if (want <= s->cap_w)
        return SIM_OK;
    size_t c = want + want / 8;   /* the slack of neighbour.c's entries */
    const struct mps_settings *S = &s->S;
    int share_g = S->re_grad == S->re_n;
    int share_l = S->re_lap == S->re_n ? 1 : S->re_lap == S->re_grad ? 2 : 0;
    double *wn = sim_realloc(s->w_n, c * sizeof *wn);
    if (!wn)
        return SIM_ERR_NOMEM;
    double *wg = share_g ? wn : sim_realloc(s->w_g == s->w_n ? NULL : s->w_g,
                                            c * sizeof *wg);
    if (!wg)
        return SIM_ERR_NOMEM;
    double *wl = share_l == 1 ? wn : share_l == 2 ? wg
               : sim_realloc(s->w_l == s->w_n || s->w_l == s->w_g ? NULL
                             : s->w_l, c * sizeof *wl);
    if (!wl)
        return SIM_ERR_NOMEM;
    s->w_n = wn;
    s->w_g = wg;
    s->w_l = wl;
    s->cap_w = c;
    return SIM_OK;
}

static double radius(const struct mps_solver *s, enum mps_radius which)
{
    const struct mps_settings *S = &s->S;
    return (which == MPS_W_N ? S->re_n : which == MPS_W_G ? S->re_grad
                                                         : S->re_lap) * s->dp;
}

struct pop_weights mps_w(const struct mps_solver *s, enum mps_radius which)
{
    const double *w = which == MPS_W_N ? s->w_n
                    : which == MPS_W_G ? s->w_g : s->w_l;
    if (w)
        return (struct pop_weights){ .w = w };
    return (struct pop_weights){
        .fn = s->S.kernel->weights, .re = radius(s, which),
        .buf = s->wrow + (size_t)which * s->wrow_threads * s->cap_wrow,
        .cap = s->cap_wrow };
}

/* Stored weights of one radius from the list's distances. */
static void store_weights(struct mps_solver *s, enum mps_radius which,
                          double *w)
{
    const struct neighbour_list *nl = &s->nl;
    const double re = radius(s, which);
    pop_weights_fn *fn = s->S.kernel->weights;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < nl->n; i++) {
        const int64_t k0 = nl->start[i], k1 = nl->start[i + 1];
        fn(neighbour_row_r(nl, i, k0, k1), k1 - k0, re, w + k0);
    }
}

/* The list (radius re_max + skin) still holds every pair within re_max
 * while no particle has moved more than half the skin since the build;
 * with the predictor the step's own displacement dt |u*| counts too. */
int mps_list_valid(const struct mps_solver *s)
{
    const struct mps_particles *P = &s->P;
    double half = 0.5 * (s->r_list - s->re_max), m = 0, um = 0;
    if (half <= 0 || s->n_builds == 0 || s->S.skin <= 0 || s->rebuild)
        return 0;
    double g = sqrt(s->S.g[0] * s->S.g[0] + s->S.g[1] * s->S.g[1]
                    + s->S.g[2] * s->S.g[2]);
#pragma omp parallel for reduction(max : m, um)
    for (int i = 0; i < P->n; i++) {
        if (P->type[i] != MPS_FLUID && !s->walls_move)
            continue;   /* fixed walls stay where the list saw them */
        double d = 0, u = 0;
        for (int q = 0; q < 3; q++) {
            d += pow(P->x[3 * i + q] - s->x_ref[3 * i + q], 2);
            u += P->u[3 * i + q] * P->u[3 * i + q];
        }
        m = fmax(m, d);
        um = fmax(um, u);
    }
    double pred = s->S.predictor ? 1.5 * s->dt_last * (sqrt(um) + g * s->dt_last)
                                 : 0.0;
    return sqrt(m) + pred < half;
}

void mps_request_rebuild(struct mps_solver *s)
{
    s->rebuild = 1;
}

/* Which particles get a row. The sums of a wall or dummy particle are read
 * only where water is near: the PPE row and free-surface test of a wet
 * wall particle (a dry one is p = 0 whatever its row), the extrapolated
 * pressure of a wall or dummy particle (0 or the partner's without fluid
 * neighbours). Dry walls and the dummy layers are most of a tank's
 * particles. Fluid cannot come within r_e of a particle with no fluid
 * within r_list before the list is rebuilt, and cells are r_list wide, so
 * "a fluid particle in one of the 3^d cells around" is a safe test. */
static int list_rows(struct mps_solver *s)
{
    const struct mps_particles *P = &s->P;
    const struct cell_grid *g = &s->grid;
    if ((size_t)g->ncell > s->cap_cells) {
        uint8_t *c = sim_realloc(s->cell_wet, (size_t)g->ncell);
        if (!c)
            return SIM_ERR_NOMEM;
        s->cell_wet = c;
        s->cap_cells = (size_t)g->ncell;
    }
    memset(s->cell_wet, 0, (size_t)g->ncell);
    for (int i = 0; i < P->n; i++)
        if (P->type[i] == MPS_FLUID && g->cell_of[i] < g->ncell)
            s->cell_wet[g->cell_of[i]] = 1;
    const int nx = g->nc[0], ny = g->nc[1], nz = g->nc[2];
    const int rz = P->dim == 3;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++) {
        int ic[3];
        uint8_t need = P->type[i] == MPS_FLUID;
        if (!need && (P->type[i] == MPS_WALL || s->dummy_rows)
            && cells_locate(g, P->x + 3 * i, ic))
            for (int z = ic[2] - rz; z <= ic[2] + rz && !need; z++)
                for (int y = ic[1] - 1; y <= ic[1] + 1 && !need; y++)
                    for (int x = ic[0] - 1; x <= ic[0] + 1 && !need; x++)
                        need = x >= 0 && x < nx && y >= 0 && y < ny
                            && z >= 0 && z < nz
                            && s->cell_wet[x + nx * (y + ny * (int64_t)z)];
        s->rows_list[i] = need;
    }
    return SIM_OK;
}

/* The list (candidates within r_list) on the current grid, and weights. */
static int build_list(struct mps_solver *s)
{
    struct mps_particles *P = &s->P;
    s->nl.rows = NULL;
    if (s->setup_rows) {
        /* the first list serves the partner search (dummy rows) and the
         * wall depth (wall rows) only: fluid rows and weights there would
         * set the run's peak memory (5.9 kB per particle in the 3-D
         * Kleefsman tank, against 3.x kB after it) */
        for (int i = 0; i < P->n; i++)
            s->rows_list[i] = P->type[i] != MPS_FLUID;
        s->nl.rows = s->rows_list;
        return neighbour_build_skin(&s->nl, &s->grid, P->x, s->re_max,
                                    s->r_list - s->re_max);
    }
    if (!s->all_rows) {
        TRY(list_rows(s));
        s->nl.rows = s->rows_list;
    }
    TRY(neighbour_build_skin(&s->nl, &s->grid, P->x, s->re_max,
                             s->r_list - s->re_max));
    memcpy(s->x_ref, P->x, sizeof *P->x * 3 * P->n);
    return SIM_OK;
}

int mps_escaped(struct mps_solver *s, long lost)
{
    const struct mps_settings *S = &s->S;
    s->n_escaped += lost;
    log_info("    %ld fluid particle(s) left the domain [%g %g %g] - "
             "[%g %g %g] and were removed (%ld in total)", lost,
             s->box_lo[0], s->box_lo[1], s->box_lo[2], s->box_hi[0],
             s->box_hi[1], s->box_hi[2], s->n_escaped);
    if (s->n_escaped > S->max_escape_fraction * s->n_fluid0)
        return sim_error(SIM_ERR_INPUT, "%ld of %d fluid particles have "
                         "left the domain (more than maxEscapeFraction "
                         "%g): the run is unstable or the tank is open",
                         s->n_escaped, s->n_fluid0, S->max_escape_fraction);
    return SIM_OK;
}

void mps_drop_list(struct mps_solver *s)
{
    const double r_inner = s->nl.r_inner;
    neighbour_free(&s->nl);
    s->nl.r_inner = r_inner;
    s->nl.measure_r = s->S.measure_r;
}

int mps_neighbours(struct mps_solver *s)
{
    struct mps_particles *P = &s->P;
    const struct mps_settings *S = &s->S;
    /* Cells of the list radius: smaller ones would visit fewer candidates
     * but renumber the particles in another order, which changes every sum
     * by round-off, and the coupled 2-D sedimentation case
     * (test/cases/mpsDemSedimentation2D.sh) amplifies that beyond its
     * tolerances; with these cells the results are those of the former
     * full-list code to the bit. */
    const double cell_h = s->r_list;
    if (mps_list_valid(s)) {
        TRY(neighbour_update(&s->nl, P->x));   /* pairs within re_max only */
        return mps_weights(s);
    }
    s->n_builds++;
    s->t.builds++;
    s->rebuild = 0;
    TRY(cells_build(&s->grid, P->dim, P->x, P->n, cell_h, s->box_lo,
                    s->box_hi));
    if (s->grid.n_outside) {
        int lost;
        TRY(mps_particles_drop_outside(s, &lost));
        TRY(mps_escaped(s, lost));
        TRY(cells_build(&s->grid, P->dim, P->x, P->n, cell_h, s->box_lo,
                        s->box_hi));
    }
    if (S->renumber_interval > 0
        && (s->n_builds - 1) % S->renumber_interval == 0) {
        memcpy(s->perm, s->grid.order, sizeof *s->perm * P->n);
        TRY(mps_particles_permute(s, s->perm, P->n));
        TRY(cells_build(&s->grid, P->dim, P->x, P->n, cell_h, s->box_lo,
                        s->box_hi));
    }
    TRY(build_list(s));
    return s->setup_rows ? SIM_OK : mps_weights(s);
}

int mps_weights(struct mps_solver *s)
{
    /* room for the longest row of the list, per radius and thread */
    TRY(neighbour_grow_rows(&s->nl, 3, &s->wrow, &s->cap_wrow,
                            &s->wrow_threads));
    if (!s->soil)
        return SIM_OK;
    TRY(grow_weights(s));
    store_weights(s, MPS_W_N, s->w_n);
    if (s->w_g != s->w_n)
        store_weights(s, MPS_W_G, s->w_g);
    if (s->w_l != s->w_n && s->w_l != s->w_g)
        store_weights(s, MPS_W_L, s->w_l);
    return SIM_OK;
}
