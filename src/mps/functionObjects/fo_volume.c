/*
 * fo_volume.c — fluid conservation: the number of fluid particles, their
 * volume N dp^d (area in 2-D), and the count of particles removed so far
 * because they left the domain (solver value "escaped"). In an
 * incompressible MPS run the count changes only through escapes.
 *
 * Keys: none beyond the schedule.
 * Columns: time, n_fluid, volume [m^3 or m^2], escaped.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "core/error.h"
#include "mps/functionObjects/mps_functionObjects.h"

static int create(const struct dict *d, const struct fo_scene *s, void **data)
{
    (void)d;
    (void)s;
    *data = NULL;
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    (void)data;
    fprintf(f, "# fluid particles and volume N dp^%d\n# time n_fluid volume "
            "escaped\n", s->dim);
    return SIM_OK;
}

static int execute(void *data, const struct fo_scene *s, FILE *f)
{
    (void)data;
    const int32_t *ty = mps_fo_field(s, "type", VTU_INT32);
    long n = 0;
    for (size_t i = 0; i < s->cloud->n; i++)
        n += !ty || ty[i] == 0;
    double esc = 0;
    for (int k = 0; k < s->nvalues; k++)
        if (strcmp(s->values[k].name, "escaped") == 0)
            esc = s->values[k].v[0];
    fprintf(f, "%.10g %ld %.8g %.0f\n", s->time, n,
            n * pow(s->spacing, s->dim), esc);
    return SIM_OK;
}

static void destroy(void *data)
{
    (void)data;
}

const struct fo_ops mps_fo_volume = {
    .name = "volume", .reference = "", .file = "volume",
    .create = create, .header = header, .execute = execute,
    .destroy = destroy,
};
