/*
 * mps.h — the incompressible MPS fluid solver (Xie et al. 2025, doc/theory.md
 * A.2-A.5, A.9, A.10 with eps = 1): particle storage, settings, and one
 * time step as a fixed sequence of phases.
 *
 *   mps_solver_init   lattice constants (n0, lambda, |F0|), the cell box,
 *                     wall/dummy book-keeping, work storage
 *   mps_step          neighbours -> prediction -> number density and free
 *                     surface -> PPE -> correction -> position update
 *   mps_propose_dt    Courant and viscous limits (A.8 eq. 37)
 *   mps_check_setup   settings that cannot run stably, refused before the
 *                     first step
 *
 * Particles (structure of arrays; vectors interleaved x y z, z = 0 in 2-D):
 * type 0 fluid, 1 wall (in the PPE; moves only with its patch's
 * prescribed motion), 2 dummy (number density
 * and neighbour sums only; pressure copied from the nearest wall particle,
 * doc/theory.md A.9). Particles are renumbered in cell order every
 * `renumberInterval` steps; `id` follows each particle.
 *
 * Coupling hooks: `inv_eps` (1/eps per particle), `f_ext` (force per unit
 * mass added in the prediction, e.g. -f_A/rho), `ppe_scale` and
 * `corr_scale` (per-particle factors of the PPE source and of the pressure
 * correction) are NULL for a single-phase case and are then neither read
 * nor allocated. Every operator takes inv_eps.
 *
 * Moving and removed walls (settings wall_motion, one per patch, from the
 * regions of system/particleDict): at the start of each step the wall and
 * dummy particles of a removed patch are deleted, and those of a moving
 * patch get the velocity (d(t + dt) - d(t))/dt, which the viscous term
 * (no-slip) and the PPE's divergence see; at its end they are moved by
 * d(t + dt) - d(t). Positions follow the prescribed displacement to
 * round-off, whatever dt (walls.c).
 */
#ifndef MPSDEM_MPS_MPS_H
#define MPSDEM_MPS_MPS_H

#include <stdint.h>

#include "core/select.h"
#include "linsolve/linsolve.h"
#include "particles/motion/motion.h"
#include "mps/operators.h"
#include "particles/cells.h"
#include "particles/halo.h"
#include "particles/neighbour.h"
#include "particles/store.h"

struct mps_kernel_ops;
struct mps_soil;
struct soil_props;
struct mps_stabiliser_ops;

enum { MPS_FLUID = 0, MPS_WALL = 1, MPS_DUMMY = 2 };

/* Free-surface flag values (field "freeSurface"). */
enum { MPS_INNER = 0, MPS_SURFACE = 1, MPS_DRY_WALL = 2 };

/* pressureGradient: eq. (8) | Koshizuka p_min | corrective matrix (GC). */
enum { MPS_GRAD_SYMMETRIC = 0, MPS_GRAD_PMIN = 1, MPS_GRAD_CORRECTED = 2 };

/* dummyPressure: nearest wall particle (A.9) | 0 | wall and dummy
 * pressure extrapolated from the fluid (Adami et al. 2012; walls.c). */
enum {
    MPS_DUMMY_P_WALL = 0, MPS_DUMMY_P_ZERO = 1, MPS_DUMMY_P_EXTRAPOLATED = 2
};

/* freeSurface { pressure }: P = 0 at surface particles (A.4) | p = 0 on
 * the surface dp/2 outside them (surface_pressure.c). */
enum { MPS_FS_P_ZERO = 0, MPS_FS_P_EXTRAPOLATED = 1 };

/* The arrays are registered by name in `st` (particles/store.h), which
 * grows, renumbers, compacts and writes them all; n and cap repeat the
 * registry's counts as int for the solver's loops. */
