/*
 * test_channel_trust.c — the channel and a segment it did not create
 * (issue 14, item 1). /dev/shm is world-writable and the channel's name is
 * predictable, so another local user can plant a file there that looks
 * like a live channel whose peer is ready. Checked here:
 *   - a file of another user (root victim; and a non-root victim that
 *     cannot even open it) is refused, naming its owner and the
 *     couplingDict key `channel`; nothing is written into it;
 *   - a file of the right owner that group or others can access (0644), or
 *     a symbolic link, is refused;
 *   - a header of the right owner, mode, magic and version whose offsets,
 *     sizes or strides point outside the mapping or the file is refused
 *     with an error, never a crash; so is a frame whose item count would
 *     overflow its layout.
 * The planted header's ready peer is this test process itself; every
 * victim runs in a child process, so that a crash is a failed check and
 * not a dead test. Needs root for the other-user cases (skipped otherwise).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "chantest.h"
#include "coupling/channel_impl.h"
#include "coupling/protocol.h"

#include <errno.h>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>

#define HDR_BYTES ((sizeof(struct chan_header) + CHAN_PAGE - 1) / CHAN_PAGE \
                   * CHAN_PAGE)
#define TIB (1ULL << 40)
#define OTHER_UID 65534 /* nobody */
#define PLANT_BYTES (HDR_BYTES + CHAN_PAGE)

/* ---- a planted segment ------------------------------------------------------ */

struct plant {
    char name[64], path[128];
    int fd;
    size_t bytes;
    struct chan_header *h;
};

/* Names this test created, removed by the teardown even when a check
 * failed half-way (other runs' segments are never touched). */
static char planted[8][128];

static void remember(const char *path)
{
    for (int i = 0; i < 8; i++)
        if (!planted[i][0]) {
            snprintf(planted[i], sizeof planted[i], "%s", path);
            return;
        }
}

static void forget(const char *path)
{
    for (int i = 0; i < 8; i++)
        if (!strcmp(planted[i], path))
            planted[i][0] = '\0';
}

static int remove_planted(void **state)
{
    (void)state;
    for (int i = 0; i < 8; i++)
        if (planted[i][0]) {
            unlink(planted[i]);
            planted[i][0] = '\0';
        }
    return 0;
}

/* Create the channel's file as an attacker would (O_CREAT | O_EXCL), sized
 * `bytes` (PLANT_BYTES: a header and a page for the peer's ring), holding a
 * header that passes every check the channel made before issue 14: right
 * magic and version, and a fluid side (the victim's peer) claimed by this
 * live process, ready, agreeing with test_settings, asking for 2 frames of
 * 4 KiB. The victim's ring would go at the end of the file. */
static void plant(struct plant *p, size_t bytes)
{
    struct channel_settings s;

    unique_name(p->name, sizeof p->name);
    snprintf(p->path, sizeof p->path, "/dev/shm%s", p->name);
    p->fd = open(p->path, O_CREAT | O_EXCL | O_RDWR | O_CLOEXEC, 0600);
    assert_true(p->fd >= 0);
    remember(p->path);
    assert_int_equal(ftruncate(p->fd, (off_t)bytes), 0);
    p->bytes = bytes;
    p->h = mmap(NULL, bytes, PROT_READ | PROT_WRITE, MAP_SHARED, p->fd, 0);
    assert_true(p->h != MAP_FAILED);
    test_settings(&s, CHANNEL_FLUID, p->name);
    struct chan_header *h = p->h;
    h->version = CHANNEL_PROTOCOL_VERSION;
    h->header_bytes = (uint32_t)HDR_BYTES;
    h->reserve_bytes = CHANNEL_RESERVE_BYTES;
    atomic_store(&h->alloc_end, bytes);
    struct chan_side *f = &h->side[CHANNEL_FLUID];
    f->start_ticks = chan_proc_start(getpid());
    atomic_store(&f->heartbeat_ns, chan_now_ns());
    snprintf(f->program, sizeof f->program, "mpsFluid");
    f->nslots_req = 2;
    f->slot_bytes_req = 4096;
    f->agree.protocol = CHANNEL_PROTOCOL_VERSION;
    f->agree.dimension = s.dimension;
    snprintf(f->agree.units, sizeof f->agree.units, "%s", s.units);
    f->agree.digest = s.digest;
    snprintf(f->agree.case_path, sizeof f->agree.case_path, "%s",
             s.case_path);
    atomic_store(&f->pid, (int32_t)getpid());
    atomic_store(&f->state, SIDE_READY);
    h->magic = CHAN_MAGIC;
}

