/* kernel_register.c — the one list of MPS kernels (doc/design.md C3). */
#include <stddef.h>

#include "mps/kernel/kernel.h"

const struct mps_kernel_ops *const mps_kernel_table[] = {
    &mps_kernel_zhang2014,
    &mps_kernel_koshizuka1996,
    &mps_kernel_poly6,
    NULL
};
