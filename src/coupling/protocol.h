/*
 * protocol.h — the messages mpsFluid and demSolid exchange through a
 * channel (doc/design.md §4). The physics that fills them lives elsewhere in
 * src/coupling; this file fixes their layout only.
 *
 * Each message is one frame whose payload is structure-of-arrays: a list
 * of fields, each `count x ncomp` doubles with the components of one item
 * together (x0 y0 z0 x1 y1 z1 ...), each field starting on a 64-byte
 * boundary. Vectors always have 3 components (z = 0 in 2-D), so the layout
 * does not depend on the dimension, which the handshake checks anyway.
 *
 *   PROTO_DEM_STATE   DEM -> fluid, count = grains, at the coupling time t_n
 *       position [m] (3), velocity [m/s] (3), radius [m] (1),
 *       drag [N] (3): drag each grain felt, averaged over the DEM sub-steps
 *       of the last coupling interval (for the reaction on the fluid).
 *   PROTO_FLUID_STATE fluid -> DEM, count = grains, same order as the last
 *       PROTO_DEM_STATE:
 *       velocity [m/s] (3): fluid velocity u_k at the grain centre,
 *       porosity [-] (1): eps_k,
 *       gradP [Pa/m] (3): pressure gradient, only with PROTO_HAS_GRADP
 *       (Model A).
 *   PROTO_CONTROL     either way, count = 1:
 *       command (1): enum proto_command, value (1): its argument
 *       (the new time step [s] for PROTO_CMD_SET_DT).
 * Grains may be added between frames (count grows; the channel grows its
 * rings); existing grains keep their positions in the arrays.
 */
#ifndef MPSDEM_COUPLING_PROTOCOL_H
#define MPSDEM_COUPLING_PROTOCOL_H

#include <stddef.h>
#include <stdint.h>

struct channel;
struct channel_frame;

enum proto_kind {
    PROTO_DEM_STATE = 1,
    PROTO_FLUID_STATE = 2,
    PROTO_CONTROL = 3
};

enum proto_flags { PROTO_HAS_GRADP = 1u << 0 };

enum proto_command {
    PROTO_CMD_WRITE_NOW = 1, /* write a time directory at this step       */
    PROTO_CMD_STOP = 2,      /* orderly end: finish the step, write, close */
    PROTO_CMD_SET_DT = 3     /* value = new coupling time step [s]         */
};

#define PROTO_MAX_FIELDS 4

/* Arrays of one DEM_STATE message; vectors are 3 x n. */
struct proto_dem_state {
    size_t n;
    const double *position, *velocity, *radius, *drag;
};

/* Arrays of one FLUID_STATE message; grad_p may be NULL (Model B). */
struct proto_fluid_state {
    size_t n;
    const double *velocity, *porosity, *grad_p;
};

/* Payload bytes of a message and the offset of each field (off may be
 * NULL). Returns the number of fields, or -1 for an unknown kind. */
int proto_layout(uint32_t kind, uint32_t flags, uint64_t count,
                 size_t off[PROTO_MAX_FIELDS], size_t *bytes);
/* Name and number of components of field i of a kind ("position", 3). */
const char *proto_field_name(uint32_t kind, int i, int *ncomp);
const char *proto_kind_name(uint32_t kind);

int proto_send_dem_state(struct channel *c, uint64_t step, double time,
                         const struct proto_dem_state *s);
int proto_send_fluid_state(struct channel *c, uint64_t step, double time,
                           const struct proto_fluid_state *s);
int proto_send_control(struct channel *c, uint64_t step, double time,
                       int command, double value);

/* Views into a received payload (valid until channel_recv_done). They
 * check that the frame is of the kind and size its header says, and return
 * SIM_ERR_PEER naming the kind otherwise. */
int proto_view_dem_state(const struct channel_frame *f, const void *payload,
                         struct proto_dem_state *out);
int proto_view_fluid_state(const struct channel_frame *f,
                           const void *payload, struct proto_fluid_state *out);
int proto_view_control(const struct channel_frame *f, const void *payload,
                       int *command, double *value);

#endif
