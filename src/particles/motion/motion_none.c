/* motion_none.c — a fixed wall (motion.h). */
#include "particles/motion/motion.h"

#include "core/error.h"

static int read_none(const struct dict *m, int dim, const char *case_dir,
                     struct wall_motion *w)
{
    (void)m, (void)dim, (void)case_dir, (void)w;
    return SIM_OK;
}

static void zero(const struct wall_motion *w, double t, double d[3])
{
    (void)w, (void)t;
    d[0] = d[1] = d[2] = 0;
}

const struct wall_motion_ops wall_motion_none = {
    .name = "none",
    .reference = "",
    .read = read_none,
    .displacement = zero,
    .velocity = zero,
};
