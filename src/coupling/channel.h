/*
 * channel.h — the shared-memory channel between mpsFluid and demSolid
 * (doc/design.md §4). It moves frames of arrays; it knows nothing of physics.
 * The messages of the coupling are defined on top of it in protocol.h.
 *
 * One POSIX shared-memory segment (/dev/shm/<name>, mode 0600) holds a
 * header (magic, protocol version, both programs' pids, start times,
 * heartbeats and states, what each side must agree on) and two
 * single-producer single-consumer rings of frames, one per direction. A
 * frame is a 64-byte header (kind, flags, step, time, count, bytes,
 * checksum) followed by `bytes` of payload, 64-byte aligned.
 *
 * Life of a channel:
 *   channel_settings_default() or channel_settings_from_dict() fill the
 *   settings; channel_open() creates or attaches the segment in either start
 *   order and runs the handshake; channel_send_begin()/channel_send_commit()
 *   and channel_recv()/channel_recv_done() move frames without extra copies;
 *   channel_close() tells the peer why we leave and unlinks the segment when
 *   we are the last program attached.
 *
 * Waiting never lasts forever. Every blocking call spins briefly, then sleeps
 * on a futex in slices of at most 50 ms, and after each slice checks, in this
 * order: the condition it waits for, the signal flag (SIGINT/SIGTERM/SIGHUP,
 * see channel_signals_install), the peer (exited: its pidfd is readable;
 * closed or failed: its state; hung or stopped: no heartbeat for
 * CHANNEL_HUNG_HEARTBEATS intervals), and the time-out. The codes returned:
 *   SIM_ERR_PEER       the peer exited, crashed, was killed, closed the
 *                      channel, disagreed at the handshake, or sent a
 *                      corrupted frame;
 *   SIM_ERR_TIMEOUT    nothing arrived within settings.timeout;
 *   SIM_ERR_INTERRUPT  a signal asked this program to stop;
 *   SIM_ERR_INPUT      bad settings, a second pair on the same channel, or
 *                      a file at the channel's name that is not this
 *                      user's own mode-0600 regular file (the message
 *                      names its owner and the couplingDict key `channel`)
 *                      or whose header is not valid (channel.c);
 *   SIM_ERR_IO         a system call on the segment failed.
 * With each, sim_error_message() says what happened, naming the peer
 * program and pid. The application then writes its last complete state and
 * calls channel_close() with the code (so the peer learns it), then stops.
 *
 * Capacity: each side asks for an initial payload capacity per frame; each
 * ring gets the larger request. A frame larger than its ring's capacity
 * makes the sender wait until the peer has consumed every frame in flight,
 * allocate a larger ring at the end of the segment, and release the old
 * pages: grains can be added without restarting either program. The segment
 * reserves CHANNEL_RESERVE_BYTES of address space (not memory) once, so
 * growth never moves a mapping.
 *
 * A stale segment (every program that claimed it is gone) is removed and
 * replaced; a program whose side of the channel is already held by a live
 * program is refused. Only one thread per program may use a channel.
 * Nothing the segment holds is trusted: sizes, offsets and strides are
 * checked against this program's mapping and the file before they address
 * memory, so a corrupted or forged header gives an error, not a crash.
 *
 * In a solver (demSolid shown; mpsFluid is the mirror image):
 *
 *     channel_signals_install();                  // before anything waits
 *     struct channel_settings cs;
 *     TRY(channel_settings_default(&cs, CHANNEL_SOLID, "demSolid", case_dir));
 *     TRY(channel_settings_from_dict(couplingDict, &cs));
 *     cs.dimension = 3;                           // and units, slot_bytes
 *     TRY(channel_open(&cs, &ch));
 *     while (time_loop_run(...)) {
 *         rc = proto_send_dem_state(ch, step, t, &state);     // protocol.h
 *         if (!rc) rc = channel_recv(ch, &frame, &payload);    // fluid state
 *         ...                                                  // sub-steps
 *         if (rc) break;
 *     }
 *     if (rc) write the last complete time directory;
 *     channel_close(ch, rc);                      // unlinks when last out
 *     if (rc) app_fatal(...);
 *
 * A step longer than 2 s between messages (DEM sub-stepping, a large PPE)
 * should call channel_poll() in its loop, e.g. once per sub-step: it costs
 * about 0.3 us (one poll() on the peer's pidfd) and lets the program notice
 * a dead peer or a signal in time, not only at its next message.
 */
#ifndef MPSDEM_COUPLING_CHANNEL_H
#define MPSDEM_COUPLING_CHANNEL_H

#include <stddef.h>
#include <stdint.h>
#include <sys/types.h>

struct dict;
struct channel;

enum channel_side { CHANNEL_FLUID = 0, CHANNEL_SOLID = 1 };

#define CHANNEL_PROTOCOL_VERSION 2 /* 2: endTime in the handshake      */
#define CHANNEL_NAME_MAX 128        /* including the leading '/'          */
#define CHANNEL_PATH_MAX 1024       /* longest case path the header keeps */
#define CHANNEL_HUNG_HEARTBEATS 20  /* silent intervals before "hung"     */
#define CHANNEL_RESERVE_BYTES (256ULL << 30) /* address space, not memory */

