/*
 * channel.c — create or attach the segment, handshake, close (channel.h).
 *
 * Creation publishes only complete segments: the creator builds the header
 * under a private name "<name>.init.<pid>" and link()s it to <name>, which
 * fails with EEXIST if the other program won the race; the loser attaches.
 * So a segment under its final name always has a valid header and at least
 * one claimed side. A creator killed before link() leaves its private name,
 * which the next creator removes once that pid is gone.
 *
 * Attaching, replacing a stale segment and unlinking at close are decided
 * under flock() on the segment, after checking that the name still refers
 * to the file we hold (another program may have replaced it meanwhile).
 *
 * Trust (issue 14): /dev/shm is writable by every user and the default name
 * is predictable, so another local user can plant a file at it before the
 * run, looking like a channel whose peer is ready. An existing name is
 * therefore used only when, by fstat of the descriptor we opened
 * (O_NOFOLLOW, O_NONBLOCK: no symbolic link followed, no FIFO waited on),
 * it is a regular file owned by our effective user with no group or other
 * permission bits: what create_segment makes. Anything else is refused
 * with SIM_ERR_INPUT and a message naming its owner and mode and the
 * couplingDict key `channel` (a non-root user cannot remove another user's
 * file from the sticky /dev/shm; another name is the way out). When it
 * cannot even be opened (EACCES, ELOOP, EISDIR) lstat names the owner the
 * same way. Dead creators' drafts are removed only when they are ours.
 *
 * Then every size and offset the segment holds is checked before it
 * addresses memory (the peer is a program of the same user, but a
 * corrupted or forged header must give an error, never a write outside
 * the mapping): at attach, header_bytes and reserve_bytes must be this
 * build's, the allocation cursor page-aligned inside [header,
 * CHANNEL_RESERVE_BYTES] and the file at least a header long
 * (SIM_ERR_INPUT, "not a valid coupling channel"); at the handshake, the
 * peer's request must be 1..CHAN_MAX_SLOTS frames within the reservation
 * (SIM_ERR_PEER, "corrupted"); every allocation is bounded by our own
 * mapping, and every frame received by the peer's ring descriptor checked
 * against the mapping and the file size (channel_frame.c, channel_impl.h).
 * Strings of the peer (program, units, case path) are read with bounds.
 *
 * The handshake (compare_agreement) stops both programs with SIM_ERR_PEER
 * and "<what> differs: <us> has '<ours>', <peer> (pid N) has '<theirs>'"
 * when they disagree on, in this order: the protocol version, the case
 * path, the dimension, the units, endTime (exactly: both read the same
 * controlDict; before protocol 2 a different endTime showed only at the
 * end, one program finishing and the other finding the channel closed),
 * and the digest of the coupling settings. deltaT and startTime show in
 * the time of the first frame (couple_fluid.c, couple_dem.c).
 */
#include "coupling/channel_impl.h"
#include "core/error.h"
#include "core/log.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <pwd.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#define SHM_DIR "/dev/shm"

static uint64_t fnv1a(const char *s)
{
    uint64_t h = 0xcbf29ce484222325ULL;
    for (; *s; s++)
        h = (h ^ (unsigned char)*s) * 0x100000001b3ULL;
    return h;
}

int channel_default_name(const char *case_abs, char *buf, size_t n)
{
    int len = snprintf(buf, n, "/mpsdem-%u-%016llx", (unsigned)getuid(),
                       (unsigned long long)fnv1a(case_abs));
    if (len < 0 || (size_t)len >= n)
        return sim_error(SIM_ERR_INTERNAL, "channel name buffer too short");
    return SIM_OK;
}

int channel_settings_default(struct channel_settings *s, int side,
                             const char *program, const char *case_dir)
{
    char abs[PATH_MAX];

    memset(s, 0, sizeof *s);
    if (side != CHANNEL_FLUID && side != CHANNEL_SOLID)
        return sim_error(SIM_ERR_INPUT, "channel side must be fluid (0) or "
                         "solid (1), not %d", side);
    if (!realpath(case_dir, abs))
        return sim_error(SIM_ERR_IO, "case directory '%s': %s", case_dir,
                         strerror(errno));
    if (strlen(abs) >= sizeof s->case_path)
        return sim_error(SIM_ERR_INPUT, "case path '%s' is longer than %d "
                         "characters", abs, CHANNEL_PATH_MAX - 1);
    strcpy(s->case_path, abs);
    snprintf(s->program, sizeof s->program, "%s", program);
    s->side = side;
    s->timeout = 60.0;
    s->heartbeat_interval = 0.1;
    s->nslots = 2;
    s->slot_bytes = 64 * 1024;
    s->dimension = 3;
    strcpy(s->units, "SI");
    return SIM_OK;
}