static void unplant(struct plant *p)
{
    munmap(p->h, p->bytes);
    close(p->fd);
    assert_int_equal(unlink(p->path), 0);
    forget(p->path);
}

/* ---- the victim: demSolid's side in a child process ------------------------- */

enum { OPEN_SEND, OPEN_RECV, OPEN_FORGE_OWN_SEND };

struct victim {
    const char *name;
    int action;
    uid_t uid;           /* != 0: drop to this user first */
};

static int victim_main(const struct victim *v)
{
    struct channel_settings s;
    struct channel *c;
    struct channel_frame f = { .kind = 1, .bytes = 8 };
    const void *data;
    double x = 1.0;
    int rc;

    if (v->uid && (setgid(v->uid) != 0 || setuid(v->uid) != 0))
        return sim_error(SIM_ERR_INTERNAL, "cannot become uid %u",
                         (unsigned)v->uid);
    test_settings(&s, CHANNEL_SOLID, v->name);
    s.timeout = 2.0;
    if ((rc = channel_open(&s, &c)))
        return rc;
    switch (v->action) {
    case OPEN_SEND:          /* both slots, no consumer needed */
        if (!(rc = channel_send(c, &f, &x)))
            rc = channel_send(c, &f, &x);
        break;
    case OPEN_RECV:
        if (!(rc = channel_recv(c, &f, &data)))
            rc = channel_recv_done(c);
        break;
    case OPEN_FORGE_OWN_SEND: {
        /* the peer rewrites the descriptor of the ring we write */
        struct chan_ring *r = &c->hdr->ring[CHANNEL_SOLID];
        r->offset = TIB;
        r->nslots = 0;
        r->slot_stride = 1ULL << 62;
        r->capacity = 1ULL << 62;
        if (!(rc = channel_send(c, &f, &x)))
            rc = channel_send(c, &f, &x);
        break;
    }
    }
    channel_close(c, rc);
    return rc;
}

/* Run the victim in a child; its error message comes back through a pipe.
 * Returns its exit status, 128 + signal when it crashed. */
static int run_victim(const struct victim *v, char *msg, size_t n)
{
    int pfd[2];
    assert_int_equal(pipe(pfd), 0);
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        /* a crash must kill the child: not cmocka's handlers, which would
         * go on running the parent's tests in it */
        static const int sigs[] = { SIGSEGV, SIGBUS, SIGFPE, SIGILL,
                                    SIGABRT };
        for (size_t i = 0; i < sizeof sigs / sizeof *sigs; i++)
            signal(sigs[i], SIG_DFL);
        close(pfd[0]);
        log_set_quiet(1);
        int rc = victim_main(v);
        const char *m = rc ? sim_error_message() : "";
        ssize_t w = write(pfd[1], m, strlen(m));
        (void)w;
        _exit(rc);
    }
    close(pfd[1]);
    size_t got = 0;
    ssize_t r;
    while (got + 1 < n && (r = read(pfd[0], msg + got, n - 1 - got)) > 0)
        got += (size_t)r;
    msg[got] = '\0';
    close(pfd[0]);
    int st = reap(pid);
    printf("    victim: status %d%s%s\n", st, got ? ": " : "", msg);
    return st;
}

static int has(const char *msg, const char *what)
{
    if (strstr(msg, what))
        return 1;
    printf("    message lacks '%s'\n", what);
    return 0;
}

/* ---- (a) owner and mode ----------------------------------------------------- */

static void test_planted_by_other_user_refused(void **state)
{
    struct plant p;
    struct stat st;
    char msg[2048];
    (void)state;
    if (geteuid() != 0) {
        printf("    (not root: cannot plant a file of another user)\n");
        skip();
    }
    plant(&p, PLANT_BYTES);
    assert_int_equal(fchown(p.fd, OTHER_UID, OTHER_UID), 0);
    /* root as the victim: it can open the file, and must not use it */
    struct victim v = { p.name, OPEN_SEND, 0 };
    assert_int_equal(run_victim(&v, msg, sizeof msg), SIM_ERR_INPUT);
    assert_true(has(msg, "owned by user nobody (uid 65534)"));
    assert_true(has(msg, "'channel"));
    assert_true(has(msg, "system/couplingDict"));
    /* nothing claimed, nothing grown, not removed */
    assert_int_equal(atomic_load(&p.h->side[CHANNEL_SOLID].pid), 0);
    assert_int_equal(fstat(p.fd, &st), 0);
    assert_int_equal((size_t)st.st_size, PLANT_BYTES);
    assert_true(segment_exists(p.name));
    /* a user that cannot even open it (mode 0600, not its file) */
    struct victim u = { p.name, OPEN_SEND, 65533 };
    assert_int_equal(run_victim(&u, msg, sizeof msg), SIM_ERR_INPUT);
    assert_true(has(msg, "owned by user nobody (uid 65534)"));
    assert_true(has(msg, "system/couplingDict"));
    unplant(&p);
}

