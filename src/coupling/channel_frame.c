/*
 * channel_frame.c — frames through the two SPSC rings, and ring growth.
 *
 * Memory order: the producer writes a slot, then publishes it with a
 * release store of head; the consumer's acquire load of head makes the slot
 * (and the ring descriptor) visible. The consumer frees the slot with a
 * release store of tail. Each side wakes the other through a futex word
 * that it bumps after the store, and calls FUTEX_WAKE only when the other
 * side said it sleeps (the word bump makes a racing FUTEX_WAIT return).
 *
 * What the peer wrote is read once into local variables, checked, and only
 * then used (a compiler barrier keeps the compiler from fetching it again):
 * the descriptor of its ring, and the header of each frame.
 */
#include "coupling/channel_impl.h"
#include "core/error.h"

#include <errno.h>
#include <fcntl.h>
#include <linux/futex.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#define FRAME_HDR CHAN_FRAME_HDR

_Static_assert(sizeof(struct channel_frame) <= FRAME_HDR,
               "frame header must fit its 64 bytes");
_Static_assert(offsetof(struct channel_frame, checksum) == 40,
               "checksummed frame fields must have no padding");

static uint64_t round_up(uint64_t n, uint64_t a) { return (n + a - 1) / a * a; }

static struct channel_frame *slot_at(const struct channel *c,
                                     const struct chan_desc *d,
                                     uint64_t counter)
{
    return (struct channel_frame *)(c->base + d->offset +
                                    (counter % d->nslots) * d->slot_stride);
}

int chan_desc_valid(struct channel *c, const struct chan_desc *d)
{
    const uint64_t reserve = CHANNEL_RESERVE_BYTES;
    struct stat st;

    if (d->nslots < 1 || d->nslots > CHAN_MAX_SLOTS ||
        d->slot_stride < FRAME_HDR + CHAN_ALIGN ||
        d->slot_stride % CHAN_ALIGN ||
        d->capacity != d->slot_stride - FRAME_HDR ||
        d->offset < CHAN_HEADER_BYTES || d->offset % CHAN_PAGE ||
        d->offset > reserve ||
        d->slot_stride > (reserve - d->offset) / d->nslots)
        return 0;
    /* the file only grows (fallocate, holes punched keep the size), so a
     * size seen once stays a lower bound */
    uint64_t end = d->offset + d->nslots * d->slot_stride;
    if (end > c->file_bytes && fstat(c->fd, &st) == 0)
        c->file_bytes = (uint64_t)st.st_size;
    return end <= c->file_bytes;
}

uint64_t chan_frame_checksum(const struct channel_frame *f,
                             const void *payload)
{
    uint64_t seed = channel_checksum(f, offsetof(struct channel_frame,
                                                 checksum),
                                     0x6d707364656dULL);
    return channel_checksum(payload, f->bytes, seed);
}

static void wake(_Atomic uint32_t *word, _Atomic uint32_t *waiting)
{
    atomic_fetch_add(word, 1);
    if (atomic_load(waiting))
        syscall(SYS_futex, (uint32_t *)word, FUTEX_WAKE, 1, NULL, NULL, 0);
}