static int check_settings(struct channel_settings *s)
{
    if (!s->name[0])
        TRY(channel_default_name(s->case_path, s->name, sizeof s->name));
    if (s->name[0] != '/' || strchr(s->name + 1, '/') || !s->name[1] ||
        strlen(s->name) > CHANNEL_NAME_MAX - 24)
        return sim_error(SIM_ERR_INPUT, "channel name '%s' must start with "
                         "'/', contain no other '/' and be at most %d "
                         "characters", s->name, CHANNEL_NAME_MAX - 24);
    if (!(s->timeout > 0) || !(s->heartbeat_interval > 0) ||
        s->heartbeat_interval > s->timeout)
        return sim_error(SIM_ERR_INPUT, "channel %s: need 0 < "
                         "heartbeatInterval (%g s) <= timeout (%g s)",
                         s->name, s->heartbeat_interval, s->timeout);
    if (s->nslots < 1 || s->nslots > 1024)
        return sim_error(SIM_ERR_INPUT, "channel %s: framesInFlight %d not "
                         "in [1, 1024]", s->name, s->nslots);
    return SIM_OK;
}

static void shm_path(const char *name, char *buf, size_t n)
{
    snprintf(buf, n, SHM_DIR "%s", name);
}

/* Remove "<name>.init.<pid>" files of creators that died before link(). */
static void remove_dead_drafts(const char *name)
{
    char prefix[CHANNEL_NAME_MAX + 8], path[sizeof SHM_DIR + 256];
    DIR *d = opendir(SHM_DIR);
    struct dirent *e;

    if (!d)
        return;
    snprintf(prefix, sizeof prefix, "%s.init.", name + 1);
    while ((e = readdir(d))) {
        struct stat st;
        if (strncmp(e->d_name, prefix, strlen(prefix)) != 0)
            continue;
        pid_t pid = (pid_t)atol(e->d_name + strlen(prefix));
        snprintf(path, sizeof path, SHM_DIR "/%s", e->d_name);
        /* root may unlink anything in /dev/shm: only our own drafts */
        if (pid > 0 && chan_proc_start(pid) == 0 && lstat(path, &st) == 0 &&
            S_ISREG(st.st_mode) && st.st_uid == geteuid())
            unlink(path);
    }
    closedir(d);
}

/* "nobody (uid 65534)", or "uid 65534" without a passwd entry. */
static void user_name(uid_t uid, char *buf, size_t n)
{
    struct passwd pw, *res = NULL;
    char tmp[1024];

    if (getpwuid_r(uid, &pw, tmp, sizeof tmp, &res) == 0 && res)
        snprintf(buf, n, "%s (uid %u)", res->pw_name, (unsigned)uid);
    else
        snprintf(buf, n, "uid %u", (unsigned)uid);
}

static const char *file_kind(mode_t m)
{
    if (S_ISDIR(m)) return "directory";
    if (S_ISLNK(m)) return "symbolic link";
    if (S_ISFIFO(m)) return "FIFO";
    if (S_ISSOCK(m)) return "socket";
    if (S_ISCHR(m) || S_ISBLK(m)) return "device";
    return "special file";
}

/* SIM_OK when st (of the file at path) is what create_segment makes: a
 * regular file of our effective user that nobody else may open (see the
 * top of this file). Otherwise SIM_ERR_INPUT naming its owner. */
