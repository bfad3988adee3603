/* drag_register.c — the one list of drag laws (doc/design.md C3) and their
 * selection from system/couplingDict (`dragModel <name>;`). */
#include <stddef.h>

#include "core/error.h"
#include "core/select.h"
#include "coupling/drag/drag.h"

const struct drag_ops *const drag_table[] = {
    &drag_ergun_wen_yu,
    &drag_gidaspow_blend,
    &drag_di_felice,
    &drag_none,
    NULL
};

int drag_select(const struct dict *d, const struct drag_ops **out)
{
    const void *m;
    TRY(model_select(d, "dragModel", "drag model",
                     (const void *const *)drag_table, "ergunWenYu", &m));
    *out = m;
    return SIM_OK;
}
