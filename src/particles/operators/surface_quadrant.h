/*
 * surface_quadrant.h — the free-surface detector of MLPG_R and ISPH
 * (Ma and Zhou 2009 variant; Pan 2022 thesis sect. 5.3.2 eqs. 5.32-5.33;
 * doc/theory.md M0-22), shared by every 2-D solver that needs it.
 */
#ifndef MPSDEM_PARTICLES_OPERATORS_SURFACE_QUADRANT_H
#define MPSDEM_PARTICLES_OPERATORS_SURFACE_QUADRANT_H

#include <stdint.h>

struct neighbour_list;

/* Flag the free-surface particles among those with rows[i] != 0 (NULL:
 * all): particle i is on the surface when at most three of the four
 * 90-degree sectors centred on +x, -x, +y, -y hold a neighbour within
 * `radius` (quadrant test) AND at most three of the four columns of half
 * width `half_width` along those directions hold one within `radius`
 * (column test). A neighbour j counts when counts[j] != 0 (counts NULL:
 * every particle of the list, walls included; a solver leaves out the
 * wall particles above the water). With `facing` (x, y at 3 j; NULL: none),
 * a neighbour j whose facing[j] is not zero occupies the sector and column
 * of that direction instead of those of its position (a wall particle's
 * normal into the solid: the wall lies on that side of the water).
 * flag[i] = 1 surface, 0 not, untouched
 * where rows[i] == 0; flag may be rows.
 * The list's radius must be at least `radius`. 2-D (x, y of x[3 i]). */
void pop_surface_quadrant(const struct neighbour_list *nl, const double *x,
                          double radius, double half_width,
                          const uint8_t *rows, const uint8_t *counts,
                          const double *facing, uint8_t *flag);

#endif
