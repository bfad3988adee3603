/*
 * dem_case.h — reading a DEM case: constant/demProperties (material and
 * contact sub-models), system/demSolution (integrator, neighbour skin,
 * start-up overlap check, domain), the walls of system/particleDict, the
 * grains of <time>/dem.vtu and the contact history of <time>/demContacts.
 * The fully commented reference of every key is
 * applications/solvers/demSolid/demSolid.reference.
 */
#ifndef MPSDEM_DEM_CASE_H
#define MPSDEM_DEM_CASE_H

#include "core/select.h"
#include "dem/dem.h"
#include "dem/integrators/integrator.h"

struct dict;

/* What system/demSolution says beyond the integrator parameters. */
struct dem_solution {
    const struct dem_integrator_ops *integrator;
    struct dem_integrator_params params;
    char table[64];                 /* storage for params.table          */
    double max_overlap;             /* fraction of the smaller radius    */
    int relax_overlap;              /* 1: relax, 0: refuse               */
    int relax_iterations;
};

/* constant/demProperties -> d->law. Errors name file:line:key. */
int dem_read_properties(const struct dict *props, struct dem *d);

/* The model choices of constant/demProperties and system/demSolution
 * (-listModels; core/select.h). */
extern const struct model_choice dem_choices[];

/* system/demSolution. Needs d->rmax set (skin default) — call after the
 * grains are read. */
int dem_read_solution(const struct dict *sol, struct dem *d,
                      struct dem_solution *s);

/* Walls from the regions of system/particleDict: tankWall (grains inside,
 * open faces skipped) and wall (grains outside), with their motion and
 * removeAt (particles/motion/motion.h; a motion table is found relative
 * to case_dir). Patch index = region index, as in
 * constant/particlePatches. Sets *dim. */
int dem_read_walls(const struct dict *pd, const char *case_dir,
                   struct dem *d, int *dim);

/* Grains from a dem.vtu (fields radius, velocity, omega, group, id). */
int dem_read_grains(const char *path, struct dem *d);

/* Write grains to a dem.vtu at time t. */
int dem_write_grains(const char *path, const struct dem *d, int binary);

/* Contact history (tangential springs) for restart: one line per pair
 * "id_i id_j hx hy hz" and per wall contact "id_i -(wall+1) hx hy hz". */
int dem_write_contacts(const char *path, const struct dem *d);
/* Read it back after dem_setup (ids matched; unknown pairs ignored).
 * A missing file is not an error (*found = 0). */
int dem_read_contacts(const char *path, struct dem *d, int *found);

/* Start-up overlap check: count pairs overlapping by more than
 * s->max_overlap of the smaller radius; refuse (SIM_ERR_INPUT naming the
 * count and the worst pair) or relax them by moving grains apart. */
int dem_check_initial_overlap(struct dem *d, const struct dem_solution *s,
                              const char *where);

#endif
