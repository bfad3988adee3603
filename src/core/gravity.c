/* gravity.c — see gravity.h. */
#include "core/gravity.h"

#include "core/dict.h"
#include "core/error.h"

int gravity_read(const struct dict *g, double out[3])
{
    static const int accel[7] = {0, 1, -2, 0, 0, 0, 0};
    if (dict_has(g, "dimensions")) {
        const struct dict_value *v;
        TRY(dict_get_value(g, "dimensions", &v));
        if (dict_value_len(v) != 1 ||
            dict_value_kind(dict_value_at(v, 0)) != DICT_DIMS)
            return dict_error(g, "dimensions", SIM_ERR_DICT,
                              "expected a dimension set [0 1 -2 0 0 0 0]");
        const int *e = dict_value_dims(dict_value_at(v, 0));
        for (int k = 0; k < 7; k++)
            if (e[k] != accel[k])
                return dict_error(g, "dimensions", SIM_ERR_DICT,
                                  "gravity must have dimensions "
                                  "[0 1 -2 0 0 0 0] (an acceleration)");
    }
    return dict_get_vector(g, "value", 3, out);
}
