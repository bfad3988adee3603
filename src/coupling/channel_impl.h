/*
 * channel_impl.h — layout of the shared segment and what the channel_*.c
 * files share. Not for applications; tests include it to corrupt frames.
 *
 * Segment (offsets from its start):
 *   0                     struct chan_header (rounded up to a page)
 *   header_bytes ...      rings, allocated by an atomic cursor (alloc_end)
 *                         as page-aligned regions; a ring region is
 *                         nslots x slot_stride, a slot is one 64-byte
 *                         struct channel_frame followed by its payload.
 * The file grows with fallocate() (which never shrinks it and fails
 * cleanly when /dev/shm is full, where ftruncate would give SIGBUS later);
 * a replaced ring's pages are released with FALLOC_FL_PUNCH_HOLE.
 *
 * Ring counters are free-running: head = frames published (producer only),
 * tail = frames consumed (consumer only); slot = counter % nslots. The ring
 * descriptor (offset, nslots, slot_stride, capacity) is rewritten by the
 * producer only while head == tail, and the consumer reads it only after an
 * acquire load saw head > tail, so the release store of head publishes it.
 *
 * Nothing read from the segment is trusted as an address: the producer
 * writes through its own copy of its descriptor (struct channel.tx), the
 * consumer reads the peer's descriptor once per frame into a local copy and
 * checks it against the mapping and the file (chan_desc_valid), and the
 * header's sizes and allocation cursor are checked at attach and bounded
 * by CHANNEL_RESERVE_BYTES of this build at every allocation.
 */
#ifndef MPSDEM_COUPLING_CHANNEL_IMPL_H
#define MPSDEM_COUPLING_CHANNEL_IMPL_H

#include "coupling/channel.h"

#include <pthread.h>
#include <stdatomic.h>

#define CHAN_MAGIC 0x48436d6564737066ULL /* "fpsdemCH" little-endian */
#define CHAN_ALIGN 64
#define CHAN_PAGE 4096
#define CHAN_SPIN 2000          /* pause iterations before sleeping      */
#define CHAN_SLICE_NS 50000000L /* longest single futex sleep [ns]        */
#define CHAN_AWAY_NS 1000000000L /* a gap between two looks at the channel
                                   longer than this: we were stopped or
                                   not scheduled, not waiting [ns]      */
#define CHAN_FRAME_HDR 64       /* slot bytes before the payload          */
#define CHAN_MAX_SLOTS 1024     /* frames in flight per ring, at most     */

enum chan_state {
    SIDE_FREE = 0,  /* nobody claimed this side                          */
    SIDE_CLAIMED,   /* pid written, handshake not yet published          */
    SIDE_READY,     /* agreement block and capacity request published    */
    SIDE_CLOSED,    /* left normally                                     */
    SIDE_FAILED     /* left with an error (exit_code)                    */
};

struct chan_agree {
    uint32_t protocol;
    int32_t dimension;
    char units[32];
    double end_time;
    uint64_t digest;
    char case_path[CHANNEL_PATH_MAX];
};

struct chan_side {
    _Alignas(CHAN_ALIGN) _Atomic int32_t pid;
    _Atomic int32_t state;            /* enum chan_state                   */
    uint64_t start_ticks;             /* /proc/<pid>/stat field 22         */
    _Atomic uint64_t heartbeat_ns;    /* CLOCK_MONOTONIC of last beat      */
    _Atomic int32_t exit_code;        /* sim error code given to close     */
    uint32_t nslots_req;
    uint64_t slot_bytes_req;
    char program[64];
    struct chan_agree agree;
};

struct chan_ring {
    _Alignas(CHAN_ALIGN) _Atomic uint64_t head; /* producer's cache line   */
    _Atomic uint32_t head_futex;
    _Atomic uint32_t cons_waiting;
    _Alignas(CHAN_ALIGN) _Atomic uint64_t tail; /* consumer's cache line   */
    _Atomic uint32_t tail_futex;
    _Atomic uint32_t prod_waiting;
    _Alignas(CHAN_ALIGN) uint64_t offset;       /* descriptor (see above)  */
    uint64_t nslots;
    uint64_t slot_stride;
    uint64_t capacity;                          /* payload bytes per slot  */
    uint64_t generation;                        /* number of (re)allocations */
};

/* A ring descriptor as a program holds it privately (see the top). */
struct chan_desc {
    uint64_t offset, nslots, slot_stride, capacity;
};

