/*
 * wet_walls.h — which wall particles of a cloud with one layer of wall
 * particles take part in the pressure equation (mlpgFluid doc/theory.md
 * M0-23, isphSediment S0-06).
 */
#ifndef MPSDEM_PARTICLES_WET_WALLS_H
#define MPSDEM_PARTICLES_WET_WALLS_H

#include <stdint.h>

struct neighbour_list;

/* wet[i] = 1 for every particle that is not a wall (type != 1), and for a
 * wall particle with a fluid particle (type 0) within `reach`; with
 * `by_height` and gravity g (x, y), unless the wall faces down (a roof:
 * normal, into the solid, within 60 degrees of up), that fluid particle
 * must not be lower than the wall particle by more than dl/2 (above the
 * water its support holds only water below it). 2-D. */
void pop_wet_walls(const struct neighbour_list *nl, const double *x,
                   const int32_t *type, const double *normal,
                   const double g[2], int by_height, double reach, double dl,
                   uint8_t *wet);

#endif