static void test_group_or_other_access_refused(void **state)
{
    struct plant p;
    char msg[2048];
    (void)state;
    plant(&p, PLANT_BYTES);
    assert_int_equal(fchmod(p.fd, 0644), 0);
    struct victim v = { p.name, OPEN_SEND, 0 };
    assert_int_equal(run_victim(&v, msg, sizeof msg), SIM_ERR_INPUT);
    assert_true(has(msg, "mode 0644"));
    assert_true(has(msg, "system/couplingDict"));
    assert_int_equal(atomic_load(&p.h->side[CHANNEL_SOLID].pid), 0);
    unplant(&p);
}

static void test_symlink_refused(void **state)
{
    struct plant p;
    char msg[2048], link_name[64], link_path[128];
    (void)state;
    plant(&p, PLANT_BYTES);           /* a valid-looking target */
    unique_name(link_name, sizeof link_name);
    snprintf(link_path, sizeof link_path, "/dev/shm%s", link_name);
    assert_int_equal(symlink(p.path, link_path), 0);
    remember(link_path);
    struct victim v = { link_name, OPEN_SEND, 0 };
    assert_int_equal(run_victim(&v, msg, sizeof msg), SIM_ERR_INPUT);
    assert_true(has(msg, "symbolic link"));
    assert_true(has(msg, "system/couplingDict"));
    assert_int_equal(atomic_load(&p.h->side[CHANNEL_SOLID].pid), 0);
    unlink(link_path);
    forget(link_path);
    unplant(&p);
}

/* ---- (b) forged offsets, sizes and strides ---------------------------------- */

enum forgery {
    RESERVE_AND_CURSOR,  /* reserve 4 TiB, alloc_end at 1 TiB (the report) */
    CURSOR_PAST_MAPPING, /* alloc_end beyond the 256 GiB we map            */
    CURSOR_UNALIGNED,
    HEADER_BYTES,
    HUGE_SLOT_REQUEST,   /* peer asks for frames of 2^63 bytes            */
    HUGE_SLOTS_REQUEST,  /* peer asks for 2^32 - 1 frames in flight       */
    PEER_RING_FAR,       /* peer's ring at 1 TiB: outside the mapping     */
    PEER_RING_PAST_EOF,  /* at 1 GiB: inside the mapping, past the file   */
    PEER_RING_NO_SLOTS,  /* nslots 0: division by zero                    */
    PEER_RING_STRIDE,    /* stride 2^62: slot 1 far away                  */
    PEER_RING_CAPACITY,  /* capacity 2^60 for 64-byte slots, frame 1 TiB  */
    NFORGERIES
};

static const char *const forgery_name[NFORGERIES] = {
    "reserve_bytes 4 TiB, alloc_end 1 TiB", "alloc_end 300 GiB",
    "alloc_end not page-aligned", "header_bytes 0",
    "peer requests 2^63-byte frames", "peer requests 2^32-1 frames",
    "peer ring at 1 TiB", "peer ring past the end of the file",
    "peer ring of 0 slots", "peer ring stride 2^62",
    "peer ring capacity 2^60, frame of 1 TiB"
};