static int check_owner(const struct channel *c, const char *path,
                       const struct stat *st)
{
    char owner[160], me[160], what[512];
    uid_t euid = geteuid();
    int mine = st->st_uid == euid;

    if (S_ISREG(st->st_mode) && mine && !(st->st_mode & 077))
        return SIM_OK;
    user_name(st->st_uid, owner, sizeof owner);
    user_name(euid, me, sizeof me);
    if (!S_ISREG(st->st_mode))
        snprintf(what, sizeof what, "it is a %s owned by user %s, not a "
                 "regular file", file_kind(st->st_mode), owner);
    else if (!mine)
        snprintf(what, sizeof what, "it is owned by user %s, not by %s who "
                 "runs %s", owner, me, c->set.program);
    else
        snprintf(what, sizeof what, "it is owned by user %s but has mode "
                 "%04o: group or others may open it (a channel has mode "
                 "0600)", owner, (unsigned)(st->st_mode & 07777));
    return sim_error(SIM_ERR_INPUT, "%s: refusing coupling channel %s: %s. "
                     SHM_DIR " is writable by every user and the channel "
                     "name is predictable, so such a file may have been put "
                     "there to intercept or crash this run; nothing was "
                     "read from it or written to it. %s",
                     c->set.program, path, what,
                     mine && S_ISREG(st->st_mode)
                         ? "Remove it if no program of yours uses it, or "
                           "give this case another name with 'channel "
                           "<word>;' in system/couplingDict."
                         : "Give this case another name with 'channel "
                           "<word>;' in system/couplingDict (only its "
                           "owner or root can remove the file).");
}

static int map_segment(struct channel *c)
{
    c->base = mmap(NULL, CHANNEL_RESERVE_BYTES, PROT_READ | PROT_WRITE,
                   MAP_SHARED | MAP_NORESERVE, c->fd, 0);
    if (c->base == MAP_FAILED) {
        c->base = NULL;
        return sim_error(SIM_ERR_IO, "%s: cannot map channel %s: %s",
                         c->set.program, c->set.name, strerror(errno));
    }
    c->hdr = (struct chan_header *)c->base;
    return SIM_OK;
}

static void unmap_segment(struct channel *c)
{
    if (c->base)
        munmap(c->base, CHANNEL_RESERVE_BYTES);
    c->base = NULL;
    c->hdr = NULL;
    if (c->fd >= 0)
        close(c->fd);
    c->fd = -1;
}

static void claim_side(struct channel *c)
{
    struct chan_side *me = &c->hdr->side[c->side];
    me->start_ticks = chan_proc_start(getpid());
    atomic_store(&me->exit_code, SIM_OK);
    atomic_store(&me->heartbeat_ns, chan_now_ns());
    snprintf(me->program, sizeof me->program, "%s", c->set.program);
    atomic_store(&me->pid, (int32_t)getpid());
    chan_set_state(c, SIDE_CLAIMED);
}

/* *created = 1 when we published a new segment, 0 when another program
 * published one first. */
static int create_segment(struct channel *c, int *created)
{
    char draft[CHANNEL_NAME_MAX + 32], from[CHANNEL_NAME_MAX + 48],
        to[CHANNEL_NAME_MAX + 16];
    size_t hbytes = CHAN_HEADER_BYTES;
    int rc = SIM_OK;

    *created = 0;
    remove_dead_drafts(c->set.name);
    snprintf(draft, sizeof draft, "%s.init.%d", c->set.name, (int)getpid());
    shm_unlink(draft);
    c->fd = shm_open(draft, O_CREAT | O_EXCL | O_RDWR | O_CLOEXEC, 0600);
    if (c->fd < 0) {
        int err = errno;
        struct stat st;
        shm_path(draft, from, sizeof from);
        /* someone else's file at our draft's name, which we cannot remove */
        if (err == EEXIST && lstat(from, &st) == 0)
            TRY(check_owner(c, from, &st));
        return sim_error(SIM_ERR_IO, "%s: cannot create shared memory %s: "
                         "%s", c->set.program, draft, strerror(err));
    }
    if (fallocate(c->fd, 0, 0, (off_t)hbytes) != 0) {
        rc = sim_error(SIM_ERR_NOMEM, "%s: cannot size shared memory %s: "
                       "%s (check df -h " SHM_DIR ")", c->set.program,
                       draft, strerror(errno));
        goto out_unlink;
    }
    TRY_GOTO(rc, map_segment(c), out_unlink);
    c->file_bytes = hbytes;
    c->hdr->version = CHANNEL_PROTOCOL_VERSION;
    c->hdr->header_bytes = (uint32_t)hbytes;
    c->hdr->reserve_bytes = CHANNEL_RESERVE_BYTES;
    atomic_store(&c->hdr->alloc_end, hbytes);
    claim_side(c);
    atomic_thread_fence(memory_order_release);
    c->hdr->magic = CHAN_MAGIC;
    shm_path(draft, from, sizeof from);
    shm_path(c->set.name, to, sizeof to);
    if (link(from, to) == 0) {
        *created = 1;
    } else if (errno != EEXIST) {
        rc = sim_error(SIM_ERR_IO, "%s: cannot publish %s: %s",
                       c->set.program, to, strerror(errno));
    }
out_unlink:
    shm_unlink(draft);
    if (!*created)
        unmap_segment(c);
    return rc;
}