struct mps_particles {
    int n, cap, dim;
    struct store st;
    double *x;        /* 3n positions [m]                                */
    double *u;        /* 3n velocities [m/s]                             */
    double *p;        /* n pressure [Pa]                                 */
    double *normal;   /* 3n wall/dummy normal, fluid -> solid            */
    int32_t *type;    /* MPS_FLUID | MPS_WALL | MPS_DUMMY                */
    int32_t *patch;   /* -1 fluid, else wall patch index                 */
    int64_t *id;      /* persistent particle id                          */
    int32_t *partner; /* dummy: index of its wall particle; else -1      */
    double *nd;       /* number density / n0 (number-density radius)     */
    uint8_t *fs;      /* MPS_INNER | MPS_SURFACE | MPS_DRY_WALL          */
    double *inv_eps;  /* NULL (single phase) or n values of 1/eps        */
    double *f_ext;    /* NULL or 3n extra acceleration [m/s^2]           */
    double *ppe_scale;  /* NULL or n factors of the PPE source (Model B:
                           eps_i, eq. 13)                                */
    double *corr_scale; /* NULL or n factors of the pressure correction
                           dt/rho grad P (Model B: 1/eps_i, eq. 5)       */
    double *phi;      /* NULL or n fluid volume fractions: particle i
                         holds phi_i dp^d of fluid (genParticles
                         grainVolume scale); the coupling then weighs
                         neighbours by phi_j/eps_j in inv_eps            */
    int32_t *phase;   /* NULL (no soil) or n: 1 soil, 0 water and walls  */
    double *accel;    /* NULL (no soil) or 3n: acceleration of the last
                         step [m/s^2], which the soil friction (10) reads */
    double *soil_frac;/* NULL (no soil) or n: wall particles, the soil's
                         share of their fluid neighbours (kernel-weighted,
                         the forces function object's phase); fluid ones,
                         their phase                                    */
    double *halo_reach; /* NULL, or n (distributed runs with deep corner
                         dummies): how far a wall particle must reach as
                         a ghost, its farthest dummy's distance [m]      */
};

struct mps_settings {
    /* constant/transportProperties, constant/g */
    double rho, nu, g[3];
    /* system/mpsSchemes */
    const struct mps_kernel_ops *kernel;
    double re_n, re_grad, re_lap;   /* radii in units of dp             */
    double gamma;                   /* PPE source mix (eq. 12)          */
    int gradient;                   /* MPS_GRAD_*: eq. (8) by default   */
    int porous_symmetric;           /* PPE weight 2/(eps_i + eps_j)     */
                                    /* instead of 1/eps_j (A.4 [P])     */
    int predictor;                  /* PPE at r* = r + dt u* (Koshizuka) */
    int clip_negative;              /* p < 0 set to 0 after the PPE     */
    double beta, alpha, fs_n_max;   /* eqs. 14, 16 and A0-07 (0.97)     */
    int fs_pressure;                /* MPS_FS_P_*: 0 on the surface     */
    int fs_simultaneous;            /* extrapolated surface values from
                                       the last step's (freeSurface/sweep
                                       simultaneous), not in index order */
    double beta_porous;             /* eq. 14 where eps < 1 (0.8)       */
    const struct mps_stabiliser_ops *collision; /* "none" by default    */
    double collision_ratio, collision_restitution;
    const struct mps_stabiliser_ops *shifting;  /* "none" by default    */
    double shifting_coeff;
    int dummy_pressure;             /* MPS_DUMMY_P_*: nearest wall      */
    int renumber_interval;          /* list rebuilds                    */
    double skin;                    /* neighbour-list skin [dp]; the    */
                                    /* list is reused while no particle */
                                    /* moved more than skin/2           */
    int measure_r;                  /* neighbourDistances measured: the */
                                    /* list keeps positions, not        */
                                    /* distances (neighbour.h)          */
    /* system/mpsSolution */
    double max_escape_fraction;     /* stop when more have escaped      */
    /* system/particleDict (set by the application): motion and removal
     * of each wall patch, borrowed; NULL: every wall fixed             */
    const struct wall_motion *wall_motion;
    int n_wall_motion;              /* entries (patches)                */
    /* system/couplingDict (set by the coupling) */
    double phi_relax_time;          /* volumeFractionRelaxation [s]: 0 =
                                       phi fixed (volume_exchange.c)    */
    int scaled_divergence;          /* ppeDivergence superficial: the
                                       PPE's divergence term is taken of
                                       ppe_scale u* (Model B: eps u*,
                                       A0-04 b) and ppe_scale scales only
                                       its density term                 */
    /* constant/soilProperties (set by the application when the particles
     * hold soil): NULL, or the soil model (doc/theory.md K, soil.c)    */
    const struct soil_props *soil;
};

/* Wall-clock seconds per phase (accumulated) and the last PPE numbers. */
struct mps_timers {
    double neighbours, explicit_, assembly, ppe, correction;
    long steps;
    long ppe_iters;
    long builds;            /* neighbour-list builds (reused otherwise)    */
    double ppe_setup, ppe_solve; /* solver-reported setup / iteration time */
    double ppe_row_iters;   /* sum over steps of iterations x unknowns     */
    double ppe_nnz_iters;   /* sum over steps of iterations x nonzeros     */
};

