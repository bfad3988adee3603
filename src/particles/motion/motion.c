/*
 * motion.c — selection of a wall motion model and the removeAt key
 * (motion.h).
 */
#include "particles/motion/motion.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/select.h"

const struct wall_motion_ops *const wall_motion_models[] = {
    &wall_motion_none, &wall_motion_translation, &wall_motion_table,
    &wall_motion_oscillation, NULL
};

void wall_motion_init(struct wall_motion *w)
{
    memset(w, 0, sizeof *w);
    w->ops = &wall_motion_none;
    w->remove_at = INFINITY;
}

void wall_motion_free(struct wall_motion *w)
{
    free(w->t);
    free(w->d);
    wall_motion_init(w);
}

void wall_motion_displacement(const struct wall_motion *w, double t,
                              double d[3])
{
    w->ops->displacement(w, t, d);
}

void wall_motion_velocity(const struct wall_motion *w, double t, double v[3])
{
    w->ops->velocity(w, t, v);
}

static int read_motion(const struct dict *region, int dim,
                       const char *case_dir, struct wall_motion *w)
{
    const struct dict *m;
    const void *ops;
    TRY(dict_get_dict(region, "motion", &m));
    TRY(model_select(m, "type", "wall motion",
                     (const void *const *)wall_motion_models, NULL, &ops));
    w->ops = ops;
    TRY(w->ops->read(m, dim, case_dir, w));
    /* genParticles places the wall at its dictionary shape, and the
     * solvers move it by d(t) - d(t0): the shape must be the wall at 0 */
    double d0[3];
    wall_motion_displacement(w, 0.0, d0);
    if (d0[0] != 0 || d0[1] != 0 || d0[2] != 0)
        return dict_error(region, "motion", SIM_ERR_DICT, "the motion "
                          "displaces the wall by (%g %g %g) m at t = 0, but "
                          "the region's shape is the wall at t = 0: the "
                          "displacement must be 0 there (translation: "
                          "start >= 0; table: 0 at t = 0)", d0[0], d0[1],
                          d0[2]);
    return SIM_OK;
}

int wall_motion_read(const struct dict *region, int is_wall, int dim,
                     const char *case_dir, struct wall_motion *w)
{
    wall_motion_init(w);
    static const char *const keys[] = { "motion", "removeAt" };
    for (int k = 0; k < 2; k++)
        if (!is_wall && dict_has(region, keys[k]))
            return dict_error(region, keys[k], SIM_ERR_DICT, "'%s' applies "
                              "to wall and tankWall regions only",
                              keys[k]);
    if (!is_wall)
        return SIM_OK;
    int rc = SIM_OK;
    if (dict_has(region, "motion"))
        rc = read_motion(region, dim, case_dir, w);
    if (!rc && dict_has(region, "removeAt")) {
        rc = dict_get_scalar(region, "removeAt", &w->remove_at);
        if (!rc && !(w->remove_at >= 0 && isfinite(w->remove_at)))
            rc = dict_error(region, "removeAt", SIM_ERR_DICT, "removeAt "
                            "%g s must be a time >= 0 (leave it out for a "
                            "wall that stays)", w->remove_at);
    }
    if (rc)
        wall_motion_free(w);
    return rc;
}
