/* stabiliser_register.c — the lists of collision and shifting models, and
 * the explicit `none`. */
#include <stddef.h>

#include "core/error.h"
#include "mps/stabiliser/stabiliser.h"

static int apply_none(struct mps_solver *s, double dt)
{
    (void)s;
    (void)dt;
    return SIM_OK;
}

const struct mps_stabiliser_ops mps_stabiliser_none = {
    .name = "none", .reference = "", .apply = apply_none,
};

const struct mps_stabiliser_ops *const mps_collision_table[] = {
    &mps_stabiliser_none, &mps_collision_lee2011, NULL
};

const struct mps_stabiliser_ops *const mps_shifting_table[] = {
    &mps_stabiliser_none, &mps_shifting_xu2009, &mps_shifting_lind2012,
    NULL
};