struct channel_settings {
    /* Segment name, "/..." without further '/'; "" = channel_default_name()
     * of case_path. */
    char name[CHANNEL_NAME_MAX];
    /* Absolute path of the case directory: default name and agreement. */
    char case_path[CHANNEL_PATH_MAX];
    char program[64];          /* this program, for messages: "mpsFluid"   */
    int side;                  /* enum channel_side                        */
    double timeout;            /* [s] handshake, and each blocking wait    */
    double heartbeat_interval; /* [s] period of this program's heartbeat   */
    int nslots;                /* frames in flight per direction, >= 1     */
    size_t slot_bytes;         /* initial payload capacity of a frame [B]  */
    /* Checked at the handshake; both sides must give the same values
     * (channel.c says in which order and how a mismatch reads). */
    int dimension;             /* 2 or 3                                   */
    char units[32];            /* "SI"                                     */
    double end_time;           /* [s] endTime of system/controlDict        */
    uint64_t digest;           /* hash of the coupling settings both read  */
    int quiet;                 /* 1: no log_info lines (tests)             */
};

/* What travels in front of every payload. `checksum` is computed by the
 * channel over the other fields and the payload (channel_checksum). */
struct channel_frame {
    uint32_t kind;     /* meaning of the payload (protocol.h)               */
    uint32_t flags;    /* kind-specific                                     */
    uint64_t step;     /* sender's step number                              */
    double time;       /* sender's time [s]                                 */
    uint64_t count;    /* number of items (grains) described                */
    uint64_t bytes;    /* payload size [B]                                  */
    uint64_t checksum;
};

/* Defaults: name "", timeout 60 s, heartbeat 0.1 s, 2 slots of 64 KiB,
 * dimension 3, units "SI", end_time 0, digest 0. case_path is made
 * absolute. */
int channel_settings_default(struct channel_settings *s, int side,
                             const char *program, const char *case_dir);

/* Read system/couplingDict entries into s (after channel_settings_default):
 *   channel            word    segment name, /dev/shm/<word> (default:
 *                              derived from the user id and case path)
 *   timeout            [s]     handshake and per wait (default 60)
 *   heartbeatInterval  [s]     liveness period        (default 0.1)
 *   framesInFlight     label   ring slots             (default 2)
 * and set s->digest to the hash of d as expanded (dict_write_expanded), so
 * that both programs prove they read the same coupling settings. Errors cite
 * the file and line. */
int channel_settings_from_dict(const struct dict *d,
                               struct channel_settings *s);

/* "/mpsdem-<uid>-<16 hex digits of a hash of the absolute case path>". */
int channel_default_name(const char *case_abs, char *buf, size_t n);

/* Create or attach, then handshake. On failure nothing is left behind
 * (the segment is unlinked when no other program holds it). */
int channel_open(const struct channel_settings *s, struct channel **out);

/* Reserve the next outgoing frame: wait for a free slot (growing the ring
 * when `bytes` exceeds its capacity) and return where to write the payload
 * (64-byte aligned, valid until channel_send_commit). */
int channel_send_begin(struct channel *c, uint32_t kind, uint32_t flags,
                       uint64_t step, double time, uint64_t count,
                       size_t bytes, void **payload);
/* Checksum and publish the reserved frame; wakes the peer. */
int channel_send_commit(struct channel *c);
/* Both in one call, copying `payload` in. */
int channel_send(struct channel *c, const struct channel_frame *f,
                 const void *payload);

/* Wait for the next incoming frame, verify its checksum, and expose it in
 * place: *payload stays valid until channel_recv_done(). */
int channel_recv(struct channel *c, struct channel_frame *f,
                 const void **payload);
int channel_recv_done(struct channel *c);

/* Without waiting: SIM_OK, or the code a wait would return now (signal,
 * peer gone). For long computations between messages; ~0.3 us a call. */
int channel_poll(struct channel *c);

/* Leave: publish `status` (SIM_OK for a normal end, else the error code)
 * to the peer, wake it, unlink the segment if the peer is gone or has left,
 * unmap, free. Safe with c == NULL. Returns SIM_OK or SIM_ERR_IO. */
int channel_close(struct channel *c, int status);

const char *channel_name(const struct channel *c);
pid_t channel_peer_pid(const struct channel *c);
const char *channel_peer_program(const struct channel *c);
/* Current payload capacity per frame of the ring this side writes [B]. */
size_t channel_capacity(const struct channel *c);

/* Install handlers for SIGINT, SIGTERM and SIGHUP that only record the
 * signal, so that a blocked wait returns SIM_ERR_INTERRUPT promptly. A
 * second signal at least one second after the first unlinks every open
 * channel's segment name and then terminates the program the default way
 * (a way out of a computation that never checks). */
int channel_signals_install(void);
/* The signal received (SIGINT, ...), or 0. */
int channel_interrupted(void);
/* Forget a received signal (tests). */
void channel_interrupt_clear(void);

/* 64-bit checksum of n bytes (four-lane multiply-rotate hash over 8-byte
 * little-endian words, the last word zero-padded), seeded. */
uint64_t channel_checksum(const void *p, size_t n, uint64_t seed);

#endif