/* flock with a deadline: a holder stopped with SIGSTOP must not hang us. */
static int lock_segment(struct channel *c, uint64_t deadline)
{
    while (flock(c->fd, LOCK_EX | LOCK_NB) != 0) {
        if (errno != EWOULDBLOCK && errno != EINTR)
            return sim_error(SIM_ERR_IO, "%s: flock on %s: %s",
                             c->set.program, c->set.name, strerror(errno));
        if (chan_now_ns() > deadline)
            return sim_error(SIM_ERR_TIMEOUT, "%s: channel %s stays locked "
                             "by another program", c->set.program,
                             c->set.name);
        TRY(chan_check_signal(c));
        nanosleep(&(struct timespec){ 0, 1000000 }, NULL);
    }
    return SIM_OK;
}

/* Non-zero when c->fd is the file currently called c->set.name. */
static int name_is_ours(const struct channel *c)
{
    char path[CHANNEL_NAME_MAX + 16];
    struct stat a, b;

    shm_path(c->set.name, path, sizeof path);
    return fstat(c->fd, &a) == 0 && stat(path, &b) == 0 &&
           a.st_ino == b.st_ino && a.st_dev == b.st_dev;
}

static const char *side_word(int s) { return s == 0 ? "fluid" : "solid"; }

/* With the lock held: decide what to do with an existing segment (st: the
 * file, already known to be ours). Returns SIM_OK with *action = 0
 * attached, 1 retry from scratch, 2 wait and retry. */
static int decide_attach(struct channel *c, const struct stat *st,
                         int *action)
{
    struct chan_header *h = c->hdr;
    const struct chan_side *me = &h->side[c->side];

    if (h->magic != CHAN_MAGIC || h->version != CHANNEL_PROTOCOL_VERSION)
        return sim_error(SIM_ERR_INPUT, "%s: " SHM_DIR "%s is not a channel "
                         "of coupling protocol version %d (magic %016llx, "
                         "version %u). If no older program runs on this "
                         "case, remove it.", c->set.program, c->set.name,
                         CHANNEL_PROTOCOL_VERSION,
                         (unsigned long long)h->magic, h->version);
    uint32_t hbytes = h->header_bytes;
    uint64_t reserve = h->reserve_bytes, end = atomic_load(&h->alloc_end);
    if (hbytes != CHAN_HEADER_BYTES || reserve != CHANNEL_RESERVE_BYTES ||
        end < CHAN_HEADER_BYTES || end > CHANNEL_RESERVE_BYTES ||
        end % CHAN_PAGE || (uint64_t)st->st_size < CHAN_HEADER_BYTES)
        return sim_error(SIM_ERR_INPUT, "%s: " SHM_DIR "%s is not a valid "
                         "coupling channel: its header says %u header "
                         "bytes (expected %llu), %llu bytes reserved "
                         "(expected %llu) and an allocation cursor at %llu "
                         "bytes (a page boundary in between), in a file of "
                         "%lld bytes. If no program of yours uses it, remove "
                         "it.", c->set.program, c->set.name, hbytes,
                         (unsigned long long)CHAN_HEADER_BYTES,
                         (unsigned long long)reserve,
                         (unsigned long long)CHANNEL_RESERVE_BYTES,
                         (unsigned long long)end, (long long)st->st_size);
    if (chan_side_alive(h, c->side))
        return sim_error(SIM_ERR_INPUT, "%s: a %s program, %.*s (pid %d), "
                         "is already coupled through channel %s (case %.*s). A "
                         "second pair cannot run on the same case: stop "
                         "the first one, or give this case its own "
                         "'channel' in system/couplingDict.", c->set.program,
                         side_word(c->side), (int)sizeof me->program,
                         me->program, (int)atomic_load(&me->pid),
                         c->set.name,
                         me->agree.case_path[0]
                             ? (int)sizeof me->agree.case_path
                             : (int)sizeof c->set.case_path,
                         me->agree.case_path[0] ? me->agree.case_path
                                                : c->set.case_path);
    if (!chan_side_alive(h, 1 - c->side)) {
        if (!c->set.quiet)
            log_info("Removing stale coupling channel " SHM_DIR "%s left "
                     "by a run that ended (pids %d and %d are gone)",
                     c->set.name, (int)atomic_load(&h->side[0].pid),
                     (int)atomic_load(&h->side[1].pid));
        shm_unlink(c->set.name);
        *action = 1;
        return SIM_OK;
    }
    if (atomic_load(&me->pid) != 0) {
        /* our side's previous program has left; its peer is leaving too */
        *action = 2;
        return SIM_OK;
    }
    claim_side(c);
    *action = 0;
    return SIM_OK;
}

