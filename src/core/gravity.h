/*
 * gravity.h — constant/g, in OpenFOAM's format, read the same way by every
 * program:
 *
 *     dimensions  [0 1 -2 0 0 0 0];   // optional; checked when present
 *     value       (0 0 -9.81);        // [m/s^2]; 2-D cases use (0 -9.81 0)
 *
 * (`g (...)` instead of `value (...)` is accepted, as mpsFluid always did.)
 */
#ifndef MPSDEM_CORE_GRAVITY_H
#define MPSDEM_CORE_GRAVITY_H

struct app;
struct dict;

/* The gravity vector from the dictionary of constant/g. */
int gravity_read(const struct dict *g, double out[3]);

/* The gravity of the case for a `dim`-dimensional run: constant/g read by
 * gravity_read, the value echoed in the log; when the file does not exist,
 * the default (0 0 -9.81) in 3-D, (0 -9.81 0) in 2-D (y is vertical there)
 * with a WARNING naming the file and the value, and the value recorded in
 * usedParameters as a default. *gd receives the dictionary, or NULL when
 * there is no file; the caller frees it. */
int gravity_case(const struct app *a, int dim, double out[3],
                 struct dict **gd);

#endif
