/*
 * sizeDistribution.h — grain diameter distributions of `lattice random`
 * regions (particleDict.reference), one model per file, selected by name:
 *
 *     diameterDistribution uniform (min max);
 *     diameterDistribution normal (mean standardDeviation) (min max);
 *
 * A distribution is by number (each grain draws its diameter), bounded by
 * [min, max] so that the packing knows its largest grain.
 */
#ifndef MPSDEM_GENPARTICLES_SIZEDISTRIBUTION_H
#define MPSDEM_GENPARTICLES_SIZEDISTRIBUTION_H

#include "../rng.h"

struct dict;
struct dict_value;

struct size_dist {
    const struct size_dist_ops *ops; /* NULL: every grain has diameter min */
    double min, max;                 /* diameters drawn lie in [min, max] [m] */
    double mean, sd;                 /* normal [m]                           */
};

struct size_dist_ops {
    const char *name;      /* the word in particleDict                  */
    const char *reference; /* printed at selection                      */
    /* The parameters: the items after the name in `entry` (a dictionary
     * entry value); every bad one is an error located at it. */
    int (*read)(const struct dict_value *entry, struct size_dist *s);
    double (*draw)(const struct size_dist *s, struct gen_rng *g);
};

extern const struct size_dist_ops size_dist_uniform;
extern const struct size_dist_ops size_dist_normal;
extern const struct size_dist_ops *const size_dist_table[]; /* NULL ended */

/* `key` of d: a model name and its parameters, or a fixed diameter
 * (fixed > 0) when the key is absent. Logs the selection. */
int size_dist_read(const struct dict *d, const char *key, double fixed,
                   struct size_dist *s);

/* A diameter [m]. */
double size_dist_draw(const struct size_dist *s, struct gen_rng *g);

/* The `i`-th list of numbers after the name in `entry`: n numbers, all
 * finite and positive (for the models' own use). `what` names them in
 * messages, e.g. "(min max)". */
int size_dist_numbers(const struct dict_value *entry, int i, int n,
                      const char *model, const char *what, double *out);

#endif
