/*
 * isph_solver.h — the two-phase ISPH step of isphSediment (Pan 2022
 * thesis ch. 5, Fig. 5.2; doc/theory.md S.3): one set of particles moves
 * with the water and carries the sediment volume fraction alpha_s and the
 * sediment velocity u_s. One step (D.7 of the thesis's algorithm):
 *
 *   1. at r^n: corrections (isph.h), grad u_f, grad u_s, grad alpha_s,
 *      div u_f; |S|, nu_t = (C dl)^2 |S| (1 - alpha_s/alpha_sm)^n (5.9),
 *      T_k = (nu_k^0 + nu_t)(grad u_k + grad u_k^T) (5.5); drag gamma
 *      (5.12)-(5.13)
 *   2. u_f* = u_f + dt [div-term (5.43) + g - gamma alpha_s (u_f - u_s)/
 *      (alpha_f rho_f)] (5.19);  r* = r + u_f* dt (5.20)
 *   3. at r*: corrections, free-surface flags (5.32)-(5.33), the pressure
 *      equation (5.24)/(5.44): (dt/rho_f) lap p = div u_f* + (alpha_f^n -
 *      alpha_f^(n-1))/(alpha_f^n dt); walls n.grad p = (rho_f/dt)
 *      n.(u_f* - U) (5.31); surface p = 0
 *   4. u_f^(n+1) = u_f* - (dt/rho_f) grad p (5.25); r^(n+1) = r^n +
 *      u_f^(n+1) dt (5.26)
 *   5. u_s^(n+1) (5.27), alpha_s^(n+1) (5.28) with (5.41) (advective, as
 *      printed) or div(alpha_s (u_s - u_f)) (conservative, or the
 *      pairwise upwind form; S0-09),
 *      clamped to [0, alpha_sm]; V = m_f/(alpha_f rho_f) (5.34)
 *
 * The drag in 2 and 5 acts on one relative velocity w = u_s - u_f, equal
 * and opposite: w^n (explicit, as printed) or, semi-implicit (S0-07),
 * w~ = (w^n + dt (a_s - a_f))/(1 + dt (k_f + k_s)) with the phases'
 * other accelerations a (grad p^n at r^n for the pressure's) and k_f =
 * gamma alpha_s/(alpha_f rho_f), k_s = gamma/rho_s: the backward-Euler
 * relaxation of w, stable for any dt gamma and exact at terminal slip.
 *
 * Wall particles (type 1) are one layer on the walls, at rest (u = U = 0),
 * pure fluid (alpha_s = 0); a wall particle with no water particle in its
 * support is dry: p = 0 and V = 0, so it takes part in no sum. Two wall
 * schemes (system/isphSchemes `wall`, doc/theory.md S0-13):
 *   neumann      one layer, the row (5.31) (the thesis);
 *   dummyLayers  the wall particles (type 1) and the dummy layers behind
 *                them (type 2; wallLayers 3 in system/particleDict) are
 *                full neighbours, and their pressure is the water's
 *                extrapolated (Adami et al. 2012 eq. 27, U = 0): p_w =
 *                sum_f W_wf (p_f + rho_f (g + d_f).(x_w - x_f)) / sum_f
 *                W_wf over the water f in reach, d_f the drag's
 *                acceleration of f's water, one row of the same matrix.
 *                A dummy out of the water's reach takes its nearest wall
 *                particle's p plus hydrostatics and is dry with it.
 */
#ifndef MPSDEM_ISPH_ISPH_SOLVER_H
#define MPSDEM_ISPH_ISPH_SOLVER_H

#include <stdint.h>

#include "isph/isph.h"
#include "linsolve/linsolve.h"
#include "particles/cells.h"
#include "particles/neighbour.h"
#include "particles/store.h"

struct dict;

enum { ISPH_FLUID = 0, ISPH_WALL = 1, ISPH_DUMMY = 2 };

/* Below this alpha_s a particle carries no sediment phase: no log factor
 * (D-09), no sediment stress and no advection of u_s (S0-11), so that
 * u_s there is a single grain's (gravity, buoyancy, drag). */
#define ISPH_ALPHA_TRACE 1e-6

struct isph_settings {
    double rho_f, nu_f, g[3];
    double rho_s, d_s, alpha_sm; /* sediment (constant/sedimentProperties) */
    double dl, h;                /* spacing, smoothing length [m]          */
    const struct isph_kernel *kernel;
    int norm;                    /* enum isph_lap_norm (S0-03)             */
    double cs, les_n;            /* Smagorinsky C (0.1), exponent n (S0-04) */
    int flux;                    /* enum isph_flux (S0-09)                 */
    int drag;                    /* enum isph_drag (S0-07)                 */
    int wall;                    /* enum isph_wall (S0-13)                 */
    int surface;                 /* enum isph_surface (S0-14)              */
    int shift;                   /* enum isph_shift (S0-15)                */
    double shift_coeff;          /* lind2012: A of D = A h^2               */
    int clip_negative;           /* 1: p < 0 set to 0 after the solve (S0-17) */
    int collision;               /* enum isph_collision (S0-16)            */
    double collision_ratio, collision_e; /* lee2011: distance [dl], e      */
    int smoothing;               /* enum isph_smoothing (S0-18)            */
    double smoothing_eps;        /* eps per step                           */
    int smoothing_surface;       /* 1: near the free surface only (S0-18)  */
    double volume_beta;          /* volumeRelaxation (S0-19), 0: off       */
};