int chan_ring_alloc(struct channel *c, uint64_t nslots, uint64_t capacity)
{
    struct chan_ring *ring = &c->hdr->ring[c->side];
    const uint64_t reserve = CHANNEL_RESERVE_BYTES;

    /* bounded first, so that nothing below can overflow */
    if (nslots < 1 || nslots > CHAN_MAX_SLOTS || capacity > reserve)
        return sim_error(SIM_ERR_NOMEM, "%s: channel %s cannot make %llu "
                         "frames in flight of %llu bytes: at most %d frames "
                         "within its address reservation of %llu GiB",
                         c->set.program, c->set.name,
                         (unsigned long long)nslots,
                         (unsigned long long)capacity, CHAN_MAX_SLOTS,
                         (unsigned long long)(reserve >> 30));
    uint64_t cap = round_up(capacity ? capacity : 1, CHAN_ALIGN);
    uint64_t stride = FRAME_HDR + cap;
    uint64_t bytes = round_up(nslots * stride, CHAN_PAGE);
    /* the cursor is shared: what it says is checked against our own
     * mapping, not against the header's reserve_bytes */
    uint64_t off = atomic_fetch_add(&c->hdr->alloc_end, bytes);

    if (off < CHAN_HEADER_BYTES || off % CHAN_PAGE)
        return sim_error(SIM_ERR_PEER, "%s: channel %s is corrupted: its "
                         "allocation cursor is at %llu bytes, not a page "
                         "past the header (%llu bytes)", c->set.program,
                         c->set.name, (unsigned long long)off,
                         (unsigned long long)CHAN_HEADER_BYTES);
    if (off > reserve || bytes > reserve - off)
        return sim_error(SIM_ERR_NOMEM, "%s: channel %s cannot grow to "
                         "frames of %llu bytes (%llu slots) at %llu bytes: "
                         "beyond its address reservation of %llu GiB",
                         c->set.program, c->set.name,
                         (unsigned long long)cap, (unsigned long long)nslots,
                         (unsigned long long)off,
                         (unsigned long long)(reserve >> 30));
    if (fallocate(c->fd, 0, (off_t)off, (off_t)bytes) != 0)
        return sim_error(SIM_ERR_NOMEM, "%s: channel %s: cannot allocate "
                         "%.1f MiB of shared memory for frames of %llu "
                         "bytes: %s (check df -h /dev/shm)", c->set.program,
                         c->set.name, (double)bytes / 1048576.0,
                         (unsigned long long)cap, strerror(errno));
    if (off + bytes > c->file_bytes)
        c->file_bytes = off + bytes;
    if (c->tx.nslots > 0) {
        /* the consumer holds no slot (ring empty): give the pages back */
        uint64_t old = round_up(c->tx.nslots * c->tx.slot_stride, CHAN_PAGE);
        fallocate(c->fd, FALLOC_FL_PUNCH_HOLE | FALLOC_FL_KEEP_SIZE,
                  (off_t)c->tx.offset, (off_t)old);
    }
    c->tx = (struct chan_desc){ .offset = off, .nslots = nslots,
                                .slot_stride = stride, .capacity = cap };
    ring->offset = off;
    ring->nslots = nslots;
    ring->slot_stride = stride;
    ring->capacity = cap;
    ring->generation++;
    return SIM_OK;
}

static int ring_has_space(struct channel *c, void *arg)
{
    struct chan_ring *ring = &c->hdr->ring[c->side];
    uint64_t h = atomic_load_explicit(&ring->head, memory_order_relaxed);
    uint64_t t = atomic_load_explicit(&ring->tail, memory_order_acquire);
    (void)arg;
    return h - t < c->tx.nslots;
}

static int ring_drained(struct channel *c, void *arg)
{
    struct chan_ring *ring = &c->hdr->ring[c->side];
    (void)arg;
    return atomic_load_explicit(&ring->tail, memory_order_acquire) ==
           atomic_load_explicit(&ring->head, memory_order_relaxed);
}

static int ring_has_frame(struct channel *c, void *arg)
{
    struct chan_ring *ring = &c->hdr->ring[c->peer];
    uint64_t t = atomic_load_explicit(&ring->tail, memory_order_relaxed);
    (void)arg;
    return atomic_load_explicit(&ring->head, memory_order_acquire) > t;
}

static int grow(struct channel *c, size_t bytes)
{
    struct chan_ring *ring = &c->hdr->ring[c->side];
    uint64_t cap = 2 * c->tx.capacity;

    if (cap < bytes)
        cap = bytes;
    TRY(chan_wait(c, ring_drained, NULL, &ring->tail_futex,
                  &ring->prod_waiting, c->set.timeout,
                  "room to grow the channel (peer still reading)"));
    TRY(chan_ring_alloc(c, c->tx.nslots, cap));
    return SIM_OK;
}

int channel_send_begin(struct channel *c, uint32_t kind, uint32_t flags,
                       uint64_t step, double time, uint64_t count,
                       size_t bytes, void **payload)
{
    struct chan_ring *ring = &c->hdr->ring[c->side];
    char what[160];

    if (c->pending)
        return sim_error(SIM_ERR_INTERNAL, "channel_send_begin called twice "
                         "without channel_send_commit");
    /* a frame for a peer that has left would be lost without a word */
    int st = atomic_load(&c->hdr->side[c->peer].state);
    if (st == SIDE_CLOSED || st == SIDE_FAILED)
        TRY(chan_check_peer(c));
    if (bytes > c->tx.capacity)
        TRY(grow(c, bytes));
    snprintf(what, sizeof what, "free frame slot (%s is not reading)",
             c->peer_program);
    TRY(chan_wait(c, ring_has_space, NULL, &ring->tail_futex,
                  &ring->prod_waiting, c->set.timeout, what));
    struct channel_frame *f = slot_at(c, &c->tx, atomic_load(&ring->head));
    *f = (struct channel_frame){ .kind = kind, .flags = flags, .step = step,
                                 .time = time, .count = count,
                                 .bytes = bytes };
    c->pending = f;
    *payload = (char *)f + FRAME_HDR;
    return SIM_OK;
}

