/* fo_generic.c — the function objects every solver offers (registration). */
#include "functionObjects/functionObject.h"

extern const struct fo_ops fo_cloud_info;

const struct fo_ops *const fo_generic_table[] = {
    &fo_cloud_info,
    NULL,
};