enum isph_flux { /* the pairwise ones last (>= ISPH_FLUX_UPWIND) */
    ISPH_FLUX_ADVECTIVE,
    ISPH_FLUX_CONSERVATIVE,
    ISPH_FLUX_UPWIND,
    ISPH_FLUX_MUSCL
};
enum isph_drag { ISPH_DRAG_EXPLICIT, ISPH_DRAG_SEMI_IMPLICIT };
enum isph_wall { ISPH_WALL_NEUMANN, ISPH_WALL_DUMMY };
enum isph_surface { ISPH_SURFACE_QUADRANT, ISPH_SURFACE_DIVERGENCE };
enum isph_shift { ISPH_SHIFT_NONE, ISPH_SHIFT_LIND2012 };
enum isph_collision { ISPH_COLLISION_NONE, ISPH_COLLISION_LEE2011 };
enum isph_smoothing {
    ISPH_SMOOTHING_NONE,
    ISPH_SMOOTHING_SHEPARD,
    ISPH_SMOOTHING_BIHARMONIC
};

/* freeSurface positionDivergence: surface below this div r (2 inside
 * the water in 2-D; Lee et al. 2008 take 1.5, S0-14 says why 1.6) */
#define ISPH_SURFACE_DIV_R 1.6

struct isph_timers {
    long steps, ppe_iters;
    double neighbours, explicit_, ppe, correction;
};

struct isph_solver {
    struct isph_settings S;
    struct store st;
    int n;
    /* registered fields */
    double *x, *u, *p, *normal, *alpha, *us, *nut;
    int32_t *type, *patch;
    int64_t *id;
    uint8_t *fs;
    /* work */
    double *x0, *ustar, *V, *m, *L, *c, *Sv, *b;
    double *dalpha_f;            /* alpha_f^n - alpha_f^(n-1) (5.24)       */
    double *anew;                /* alpha_s^(n+1) (5.28)                   */
    double *aflux;               /* the sediment flux term of (5.28) at n  */
    double *aw;                  /* at n, 2 per particle: alpha_s (u_s - u_f)
                                    (conservative), grad alpha_s (muscl)  */
    double *gp;                  /* grad p^n at r^n (semi-implicit drag)    */
    double *w;                   /* the relative velocity u_s - u_f that the
                                    drag acts on, 2 per particle (S0-07)   */
    double *gu, *gus, *divu, *Tf, *Ts, *acc_f, *acc_s, *gamma;
    uint8_t *rows;               /* 1: water, wet wall (isph_cloud.active)   */
    int *anchor;                 /* a dummy's nearest wall particle, else -1 */
    double *divr;                /* div r (isph_cloud.divr)                 */
    double *theta;               /* kernel sum (isph_cloud.theta)           */
    double theta_ref;            /* its value inside the start lattice      */
    double flux_scale;           /* 2/div r of that lattice (upwind, S0-09) */
    uint8_t *truncated;          /* 1: a free-surface, isolated or dry
                                    particle in reach (S0-18, S0-19)      */
    uint8_t *isolated;           /* 1: singular corrections (isph.h): a
                                    water particle has p = 0 and no
                                    gradients, a wall particle is dry     */
    struct cell_grid grid;
    struct neighbour_list nl;
    struct isph_cloud cl;
    struct csr_matrix A;
    size_t capA;
    struct linsolve *ls;
    struct linsolve_stats last;
    struct isph_timers t;
    long n_surface, n_clipped;
    long n_pushed;               /* water particles put back off a wall    */
};

/* constant/transportProperties (rho, nu), constant/sedimentProperties
 * (rho, d, alphaMax), system/isphSchemes (kernel, smoothingLength,
 * laplacian, lesCoefficient, lesExponent). */
int isph_settings_read(const struct dict *transport,
                       const struct dict *sediment, const struct dict *schemes,
                       struct isph_settings *S);
extern const struct model_choice isph_solver_choices[];

/* Register the fields in s->st and size it for n particles. */
int isph_fields_alloc(struct isph_solver *s, int n);

/* Take the settings and the linear solver (owned from now on); the store
 * must hold the particles with x, u, p, normal, type, patch, alpha, us. */
int isph_solver_init(struct isph_solver *s, const struct isph_settings *S,
                     struct linsolve *ls);

int isph_step(struct isph_solver *s, double dt);

/* shifting lind2012 (shifting.c; doc/theory.md S0-15): move the water
 * particles at r^(n+1) by the Fickian shift, with the free-surface flags
 * of the step. */
void isph_shift(struct isph_solver *s);

/* velocitySmoothing (smoothing.c; S0-18), after the update. */
void isph_smooth_velocities(struct isph_solver *s);

/* wall dummyLayers (walls.c; S0-13, S0-17): each dummy's nearest wall
 * particle (anchor, -1 if none in reach), once; the wall and dummy rows
 * evaluated again after the water's p < 0 is clipped; water particles
 * put back off the walls after the step. */
void isph_find_anchors(struct isph_solver *s);
void isph_clip_negative(struct isph_solver *s);
void isph_keep_off_walls(struct isph_solver *s);

void isph_solver_free(struct isph_solver *s);

#endif