int channel_send_commit(struct channel *c)
{
    struct chan_ring *ring = &c->hdr->ring[c->side];
    struct channel_frame *f = c->pending;

    if (!f)
        return sim_error(SIM_ERR_INTERNAL, "channel_send_commit without "
                         "channel_send_begin");
    f->checksum = chan_frame_checksum(f, (char *)f + FRAME_HDR);
    c->pending = NULL;
    atomic_store_explicit(&ring->head, atomic_load(&ring->head) + 1,
                          memory_order_release);
    wake(&ring->head_futex, &ring->cons_waiting);
    return SIM_OK;
}

int channel_send(struct channel *c, const struct channel_frame *f,
                 const void *payload)
{
    void *dst;
    TRY(channel_send_begin(c, f->kind, f->flags, f->step, f->time, f->count,
                           f->bytes, &dst));
    if (f->bytes)
        memcpy(dst, payload, f->bytes);
    return channel_send_commit(c);
}

int channel_recv(struct channel *c, struct channel_frame *out,
                 const void **payload)
{
    struct chan_ring *ring = &c->hdr->ring[c->peer];
    char what[160];

    if (c->receiving)
        return sim_error(SIM_ERR_INTERNAL, "channel_recv called twice "
                         "without channel_recv_done");
    snprintf(what, sizeof what, "frame from %s", c->peer_program);
    TRY(chan_wait(c, ring_has_frame, NULL, &ring->head_futex,
                  &ring->cons_waiting, c->set.timeout, what));
    uint64_t t = atomic_load_explicit(&ring->tail, memory_order_relaxed);
    struct chan_desc d = { .offset = ring->offset, .nslots = ring->nslots,
                           .slot_stride = ring->slot_stride,
                           .capacity = ring->capacity };
    atomic_signal_fence(memory_order_seq_cst);
    if (!chan_desc_valid(c, &d))
        return sim_error(SIM_ERR_PEER, "%s: channel %s is corrupted: the "
                         "ring of %s (pid %d) says %llu slots of %llu bytes "
                         "(payload %llu) at %llu bytes, outside the segment "
                         "(a file of %llu bytes, %llu GiB mapped)",
                         c->set.program, c->set.name, c->peer_program,
                         (int)c->peer_pid, (unsigned long long)d.nslots,
                         (unsigned long long)d.slot_stride,
                         (unsigned long long)d.capacity,
                         (unsigned long long)d.offset,
                         (unsigned long long)c->file_bytes,
                         (unsigned long long)(CHANNEL_RESERVE_BYTES >> 30));
    const struct channel_frame *f = slot_at(c, &d, t);
    *out = *f;
    atomic_signal_fence(memory_order_seq_cst);
    if (out->bytes > d.capacity)
        return sim_error(SIM_ERR_PEER, "%s: channel %s is corrupted: frame "
                         "%llu from %s claims %llu bytes, more than its slot "
                         "holds (%llu)", c->set.program, c->set.name,
                         (unsigned long long)t, c->peer_program,
                         (unsigned long long)out->bytes,
                         (unsigned long long)d.capacity);
    const void *data = (const char *)f + FRAME_HDR;
    uint64_t sum = chan_frame_checksum(out, data);
    if (sum != out->checksum)
        return sim_error(SIM_ERR_PEER, "%s: frame %llu from %s (kind %u, "
                         "step %llu, %llu bytes) is corrupted: checksum "
                         "%016llx, expected %016llx", c->set.program,
                         (unsigned long long)t, c->peer_program, out->kind,
                         (unsigned long long)out->step,
                         (unsigned long long)out->bytes,
                         (unsigned long long)sum,
                         (unsigned long long)out->checksum);
    c->receiving = 1;
    *payload = data;
    return SIM_OK;
}

int channel_recv_done(struct channel *c)
{
    struct chan_ring *ring = &c->hdr->ring[c->peer];

    if (!c->receiving)
        return sim_error(SIM_ERR_INTERNAL, "channel_recv_done without "
                         "channel_recv");
    c->receiving = 0;
    atomic_store_explicit(&ring->tail, atomic_load(&ring->tail) + 1,
                          memory_order_release);
    wake(&ring->tail_futex, &ring->prod_waiting);
    return SIM_OK;
}