struct mps_solver {
    struct mps_particles P;
    struct mps_settings S;
    double dp;
    struct pop_lattice Ln, Lg, Ll;  /* per operator radius               */
    double re_max;                  /* largest operator radius [m]       */
    double r_list;                  /* neighbour-list radius (+ skin)    */
    double *x_ref;                  /* positions at the last list build  */
    long n_builds;                  /* neighbour-list builds             */
    double dt_last;                 /* step size, for the reuse test     */
    int rebuild;                    /* build the list at the next step   */
    double box_lo[3], box_hi[3];    /* particles leaving it are removed  */
    long n_escaped;                 /* removed so far                    */
    int n_fluid0;                   /* fluid particles at start          */
    long step;
    double time;                    /* [s] of the state: the caller sets
                                       it after init (the start time);
                                       mps_step advances it            */
    int walls_move;                 /* some patch moves or is removed   */
    double *wall_dx;                /* 3 per patch: this step's
                                       displacement (walls.c)           */
    /* per-step work (capacity cap) */
    struct cell_grid grid;
    struct neighbour_list nl;
    /* the weights of the three radii (mps_w): computed row by row where
     * they are read, into wrow; stored, aligned with nl, only for the
     * soil model, whose sums read them as arrays (mps_weights) */
    double *w_n, *w_g, *w_l;        /* NULL unless stored                */
    size_t cap_w;
    double *wrow;                   /* 3 x wrow_threads rows of cap_wrow */
    int64_t cap_wrow;
    int wrow_threads;
    double *ustar, *grad, *lap, *div;
    uint8_t *rows_fluid, *rows_ppe;
    uint8_t *rows_list;             /* rows the list builds (nl.rows)    */
    int setup_rows;                 /* the first list: rows of walls and
                                       dummies (partners, wall depth),
                                       no weights                       */
    int all_rows;                   /* every particle gets its row       */
    int dummy_rows;                 /* dummies near water get rows
                                       (dummyPressure extrapolated)     */
    uint8_t *cell_wet;              /* per cell of the grid: holds fluid */
    size_t cap_cells;
    int n_thin_walls;               /* found on the first list           */
    int32_t *perm;                  /* renumbering and removal lists     */
    /* PPE */
    struct csr_matrix A;
    size_t cap_nnz;
    int32_t *unk;                   /* particle -> unknown index or -1   */
    double *b, *sol;
    struct linsolve *ls;            /* owned                             */
    struct linsolve_stats last;
    struct mps_timers t;
    struct mps_soil *soil;          /* NULL without soil (soil.c)        */
    /* A distributed run (mps_halo.c): NULL in one process. */
    struct pop_halo *halo;
    int64_t *gunk;                  /* particle -> global unknown or -1  */
    int32_t *gcol;                  /* local unknown -> global           */
    int cap_work;                   /* particles the work arrays hold    */
};

/* Take ownership of the particles in P (arrays allocated with capacity
 * P->cap), the settings, spacing dp [m] and a created linear solver.
 * Computes the lattice constants and the box. */
int mps_solver_init(struct mps_solver *s, struct mps_particles *P,
                    const struct mps_settings *S, double dp,
                    struct linsolve *ls);
void mps_solver_free(struct mps_solver *s);

/* The weights of number density, gradient or Laplacian on s->nl (valid
 * until the list changes). */
enum mps_radius { MPS_W_N, MPS_W_G, MPS_W_L };
struct pop_weights mps_w(const struct mps_solver *s, enum mps_radius which);

/* The domain box that mps_solver_init puts around the particles must fit
 * the neighbour cells (cells_build's limits); otherwise SIM_ERR_INPUT
 * naming the particle farthest from the others (id, position) and
 * `origin`, the file they came from (NULL: "the start state"). */
int mps_check_extent(const struct mps_particles *P,
                     const struct mps_settings *S, double dp,
                     const char *origin);

/* Allocate particle arrays for n particles (zeroed; partner = -1, id = i).
 * A caller that sets P->n to fewer particles afterwards (a test filling
 * part of the room) is taken at its word by mps_solver_init. */
int mps_particles_alloc(struct mps_particles *P, int n, int dim);

/* The optional fields (coupling hooks), allocated zero for cap particles
 * and registered so that they follow renumbering and removal; fields
 * already present are kept. */
