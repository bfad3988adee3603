/*
 * uniform.c — `diameterDistribution uniform (min max);`: diameters
 * uniform in [min, max] by number.
 */
#include "sizeDistribution.h"

#include <math.h>

#include "core/dict.h"
#include "core/error.h"

static int uniform_read(const struct dict_value *entry, struct size_dist *s)
{
    double p[2];
    TRY(size_dist_numbers(entry, 1, 2, "uniform", "(min max)", p));
    if (dict_value_len(entry) > 2)
        return dict_value_error(dict_value_at(entry, 2), SIM_ERR_DICT,
                                "uniform takes one list, (min max)");
    if (!(p[1] >= p[0]))
        return dict_value_error(dict_value_at(entry, 1), SIM_ERR_DICT,
                                "uniform (min max): max %g is below min %g",
                                p[1], p[0]);
    s->min = p[0];
    s->max = p[1];
    s->mean = 0.5 * (p[0] + p[1]);
    s->sd = (p[1] - p[0]) / sqrt(12.0);
    return SIM_OK;
}

static double uniform_draw(const struct size_dist *s, struct gen_rng *g)
{
    return s->min + (s->max - s->min) * gen_rng_uniform(g);
}

const struct size_dist_ops size_dist_uniform = {
    "uniform", "by number, in [min, max]", uniform_read, uniform_draw
};