static void forge(struct plant *p, int what)
{
    struct chan_header *h = p->h;
    struct chan_ring *r = &h->ring[CHANNEL_FLUID];
    struct chan_side *f = &h->side[CHANNEL_FLUID];

    /* a published frame in the peer's ring (read only by channel_recv) */
    if (what >= PEER_RING_FAR) {
        r->offset = HDR_BYTES;
        r->nslots = 2;
        r->slot_stride = 128;
        r->capacity = 64;
        r->generation = 1;
        atomic_store(&r->head, 1);
    }
    switch (what) {
    case RESERVE_AND_CURSOR:
        h->reserve_bytes = 4 * TIB;
        atomic_store(&h->alloc_end, TIB);
        break;
    case CURSOR_PAST_MAPPING:
        atomic_store(&h->alloc_end, 300ULL << 30);
        break;
    case CURSOR_UNALIGNED:
        atomic_store(&h->alloc_end, HDR_BYTES + 100);
        break;
    case HEADER_BYTES:
        h->header_bytes = 0;
        break;
    case HUGE_SLOT_REQUEST:
        f->slot_bytes_req = 1ULL << 63;
        break;
    case HUGE_SLOTS_REQUEST:
        f->nslots_req = 0xffffffffu;
        break;
    case PEER_RING_FAR:
        r->offset = TIB;
        break;
    case PEER_RING_PAST_EOF:
        r->offset = 1ULL << 30;
        break;
    case PEER_RING_NO_SLOTS:
        r->nslots = 0;
        break;
    case PEER_RING_STRIDE:
        r->slot_stride = 1ULL << 62;
        atomic_store(&r->tail, 1);     /* frame 1 is in slot 1 */
        atomic_store(&r->head, 2);
        break;
    case PEER_RING_CAPACITY: {
        r->capacity = 1ULL << 60;
        struct channel_frame *fr =
            (struct channel_frame *)((char *)h + HDR_BYTES);
        fr->kind = 1;
        fr->bytes = TIB;
        break;
    }
    }
}

static void test_forged_header_refused(void **state)
{
    char msg[2048];
    int failures = 0;
    (void)state;
    for (int w = 0; w < NFORGERIES; w++) {
        struct plant p;
        plant(&p, PLANT_BYTES);
        forge(&p, w);
        printf("  forged: %s\n", forgery_name[w]);
        struct victim v = { p.name, w >= PEER_RING_FAR ? OPEN_RECV
                                                        : OPEN_SEND, 0 };
        int st = run_victim(&v, msg, sizeof msg);
        if (st >= 128) {
            printf("    FAILED: the victim crashed (signal %d)\n", st - 128);
            failures++;
        } else if (st == 0) {
            printf("    FAILED: the victim accepted it\n");
            failures++;
        } else if (!strstr(msg, p.name) ||
                   !(strstr(msg, "corrupted") ||
                     strstr(msg, "not a valid coupling channel"))) {
            printf("    FAILED: the message does not say that channel %s "
                   "is corrupted or not valid\n", p.name);
            failures++;
        }
        unplant(&p);
    }
    assert_int_equal(failures, 0);
}

/* The peer rewrites the descriptor of the ring we write, after the
 * handshake: we keep writing where we allocated. */
static void test_own_ring_descriptor_not_trusted(void **state)
{
    struct plant p;
    char msg[2048];
    (void)state;
    plant(&p, PLANT_BYTES);
    struct victim v = { p.name, OPEN_FORGE_OWN_SEND, 0 };
    assert_int_equal(run_victim(&v, msg, sizeof msg), SIM_OK);
    unplant(&p);
}

/* A frame header is the peer's too: 2^61 grains x 3 doubles x 8 bytes
 * wraps to 0 bytes, which a 0-byte payload would match. */
static void test_frame_count_overflow_refused(void **state)
{
    struct channel_frame f = { .kind = PROTO_DEM_STATE,
                               .count = 1ULL << 61, .bytes = 0 };
    struct proto_dem_state ds;
    struct proto_fluid_state fs;
    (void)state;
    assert_int_equal(proto_view_dem_state(&f, "", &ds), SIM_ERR_PEER);
    assert_non_null(strstr(sim_error_message(), "malformed"));
    f.kind = PROTO_FLUID_STATE;
    assert_int_equal(proto_view_fluid_state(&f, "", &fs), SIM_ERR_PEER);
    /* an empty state is still fine */
    f.count = 0;
    assert_int_equal(proto_view_fluid_state(&f, "", &fs), SIM_OK);
    assert_int_equal(fs.n, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_planted_by_other_user_refused,
                                  remove_planted),
        cmocka_unit_test_teardown(test_group_or_other_access_refused,
                                  remove_planted),
        cmocka_unit_test_teardown(test_symlink_refused, remove_planted),
        cmocka_unit_test_teardown(test_forged_header_refused,
                                  remove_planted),
        cmocka_unit_test_teardown(test_own_ring_descriptor_not_trusted,
                                  remove_planted),
        cmocka_unit_test(test_frame_count_overflow_refused),
    };
    log_set_quiet(1);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
