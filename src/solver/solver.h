/*
 * solver.h — the scaffold every particle solver's main() runs in, so that
 * the program itself holds only its algorithm: command line and
 * -listModels, the case lock, system/controlDict (startFrom latestTime;
 * a coupled run restarts only from a time that holds both clouds),
 * function objects, output (<t>/, <cloud>.pvd truncated on restart and
 * extended at each write, failed.<t>/ dumps), the time loop with its
 * progress line, the end-of-run statistics and the way a run stops on an
 * error. Coupling enters as hooks (struct solver_coupling), called only
 * when system/couplingDict says `coupled yes`.
 *
 * A program embeds struct solver as the first member of its own state and
 * casts back in its hooks:
 *
 *     struct fluid { struct solver sv; struct mps_solver s; ... };
 *     static int advance(struct solver *sv)
 *     {
 *         struct fluid *f = (struct fluid *)sv;
 *         return mps_step(&f->s, sv->rt.dt);
 *     }
 *     int main(int argc, char **argv)
 *     {
 *         static struct fluid f;
 *         return solver_main(&fluid_ops, &f.sv, argc, argv);
 *     }
 *
 * `-relax T` (programs with a rest hook) makes a relaxed start instead of
 * a run: the program alone, from the start time, T s with no function
 * object and no output; that state at rest then replaces the start time's
 * cloud (doc/theory.md A0-25).
 *
 * Order of a run (doc/design.md §4 relies on it for the coupled programs):
 *   app_init; -listModels; lock; controlDict (+ couplingDict); create;
 *   refresh_scene + function objects; .pvd and usedParameters; unused-key
 *   warnings; coupling->open; "Starting time loop"; per step:
 *     time_set_step(propose_dt)   coupling->before_step   time_increment
 *     advance   coupling->after_step   check   refresh_scene
 *     function objects   [write time: prepare_write, write, times]
 *     progress line
 *   then coupling->finish, coupling->close(SIM_OK), stats, cleanup, "End".
 */
#ifndef MPSDEM_SOLVER_SOLVER_H
#define MPSDEM_SOLVER_SOLVER_H

#include <stddef.h>
#include <stdint.h>

#include "core/app.h"
#include "core/time.h"
#include "functionObjects/functionObject.h"

struct dict;
struct solver;

#define SOLVER_MAX_CHECKED 8

/* The peer of a coupled run. Every hook but finish and keeps_state is
 * required. */
struct solver_coupling {
    /* After set-up and the unused-key warnings, before the time loop:
     * connect to the peer (and send what it waits for first). */
    int (*open)(struct solver *sv);
    /* After time_set_step, before time_increment and the advance. */
    int (*before_step)(struct solver *sv);
    /* After the advance (NULL: nothing to do). */
    int (*after_step)(struct solver *sv);
    /* Does a failure rc of open/before_step/after_step leave a complete
     * state worth writing? NULL: always. */
    int (*keeps_state)(int rc);
    /* The run reached endTime: a last log line before the close. */
    void (*finish)(struct solver *sv);
    /* Tell the peer we leave (SIM_OK or the error); idempotent. */
    void (*close)(struct solver *sv, int rc);
};