/* *attached = 0: the name vanished or was replaced, try again. */
static int attach_segment(struct channel *c, uint64_t deadline, int *attached)
{
    int rc = SIM_OK, action = 1;
    char path[CHANNEL_NAME_MAX + 16];
    struct stat st;

    *attached = 0;
    shm_path(c->set.name, path, sizeof path);
    c->fd = open(path, O_RDWR | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
    if (c->fd < 0) {
        int err = errno;
        if (err == ENOENT)
            return SIM_OK;
        if (lstat(path, &st) == 0)
            TRY(check_owner(c, path, &st));
        return sim_error(SIM_ERR_IO, "%s: cannot open channel %s: %s",
                         c->set.program, c->set.name, strerror(err));
    }
    /* before anything else, flock included: it could be held forever */
    if (fstat(c->fd, &st) != 0) {
        rc = sim_error(SIM_ERR_IO, "%s: fstat of channel %s: %s",
                       c->set.program, c->set.name, strerror(errno));
        goto out_close;
    }
    TRY_GOTO(rc, check_owner(c, path, &st), out_close);
    TRY_GOTO(rc, lock_segment(c, deadline), out_close);
    if (!name_is_ours(c))
        goto out_close;
    if (fstat(c->fd, &st) != 0 || (size_t)st.st_size <
                                      sizeof(struct chan_header)) {
        rc = sim_error(SIM_ERR_INPUT, "%s: " SHM_DIR "%s exists but is not "
                       "a coupling channel (size %lld); remove it",
                       c->set.program, c->set.name,
                       (long long)st.st_size);
        goto out_close;
    }
    c->file_bytes = (uint64_t)st.st_size;
    TRY_GOTO(rc, map_segment(c), out_close);
    TRY_GOTO(rc, decide_attach(c, &st, &action), out_close);
    if (action == 0) {
        flock(c->fd, LOCK_UN);
        *attached = 1;
        return SIM_OK;
    }
    if (action == 2)
        nanosleep(&(struct timespec){ 0, 10000000 }, NULL);
out_close:
    if (c->fd >= 0)
        flock(c->fd, LOCK_UN);
    unmap_segment(c);
    return rc;
}

static int ready_peer_published(struct channel *c, void *arg)
{
    (void)arg;
    return atomic_load(&c->hdr->side[c->peer].state) >= SIDE_READY;
}

/* The shortest "%.*g" that reads back as x: "0.5", not 0.50000000000000000. */
static void shortest_g(char *buf, size_t n, double x)
{
    for (int p = 1; p <= 17; p++) {
        snprintf(buf, n, "%.*g", p, x);
        if (strtod(buf, NULL) == x)
            return;
    }
}

/* What this side agrees to, from its own settings (not read back). */
static void own_agreement(const struct channel *c, struct chan_agree *a)
{
    memset(a, 0, sizeof *a);
    a->protocol = CHANNEL_PROTOCOL_VERSION;
    a->dimension = c->set.dimension;
    snprintf(a->units, sizeof a->units, "%s", c->set.units);
    a->end_time = c->set.end_time;
    a->digest = c->set.digest;
    snprintf(a->case_path, sizeof a->case_path, "%s", c->set.case_path);
}

static int compare_agreement(struct channel *c)
{
    struct chan_agree own, peer;
    const struct chan_agree *a = &own, *b = &peer;
    const char *what = NULL;
    char mine[CHANNEL_PATH_MAX + 32], theirs[CHANNEL_PATH_MAX + 32];

    own_agreement(c, &own);
    /* the peer's copy, its strings terminated whatever the segment holds */
    memcpy(&peer, &c->hdr->side[c->peer].agree, sizeof peer);
    atomic_signal_fence(memory_order_seq_cst);
    peer.units[sizeof peer.units - 1] = '\0';
    peer.case_path[sizeof peer.case_path - 1] = '\0';

    if (a->protocol != b->protocol) {
        what = "coupling protocol version";
        snprintf(mine, sizeof mine, "%u", a->protocol);
        snprintf(theirs, sizeof theirs, "%u", b->protocol);
    } else if (strcmp(a->case_path, b->case_path) != 0) {
        what = "case path";
        snprintf(mine, sizeof mine, "%s", a->case_path);
        snprintf(theirs, sizeof theirs, "%s", b->case_path);
    } else if (a->dimension != b->dimension) {
        what = "dimension";
        snprintf(mine, sizeof mine, "%d", a->dimension);
        snprintf(theirs, sizeof theirs, "%d", b->dimension);
    } else if (strcmp(a->units, b->units) != 0) {
        what = "units";
        snprintf(mine, sizeof mine, "%.*s", (int)sizeof a->units, a->units);
        snprintf(theirs, sizeof theirs, "%.*s", (int)sizeof b->units,
                 b->units);
    } else if (!(a->end_time == b->end_time)) {
        /* exactly: both read the same controlDict, and a program whose
         * endTime is larger by a round-off would take one more (tiny) step
         * and wait for a peer that has left */
        what = "endTime (system/controlDict; was it edited between the two "
               "starts?)";
        shortest_g(mine, sizeof mine, a->end_time);
        shortest_g(theirs, sizeof theirs, b->end_time);
    } else if (a->digest != b->digest) {
        what = "coupling settings (digest of system/couplingDict as "
               "expanded; was it edited between the two starts?)";
        snprintf(mine, sizeof mine, "%016llx", (unsigned long long)a->digest);
        snprintf(theirs, sizeof theirs, "%016llx",
                 (unsigned long long)b->digest);
    }
    if (!what)
        return SIM_OK;
    return sim_error(SIM_ERR_PEER, "%s: coupling handshake failed on channel "
                     "%s: %s differs: %s has '%s', %s (pid %d) has '%s'",
                     c->set.program, c->set.name, what, c->set.program, mine,
                     c->peer_program, (int)c->peer_pid, theirs);
}

static int handshake(struct channel *c)
{
    struct chan_side *me = &c->hdr->side[c->side];
    const struct chan_side *peer = &c->hdr->side[c->peer];

    own_agreement(c, &me->agree);
    me->nslots_req = (uint32_t)c->set.nslots;
    me->slot_bytes_req = c->set.slot_bytes;
    chan_set_state(c, SIDE_READY);
    TRY(chan_wait(c, ready_peer_published, NULL, &c->hdr->state_futex, NULL,
                  c->set.timeout, "peer program attached to the channel"));
    TRY(chan_watch_peer(c));
    TRY(compare_agreement(c));
    /* a peer that already closed normally did its part of the handshake
     * (and may have sent frames we still have to read) */
    if (atomic_load(&peer->state) != SIDE_CLOSED)
        TRY(chan_check_peer(c));
    /* the larger request of the two, the peer's read once and bounded */
    uint64_t pslots = peer->nslots_req, pbytes = peer->slot_bytes_req;
    atomic_signal_fence(memory_order_seq_cst);
    if (pslots < 1 || pslots > CHAN_MAX_SLOTS ||
        pbytes > CHANNEL_RESERVE_BYTES / pslots)
        return sim_error(SIM_ERR_PEER, "%s: channel %s is corrupted: %s "
                         "(pid %d) asks for %llu frames in flight of %llu "
                         "bytes (a channel holds 1 to %d frames, %llu GiB "
                         "in all)", c->set.program, c->set.name,
                         c->peer_program, (int)c->peer_pid,
                         (unsigned long long)pslots,
                         (unsigned long long)pbytes, CHAN_MAX_SLOTS,
                         (unsigned long long)(CHANNEL_RESERVE_BYTES >> 30));
    uint64_t nslots = (uint64_t)c->set.nslots > pslots
                          ? (uint64_t)c->set.nslots : pslots;
    uint64_t cap = c->set.slot_bytes > pbytes ? c->set.slot_bytes : pbytes;
    TRY(chan_ring_alloc(c, nslots, cap));
    if (!c->set.quiet)
        log_info("Coupled with %s (pid %d) through " SHM_DIR "%s: %llu "
                 "frames in flight of %llu bytes", c->peer_program,
                 (int)c->peer_pid, c->set.name, (unsigned long long)nslots,
                 (unsigned long long)c->tx.capacity);
    return SIM_OK;
}

static int connect_segment(struct channel *c)
{
    uint64_t deadline = chan_now_ns() + (uint64_t)(c->set.timeout * 1e9);

    for (;;) {
        int done = 0;
        TRY(chan_check_signal(c));
        TRY(attach_segment(c, deadline, &done));
        if (done)
            return SIM_OK;
        TRY(create_segment(c, &done));
        if (done)
            return SIM_OK;
        if (chan_now_ns() > deadline)
            return sim_error(SIM_ERR_TIMEOUT, "%s: could not attach channel "
                             "%s within %g s: it is held by the previous "
                             "run's programs", c->set.program, c->set.name,
                             c->set.timeout);
    }
}

int channel_open(const struct channel_settings *s, struct channel **out)
{
    struct channel *c = sim_calloc(1, sizeof *c);
    int rc;

    *out = NULL;
    if (!c)
        return SIM_ERR_NOMEM;
    c->set = *s;
    c->fd = -1;
    c->peer_pidfd = -1;
    c->registry_slot = -1;
    c->owner = getpid();
    c->side = s->side;
    c->peer = 1 - s->side;
    c->hung_ns = (uint64_t)(CHANNEL_HUNG_HEARTBEATS * s->heartbeat_interval
                            * 1e9);
    TRY_GOTO(rc, check_settings(&c->set), out_free);
    TRY_GOTO(rc, connect_segment(c), out_free);
    TRY_GOTO(rc, chan_registry_add(c), out_close);
    TRY_GOTO(rc, chan_heartbeat_start(c), out_close);
    TRY_GOTO(rc, handshake(c), out_close);
    *out = c;
    return SIM_OK;
out_close:
    channel_close(c, rc);
    return rc;
out_free:
    free(c);
    return rc;
}

int channel_close(struct channel *c, int status)
{
    int rc = SIM_OK;

    if (!c)
        return SIM_OK;
    chan_heartbeat_stop(c);
    if (c->hdr) {
        atomic_store(&c->hdr->side[c->side].exit_code, status);
        chan_set_state(c, status == SIM_OK ? SIDE_CLOSED : SIDE_FAILED);
        /* a short bounded lock: leaving must not hang either */
        uint64_t deadline = chan_now_ns() + 500000000ULL;
        while (flock(c->fd, LOCK_EX | LOCK_NB) != 0 &&
               chan_now_ns() < deadline)
            nanosleep(&(struct timespec){ 0, 1000000 }, NULL);
        /* a hung peer that resumes finds us FAILED and needs no name */
        if ((c->peer_hung || !chan_side_alive(c->hdr, c->peer)) &&
            name_is_ours(c) &&
            shm_unlink(c->set.name) != 0 && errno != ENOENT)
            rc = sim_error(SIM_ERR_IO, "%s: cannot remove channel %s: %s",
                           c->set.program, c->set.name, strerror(errno));
        flock(c->fd, LOCK_UN);
        remove_dead_drafts(c->set.name);
    }
    chan_registry_remove(c);
    unmap_segment(c);
    if (c->peer_pidfd >= 0)
        close(c->peer_pidfd);
    free(c);
    return rc;
}

const char *channel_name(const struct channel *c) { return c->set.name; }
pid_t channel_peer_pid(const struct channel *c) { return c->peer_pid; }
const char *channel_peer_program(const struct channel *c)
{
    return c->peer_program;
}
size_t channel_capacity(const struct channel *c)
{
    return c->tx.capacity;
}

int channel_poll(struct channel *c)
{
    return chan_check_peer(c);
}
