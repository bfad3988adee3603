/* files.c — see files.h. */
#include "core/files.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/error.h"

static int make_one(const char *dir)
{
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        return sim_error(SIM_ERR_IO, "cannot create directory '%s': %s", dir,
                         strerror(errno));
    return SIM_OK;
}

int files_mkdir_p(const char *dir)
{
    char *tmp = sim_strdup(dir);
    if (!tmp)
        return SIM_ERR_NOMEM;
    int rc = SIM_OK;
    for (char *s = tmp + 1; *s && rc == SIM_OK; s++) {
        if (*s != '/')
            continue;
        *s = '\0';
        rc = make_one(tmp);
        *s = '/';
    }
    if (rc == SIM_OK)
        rc = make_one(tmp);
    free(tmp);
    return rc;
}