enum {
    MPS_P_INV_EPS = 1u << 0, MPS_P_F_EXT = 1u << 1,
    MPS_P_PPE_SCALE = 1u << 2, MPS_P_CORR_SCALE = 1u << 3,
    MPS_P_PHI = 1u << 4,   /* "volumeFraction", written to fluid.vtu */
    MPS_P_SOIL = 1u << 5,  /* "phase", "acceleration", "soilFraction",
                              written                                  */
};
int mps_particles_add(struct mps_particles *P, unsigned which);
void mps_particles_free(struct mps_particles *P);

/* Settings with the documented defaults (mps_solver.c; the paper's method:
 * Zhang kernel, r_e 2.1/2.1/3.1 dp, gamma 0.01, beta 0.8, alpha 0.9, no
 * predictor, no clipping, no collision, no shifting). */
void mps_settings_default(struct mps_settings *S);

/* Settings from constant/transportProperties, constant/g (may be NULL:
 * no gravity), system/mpsSchemes and system/mpsSolution (may be NULL).
 * Errors cite the file and line. */
struct dict;
int mps_settings_read(const struct dict *transport, const struct dict *g,
                      const struct dict *schemes, const struct dict *solution,
                      struct mps_settings *S);

/* Make s one rank's part of a distributed run (particles/halo.h; the
 * caller split the cloud, s->P holds the own particles and the ghosts):
 * the steps then exchange what the neighbours' rows read, and the PPE is
 * solved over the ranks by h->ops->solve. Refused (SIM_ERR_INPUT, naming
 * the setting) for what does not run distributed yet: soil, removed
 * wall patches, the extrapolated surface pressure (its fit runs in index
 * order, one surface particle after another); located in schemes
 * (system/mpsSchemes, may be NULL)
 * where the setting is its key. Renumbering is off (the own particles
 * stay first). */
int mps_distribute(struct mps_solver *s, struct pop_halo *h,
                   const struct dict *schemes);

/* Before the split of a distributed run (every rank holding the whole
 * cloud, partners found): a dummy leans on its partner's pressure, and a
 * dummy of a deep corner has borrowed a partner beyond the list radius
 * r_list; such partners get the field "haloReach" (halo.h) with that
 * distance, so that they reach the rank of their dummy as ghosts. */
int mps_halo_reach(struct mps_solver *s);

/* The weights of decomposeParDict's balance (particles/decompose.h) for
 * particles [0, n): fluid particles 1, walls and dummies 0 (their rows
 * exist only near water), or 1 each with all. */
void mps_balance_weights(const struct mps_particles *P, int n, int all,
                         double *w);

/* The particles this process owns: [0, mps_own(s)). */
int mps_own(const struct mps_solver *s);

/* Radius of the neighbour list [m]: the largest operator radius plus the
 * skin (half a spacing with the predictor when no skin is set). What a
 * particle's sums can reach within one list's life: also the halo a
 * distributed run exchanges (particles/decompose.h). */
double mps_list_radius(const struct mps_settings *S, double dp);

/* One step of size dt [s]. Errors: SIM_ERR_SOLVER (PPE not converged),
 * SIM_ERR_NUMERIC (NaN: message names step, particle id and field),
 * SIM_ERR_INPUT (too many particles escaped). */
int mps_step(struct mps_solver *s, double dt);

/* Build the neighbour list (and renumber) at the next step, as a restart
 * from the state just written would: called at writes so that a restarted
 * run repeats the continuous one to round-off. */
void mps_request_rebuild(struct mps_solver *s);

/* Largest stable dt: min(maxCo dp/|u|max, 0.2 dp^2/nu); |u|max includes
 * sqrt(2 g H) of the fluid column when u = 0 (first step). */
/* The model choices of system/mpsSchemes (-listModels; core/select.h). */
extern const struct model_choice mps_choices[];

double mps_propose_dt(const struct mps_solver *s, double max_co);

/* Pre-run checks; the message says what to change. co_limit: maxCo. */
int mps_check_setup(const struct mps_solver *s, double dt, int adjustable,
                    double max_co);

/* Sum of p dp^(d-1) n over the wall particles of each patch: force[3*k]
 * for patch k < npatch [N, or N/m in 2-D]. */
void mps_wall_forces(const struct mps_solver *s, int npatch, double *force);

/* Scan u, p, x for non-finite values; SIM_ERR_NUMERIC naming them. */
int mps_check_finite(const struct mps_solver *s);

/* Free-surface flags (eqs. 14-16, A0-06/07) from nd; exposed for tests. */
void mps_free_surface(struct mps_solver *s);

#endif
