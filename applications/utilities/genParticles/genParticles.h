/*
 * genParticles.h — the case read from system/particleDict and the clouds
 * made from it (internal to the genParticles utility).
 *
 * The reference for every key is particleDict.reference beside this file.
 */
#ifndef MPSDEM_GENPARTICLES_H
#define MPSDEM_GENPARTICLES_H

#include <stddef.h>
#include <stdint.h>

#include "particles/geometry.h"
#include "particles/lattice.h"
#include "sizeDistribution/sizeDistribution.h"

struct app;
struct dict;
struct grain_format_ops;

enum region_type { REGION_TANK_WALL, REGION_WALL, REGION_FLUID, REGION_GRAINS,
                   REGION_SOIL };
extern const char *const region_type_names[]; /* NULL terminated */

/* Shape words of a region: geom_shape_names, then "file" (grains read
 * from a file: fileGrains.c), NULL terminated. */
enum { SHAPE_FILE = GEOM_HALFSPACE + 1 };
extern const char *const region_shape_names[];

/* How a grains region places its grains: on a lattice (r->lattice), by
 * random sequential addition (randomPack.c), or as a file lists them. */
enum grain_layout { GRAINS_LATTICE, GRAINS_RANDOM, GRAINS_FILE };

/* MPS particle types (field "type" of fluid.vtu). */
enum { TYPE_FLUID = 0, TYPE_WALL = 1, TYPE_DUMMY = 2 };

struct region {
    char name[64];
    enum region_type type;
    struct geom g;
    int shape;              /* the shape word given (geom may differ: a   */
                            /* 2-D cylinder along z becomes a circle)     */
    const struct dict *d;   /* its sub-dictionary, for error locations  */
    unsigned open;          /* tankWall box: bit 2 axis + side open      */
    int bounded;            /* shape has a finite bounding box           */
    double velocity[3];     /* fluid, grains [m/s]                       */
    double omega[3];        /* grains [rad/s]                            */
    int hydrostatic;        /* fluid: initial hydrostatic pressure       */
    int surface_nodes;      /* wall, 2-D circle: one layer of nodes ON   */
                            /* the surface (mlpgFluid), surfaceNodes.c   */
    double clearance;       /* surface nodes: fluid kept this far [dp]   */
    int has_surface;        /* fluid: surfaceHeight given                */
    double surface;         /* fluid: free-surface height [m]            */
    double diameter;        /* grains [m]                                */
    double spacing;         /* grains: lattice spacing [m]               */
    double jitter;          /* amplitude: grains, fraction of spacing;
                               fluid, fraction of dp                     */
    long seed;              /* jitter seed (grains, fluid)               */
    enum lattice_kind lattice; /* grains                                 */
    enum grain_layout layout;  /* grains                                 */
    struct size_dist dist;  /* random: grain diameters                   */
    double solid_fraction;  /* random: target                            */
    long max_attempts;      /* random: tries per grain                   */
    char *file;             /* file: the path opened                     */
    const struct grain_format_ops *format; /* file                       */
    double max_overlap;     /* file: largest overlap / smaller radius    */
    size_t fn;              /* file: grains read                         */
    double *fx, *fr;        /* file: centres (3 fn) and radii [m]        */
    long *fline;            /* file: line of each grain in the file      */
    /* filled in by the generator */
    double clo[3], chi[3];  /* box outside which it claims no site [m]   */
    size_t count[4];        /* fluid, wall, dummy, grains                */
    double top;             /* fluid: highest particle + dp/2 [m]        */
};

struct gen_case {
    const struct app *app;  /* the case: files are relative to it        */
    const char *dict_path;  /* "system/particleDict" as opened          */
    const struct dict *d;
    int dim;                /* 2 or 3                                    */
    int vertical;           /* 2 in 3-D (z), 1 in 2-D (y)                */
    double dp;              /* fluid spacing [m]                         */
    int layers;             /* wall + dummy layers                       */
    int binary;             /* writeFormat                               */
    double origin[3];       /* one fluid lattice site [m]                */
    int nregions;
    struct region *r;
    double lo[3], hi[3];    /* box the MPS lattice is scanned over       */
    double rho, g[3];       /* only when a region asks for hydrostatics  */
    double rho_soil;        /* constant/soilProperties rho: only then    */
};

/* The MPS cloud (fluid, wall and dummy particles), structure of arrays. */
struct mps_cloud {
    size_t n;
    double *x, *u, *p, *normal;
    int32_t *type, *patch, *region;
    double *phi;            /* NULL, or the fluid volume fraction of each
                               particle (grainVolume scale)              */
    int32_t *phase;         /* NULL without soil regions, else 1 for the
                               particles of a soil region, 0 for others */
};

struct dem_cloud {
    size_t n;
    double *x, *radius, *u, *omega;
    int32_t *group;
};

/* surfaceNodes.c: replace the lattice sites of every wall region with
 * surfaceNodes by nodes on its surface, and drop the fluid sites closer
 * to it than its clearance. */
int gen_surface_nodes(struct gen_case *c, struct mps_cloud *m);

/* particleDict.c: read and check the dictionary; kernel_radius_hint is
 * r_e / dp from system/mpsSchemes or 0 when unknown; binary_default the
 * writeFormat of system/controlDict (1 binary, 0 ascii). */
int gen_read(struct gen_case *c, const struct app *a, const struct dict *d,
             const char *path, double kernel_radius_hint, int binary_default);
void gen_case_free(struct gen_case *c);

/* fileGrains.c: `shape file` regions. gen_file_read reads the region's
 * keys and its file (every row checked, radii positive); gen_file_check,
 * once every region is known, refuses grains outside the tanks and
 * overlaps above maxOverlap, naming the lines. */
int gen_file_read(const struct gen_case *c, struct region *r);
int gen_file_check(const struct gen_case *c, const struct region *r);

/* randomPack.c: `lattice random` regions. gen_random_read reads their
 * keys; gen_random_pack places the grains (centres 3n, radii n). */
int gen_random_read(const struct gen_case *c, struct region *r);
double gen_region_volume(const struct region *r);
int gen_random_pack(const struct gen_case *c, const struct region *r,
                    double **x, double **radius, size_t *n);

/* generate.c */
int gen_check_memory(const struct gen_case *c);
int gen_mps(struct gen_case *c, struct mps_cloud *m);
int gen_dem(struct gen_case *c, struct dem_cloud *m);
int gen_hydrostatic(struct gen_case *c, struct mps_cloud *m);
/* grainVolume.c: fluid regions with `grainVolume scale;` give each fluid
 * particle the volume fraction phi = porosity at its site (m->phi; reads
 * system/couplingDict). */
struct app;
int gen_grain_volume(const struct app *a, struct gen_case *c,
                     struct mps_cloud *m, const struct dem_cloud *g);
void mps_cloud_free(struct mps_cloud *m);
void dem_cloud_free(struct dem_cloud *m);

#endif
