/* hol_world_impl.h - internals shared by the hol_world*.c files (not an API).
 *
 * Contract
 * - hol_world is one block: the struct, then the store (entries), then the
 *   scratch arrays of one generation batch. Nothing is allocated later.
 * - The store is an open-addressing table with linear probing keyed by the
 *   tile word; deletion shifts back, so there are no tombstones.
 * - Domains of uncollapsed tiles are not stored: a batch derives them from
 *   the collapsed neighbours in the store (exact demands), which keeps them
 *   right whatever was evicted before.
 * - The 29 tile states, their connectors and the biome weights live in
 *   hol_wfc.c; the other files use them through the functions below.
 */
#ifndef HOL_WORLD_IMPL_H
#define HOL_WORLD_IMPL_H

#include "hol_world.h"

#define HOL__NSTATES 29
#define HOL__UNSET 0xffu
#define HOL__ALL_STATES ((UINT32_C(1) << HOL__NSTATES) - 1)
#define HOL__MAX_DEPTH 5

/* entry flags */
#define HOL__F_USED 0x01u
#define HOL__F_SEEN 0x02u  /* was within the radius of the user */
#define HOL__F_TREES 0x04u /* trees cached */
#define HOL__F_PLACED 0x08u /* a designer placement (any biome allowed) */
#define HOL__F_KEPT 0x10u   /* image records only: a seen tile outside the store */
#define HOL__F_KNOWN 0x1Fu

typedef struct hol__entry {
    hol_tile tile;
    uint32_t stamp;  /* last update that had it within radius + 1 */
    uint8_t state;   /* 0..HOL__NSTATES-1, or HOL__UNSET */
    uint8_t biome;   /* hol_biome or HOL_BIOME_NONE */
    uint8_t depth;   /* biome propagation depth */
    uint8_t flags;
    uint8_t game;    /* HOL_OBJ_NONE or a game object */
    uint8_t pad;
    uint16_t trees;  /* 4 bits per corner: kind | size << 2 */
} hol__entry;

/* A seen tile remembered after eviction (open addressing on the tile). */
typedef struct hol__kept {
    hol_tile tile;
    uint8_t state, biome, depth, used;
    uint32_t pad;
} hol__kept;

/* One tile of a generation batch. */
typedef struct hol__slot {
    uint32_t entry;   /* index in the store */
    uint32_t dom;     /* domain (collapsed: one bit) */
    uint64_t hash;    /* hash(seed, tile), for ties and choices */
    int32_t nb[4];    /* slot of the neighbour across edge d; -1 beyond the
                         reach; -2 not known (outer ring) */
    uint8_t nbe[4];   /* that edge as seen from the neighbour */
    uint8_t dist;     /* from the batch centre */
    uint8_t ring;     /* 1: outer ring (radius + 1), not collapsed */
    uint8_t pad[2];   /* [0] ring tile next to an open ball tile;
                         [1] choices drawn so far (attempt counter) */
    uint32_t open_pos; /* index in the open list, or UINT32_MAX */
} hol__slot;

typedef struct hol__trail {
    uint32_t slot;
    uint32_t dom;
    uint8_t state, biome, depth, pad;
} hol__trail;

typedef struct hol__decision {
    uint32_t trail_pos;
    uint32_t slot;
    uint32_t state;
    uint32_t choices; /* states in the domain when decided */
} hol__decision;

struct hol_world {
    uint64_t seed;
    int radius;
    int q;               /* the tiling {4,q} */
    uint32_t cap;        /* power of two */
    uint32_t mask;
    uint32_t count;
    uint32_t stamp;      /* update counter */
    uint32_t reject_per_mille;
    hol_room user;
    int ready;           /* the ball around user.tile is collapsed */
    hol__entry *entries;
    /* batch scratch */
    hol__slot *slots;
    uint32_t max_slots, nslots;
    uint32_t *map_key;   /* entry index + 1, 0 empty */
    uint32_t *map_val;   /* slot */
    uint32_t map_mask;
    hol__trail *trail;
    uint32_t max_trail, ntrail;
    hol__decision *dec;
    uint32_t ndec;
    uint32_t *queue;
    uint32_t *open;      /* open (uncollapsed) ball slots */
    uint32_t nopen;
    hol_tile *reserve_tiles;
    uint32_t max_reserve;
    uint64_t choice_counter;
    hol_world_place places[HOL_WORLD_MAX_PLACES]; /* designer placements */
    uint32_t nplaces;
    /* seen tiles remembered after eviction (hol_world.c) */
    hol__kept *kept;
    uint32_t kept_mask, kept_count, kept_max;
    uint64_t kept_lost;
    /* incremental eviction sweep (hol_world.c) */
    uint32_t sweep_phase; /* 0 idle, 1 stamp range, 2 histogram, 3 evict */
    uint32_t sweep_pos, sweep_lo, sweep_hi, sweep_n, sweep_limit;
    uint32_t sweep_hist[256];
    /* statistics */
    uint64_t collapsed, backtracks, updates, evicted;
    size_t bytes;
    void (*free_fn)(void *ptr, void *user);
    void *free_user;
};

/* hol_world.c: the store */
uint32_t hol__ball_size(int q, int radius); /* tiles within radius, 0..9 */
int64_t hol__find(const hol_world *w, hol_tile t);       /* index or -1 */
const hol__kept *hol__kept_find(const hol_world *w, hol_tile t); /* or NULL */
void hol__keep(hol_world *w, const hol__entry *e); /* remember a seen tile */
/* Index of t, inserted uncollapsed if missing; -1 if the store is full. */
int64_t hol__insert(hol_world *w, hol_tile t);
/* Full-store policy: over 3/4 full, run a bounded step of the eviction
 * sweep (the whole sweep at once when over 7/8 full). */
void hol__maybe_evict(hol_world *w);
uint64_t hol__mix(uint64_t a, uint64_t b);
uint64_t hol__tile_hash(uint64_t seed, hol_tile t);
int hol__tile_valid(hol_tile t); /* a canonical tile word in reach (any tiling) */

/* hol_wfc.c: the tile set */
int hol__state_obj(int s);
int hol__state_rot(int s); /* -1: from the seed */
int hol__state_conn(int s, int edge);
uint32_t hol__compat(int edge, int conn); /* states with conn on edge */
/* Positive when a free choice of state s is allowed in biome b. */
uint32_t hol__weight(int biome, int s);
/* Batch: collapse everything within radius of centre. */
hol_err hol__generate(hol_world *w, hol_tile centre, int radius, int mark_seen);

/* hol_wfc.c: the content of a collapsed entry */
void hol__fill_content(const hol_world *w, const hol__entry *e,
                       hol_tile_content *out);

/* hol_world_tree.c: vertices and trees, pure in (seed, vertex). It uses
 * neither the tile set nor the generator: hol_wfc.c calls it, never the
 * other way round. */
uint16_t hol__trees_packed(uint64_t seed, hol_tile t);

/* hol_world_io.c: checksum of an image's first n bytes (tests use it to
 * forge images that pass the checksum but break a rule) */
uint64_t hol__image_checksum(const uint8_t *p, size_t n);

/* hol_world_check.c: constraint check over any lookup */
typedef struct hol__rec {
    hol_tile tile;
    uint32_t stamp;
    uint8_t state, biome, depth, flags, game;
} hol__rec;
typedef int (*hol__lookup_fn)(const void *ctx, hol_tile t, hol__rec *out);
/* Check one record against the tile set and its neighbours. */
hol_err hol__check_rec(const hol__rec *r, hol__lookup_fn look, const void *ctx,
                       char *msg, size_t cap);

#endif
