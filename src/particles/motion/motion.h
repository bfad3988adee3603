/*
 * motion.h — prescribed rigid translation and removal of a wall region
 * (system/particleDict: `motion { type ...; }` and `removeAt`), read once
 * by genParticles, demSolid and mpsFluid so that the three see one
 * geometry at every time (doc/design.md "Moving and removed walls").
 *
 * The region's shape in the dictionary is the wall at t = 0; at time t it
 * is that shape translated by the displacement d(t) of the motion model,
 * which is therefore 0 at t = 0. A model is selected by name from
 * wall_motion_models (select.h):
 *
 *   none         d = 0 (a fixed wall; the default)
 *   translation  d = velocity (min(max(t, start), end) - start): constant
 *                velocity in [start, end), at rest before and after
 *   table        d linear between the rows "t x y z" of a file, constant
 *                beyond its first and last time
 *   oscillation  d = amplitude (1 - cos(omega t)): a wavemaker's piston
 *
 * removeAt T: the wall exists for t < T only (T >= 0; 0 removes it before
 * the first step, e.g. the gate of a dam break).
 */
#ifndef MPSDEM_PARTICLES_MOTION_H
#define MPSDEM_PARTICLES_MOTION_H

#include <stddef.h>

struct dict;
struct wall_motion;

struct wall_motion_ops {
    const char *name;
    const char *reference;
    /* Read the model's keys of the motion dictionary m (dim 2: the z
     * components are dropped); files relative to case_dir. */
    int (*read)(const struct dict *m, int dim, const char *case_dir,
                struct wall_motion *w);
    void (*displacement)(const struct wall_motion *w, double t, double d[3]);
    void (*velocity)(const struct wall_motion *w, double t, double v[3]);
};

struct wall_motion {
    const struct wall_motion_ops *ops;  /* &wall_motion_none if no motion */
    double velocity[3];                 /* translation [m/s]              */
    double start, end;                  /* translation: [start, end) [s]  */
    double amplitude[3], omega;         /* oscillation [m], [rad/s]       */
    size_t nrows;                       /* table                          */
    double *t, *d;                      /* table: times [s], 3 per row [m]*/
    double remove_at;                   /* [s]; INFINITY: never removed   */
};

extern const struct wall_motion_ops wall_motion_none;
extern const struct wall_motion_ops wall_motion_translation;
extern const struct wall_motion_ops wall_motion_table;
extern const struct wall_motion_ops wall_motion_oscillation;
/* NULL terminated, for model_select. */
extern const struct wall_motion_ops *const wall_motion_models[];

/* A fixed wall that stays (what a region without motion/removeAt is). */
void wall_motion_init(struct wall_motion *w);
void wall_motion_free(struct wall_motion *w);

/* `motion { ... }` and `removeAt` of one region dictionary. is_wall: the
 * region is a wall or tankWall (any other region with either key is an
 * error). Errors cite file:line of the key (and the table file's line).
 * On error *w holds nothing to free. */
int wall_motion_read(const struct dict *region, int is_wall, int dim,
                     const char *case_dir, struct wall_motion *w);

/* 1 if the wall ever moves (its particles/geometry need updating). */
static inline int wall_motion_moves(const struct wall_motion *w)
{
    return w->ops != &wall_motion_none;
}

/* 1 if the wall has been removed at time t. Times that accumulate steps
 * miss removeAt by round-off: a step that lands within 1e-9 s of it
 * counts as reaching it. */
static inline int wall_motion_removed(const struct wall_motion *w, double t)
{
    return t >= w->remove_at - 1e-9;
}

/* d(t) and v(t) = d'(t) (0 at the kinks' left side for a table). */
void wall_motion_displacement(const struct wall_motion *w, double t,
                              double d[3]);
void wall_motion_velocity(const struct wall_motion *w, double t, double v[3]);

#endif
