/*
 * motion_oscillation.c — the piston of a wavemaker (motion.h):
 *
 *   d(t) = amplitude (1 - cos(omega t)),  v(t) = amplitude omega sin(omega t)
 *
 * (Pan 2022 thesis eqs. 4.39-4.40): at rest at t = 0, swinging between 0
 * and 2 amplitude. Keys: amplitude (a vector [m]), omega [rad/s].
 */
#include "particles/motion/motion.h"

#include <math.h>

#include "core/dict.h"
#include "core/error.h"

static int read_oscillation(const struct dict *m, int dim,
                            const char *case_dir, struct wall_motion *w)
{
    (void)case_dir;
    TRY(dict_get_vector(m, "amplitude", 3, w->amplitude));
    if (dim == 2)
        w->amplitude[2] = 0;
    for (int a = 0; a < 3; a++)
        if (!isfinite(w->amplitude[a]))
            return dict_error(m, "amplitude", SIM_ERR_DICT, "amplitude "
                              "must be finite");
    TRY(dict_get_scalar(m, "omega", &w->omega));
    TRY(dict_range(m, "omega", w->omega, 0, 1e6, 1));
    return SIM_OK;
}

static void displacement(const struct wall_motion *w, double t, double d[3])
{
    double s = 1 - cos(w->omega * t);
    for (int a = 0; a < 3; a++)
        d[a] = w->amplitude[a] * s;
}

static void velocity(const struct wall_motion *w, double t, double v[3])
{
    double s = w->omega * sin(w->omega * t);
    for (int a = 0; a < 3; a++)
        v[a] = w->amplitude[a] * s;
}

const struct wall_motion_ops wall_motion_oscillation = {
    .name = "oscillation",
    .reference = "Pan 2022 eqs. 4.39-4.40: a (1 - cos omega t)",
    .read = read_oscillation,
    .displacement = displacement,
    .velocity = velocity,
};
