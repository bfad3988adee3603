/*
 * functionObject.h — scheduled diagnostics (OpenFOAM function objects,
 * Gerris events; doc/design.md C14). A solver never knows which diagnostics
 * exist: it describes its state as a `struct fo_scene` and calls
 * fo_list_execute() once per step.
 *
 * controlDict:
 *   functions
 *   {
 *       gauge1                       // name: output under postProcessing/gauge1/
 *       {
 *           type            waveGauges;   // selected from the registry
 *           writeControl    timeStep;     // timeStep | runTime | adjustableRunTime | writeTime
 *           writeInterval   1;            // steps, or [s]
 *           timeStart       0;            // [s] optional
 *           timeEnd         1e30;         // [s] optional
 *           enabled         yes;
 *           ...                           // the type's own keys
 *       }
 *   }
 *
 * Each function object writes postProcessing/<name>/<startTime>/<file>.dat:
 * `#` header lines naming the columns, then one row per execution, time
 * first. A restarted run opens a new <startTime> directory, as OpenFOAM does.
 */
#ifndef MPSDEM_FUNCTIONOBJECTS_FUNCTIONOBJECT_H
#define MPSDEM_FUNCTIONOBJECTS_FUNCTIONOBJECT_H

#include <stdio.h>

#include "particles/store.h"

struct dict;

/* A named global value a solver publishes for diagnostics, e.g.
 * "wallForce.obstacle" (3 components) or "n0" (1). */
struct fo_value {
    const char *name;
    int ncomp;
    double v[9];
};

/* What a function object sees of the solver, valid during one call. */
struct fo_scene {
    double time, dt;
    long step;
    int dim;                       /* 2 or 3                                  */
    const char *cloud_name;        /* "fluid" or "dem"                        */
    const struct store *store;     /* the cloud's fields by name (store_require,
                                      "position" among them); n particles     */
    double spacing;                /* fluid dp, or mean grain diameter [m]    */
    const char *const *patch_names;/* patch id -> name (constant/particlePatches) */
    int npatches;
    const struct fo_value *values; /* solver globals                          */
    int nvalues;
    void *solver;                  /* for solver-specific function objects    */
};

/* Ops of one function-object type. */
struct fo_ops {
    const char *name;        /* `type` keyword                               */
    const char *reference;   /* "" or the source of a definition             */
    const char *file;        /* output file name without .dat ("" = name)    */
    /* Read the type's keys from d (the entry's sub-dictionary) and create the
     * private data. The scene is the initial state (fields exist by name). */
    int (*create)(const struct dict *d, const struct fo_scene *s, void **data);
    /* Write the `#` header lines (column names) to f. */
    int (*header)(void *data, const struct fo_scene *s, FILE *f);
    /* Compute and write one row (time first) to f. */
    int (*execute)(void *data, const struct fo_scene *s, FILE *f);
    void (*destroy)(void *data);
};

struct fo_list;

/* Create every entry of `functions` (may be NULL: an empty list), selecting
 * each `type` among the tables given (NULL-terminated arrays of ops
 * pointers; `tables` itself ends with NULL), so that a solver adds its own
 * types to the generic ones: { fo_generic_table, mps_fo_table, NULL }. */
int fo_list_create(const struct dict *functions, const struct fo_ops *const *const *tables,
                   const struct fo_scene *s, const char *case_dir,
                   double start_time, int precision, struct fo_list **out);

/* Run the entries whose schedule is due at this step (write_time: this step
 * is also a write of the fields, for writeControl writeTime). Rows are
 * flushed to disk at each call. */
int fo_list_execute(struct fo_list *l, const struct fo_scene *s, int write_time);

/* Would fo_list_execute run some entry at (time, step)? (l may be NULL.)
 * A distributed solver gathers its cloud only for those steps. */
int fo_list_due(struct fo_list *l, double time, long step, double dt,
                int write_time);

void fo_list_free(struct fo_list *l);

/* Generic function objects that need only a cloud (cloudInfo: counts per
 * type and bounding box). */
extern const struct fo_ops *const fo_generic_table[];

#endif