struct chan_header {
    uint64_t magic;        /* written last at creation                    */
    uint32_t version;      /* CHANNEL_PROTOCOL_VERSION                    */
    uint32_t header_bytes;
    uint64_t reserve_bytes;
    _Atomic uint64_t alloc_end;  /* allocation cursor [B]                 */
    _Atomic uint32_t state_futex; /* bumped on every side state change     */
    struct chan_side side[2];
    struct chan_ring ring[2];    /* ring[s] carries frames written by s   */
};

/* Bytes before the first ring: the header rounded up to a page. */
#define CHAN_HEADER_BYTES \
    ((sizeof(struct chan_header) + CHAN_PAGE - 1) / CHAN_PAGE * CHAN_PAGE)

struct channel {
    struct channel_settings set;
    int fd;
    char *base;                 /* mapping of CHANNEL_RESERVE_BYTES        */
    struct chan_header *hdr;
    uint64_t file_bytes;        /* size of the file when last looked at    */
    struct chan_desc tx;        /* the ring we write, as we allocated it   */
    int side, peer;
    int peer_pidfd;             /* -1: pid unknown yet; -2: already gone   */
    pid_t peer_pid;
    char peer_program[64];
    uint64_t hung_ns;           /* heartbeat silence that means "hung"     */
    int peer_hung;              /* we gave up on a live but silent peer    */
    uint64_t beat_seen;         /* peer heartbeat value last seen ...      */
    uint64_t beat_seen_at;      /* ... since this local time [ns]          */
    uint64_t last_check;        /* time of our previous peer check [ns]    */
    uint64_t peer_ticks;        /* its CPU time half a silence ago, ...    */
    int peer_ticks_set;         /* ... once sampled                        */
    /* frame reserved by send_begin, waiting for commit */
    struct channel_frame *pending;
    /* frame exposed by recv, waiting for recv_done */
    int receiving;
    /* heartbeat thread */
    pthread_t hb_thread;
    int hb_running;
    pthread_mutex_t hb_lock;
    pthread_cond_t hb_cond;
    int hb_stop;
    int registry_slot;
    pid_t owner;                /* process that opened it (not a fork)     */
};

/* channel_wait.c */
uint64_t chan_now_ns(void);
void chan_futex_wake(_Atomic uint32_t *word);
/* Wait until ready(c, arg) is non-zero; `word` is the futex the other side
 * bumps when the condition may have changed, `waiting` a flag telling it
 * that we sleep (may be NULL: it always wakes). `what` names the wait in
 * messages ("a frame from demSolid"). */
int chan_wait(struct channel *c, int (*ready)(struct channel *, void *),
              void *arg, _Atomic uint32_t *word, _Atomic uint32_t *waiting,
              double timeout, const char *what);
/* SIM_OK, or SIM_ERR_PEER / SIM_ERR_INTERRUPT with a message. */
int chan_check_peer(struct channel *c);
int chan_check_signal(const struct channel *c);
/* Start watching the peer once its pid is in the header. */
int chan_watch_peer(struct channel *c);
int chan_heartbeat_start(struct channel *c);
void chan_heartbeat_stop(struct channel *c);
void chan_set_state(struct channel *c, int state);

/* channel_proc.c */
/* Start time of a process in clock ticks since boot, 0 when it does not
 * exist or is a zombie (exited, not yet reaped). */
uint64_t chan_proc_start(pid_t pid);
/* The scheduler state of process pid (field 3 of /proc/<pid>/stat: 'R'
 * running or runnable, 'S' asleep, 'T' stopped, ...) and the CPU time of
 * all its threads (utime + stime, clock ticks); 0 when it cannot be read. */
int chan_proc_cpu(pid_t pid, char *state, uint64_t *ticks);
/* Non-zero when side s was claimed by a program still running (and not
 * closed or failed). */
int chan_side_alive(const struct chan_header *h, int s);

/* channel_signal.c */
int chan_registry_add(struct channel *c);
void chan_registry_remove(struct channel *c);

/* channel_frame.c */
/* Allocate (or grow) the ring this side writes: nslots in
 * [1, CHAN_MAX_SLOTS], payload capacity rounded up to CHAN_ALIGN, inside
 * this build's reservation whatever the shared cursor says. */
int chan_ring_alloc(struct channel *c, uint64_t nslots, uint64_t capacity);
/* Non-zero when d lies inside the mapping, past the header, and inside the
 * file (fstat again when the size last seen is too small), with sane
 * slots: what a descriptor read from the segment must pass before it
 * addresses anything. */
int chan_desc_valid(struct channel *c, const struct chan_desc *d);
uint64_t chan_frame_checksum(const struct channel_frame *f,
                             const void *payload);

#endif
