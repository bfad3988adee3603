/*
 * surface_pressure.h — Dirichlet pressure of free-surface particles
 * extrapolated from p = 0 on the surface dp/2 outside them
 * (`freeSurface { pressure extrapolated; }`); see surface_pressure.c.
 */
#ifndef MPSDEM_MPS_SURFACE_PRESSURE_H
#define MPSDEM_MPS_SURFACE_PRESSURE_H

struct mps_solver;

/* Set P->p of every fluid particle flagged MPS_SURFACE from the current
 * (previous-step) pressure field of their neighbours: in index order, or
 * with `sweep simultaneous` all from the last step's values (a
 * distributed run's own particles, then refreshed at the ghosts). */
int mps_surface_pressure(struct mps_solver *s);

#endif
