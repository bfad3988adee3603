/* protocol.c — layouts and pack/view of the coupling messages (protocol.h). */
#include "coupling/protocol.h"
#include "coupling/channel.h"
#include "core/error.h"

#include <string.h>

struct field {
    const char *name;
    int ncomp;
    uint32_t needs_flag; /* 0: always present */
};

static const struct field dem_fields[] = {
    { "position", 3, 0 }, { "velocity", 3, 0 }, { "radius", 1, 0 },
    { "drag", 3, 0 }, { NULL, 0, 0 }
};
static const struct field fluid_fields[] = {
    { "velocity", 3, 0 }, { "porosity", 1, 0 },
    { "gradP", 3, PROTO_HAS_GRADP }, { NULL, 0, 0 }
};
static const struct field control_fields[] = {
    { "command", 1, 0 }, { "value", 1, 0 }, { NULL, 0, 0 }
};

static const struct field *fields_of(uint32_t kind)
{
    switch (kind) {
    case PROTO_DEM_STATE:   return dem_fields;
    case PROTO_FLUID_STATE: return fluid_fields;
    case PROTO_CONTROL:     return control_fields;
    default:                return NULL;
    }
}

const char *proto_kind_name(uint32_t kind)
{
    switch (kind) {
    case PROTO_DEM_STATE:   return "DEM state";
    case PROTO_FLUID_STATE: return "fluid state";
    case PROTO_CONTROL:     return "control";
    default:                return "unknown";
    }
}

const char *proto_field_name(uint32_t kind, int i, int *ncomp)
{
    const struct field *f = fields_of(kind);
    for (int k = 0; f && f[k].name; k++)
        if (k == i) {
            *ncomp = f[k].ncomp;
            return f[k].name;
        }
    *ncomp = 0;
    return NULL;
}

int proto_layout(uint32_t kind, uint32_t flags, uint64_t count,
                 size_t off[PROTO_MAX_FIELDS], size_t *bytes)
{
    const struct field *f = fields_of(kind);
    size_t pos = 0;
    int n = 0;

    if (!f)
        return -1;
    for (int k = 0; f[k].name; k++) {
        if (f[k].needs_flag && !(flags & f[k].needs_flag))
            continue;
        if (off)
            off[n] = pos;
        pos += (count * (size_t)f[k].ncomp * sizeof(double) + 63) / 64 * 64;
        n++;
    }
    *bytes = pos;
    return n;
}

/* Reserve a frame and copy the arrays in, field by field. */
static int send_fields(struct channel *c, uint32_t kind, uint32_t flags,
                       uint64_t step, double time, uint64_t count,
                       const double *const src[], int nsrc)
{
    size_t off[PROTO_MAX_FIELDS], bytes;
    int n = proto_layout(kind, flags, count, off, &bytes);
    void *dst;

    if (n != nsrc)
        return sim_error(SIM_ERR_INTERNAL, "%s message: %d arrays for %d "
                         "fields", proto_kind_name(kind), nsrc, n);
    TRY(channel_send_begin(c, kind, flags, step, time, count, bytes, &dst));
    for (int i = 0, k = 0; i < n; k++) {
        const struct field *f = &fields_of(kind)[k];
        if (f->needs_flag && !(flags & f->needs_flag))
            continue;
        memcpy((char *)dst + off[i], src[i],
               count * (size_t)f->ncomp * sizeof(double));
        i++;
    }
    return channel_send_commit(c);
}

int proto_send_dem_state(struct channel *c, uint64_t step, double time,
                         const struct proto_dem_state *s)
{
    const double *src[] = { s->position, s->velocity, s->radius, s->drag };
    return send_fields(c, PROTO_DEM_STATE, 0, step, time, s->n, src, 4);
}

int proto_send_fluid_state(struct channel *c, uint64_t step, double time,
                           const struct proto_fluid_state *s)
{
    const double *src[] = { s->velocity, s->porosity, s->grad_p };
    uint32_t flags = s->grad_p ? PROTO_HAS_GRADP : 0;
    return send_fields(c, PROTO_FLUID_STATE, flags, step, time, s->n, src,
                       s->grad_p ? 3 : 2);
}

int proto_send_control(struct channel *c, uint64_t step, double time,
                       int command, double value)
{
    double cmd = command;
    const double *src[] = { &cmd, &value };
    return send_fields(c, PROTO_CONTROL, 0, step, time, 1, src, 2);
}

/* Offsets of a received frame after checking its kind and size. */
static int view(const struct channel_frame *f, uint32_t kind,
                size_t off[PROTO_MAX_FIELDS])
{
    size_t bytes;

    if (f->kind != kind)
        return sim_error(SIM_ERR_PEER, "expected a %s message, received a "
                         "%s message (kind %u, step %llu)",
                         proto_kind_name(kind), proto_kind_name(f->kind),
                         f->kind, (unsigned long long)f->step);
    /* every kind has a field of at least one double per item: a larger
     * count would overflow the layout and index past the payload */
    if (f->count > f->bytes / sizeof(double))
        return sim_error(SIM_ERR_PEER, "malformed %s message (step %llu): "
                         "%llu items in %llu bytes",
                         proto_kind_name(kind), (unsigned long long)f->step,
                         (unsigned long long)f->count,
                         (unsigned long long)f->bytes);
    proto_layout(kind, f->flags, f->count, off, &bytes);
    if (bytes != f->bytes)
        return sim_error(SIM_ERR_PEER, "malformed %s message (step %llu): "
                         "%llu bytes for %llu items, expected %zu",
                         proto_kind_name(kind), (unsigned long long)f->step,
                         (unsigned long long)f->bytes,
                         (unsigned long long)f->count, bytes);
    return SIM_OK;
}

int proto_view_dem_state(const struct channel_frame *f, const void *payload,
                         struct proto_dem_state *out)
{
    size_t off[PROTO_MAX_FIELDS];
    const char *p = payload;

    TRY(view(f, PROTO_DEM_STATE, off));
    out->n = f->count;
    out->position = (const double *)(p + off[0]);
    out->velocity = (const double *)(p + off[1]);
    out->radius = (const double *)(p + off[2]);
    out->drag = (const double *)(p + off[3]);
    return SIM_OK;
}

int proto_view_fluid_state(const struct channel_frame *f,
                           const void *payload, struct proto_fluid_state *out)
{
    size_t off[PROTO_MAX_FIELDS];
    const char *p = payload;

    TRY(view(f, PROTO_FLUID_STATE, off));
    out->n = f->count;
    out->velocity = (const double *)(p + off[0]);
    out->porosity = (const double *)(p + off[1]);
    out->grad_p = (f->flags & PROTO_HAS_GRADP)
                      ? (const double *)(p + off[2]) : NULL;
    return SIM_OK;
}

int proto_view_control(const struct channel_frame *f, const void *payload,
                       int *command, double *value)
{
    size_t off[PROTO_MAX_FIELDS];
    const char *p = payload;
    double cmd;

    TRY(view(f, PROTO_CONTROL, off));
    if (f->count != 1)
        return sim_error(SIM_ERR_PEER, "control message with count %llu",
                         (unsigned long long)f->count);
    memcpy(&cmd, p + off[0], sizeof cmd);
    memcpy(value, p + off[1], sizeof *value);
    if (cmd != PROTO_CMD_WRITE_NOW && cmd != PROTO_CMD_STOP &&
        cmd != PROTO_CMD_SET_DT)
        return sim_error(SIM_ERR_PEER, "unknown control command %g", cmd);
    *command = (int)cmd;
    return SIM_OK;
}
