/* integrator_register.c — the list of DEM integrators (doc/design.md C3). */
#include <stddef.h>

#include "dem/integrators/integrator.h"

const struct dem_integrator_ops *const dem_integrator_table[] = {
    &dem_integrator_arkode, &dem_integrator_verlet, &dem_integrator_auto,
    NULL};
