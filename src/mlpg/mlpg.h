/*
 * mlpg.h — the meshless local Petrov-Galerkin method with a Rankine source
 * (MLPG_R, Ma 2005) and its improved wall scheme (Pan 2022, PhD thesis ch. 3-4;
 * doc/theory.md part M): the rows of the pressure equation of a 2-D cloud
 * of nodes, the first-order MLS approximation they rest on, and the SFDI
 * gradient. The solver that steps a flow with them is mlpg_solver.h;
 * this part is geometry and linear algebra only, so that the patch test
 * (applications/utilities/mlpgPatchTest) and the unit tests of E3-01 ...
 * E3-05 call exactly what the solver calls.
 *
 * Nodes. Fluid nodes carry the full circle of radius R_I (doc M0-09) as
 * their sub-domain. A wall node lies on the wall and carries the part of
 * the disc of radius R_K = 0.8 dl on the fluid side: a half disc on a
 * straight wall (sector pi), a quarter disc in a 90-degree container
 * corner (sector pi/2, doc M0-07); `normal` is the unit normal into the
 * fluid (the bisector at a corner). The sector runs from theta0 =
 * angle(normal) - sector/2 to theta0 + sector; its straight sides are the
 * wall segments, with outward normals e(theta0 - pi/2) and
 * e(theta0 + sector + pi/2) (pointing into the wall).
 *
 * Rows (sign chosen so that the diagonal is positive; eqs. 4.22-4.24 with
 * the 2-point Gauss rule on each quarter arc, doc M.5):
 *
 *   improved / fluid:  (sector/2pi) p(x_i) - (1/8) sum_q p(x_q)
 *                    = -(rho/dt) D_i - sum_s (R/2pi) ((rho/dt) n_s.u*_i - g_s)
 *   improvedConsistent: the same with g_s scaled by the quadrature's
 *                    weight of a linear mode, 0.99845 (doc M0-20)
 *   original (wall):   (R/pi) n_out.grad p(x_i)  = (R/pi) g      (SFDI gradient)
 *
 * p(x) is the MLS approximant (3.17); D_i the domain integral (S-9)/2pi of
 * u*; g_s = n_s.grad p the Neumann data of segment s, for a flow
 * (rho/dt) n_s.(u* - U) (S-2), for the patch test the analytic flux. Both
 * wall rows approximate the same quantity (for linear p, p_K/2 minus the
 * half-arc mean is (R/pi) n_out.grad p), which is why the old row is
 * scaled by R/pi.
 */
#ifndef MPSDEM_MLPG_MLPG_H
#define MPSDEM_MLPG_MLPG_H

#include <stdint.h>

#include "core/select.h"

struct neighbour_list;
struct csr_matrix;

/* Node classes. */
enum { MLPG_FLUID = 0, MLPG_WALL = 1 };

/* The cloud the rows are built on (2-D: positions x y z with z = 0). */
struct mlpg_cloud {
    int n;
    double dl;                 /* initial spacing [m]                       */
    double rs;                 /* MLS support radius, 1.85 dl (C.3)         */
    double R0;                 /* sub-domain radius, 0.8 dl (4.11)          */
    const double *x;           /* 3 per node [m]                            */
    const int32_t *type;       /* MLPG_FLUID / MLPG_WALL                    */
    const double *normal;      /* 3 per node: wall, unit, into the fluid    */
    const double *sector;      /* per node: wall, fluid angle [rad]         */
    const double *R;           /* per node: sub-domain radius (mlpg_radii)  */
    const uint8_t *dirichlet;  /* NULL, or 1: p given (free surface, pin)   */
    const uint8_t *exclude;    /* NULL, or 1: in no other node's row (a    */
                               /* wall node above the water)               */
    const struct neighbour_list *nl; /* rc >= rs + R0                       */
    int self_nodal;            /* doc M0-03: p_i instead of p(x_i)          */
};

/* The wall scheme: how a wall node's row is made. */
struct mlpg_wall_ops {
    const char *name;
    const char *reference;
    /* Coefficients over the candidates (cand[0] = i, then row i of the
     * list) of wall node i's row, and the factor of its Neumann data:
     * the row is sum_k coef[k] p_cand[k] = rhs_geometric + gfac . g. */
    int (*row)(const struct mlpg_cloud *c, int i, const int32_t *cand, int m,
               double *coef, double *work);
    /* The right-hand side of node i's row from its segments' Neumann data
     * g[s] (outward normals n[s]) and the u* part. */
    double (*rhs)(const struct mlpg_cloud *c, int i, double rho_dt,
                  double D, const double ustar_i[3], int nseg,
                  const double n[2][2], const double g[2]);
};

extern const struct mlpg_wall_ops mlpg_wall_improved, mlpg_wall_consistent,
    mlpg_wall_original;
extern const struct mlpg_wall_ops *const mlpg_wall_schemes[];

/* ---- MLS and SFDI (mls.c) ------------------------------------------------ */

/* MLS weight (doc M0-02): the quartic spline 1 - 6s^2 + 8s^3 - 3s^4 of
 * s = r/rs, 0 for s >= 1. */
double mlpg_weight(double r, double rs);

/* Solve the SPD n x n system a x = b by Cholesky, a overwritten by its
 * factor, b by x; 0 when a pivot falls below rtol times the largest
 * diagonal entry (then a and b are garbage). */
int mlpg_spd_solve(int n, double *a, double *b, double rtol);

