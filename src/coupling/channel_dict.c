/*
 * channel_dict.c — channel settings from system/couplingDict (channel.h).
 *
 * Kept apart from the rest of the channel so that programs and tests that
 * build the settings by hand do not link the dictionary code.
 *
 * The digest is a hash of the dictionary as expanded (includes and $var
 * substitutions resolved, comments dropped): two programs agree on it
 * exactly when they read the same coupling settings, whatever the layout.
 */
#include "coupling/channel.h"
#include "core/dict.h"
#include "core/error.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The channel counts waits in uint64_t nanoseconds and the heartbeat
 * period in a long, and declares a peer hung after CHANNEL_HUNG_HEARTBEATS
 * silent periods: seconds above ~1.8e10 (9e8 for the heartbeat) overflow
 * and fail at once. 1e8 s (three years) keeps all of them exact. */
#define SETTINGS_MAX_SECONDS 1e8

static int settings_digest(const struct dict *d, uint64_t *out)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    int rc;

    if (!f)
        return sim_error(SIM_ERR_NOMEM, "cannot expand %s", dict_file(d));
    rc = dict_write_expanded(d, f);
    fclose(f);
    if (rc == SIM_OK)
        *out = channel_checksum(text, len, 0);
    free(text);
    return rc;
}

int channel_settings_from_dict(const struct dict *d,
                               struct channel_settings *s)
{
    const char *name;
    long slots;

    TRY(dict_get_string_or(d, "channel", "", &name));
    if (name[0]) {
        const char *bare = name[0] == '/' ? name + 1 : name;
        if (!bare[0] || strchr(bare, '/') ||
            strlen(bare) > CHANNEL_NAME_MAX - 25)
            return dict_error(d, "channel", SIM_ERR_DICT, "channel name "
                              "'%s' must be a non-empty word without '/' "
                              "(an optional leading '/' aside) of at most "
                              "%d characters", name, CHANNEL_NAME_MAX - 25);
        snprintf(s->name, sizeof s->name, "/%s", bare);
    }
    TRY(dict_get_scalar_or(d, "timeout", s->timeout, &s->timeout));
    if (!(s->timeout > 0) || !(s->timeout <= SETTINGS_MAX_SECONDS))
        return dict_error(d, "timeout", SIM_ERR_DICT, "timeout must be in "
                          "(0, %g] [s], not %g", SETTINGS_MAX_SECONDS,
                          s->timeout);
    TRY(dict_get_scalar_or(d, "heartbeatInterval", s->heartbeat_interval,
                           &s->heartbeat_interval));
    if (!(s->heartbeat_interval > 0) ||
        !(s->heartbeat_interval <= s->timeout))
        return dict_error(d, "heartbeatInterval", SIM_ERR_DICT,
                          "heartbeatInterval must be in (0, timeout = %g] "
                          "[s], not %g", s->timeout, s->heartbeat_interval);
    TRY(dict_get_label_or(d, "framesInFlight", s->nslots, &slots));
    if (slots < 1 || slots > 1024)
        return dict_error(d, "framesInFlight", SIM_ERR_DICT,
                          "framesInFlight must be in [1, 1024], not %ld",
                          slots);
    s->nslots = (int)slots;
    return settings_digest(d, &s->digest);
}
