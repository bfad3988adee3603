/*
 * soil_step.h — the soil phase inside the MPS step (soil_step.c,
 * doc/theory.md K). Every function is called only when s->soil exists
 * (the particles hold soil and constant/soilProperties was read).
 */
#ifndef MPSDEM_MPS_SOIL_STEP_H
#define MPSDEM_MPS_SOIL_STEP_H

#include <stdint.h>

#include "linsolve/linsolve.h"

struct mps_solver;

/* Per-particle work of a step, sized for the solver's capacity. */
struct mps_soil {
    uint8_t *role;      /* enum soil_role                                 */
    double *rho;        /* density [kg/m^3]                               */
    double *ratio;      /* rho_0/rho: PPE pair weights and correction     */
    double *p_h;        /* column weight, eq. (13) [N/m^3]                */
    double *S;          /* scratch: the drag's; p' of the viscoplastic
                           model (K0-12)                                  */
    double *F, *Fd;     /* 3n friction and drag [N/m^3]                   */
    double *acc;        /* 3n accelerations of the soil forces and of the
                           drag reaction [m/s^2]                          */
    double *u_old;      /* 3n velocities at the start of the step         */
    /* viscoplastic model (K.6): viscosities, the implicit viscous system */
    double *nu, *nu_w;  /* n [m^2/s]: own, and against walls (K0-13)      */
    int32_t *unk;       /* n: row of a soil particle, -1 for the others   */
    struct csr_matrix A;
    size_t cap_nnz;
    double *b, *rhs, *sol; /* 3n, n, n                                    */
    struct linsolve *ls;
};

/* s->soil when s->S.soil is set and the particles have a phase field;
 * nothing otherwise. */
int mps_soil_init(struct mps_solver *s);
void mps_soil_free(struct mps_solver *s);

/* After the neighbour search: roles, densities, ratios, u^m, and the
 * soil fraction of the wall particles (P->soil_frac). */
void mps_soil_begin(struct mps_solver *s);

/* Before the prediction: s->soil->acc (the solid model's forces per unit
 * mass on soil particles, the drag reaction on water; 0 otherwise). */
int mps_soil_forces(struct mps_solver *s);

/* Whether the soil model has an implicit viscous step (viscoplastic). */
int mps_soil_implicit_wanted(const struct mps_solver *s);

/* The particles particle shifting leaves alone (doc/theory.md K0-15):
 * the phase field when the soil is viscoplastic (skip those with phase
 * 1), NULL otherwise (shift every fluid particle). */
const int32_t *mps_soil_unshifted(const struct mps_solver *s);

/* The viscoplastic model's implicit viscous step (K.6d): v (3n) holds the
 * velocities the step starts from (soil) and the known velocities of the
 * other particles; the soil rows are replaced by the solution. */
int mps_soil_implicit(struct mps_solver *s, double dt, double *v);

/* Kinematic viscosity of particle i's phase in the explicit prediction
 * [m^2/s] (0 for soil that is not a liquid). */
double mps_soil_viscosity(const struct mps_solver *s, int i);

/* After the move: the acceleration of this step into P->accel. */
void mps_soil_end(struct mps_solver *s, double dt);

#endif
