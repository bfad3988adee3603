/*
 * store.h — per-particle fields registered by name: the particle container
 * every solver stands on (issue 16, item 1).
 *
 * A solver keeps each field as a plain pointer member (P->u, d->v ...) so
 * that its loops read the arrays directly, and registers the member's
 * address with a name, a type and a component count. The registry then
 * does, for every field at once, what each solver used to write by hand:
 *
 *   store_resize    growth; new entries are zero
 *   store_permute   renumbering (cell order): new i <- old perm[i]
 *   store_compact   removal (escaped particles): keep an increasing list
 *   store_cloud     the .vtu view: positions and the STORE_WRITE fields,
 *                   in the order they were registered
 *   store_find, store_require
 *                   lookup by name (function objects); an unknown name is
 *                   the one message of core/select.h: the valid names and
 *                   "did you mean"
 *
 * A field flagged STORE_INDEX holds particle indices (int32, -1 for none)
 * and is remapped by permute and compact; an index to a removed particle
 * becomes -1. A STORE_VIEW field is an array owned elsewhere (a coupling's
 * per-particle output, a cloud read from a file): written and looked up,
 * never allocated, moved or freed.
 *
 * Every array has room for `cap` particles plus 64 bytes, so that a loop
 * vectorised past n (or an empty cloud) reads allocated memory.
 */
#ifndef MPSDEM_PARTICLES_STORE_H
#define MPSDEM_PARTICLES_STORE_H

#include <stddef.h>
#include <stdint.h>

#include "io/vtu.h"

#define STORE_MAX_FIELDS 32

enum {
    STORE_WRITE = 1u << 0,  /* in the .vtu cloud                          */
    STORE_INDEX = 1u << 1,  /* int32 particle indices, remapped           */
    STORE_VIEW = 1u << 2,   /* owned elsewhere: not grown, moved, freed   */
    STORE_POINTS = 1u << 3, /* the positions: the cloud's Points          */
};

struct store_field {
    /* the two members of struct model_head (core/select.h), so that an
     * unknown name gets the project's one "did you mean" message */
    const char *name;     /* borrowed: a string literal                   */
    const char *doc;      /* "" or unit and meaning                        */
    enum vtu_type type;
    int ncomp;            /* components per particle                      */
    unsigned flags;       /* STORE_*                                      */
    size_t elem;          /* bytes per particle                           */
    void **ref;           /* the owner's pointer to the array             */
};

struct store {
    size_t n, cap;                /* particles, room for                 */
    const char *category;         /* "field of the fluid cloud"          */
    int nfields;
    struct store_field f[STORE_MAX_FIELDS];
    void *scratch;                /* permute: one field's worth          */
    size_t scratch_bytes;
    int32_t *inv;                 /* old index -> new, for STORE_INDEX   */
    size_t inv_cap;
};

/* An empty store (n = cap = 0); category names its fields in errors. */
void store_init(struct store *s, const char *category);

/* Frees the arrays of every field that is not a view and sets the owners'
 * pointers to NULL; the store is then empty (fields unregistered). */
void store_free(struct store *s);

/* Register the array *ref (the address of the owner's pointer member) as
 * field `name` of `ncomp` components of `type`. Unless STORE_VIEW, the
 * array is allocated here for cap particles, zeroed (whatever *ref held
 * is not freed: it must be NULL). Errors: SIM_ERR_INTERNAL for a name
 * registered twice, a full table or STORE_INDEX not on Int32 x1;
 * SIM_ERR_NOMEM. */
int store_add(struct store *s, const char *name, const char *doc,
              enum vtu_type type, int ncomp, unsigned flags, void *ref);

/* Room for cap particles in every field (never shrinks). */
int store_reserve(struct store *s, size_t cap);

/* n particles: grows to exactly n when cap < n; entries from the old n to
 * n are zero. */
int store_resize(struct store *s, size_t n);

/* Keep m particles, new i <- old perm[i] (perm: distinct indices < n);
 * STORE_INDEX fields are remapped. n becomes m. */
int store_permute(struct store *s, const int32_t *perm, size_t m);

/* The same for an increasing list `kept`, done in place (removal). */
int store_compact(struct store *s, const int32_t *kept, size_t m);
/* The same leaving the index fields as they are: while particles travel
 * between ranks they hold particle ids (particles/distribute.c). */
int store_compact_unmapped(struct store *s, const int32_t *kept, size_t m);

/* The owner struct holding the registered pointers was copied from `old`
 * to `now` (size bytes): references into it follow. */
void store_moved(struct store *s, const void *old, void *now, size_t size);

/* The field called name, or NULL. */
const struct store_field *store_find(const struct store *s, const char *name);

/* Its array (NULL for an empty store) after checking type and components
 * (type < 0 or ncomp <= 0: not checked). SIM_ERR_INPUT naming `who` and
 * the field: an unknown name lists the valid ones ("did you mean"). */
int store_require(const struct store *s, const char *who, const char *name,
                  int type, int ncomp, const void **data);

/* The cloud to write: n, the STORE_POINTS field as points, the STORE_WRITE
 * fields in registration order, described in out (room for
 * STORE_MAX_FIELDS); borrowed, valid until the store changes. */
void store_cloud(const struct store *s, double time, struct vtu_field *out,
                 struct vtu_cloud *c);

/* Views of a cloud's points ("position") and fields, so that a cloud read
 * from a file (or made by a test) can be looked up like a solver's. The
 * cloud must stay where it is while the store is used. */
int store_view_cloud(struct store *s, struct vtu_cloud *c);

#endif
