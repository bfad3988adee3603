/*
 * dem_fo.h — DEM function objects (doc/design.md C14): kineticEnergy,
 * wallForces, front, bedHeight, grainState, contacts. Grain fields are
 * looked up by name in fo_scene.store (grainState, kineticEnergy); what
 * only the solver has (neighbour list, walls, patch forces, contact
 * counts) is read from its struct dem through fo_scene.solver. demSolid
 * passes dem_fo_table to fo_list_create beside fo_generic_table.
 */
#ifndef MPSDEM_DEM_FO_H
#define MPSDEM_DEM_FO_H

#include "functionObjects/functionObject.h"

struct dem;

extern const struct fo_ops dem_fo_kinetic_energy;
extern const struct fo_ops dem_fo_wall_forces;
extern const struct fo_ops dem_fo_front;
extern const struct fo_ops dem_fo_bed_height;
extern const struct fo_ops dem_fo_grain_state;
extern const struct fo_ops dem_fo_contacts;
extern const struct fo_ops *const dem_fo_table[];

/* Number of contacts (grains and walls) of every grain, into cnt (n). */
void dem_fo_contact_counts(const struct dem *d, int *cnt);

#endif