struct solver_ops {
    const char *name;           /* "mpsFluid"                            */
    const char *description;    /* one line, for the header and -help    */
    const char *cloud;          /* "fluid": <t>/fluid.vtu, fluid.pvd     */
    const char *peer_cloud;     /* the coupled peer's, e.g. "dem"        */
    /* -listModels (NULL: no such option). */
    void (*list_models)(void);
    /* Everything the algorithm needs; sv->rt, sv->control, sv->coupling
     * and sv->coupled are set. Register the dictionaries whose unused keys
     * are to be warned about with solver_check_unused. */
    int (*create)(struct solver *sv);
    /* Function-object tables (fo_list_create). */
    const struct fo_ops *const *const *fo_tables;
    /* Fill sv->scene (and the cloud it points to) for the current time. */
    int (*refresh_scene)(struct solver *sv);
    /* The step wanted (NULL: deltaT); time_set_step bounds it. */
    double (*propose_dt)(struct solver *sv);
    /* Advance the state to sv->rt.value (time_increment was called). */
    int (*advance)(struct solver *sv);
    /* A failed advance leaves a state to inspect: written to failed.<t>/. */
    int dump_failed_advance;
    /* After the step (and its exchange), before the function objects
     * (NULL: none). */
    int (*check)(struct solver *sv);
    /* Before the fields of a write time are written (NULL: none). */
    int (*prepare_write)(struct solver *sv);
    /* Write the clouds into dir (which exists); on failure remove what
     * was written, so that the scaffold can discard the directory. */
    int (*write)(struct solver *sv, const char *dir);
    /* Appended to the progress line (NULL: nothing). */
    void (*progress)(struct solver *sv, char *buf, size_t n);
    /* The final statistics frame (NULL: none). */
    void (*stats)(struct solver *sv);
    /* -relax: bring the state to rest (every velocity 0), before and
     * after the relaxation run; an error refuses the relaxation (walls
     * that move with time, say). NULL: the program has no -relax. */
    int (*rest)(struct solver *sv);
    /* Free what create made (the scaffold frees its own part). */
    void (*cleanup)(struct solver *sv);
    /* NULL: the program runs alone only (a case whose couplingDict says
     * coupled yes is an input error). */
    const struct solver_coupling *coupling;
    /* The program runs distributed with -parallel (MPI builds; doc/
     * design.md §8). Then every rank runs every hook; the hooks that
     * gather (refresh_scene, write) are collective, and write is called
     * with dir NULL on the ranks other than 0, which write nothing. */
    int parallel;
};

struct solver {
    struct app app;
    const struct solver_ops *ops;
    struct dict *control;       /* system/controlDict                     */
    struct dict *coupling;      /* system/couplingDict, or NULL           */
    int coupled;                /* couplingDict says coupled yes          */
    struct run_time rt;
    struct fo_list *fos;
    struct fo_scene scene;      /* filled by ops->refresh_scene           */
    const struct dict *checked[SOLVER_MAX_CHECKED];
    int nchecked;
    /* -parallel: this process's rank (0 in one process); only rank 0
     * logs, locks the case and writes. */
    int rank;
    int distributed;            /* -parallel was given                    */
};

/* Run the program: returns the exit status of a complete run; on an error
 * it stops the program through app_fatal (after a coupled run's peer has
 * been told). */
int solver_main(const struct solver_ops *ops, struct solver *sv, int argc,
                char **argv);

/* Warn about the unused keys of d once set-up is done (after
 * controlDict's), in the order of the calls. */
int solver_check_unused(struct solver *sv, const struct dict *d);

/* constant/particlePatches (genParticles): the lattice's dimension and
 * spacing (lattice_read_patches) into *dim and *dp, the patch names (at
 * most max; they point into *patches, which the caller frees). only_dim
 * 2: a 2-D solver, any other dimension is an error naming the program;
 * 0: 2 or 3. */
int solver_read_patches(struct solver *sv, int only_dim, struct dict **patches,
                        int *dim, double *dp, const char **names, int max,
                        int *n);

/* The start cloud of a 2-D solver with one layer of wall particles on the
 * walls (mlpgFluid's nodes, isphSediment's particles; genParticles with
 * `wallLayers 1` and `origin` on the tank's corner). `noun` names a
 * particle in the messages ("node", "particle").
 *
 * solver_wall_cloud_size: the .vtu `c` read from `path` has the fields
 * type, patch (Int32), velocity, normal (Float64 x 3), pressure (Float64)
 * and, if any, id (Int64), and at most 1e8 particles: *n of them.
 * solver_wall_cloud_copy: those fields into w's arrays of n (id i where
 * the cloud has none); every particle of type 0 (fluid) or 1 (wall), or
 * with `dummies` also 2 (dummy), z = 0, walls with a unit normal in the
 * x-y plane. */
struct vtu_cloud;
struct solver_wall_cloud {
    double *x, *u, *p, *normal;
    int32_t *type, *patch;
    int64_t *id;
    int dummies;                 /* 1: dummy layers (type 2) accepted */
};
int solver_wall_cloud_size(const struct vtu_cloud *c, const char *path,
                           const char *noun, int *n);
int solver_wall_cloud_copy(const struct vtu_cloud *c, const char *path,
                           const char *noun,
                           const struct solver_wall_cloud *w);

/* The clouds into <t>/ (prefix "") and the .pvd, or into <prefix><t>/
 * ("failed.": a state to inspect, not to restart from, not in the .pvd).
 * A failed write leaves no directory behind for latestTime. */
int solver_write(struct solver *sv, const char *prefix);

#endif
