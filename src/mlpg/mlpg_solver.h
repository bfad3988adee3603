/*
 * mlpg_solver.h — the MLPG_R flow solver of mlpgFluid (Pan 2022 thesis
 * sect. 4.1 and App. A; doc/theory.md M.1, M.8): a 2-D cloud of fluid and
 * wall nodes advanced by Chorin's projection,
 *
 *   u*      = u^n + dt (nu lap u^n + g [- (u^n.grad) u^n on fixed nodes])   (4.5)
 *   A p     = b   (the MLPG_R rows of mlpg.h, at the nodes' positions)      (4.22)
 *   u^{n+1} = u* - (dt/rho) grad p                                          (4.8)
 *   r^{n+1} = r^n + u^{n+1} dt   (Lagrangian nodes)                          (4.9)
 *
 * Wall nodes carry u* like fluid nodes (doc M0-06) and the wall's velocity
 * U afterwards (no slip). A wall node's U is its velocity in the start
 * cloud: a lid is a conveyor whose nodes keep their places. `nodes fixed`
 * (doc M0-14) keeps every node where it is and adds the advection term
 * with the SFDI gradient; the matrix, the gradient and Laplacian
 * coefficients are then made once. A closed domain has its pressure fixed
 * at one node (pRefPoint, pRefValue; doc M0-08).
 */
#ifndef MPSDEM_MLPG_MLPG_SOLVER_H
#define MPSDEM_MLPG_MLPG_SOLVER_H

#include <stdint.h>

#include "linsolve/linsolve.h"
#include "mlpg/mlpg.h"
#include "particles/cells.h"
#include "particles/motion/motion.h"
#include "particles/neighbour.h"
#include "particles/store.h"

struct dict;

enum mlpg_nodes { MLPG_NODES_FIXED, MLPG_NODES_LAGRANGIAN };
enum mlpg_shift { MLPG_SHIFT_NONE, MLPG_SHIFT_LIND2012 };
enum mlpg_move { MLPG_MOVE_END_VELOCITY, MLPG_MOVE_SECOND_ORDER };

/* Wall nodes that move: a patch's nodes inside a box slide in place at a
 * velocity (a lid) or move rigidly with a motion model (a piston). */
struct mlpg_wall_group {
    double U[3];               /* velocity of nodes that stay [m/s]        */
    struct wall_motion motion; /* none: the nodes stay                     */
    int free_slip;             /* -1: the global wallCondition, 0, 1       */
};

/* Fluid nodes in a box whose pressure is given (an outlet). */
struct mlpg_fixed_pressure {
    double lo[3], hi[3], value;
};

/* Is the 2-D point x in the box [lo, hi] (edges included)? */
static inline int mlpg_in_box(const double *x, const double *lo,
                              const double *hi)
{
    return x[0] >= lo[0] && x[0] <= hi[0] && x[1] >= lo[1] && x[1] <= hi[1];
}

struct mlpg_settings {
    double rho, nu, g[3];
    double dl;
    const struct mlpg_wall_ops *wall;
    int nodes;                 /* enum mlpg_nodes                          */
    int self_nodal;            /* doc M0-03                                */
    int free_surface;          /* quadrant + column detector (M0-22)       */
    int free_slip;             /* walls: free slip instead of no slip      */
    int has_pref;              /* pRefPoint given                          */
    double support, radius;    /* MLS support and R_I, in dl               */
    int shift;                 /* enum mlpg_shift (doc M0-25)              */
    double shift_coeff;        /* lind2012: A                              */
    int move;                  /* enum mlpg_move (doc M0-27)               */
    double pref_point[3], pref_value;
};

struct mlpg_timers {
    long steps, builds, ppe_iters;
    double neighbours, explicit_, assembly, ppe, correction;
};

struct mlpg_solver {
    struct mlpg_settings S;
    /* the cloud: registered fields of st */
    struct store st;
    int n;
    double *x, *u, *p, *normal; /* normal: genParticles', into the solid */
    int32_t *type, *patch;
    int64_t *id;               /* persistent: nodes are never reordered    */
    double *wall_area, *traction; /* mlpg_wall_stress                    */
    /* work */
    double *ustar, *nin, *sector, *R, *pgiven, *wallU, *b;
    uint8_t *dirichlet, *exclude;
    uint8_t *fsflag;           /* work: free-surface flags, free-slip nodes */
    uint8_t *surface;          /* 1: a fluid node on the free surface      */
    double *lap, (*sfdi)[2];   /* per list entry + self (fixed nodes)      */
    int64_t *coef_start;       /* n + 1: node i's entries                  */
    int32_t *cand;             /* per entry: the node (mlpg_candidates)    */
    double *dw;                /* fixed nodes: arc weights (mlpg.h)        */
    int64_t *dw_start;
    int pin;                   /* the reference node, or -1                */
    int32_t *group;            /* per node: wall group, or -1              */
    struct mlpg_wall_group *groups;
    int ngroups;
    double *x0;                /* moving wall nodes: position at t = 0     */
    struct mlpg_fixed_pressure *fixed_p;
    int nfixed_p;
    long n_surface;            /* free-surface nodes of the last step      */
    struct cell_grid grid;
    struct neighbour_list nl;
    struct csr_matrix A;
    size_t capA;
    int assembled;             /* fixed nodes: A and coefficients made     */
    struct linsolve *ls;
    struct linsolve_stats last;
    struct mlpg_cloud c;
    struct mlpg_timers t;
    double time, last_dt;
    double shift_n0;           /* sum of the MLS weights on a lattice      */
};

/* The keys of the rows: selfTerm (approximant | nodal, doc M0-03),
 * supportRadius (MLS support / dl, 1.85), subdomainRadius (R_I / dl, 0.8):
 * shared by mlpgFluid (system/mlpgSchemes) and mlpgPatchTest. */
int mlpg_rows_read(const struct dict *d, int *self_nodal, double *support,
                   double *radius);

/* system/mlpgSchemes and system/mlpgSolution (the PPE sub-dictionary is
 * read by the caller), constant/transportProperties. */
int mlpg_settings_read(const struct dict *transport,
                       const struct dict *schemes,
                       const struct dict *solution, struct mlpg_settings *S);
extern const struct model_choice mlpg_solver_choices[];

/* Take the settings and the linear solver (owned from now on); the store
 * st must hold n nodes with x, u, p, normal, type, patch filled, and
 * group/groups set (or NULL: no wall moves; groups owned from now on),
 * fixed_p/nfixed_p (owned from now on).
 * s->time must hold the start time. */
int mlpg_solver_init(struct mlpg_solver *s, const struct mlpg_settings *S,
                     struct linsolve *ls);

/* One projection step of dt. */
int mlpg_step(struct mlpg_solver *s, double dt);

/* Lagrangian nodes: shift the fluid nodes after the step (shifting.c,
 * doc/theory.md M0-25). */
void mlpg_shift(struct mlpg_solver *s);

/* wallArea and viscousTraction of the wall nodes from the last step's
 * velocities and rows (wall_stress.c, doc/theory.md M0-24); zeros before
 * the first step and on dry wall nodes. */
void mlpg_wall_stress(struct mlpg_solver *s);

/* Register the cloud's fields in s->st (positions, velocity, pressure,
 * type, patch, id, normal, and the output fields pressureFixed, wallArea,
 * viscousTraction) and size it for n nodes. */
int mlpg_fields_alloc(struct mlpg_solver *s, int n);

void mlpg_solver_free(struct mlpg_solver *s);

#endif
