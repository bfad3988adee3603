/*
 * motion_translation.c — translation at a constant velocity during
 * [start, end), at rest before and after (motion.h).
 */
#include "particles/motion/motion.h"

#include <math.h>

#include "core/dict.h"
#include "core/error.h"

static int read_translation(const struct dict *m, int dim,
                            const char *case_dir, struct wall_motion *w)
{
    (void)case_dir;
    TRY(dict_get_vector(m, "velocity", 3, w->velocity));
    if (dim == 2)
        w->velocity[2] = 0;
    for (int a = 0; a < 3; a++)
        if (!isfinite(w->velocity[a]))
            return dict_error(m, "velocity", SIM_ERR_DICT, "velocity must "
                              "be finite");
    TRY(dict_get_scalar_or(m, "start", 0.0, &w->start));
    TRY(dict_get_scalar_or(m, "end", INFINITY, &w->end));
    if (!(w->start >= 0 && isfinite(w->start)))
        return dict_error(m, "start", SIM_ERR_DICT, "start %g s must be a "
                          "time >= 0", w->start);
    if (!(w->end > w->start))
        return dict_error(m, "end", SIM_ERR_DICT, "end %g s must come after "
                          "start %g s", w->end, w->start);
    return SIM_OK;
}

static void displacement(const struct wall_motion *w, double t, double d[3])
{
    double s = fmin(fmax(t, w->start), w->end) - w->start;
    for (int a = 0; a < 3; a++)
        d[a] = w->velocity[a] * s;
}

static void velocity(const struct wall_motion *w, double t, double v[3])
{
    int on = t >= w->start && t < w->end;
    for (int a = 0; a < 3; a++)
        v[a] = on ? w->velocity[a] : 0.0;
}

const struct wall_motion_ops wall_motion_translation = {
    .name = "translation",
    .reference = "constant velocity in [start, end)",
    .read = read_translation,
    .displacement = displacement,
    .velocity = velocity,
};
