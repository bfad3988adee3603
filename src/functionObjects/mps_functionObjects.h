/*
 * mps_functionObjects.h — function objects of the MPS fluid
 * (doc/design.md C14), passed by mpsFluid to fo_list_create() beside
 * fo_generic_table:
 *
 *     const struct fo_ops *const *const tables[] =
 *         { fo_generic_table, mps_fo_table, NULL };
 *
 *   probes      pressure at points (Shepard average or nearest wall
 *               particle, doc/theory.md A.9)                 fo_probes.c
 *   waveGauges  free-surface elevation in vertical columns (A.12.3)
 *                                                         fo_waveGauges.c
 *   front       leading edge of the fluid along a direction (A.12.2),
 *               optionally Martin & Moyce's Z and T        fo_front.c
 *   forces      pressure force on named wall patches (A.9) fo_forces.c
 *   volume      fluid particle count, volume, relative change, escaped
 *                                                         fo_volume.c
 *
 * Keys and columns of each type: doc/controlDict.md and each file's header.
 *
 * ---- Contract: what the solver publishes in struct fo_scene -------------
 *
 * scene->store (particles/store.h, the solver's own field registry) has
 * the positions, "position" (Float64 x3; z = 0 in 2-D), and these fields,
 * by name (type, components); store_require() checks them, and answers an
 * unknown name with the valid ones and "did you mean":
 *
 *   type           Int32   x1  0 fluid, 1 wall (in the PPE), 2 dummy
 *   patch          Int32   x1  -1 fluid, else the wall patch index k;
 *                              its name is scene->patch_names[k]
 *   pressure       Float64 x1  [Pa]; dummies carry a copy (not used here)
 *   velocity       Float64 x3  [m/s]
 *   normal         Float64 x3  wall/dummy unit normal from the fluid into
 *                              the solid (a floor has (0 -1 0) in 2-D)
 *   numberDensity  Float64 x1  n_i/n0, with the number-density radius
 *   freeSurface    UInt8   x1  0 inner, 1 surface (2 dry wall)
 *   id             Int64   x1  persistent particle id
 *   phase          Int32   x1  optional: 1 soil, 0 water (cases with soil,
 *                              doc/theory.md K); front, waveGauges and
 *                              volume select one with the key `phase`
 *   soilFraction   Float64 x1  optional (cases with soil): of a wall
 *                              particle, the soil's share of its fluid
 *                              neighbours; forces splits the load by it
 *   wallArea       Float64 x1  optional: the wall area (length in 2-D)
 *                              a wall particle stands for [m^(d-1)];
 *                              without it forces takes dp^(d-1)
 *   viscousTraction Float64 x3 optional: of a wall particle, the viscous
 *                              stress the fluid exerts on the wall [Pa];
 *                              forces adds it (mlpgFluid, doc M0-24)
 *
 * scene->spacing = dp [m]; scene->dim = 2 (x-y plane, vertical y) or 3
 * (vertical z); scene->patch_names/npatches name the wall patches;
 * scene->values may hold "escaped" (1 component: particles removed so far).
 *
 * Each type checks the fields it uses at create time (a missing or
 * mistyped field is an error naming it) and looks them up again at every
 * execution: the solver's arrays may move between steps (renumbering,
 * reallocation), so no data pointer is kept across calls. Particle
 * indices are never kept either; `id` is the stable identity.
 */
#ifndef MPSDEM_FUNCTIONOBJECTS_MPS_FUNCTIONOBJECTS_H
#define MPSDEM_FUNCTIONOBJECTS_MPS_FUNCTIONOBJECTS_H

#include <stdint.h>

#include "functionObjects/functionObject.h"

struct dict;

extern const struct fo_ops *const mps_fo_table[];

/* ---- helpers shared by the MPS function objects (mps_functionObjects.c) */

/* Fields of the contract, as bits for mps_fo_fields_get(). */
enum {
    MPS_FO_TYPE = 1u << 0,
    MPS_FO_PATCH = 1u << 1,
    MPS_FO_PRESSURE = 1u << 2,
    MPS_FO_VELOCITY = 1u << 3,
    MPS_FO_NORMAL = 1u << 4,
    MPS_FO_ND = 1u << 5,
    MPS_FO_FS = 1u << 6,
    MPS_FO_ID = 1u << 7,
};

/* Borrowed views of the scene's arrays, valid during one call only. */
struct mps_fo_fields {
    size_t n;
    const double *x;       /* 3n positions              */
    const int32_t *type, *patch;
    const double *p, *u, *normal, *nd;
    const uint8_t *fs;
    const int64_t *id;
    const int32_t *phase;  /* the optional field "phase", or NULL */
    const double *soil_frac; /* the optional field "soilFraction", or NULL */
    const double *wall_area; /* the optional field "wallArea", or NULL */
    const double *traction;  /* the optional "viscousTraction", or NULL */
};

/* Fill f with the fields named in `mask` (others NULL) after checking type
 * and components; `who` (the function object's dictionary) is named in the
 * error, which is SIM_ERR_INPUT. Also checks dim (2 or 3) and spacing. */
int mps_fo_fields_get(const struct dict *who, const struct fo_scene *s,
                      unsigned mask, struct mps_fo_fields *f);

/* The fluid particles a function object looks at: its key
 *     phase   all;    // all (default) | water | soil
 * (cases with soil, doc/theory.md K). `soil` on a cloud without the field
 * "phase" is an error naming the key; `water` there is every fluid
 * particle. */
enum mps_fo_phase { MPS_FO_ALL_PHASES = 0, MPS_FO_WATER, MPS_FO_SOIL };
int mps_fo_read_phase(const struct dict *d, const struct fo_scene *s,
                      int *phase);
extern const struct model_head *const mps_fo_phase_table[];

/* Non-zero when particle i is a fluid particle (type 0) of `phase`. */
static inline int mps_fo_in_phase(const struct mps_fo_fields *f, long i,
                                  int phase)
{
    if (f->type[i] != 0)
        return 0;
    if (phase == MPS_FO_ALL_PHASES || !f->phase)
        return 1;
    return (f->phase[i] == 1) == (phase == MPS_FO_SOIL);
}

/* Index of the vertical axis: 1 in 2-D, 2 in 3-D. */
int mps_fo_vertical(int dim);

/* Read the list `key` of points "((a b ...) ...)" (at least one). Each
 * point has between nmin and nmax numbers; they are stored in 3 slots per
 * point, missing ones zero. With nmin = 1 an item may also be a bare
 * number, "(x0 x1 ...)". *pts is allocated (free it). Errors are
 * SIM_ERR_DICT located at the offending item. */
int mps_fo_read_points(const struct dict *d, const char *key, int nmin,
                       int nmax, double **pts, int *n);

/* Value `name` published by the solver, or NULL. */
const struct fo_value *mps_fo_value(const struct fo_scene *s,
                                    const char *name);

#endif
