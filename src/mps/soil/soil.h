/*
 * soil.h — the forces of Kim's solid-soil model on MPS particles
 * (doc/theory.md K.2-K.4): friction between soil particles and with the
 * walls (eqs. 10-14), the weight of the column above a particle (eq. 13)
 * and the drag of the fluid neighbours (K.1) with its reaction.
 *
 * The functions work on plain arrays and a CSR neighbour list (a full,
 * symmetric list: j in row i iff i in row j), so that they are tested on
 * small clouds and any particle solver can call them. Forces are per unit
 * volume [N/m^3], as eq. (9) needs; the drag reaction is an acceleration
 * [m/s^2] of the fluid particles.
 */
#ifndef MPSDEM_MPS_SOIL_H
#define MPSDEM_MPS_SOIL_H

#include <stdint.h>

struct dict;
struct model_head;
struct neighbour_list;

/* The role of a particle in the soil forces. */
enum soil_role { SOIL_OTHER = 0, SOIL_FLUID, SOIL_SOIL, SOIL_WALL };

/* Friction of eqs. (10)-(14), K0-03...K0-05. */
struct soil_friction_params {
    double mu;              /* friction coefficient of the soil [-]          */
    int kernel_weight;      /* K0-04: 0 literal sums, 1 pair terms x d w/n0  */
    int cap;                /* K0-05: 1 caps the impulse of a step           */
    double dt;              /* step [s], read when cap is set                */
    double n0;              /* number density of the weights' radius         */
};

/*
 * eq. (13): p_h[i] = sum of rho[j] g over the soil particles j above soil
 * particle i (z_j > z_i; z is y in 2-D) whose horizontal distance to i is
 * below b [m] (K0-03); 0 for particles that are not soil. x holds 3
 * components per particle. Returns SIM_OK, or SIM_ERR_NOMEM.
 */
int soil_column_weight(int n, int dim, const double *x, const uint8_t *role,
                       const double *rho, double g, double b, double *p_h);

/*
 * eqs. (10)-(12), (14): the friction F [N/m^3, 3 per particle] of every
 * soil particle (0 for the others), summed over its soil and wall
 * neighbours in nl with w[k] > 0 (w: the kernel weight of entry k of nl at
 * the radius of the sums, 0 beyond it). a: the acceleration of the
 * previous step; v: velocities (a wall's own); p_h from
 * soil_column_weight. A wall neighbour has a = 0 and carries the
 * column's weight: p_s = p_h[i] (doc/theory.md K.3).
 */
void soil_friction(const struct soil_friction_params *p, int dim,
                   const struct neighbour_list *nl, const double *w,
                   const double *x, const double *v, const double *a,
                   const double *rho, const double *p_h,
                   const uint8_t *role, double *F);

/* Drag of K.1 (K0-06). */
struct soil_drag_params {
    double cd;              /* drag coefficient C_D [-]                      */
    double rho_f;           /* fluid density [kg/m^3]                        */
    double l0;              /* particle spacing [m]                          */
    double n0;              /* number density of the weights' radius         */
};

/*
 * K.1: the drag F [N/m^3, 3 per particle] of the fluid neighbours on every
 * soil particle (0 for the others). With a_fluid != NULL the reaction is
 * added to the fluid particles' accelerations [m/s^2]: soil particle i
 * gives fluid neighbour j the force -F_i V w_ij / sum_k w_ik (k over i's
 * fluid neighbours), V = l0^dim, so the momentum of both phases together
 * is unchanged by the drag (E5-06). w as in soil_friction. S is scratch
 * of n doubles.
 */
void soil_drag(const struct soil_drag_params *p,
               const struct neighbour_list *nl, const double *w,
               const double *v, const uint8_t *role, double *F,
               double *a_fluid, double *S);

/* Viscoplastic soil, K.6 (soil_viscoplastic.c). */
struct soil_vp_params {
    double mu;              /* friction coefficient tan(phi) [-]             */
    double cohesion;        /* c [Pa]                                        */
    double rho;             /* soil density [kg/m^3]                         */
    double nu_max;          /* viscosity cap [m^2/s] (K0-11)                 */
    double p_wall;          /* added to p' against a wall [Pa] (K0-13)       */
};

/*
 * K.6a-c: nu[i] [m^2/s] of every soil particle (0 for the others) from the
 * strain rate of v (corrected gradient over the neighbours with w[k] > 0)
 * and the yield pressure pres (K0-12). n0: the weights' number density (the fallback
 * normalisation d/n0 where the moment matrix is singular).
 */
void soil_vp_viscosity(const struct soil_vp_params *p, int dim,
                       const struct neighbour_list *nl, const double *w,
                       double n0, const double *x, const double *v,
                       const double *pres, const uint8_t *role, double *nu,
                       double *nu_w);

/*
 * K.6d: the rows of the implicit viscous step of the soil particles
 * (unk[i] >= 0: row unk[i]; rowptr from pop_matrix_rowptr with the same
 * w and unk). c_dt = dt 2d/(n0 lambda) of the Laplacian weights w; nu_f
 * the water's viscosity; v (3 per particle) the velocities the step starts
 * from for the soil and the known velocities of the other particles; wn
 * (3 per particle) the normals of wall and dummy particles: a wall drags
 * the tangential velocity only (K0-13). Writes col, val
 * (diagonal first in each row) and b (3 right-hand sides per row,
 * interleaved).
 */
void soil_vp_system(const struct neighbour_list *nl, const double *w,
                    double c_dt, double nu_f, const double *nu,
                    const double *nu_w, const uint8_t *role, const int32_t *unk,
                    const double *v, const double *wn,
                    const int64_t *rowptr, int32_t *col, double *val,
                    double *b);

/* constant/soilProperties (doc/theory.md K0-01 ... K0-13). */
enum soil_model { SOIL_MODEL_SOLID, SOIL_MODEL_LIQUID,
                  SOIL_MODEL_VISCOPLASTIC };

struct soil_props {
    int model;              /* enum soil_model                               */
    double rho;             /* soil density [kg/m^3]                         */
    double mu;              /* friction coefficient [-] (solid)              */
    double column_half_width; /* b of eq. (13) [l0] (solid)                  */
    int kernel_weight;      /* frictionWeight none | kernel (solid)          */
    int cap;                /* frictionCap (solid)                           */
    int load_total;         /* frictionLoad: 0 withoutFriction, 1 total      */
    double cd;              /* dragCoefficient C_D [-] (solid)               */
    int drag_reaction;      /* dragReaction (solid)                          */
    double nu;              /* kinematic viscosity [m^2/s] (liquid)          */
    double cohesion;        /* c [Pa] (viscoplastic)                         */
    double nu_max;          /* viscosity cap [m^2/s] (viscoplastic)          */
};

/* The model and option tables, for the solver's -listModels list. */
extern const struct model_head *const soil_model_table[];
extern const struct model_head *const soil_friction_weight_table[];
extern const struct model_head *const soil_friction_load_table[];

/* Read d (constant/soilProperties) into p; errors name the entry. */
int soil_props_read(const struct dict *d, struct soil_props *p);

#endif