/* First-order MLS shape functions (3.17)-(3.21) at point p over the nodes
 * cand[0..m): phi[k] = Phi_cand[k](p). The basis is shifted to p and
 * scaled by dl. SIM_ERR_NUMERIC when fewer than three non-collinear nodes
 * lie within rs of p (the moment matrix is singular). */
int mlpg_mls(const struct mlpg_cloud *c, const int32_t *cand, int m,
             const double p[2], double *phi);

/* The SFDI gradient of node i (Ma 2008; weighted least squares on the
 * first-order Taylor expansion, doc M.7):
 *   grad p_i = sum_k a[k] (p_cand[k] - p_i),
 * a[k] = M^-1 w_k dx_k, M = sum_k w_k dx_k dx_k^T, k over cand[0..m)
 * within rs of node i (others get 0). SIM_ERR_NUMERIC when M is
 * singular. */
int mlpg_sfdi(const struct mlpg_cloud *c, int i, const int32_t *cand, int m,
              double (*a)[2]);

/* Derivatives by the second-order weighted least-squares fit on `radius`
 * (qsfdi.c): op f_i = sum_k l[k] (f_cand[k] - f_i) for op the Laplacian
 * (the viscous term) or d/dx, d/dy (a wall's shear stress).
 * SIM_ERR_NUMERIC when fewer than five independent nodes lie within it. */
enum mlpg_fit2 { MLPG_FIT2_LAPLACIAN, MLPG_FIT2_DX, MLPG_FIT2_DY };
int mlpg_fit2_coeffs(const struct mlpg_cloud *c, int i, const int32_t *cand,
                     int m, double radius, enum mlpg_fit2 op, double *l);

/* ---- sub-domains and rows (rows.c) --------------------------------------- */

/* Sub-domain radii (doc M0-09): R0 for walls; for fluid nodes
 * min(R0, 0.95 x the distance to the nearest straight-wall line through
 * a wall node of the list). */
void mlpg_radii(const struct mlpg_cloud *c, double *R);

/* Sector of node i: start angle, angle, and the outward normals of its
 * straight sides (nseg = 0 for a fluid node, else 2). */
void mlpg_sector(const struct mlpg_cloud *c, int i, double *theta0,
                 double *angle, int *nseg, double n[2][2]);

/* Candidates of node i's row: i, then row i of the list but the excluded
 * nodes. Returns m (cand NULL: only counts). */
int mlpg_candidates(const struct mlpg_cloud *c, int i, int32_t *cand);

/* The Rankine-source row of node i over its sector (fluid, and the
 * improved wall scheme): coef[k] for cand[0..m). work: 2 m doubles. */
int mlpg_row_rankine(const struct mlpg_cloud *c, int i, const int32_t *cand,
                     int m, double *coef, double *work);

/* D_i = (1/2pi) int_sector u*_r dr dtheta (S-9), with u* linear on each
 * quarter between node i (its own u*) and the MLS values at the quarter's
 * corner points on the arc. work: 5 m doubles. */
int mlpg_domain_integral(const struct mlpg_cloud *c, int i,
                         const int32_t *cand, int m, const double *ustar,
                         double *work, double *D);

/* The same in two parts, so that nodes that do not move compute the MLS
 * weights of the arc points once: mlpg_domain_points(i) points (at most
 * 5), their weights w[a m + k] (mlpg_domain_weights), and D_i from them
 * (mlpg_domain_sum). */
int mlpg_domain_points(const struct mlpg_cloud *c, int i);
int mlpg_domain_weights(const struct mlpg_cloud *c, int i,
                        const int32_t *cand, int m, double *w);
double mlpg_domain_sum(const struct mlpg_cloud *c, int i, const int32_t *cand,
                       int m, const double *w, const double *ustar);

/* (S-9) for one quarter (th1, th2) of radius R, u0 at the centre and the
 * linear coefficients: exposed for the unit tests. */
double mlpg_quarter_integral(double R, double th1, double th2,
                             const double u0[2], double cux, double cuy,
                             double cvx, double cvy);

/* ---- the linear system (system.c) ---------------------------------------- */

/* Neumann data of a wall node's segments: n[s], g[s] = n[s].grad p. */
typedef void mlpg_neumann_fn(void *ctx, int i, int nseg, const double n[2][2],
                             double g[2]);

struct mlpg_system {
    const struct mlpg_wall_ops *wall;
    double rho_dt;             /* rho/dt (0 for a Laplace problem)          */
    const double *ustar;       /* 3 per node, or NULL (u* = 0)              */
    mlpg_neumann_fn *neumann;  /* wall data                                 */
    void *ctx;
    const double *p_given;     /* Dirichlet values (NULL: 0)                */
    /* NULL, or the arc weights of every node (mlpg_domain_weights at
     * dw + dw_start[i]) for the nodes of the last assembly */
    const double *dw;
    const int64_t *dw_start;
};

/* Assemble A p = b over every node (row i = node i): Rankine rows for
 * fluid nodes, the wall scheme's rows for wall nodes, identity rows for
 * Dirichlet nodes. A's arrays are grown as needed (*cap: capacity of col
 * and val); b has n entries. */
int mlpg_assemble(const struct mlpg_cloud *c, const struct mlpg_system *S,
                  struct csr_matrix *A, size_t *cap, double *b);

/* The right-hand side alone, for the nodes and Dirichlet set of A's last
 * assembly (fixed nodes: the matrix does not change). A is not written. */
int mlpg_rhs(const struct mlpg_cloud *c, const struct mlpg_system *S,
             const struct csr_matrix *A, double *b);

#endif
