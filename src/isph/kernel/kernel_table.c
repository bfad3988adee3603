/* kernel_table.c — the kernels selectable by name (isph.h). */
#include <stddef.h>

#include "isph/isph.h"

const struct isph_kernel *const isph_kernels[] = {
    &isph_wendland_c2, &isph_cubic_spline, NULL };
