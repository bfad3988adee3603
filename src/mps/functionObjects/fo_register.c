/* fo_register.c — the list of MPS function objects and shared helpers. */
#include <stddef.h>

#include "mps/functionObjects/mps_functionObjects.h"

const struct fo_ops *const mps_fo_table[] = {
    &mps_fo_probes, &mps_fo_wave_gauges, &mps_fo_front, &mps_fo_forces,
    &mps_fo_volume, NULL
};

const void *mps_fo_field(const struct fo_scene *s, const char *name, int type)
{
    const struct vtu_field *f = vtu_find(s->cloud, name);
    if (!f || (int)f->type != type)
        return NULL;
    return f->data;
}

int mps_fo_vertical(const struct fo_scene *s)
{
    return s->dim == 2 ? 1 : 2;
}
