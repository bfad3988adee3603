/*
 * stabiliser.h — optional robustness additions that are not part of the
 * paper's method (doc/theory.md A.10 [P]): off by default and named in
 * system/mpsSchemes (`collision none;`, `shifting none;`).
 *
 * apply(s, dt) is called once per step: collision on the predicted
 * velocity u* before the pressure equation, shifting after the position
 * update (it moves positions; the neighbour list of the step is reused). A non-zero
 * return is an error code.
 */
#ifndef MPSDEM_MPS_STABILISER_H
#define MPSDEM_MPS_STABILISER_H

struct mps_solver;

struct mps_stabiliser_ops {
    const char *name;
    const char *reference;
    int (*apply)(struct mps_solver *s, double dt);
};

extern const struct mps_stabiliser_ops mps_stabiliser_none;
extern const struct mps_stabiliser_ops mps_collision_lee2011;
extern const struct mps_stabiliser_ops mps_shifting_xu2009;
extern const struct mps_stabiliser_ops mps_shifting_lind2012;

extern const struct mps_stabiliser_ops *const mps_collision_table[];
extern const struct mps_stabiliser_ops *const mps_shifting_table[];

#endif
