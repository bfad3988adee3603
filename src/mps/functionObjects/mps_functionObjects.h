/*
 * mps_functionObjects.h — function objects of the MPS fluid (STYLE.md
 * C14), passed to fo_list_create() beside fo_generic_table:
 *
 *   probes      pressure at points (Shepard average of fluid and wall
 *               particles within a radius)
 *   waveGauges  free-surface elevation at horizontal positions
 *   front       leading edge of the fluid along a direction, ignoring
 *               isolated splash
 *   forces      pressure force on named wall patches
 *   volume      fluid particle count and volume (conservation)
 *
 * They read the scene only: cloud fields "type", "pressure",
 * "numberDensity" (n/n0) and the solver values "wallForce.<patch>",
 * "escaped". Keys of each type: mpsFluid.reference.
 */
#ifndef MPSDEM_MPS_FUNCTIONOBJECTS_H
#define MPSDEM_MPS_FUNCTIONOBJECTS_H

#include "functionObjects/functionObject.h"

extern const struct fo_ops mps_fo_probes, mps_fo_wave_gauges, mps_fo_front,
    mps_fo_forces, mps_fo_volume;

extern const struct fo_ops *const mps_fo_table[];

/* Field of the scene's cloud with the given type and 1 component, or
 * NULL (helpers shared by the MPS function objects). */
const void *mps_fo_field(const struct fo_scene *s, const char *name,
                         int type);

/* Index of the vertical axis (gravity): 1 in 2-D, 2 in 3-D. */
int mps_fo_vertical(const struct fo_scene *s);

#endif
