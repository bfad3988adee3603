/*
 * normal.c — `diameterDistribution normal (mean standardDeviation) (min
 * max);`: a normal distribution of diameters by number, truncated to
 * [min, max] (a draw outside is drawn again, so that no diameter piles up
 * on a bound as clamping would do). Draws: Box & Muller (1958).
 */
#include "sizeDistribution.h"

#include <math.h>

#include "core/dict.h"
#include "core/error.h"

/* Probability that a draw lands in [min, max]. */
static double kept(const struct size_dist *s)
{
    if (s->sd == 0)
        return s->mean >= s->min && s->mean <= s->max;
    double a = (s->min - s->mean) / (s->sd * M_SQRT2);
    double b = (s->max - s->mean) / (s->sd * M_SQRT2);
    return 0.5 * (erf(b) - erf(a));
}

static int normal_read(const struct dict_value *entry, struct size_dist *s)
{
    double ms[2], range[2];
    TRY(size_dist_numbers(entry, 1, 2, "normal", "(mean standardDeviation)",
                          ms));
    TRY(size_dist_numbers(entry, 2, 2, "normal", "the clip range (min max)",
                          range));
    if (dict_value_len(entry) > 3)
        return dict_value_error(dict_value_at(entry, 3), SIM_ERR_DICT,
                                "normal takes two lists, (mean "
                                "standardDeviation) (min max)");
    if (!(range[1] >= range[0]))
        return dict_value_error(dict_value_at(entry, 2), SIM_ERR_DICT,
                                "normal (min max): max %g is below min %g",
                                range[1], range[0]);
    s->mean = ms[0];
    s->sd = ms[1];
    s->min = range[0];
    s->max = range[1];
    /* below 1e-3 the redraws would cost more than the packing, and the
     * distribution is not what the numbers suggest */
    if (kept(s) < 1e-3)
        return dict_value_error(dict_value_at(entry, 2), SIM_ERR_DICT,
                                "normal (%g %g) keeps a fraction %.2g of its "
                                "draws in (%g %g): put the clip range "
                                "around the mean", s->mean, s->sd, kept(s),
                                s->min, s->max);
    return SIM_OK;
}

static double normal_draw(const struct size_dist *s, struct gen_rng *g)
{
    for (;;) {
        double d = s->mean + s->sd * gen_rng_normal(g);
        if (d >= s->min && d <= s->max)
            return d;
    }
}

const struct size_dist_ops size_dist_normal = {
    "normal", "by number, truncated to [min, max]", normal_read, normal_draw
};
