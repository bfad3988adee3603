/*
 * gravity.h — constant/g, in OpenFOAM's format, read the same way by every
 * program:
 *
 *     dimensions  [0 1 -2 0 0 0 0];   // optional; checked when present
 *     value       (0 0 -9.81);        // [m/s^2]; 2-D cases use (0 -9.81 0)
 */
#ifndef MPSDEM_CORE_GRAVITY_H
#define MPSDEM_CORE_GRAVITY_H

struct dict;

/* The gravity vector from the dictionary of constant/g. */
int gravity_read(const struct dict *g, double out[3]);

#endif
