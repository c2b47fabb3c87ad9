/* hol_world.h - the seeded forest: content model, lazy WFC generation,
 * fixed-capacity store, save/load to memory.
 *
 * Contract
 * - Content model. Every tile has a biome, one floor object with a rotation
 *   (0..3, quarter turns counter-clockwise relative to the tile's canonical
 *   heading) and a connector on each of its four edges (edge d = the edge in
 *   direction d, 0 forward, 1 left, 2 back, 3 right, as hol_tile_step).
 *   Connectors match on both sides of every edge: if hol_tile_step(t, d,
 *   &nb, &arrive) then conn[d] of t equals conn[(arrive + 2) & 3] of nb.
 *   - A creek (HOL_CONN_CREEK) continues across edges: a CREEK tile has 2, 3
 *     or 4 creek edges, a SPRING or an end POOL exactly 1 (a creek begins or
 *     ends there); a POOL with no creek edge is a pond.
 *   - A log spans exactly two neighbouring tiles: both halves are HOL_OBJ_LOG,
 *     each has HOL_CONN_LOG on the shared edge only, and log_partner names
 *     that edge (-1 on every other tile).
 *   - Trees: a trunk stands on every vertex. Corner c of a tile is the vertex
 *     between its edges c and c + 1 (so corner 0 is front-left). Q tiles
 *     meet at a vertex (five in {4,5}; the world's tiling, desc.tiling_q);
 *     hol_world_vertex_canon names the vertex by the least (tile word,
 *     corner) pair of the Q, and the tree is a pure function of
 *     (seed, canonical vertex), so every tile reports the same tree.
 *   - Game objects (FLAG, KEY, CHEST) are never generated; the game places
 *     them on free tiles with hol_world_reserve.
 * - Biomes as in the original system: a tile reached without a biome gets
 *   one (from the seed) with a propagation depth above zero; when a tile with
 *   depth d > 0 collapses, neighbours without a biome get its biome with depth
 *   d - 1. The biome weights (and so restricts) the free choice of objects;
 *   creek continuations and the second half of a log are allowed everywhere.
 * - Generation is wave function collapse over 29 tile states: the
 *   uncollapsed tile of lowest entropy first, arc-consistent propagation to
 *   the neighbours, backtracking on contradiction. hol_world_update collapses
 *   every tile within the radius of the user before returning, so nothing is
 *   seen uncollapsed. Backtracking only undoes choices of the running update
 *   (tiles nobody has seen); a collapsed tile never changes while it is in
 *   the store (except that hol_world_reserve puts a game object on it).
 *   The tile set has a completion for every mix of fixed neighbours that the
 *   generator can produce (the tests check all of them exhaustively).
 * - Determinism: per-tile choices come from hash(seed, tile word), so the
 *   same seed and the same sequence of calls give the same world bit for
 *   bit; another seed gives another world. Tiles that hol_world_get
 *   collapses beyond the radius depend on the order they are asked for:
 *   to keep the world a function of seed and walk alone, read only within
 *   the radius, or choose a radius (up to 8) that covers what is shown.
 * - Fixed memory: one allocation at hol_world_make (or caller memory with
 *   hol_world_init, which clears the store: its pages are touched then,
 *   so no update takes a page fault; hol_world_make's default allocator is
 *   calloc instead, whose pages are mapped when first written, and so is
 *   caller memory said to hold zeros, desc.mem_zeroed; hol_world_reinit
 *   clears an empty store not again); the store is an open-addressing
 *   table keyed by the tile word. Full-store policy: when an update (or a get that must generate)
 *   finds the store over 3/4 full, it evicts, in an incremental sweep of
 *   cap/256 table slots per call (all at once over 7/8), the tiles least
 *   recently used -
 *   within radius + 1 of the user at an update, or read by hol_world_get -
 *   oldest first, until at most 1/2 remains (tiles of one age go together,
 *   so it may evict more). In a hyperbolic walk the least recently used
 *   tiles are the farthest. Never evicted: tiles used by the last or the
 *   running update, and tiles holding a game object. An evicted tile is
 *   regenerated, consistent with its neighbours in the store, if the user
 *   comes back (it may then differ from before). The store never grows, and
 *   no call crashes: HOL_ENOMEM when it is full of tiles it may not evict.
 * - Save/load (hol_world_save / hol_world_load) work on caller buffers; the
 *   core does no file I/O. The format is versioned, little-endian, sorted by
 *   tile word, with a 64-bit checksum; hol_world_load validates everything
 *   (header, checksum, every record, every constraint) before it touches the
 *   world, so a bad buffer leaves the world unchanged.
 * - No globals, no OS calls, no allocation after make/init. Not thread safe:
 *   one world per thread, or lock around calls.
 */
#ifndef HOL_WORLD_H
#define HOL_WORLD_H

#include <stddef.h>
#include <stdint.h>

#include "hol_alloc.h"
#include "hol_err.h"
#include "hol_room.h"
#include "hol_tile.h"

#define HOL_WORLD_DEFAULT_CAPACITY (1u << 20)
#define HOL_WORLD_MIN_CAPACITY 1024u
#define HOL_WORLD_DEFAULT_RADIUS 4
#define HOL_WORLD_MAX_RADIUS 8

typedef enum hol_biome {
    HOL_BIOME_MEADOW = 0,
    HOL_BIOME_PINE,
    HOL_BIOME_WETLAND,
    HOL_BIOME_AUTUMN,
    HOL_BIOME_COUNT,
    HOL_BIOME_NONE = 0xff /* only inside the store, never reported */
} hol_biome;

typedef enum hol_object {
    HOL_OBJ_NONE = 0, /* bare forest floor */
    HOL_OBJ_GRASS,
    HOL_OBJ_FLOWERS,  /* a flower patch, one tile */
    HOL_OBJ_LOG,      /* half of a log spanning two tiles */
    HOL_OBJ_CREEK,    /* a creek crossing the tile (2..4 creek edges) */
    HOL_OBJ_SPRING,   /* a creek begins here (1 creek edge) */
    HOL_OBJ_POOL,     /* a creek ends here (1 creek edge) or a pond (0) */
    HOL_OBJ_ROCK,
    HOL_OBJ_MUSHROOM,
    HOL_OBJ_FLAG,     /* game objects: only through hol_world_reserve */
    HOL_OBJ_KEY,
    HOL_OBJ_CHEST,
    HOL_OBJ_COUNT
} hol_object;

typedef enum hol_conn {
    HOL_CONN_NONE = 0,
    HOL_CONN_CREEK,
    HOL_CONN_LOG,
    HOL_CONN_COUNT
} hol_conn;

typedef enum hol_tree_kind {
    HOL_TREE_PINE = 0,
    HOL_TREE_BIRCH,
    HOL_TREE_OAK,
    HOL_TREE_MAPLE,
    HOL_TREE_COUNT
} hol_tree_kind;

typedef struct hol_tree {
    uint8_t kind; /* hol_tree_kind */
    uint8_t size; /* 0..3, small to large */
} hol_tree;

/* Everything the renderer needs about one tile. Directions, corners and the
 * rotation are relative to the tile's canonical heading. */
typedef struct hol_tile_content {
    uint8_t biome;       /* hol_biome, never HOL_BIOME_NONE */
    uint8_t object;      /* hol_object */
    uint8_t rotation;    /* 0..3 */
    int8_t log_partner;  /* edge 0..3 towards the other log half, or -1 */
    uint8_t conn[4];     /* hol_conn per edge */
    hol_tree tree[4];    /* tree on corner c (between edges c and c + 1) */
} hol_tile_content;

/* Rotation of the shapes: the object's model is drawn facing the tile's
 * edge `rotation`. For creeks the creek edges are a shape rotated by
 * `rotation`: straight {0,2}, bend {0,1}, tee {0,1,2}, cross {0,1,2,3}.
 * SPRING/end POOL: rotation is the creek edge. LOG: rotation is the partner
 * edge. Other objects: a rotation from the seed, for variety. */

/* the shared allocator hooks (core/hol_alloc.h) */
typedef hol_alloc hol_world_allocator;

/* A designer placement: tile t is generated with this object. (40: a
 * level's 32 designer placements and the game's objective tiles.) */
#define HOL_WORLD_MAX_PLACES 40
typedef struct hol_world_place {
    hol_tile tile;
    int object; /* HOL_OBJ_NONE (a clearing), GRASS, FLOWERS, ROCK, MUSHROOM,
                   or POOL (a pond: no creek) */
} hol_world_place;

typedef struct hol_world_desc {
    uint64_t seed;      /* any value, 0 included */
    uint32_t capacity;  /* tiles; 0 = HOL_WORLD_DEFAULT_CAPACITY; raised to
                           at least HOL_WORLD_MIN_CAPACITY and 8 times the
                           tiles within radius + 1 (4096 for radius 4), then
                           rounded up to a power of two; at most 2^31 */
    int radius;         /* collapsed radius around the user; 0 = 4; at most
                           HOL_WORLD_MAX_RADIUS */
    hol_world_allocator allocator;
    /* Testing only: reject this many per mille of the candidate states at
     * random, as if they had led to a contradiction, so the backtracking is
     * exercised. 0 in real use. */
    uint32_t test_reject_per_mille;
    /* Designer placements, as the original allows before generation fills
     * in the rest: each tile is collapsed only to states with its object
     * (any rotation; the biome still comes from the seed), and the rest of
     * the world is generated around it under the usual constraints (the
     * objects allowed have no connectors, so a completion always exists).
     * At most HOL_WORLD_MAX_PLACES, copied at init; a tile placed twice or
     * another object is HOL_EARG. They hold for every generation of the
     * tile, evicted and regenerated included. */
    const hol_world_place *places;
    uint32_t nplaces;
    /* Seen tiles kept after eviction: up to this many tiles the user has
     * seen (within the radius after an update) are remembered exactly
     * (state, biome) when the store evicts them, and come back the same;
     * 0: as many as the store's capacity. Fixed memory, 24 bytes a tile,
     * allocated at init. */
    uint32_t keep_capacity;
    /* The tiling {4,Q}, 4..8; 0: 5. Every tile and room state given to the
     * world must be of it (HOL_EARG otherwise); trees stand on vertices
     * with Q tiles round them. */
    int tiling_q;
    /* hol_world_init only: 1 when the memory given holds zeros (from
     * calloc or a fresh mapping, never written): the store is then not
     * cleared, so its pages are mapped when first written (a short run
     * touches a few of them) instead of all at init. */
    int mem_zeroed;
} hol_world_desc;

typedef struct hol_world hol_world;

typedef struct hol_world_stats {
    uint64_t tiles_collapsed;  /* collapses committed (over all updates) */
    uint64_t backtracks;       /* choices undone */
    uint64_t updates;
    uint64_t evicted;          /* tiles evicted by the full-store policy */
    uint32_t kept;             /* seen tiles remembered outside the store */
    uint32_t keep_capacity;
    uint64_t keep_lost;        /* seen tiles evicted when the memory of
                                  seen tiles was full (they may change) */
    uint32_t count;            /* tiles in the store now */
    uint32_t capacity;
    size_t bytes;              /* memory of the whole world (fixed) */
} hol_world_stats;

/* The capacity a world made from desc has (after raising and rounding up,
 * as hol_world_desc.capacity says); 0 for an invalid desc. */
uint32_t hol_world_capacity_of(const hol_world_desc *desc);
/* Bytes hol_world_init needs for this desc (0 for an invalid desc). */
size_t hol_world_mem_size(const hol_world_desc *desc);
/* A world over caller memory (aligned to 16, mem_size bytes). */
hol_err hol_world_init(void *mem, size_t size, const hol_world_desc *desc,
                       hol_world **out_world);
/* hol_world_init again over memory that holds a world (made on it by
 * hol_world_init or hol_world_make, or whose last init there failed; the
 * same mem and size): the same result, but a store that holds no tile (no
 * update since it was made, nothing remembered) and stays where it was
 * for desc is not cleared again, so a level started before any update
 * does not touch the pages a zeroed init left unmapped. A world from
 * hol_world_make stays the caller's to destroy (also after an error). */
hol_err hol_world_reinit(void *mem, size_t size, const hol_world_desc *desc,
                         hol_world **out_world);
/* A world in one allocation through the desc's hooks. */
hol_err hol_world_make(const hol_world_desc *desc, hol_world **out_world);
void hol_world_destroy(hol_world *w); /* only for hol_world_make; NULL ok */

uint64_t hol_world_seed(const hol_world *w);
int hol_world_tiling(const hol_world *w); /* Q of its tiling {4,Q} */
int hol_world_radius(const hol_world *w);
/* The room state of the last update (the start before the first). */
hol_room hol_world_user(const hol_world *w);
void hol_world_get_stats(const hol_world *w, hol_world_stats *out);

/* Collapse every tile within the radius of room->tile (call after every
 * room step, before drawing; a call on the tile of the last successful
 * update only records the room state and costs nothing, so calling it
 * every frame is fine). Tiles beyond the reach of tile words (distance
 * HOL_TILE_MAX_DIST from O) do not exist: the ball simply ends there and no
 * connector leads out of it. Errors: HOL_EARG (an invalid room state),
 * HOL_ENOMEM (the store is full of tiles it may not evict), HOL_EBUDGET
 * (backtracking gave up; only possible with test_reject_per_mille). On
 * error the tiles already in the store are unchanged. */
hol_err hol_world_update(hol_world *w, const hol_room *room);

/* Content of tile t; collapses t first if it is not yet (anywhere: a tile
 * far from the user is collapsed alone, consistent with its neighbours).
 * Marks t as used now, so a tile the renderer keeps reading is not evicted.
 * Errors: HOL_EARG (t beyond the reach), HOL_ENOMEM, HOL_EBUDGET. */
hol_err hol_world_get(hol_world *w, hol_tile t, hol_tile_content *out);
/* Content of t without generating or marking it used (const): HOL_EARG if
 * t is not collapsed. */
hol_err hol_world_peek(const hol_world *w, hol_tile t, hol_tile_content *out);

/* Put game object obj (FLAG, KEY or CHEST) on a free tile (object NONE,
 * GRASS, FLOWERS or MUSHROOM, no connectors, no game object yet): t itself if
 * free, else the nearest free tile within max_dist steps of t (max_dist is
 * capped at the world's radius; ties broken in breadth-first order over
 * the edges 0..3). The tile is collapsed first if needed and is never
 * evicted. Errors: HOL_EARG (obj not a game object), HOL_ENOMEM (no free
 * tile in reach, or the store is full). */
hol_err hol_world_reserve(hol_world *w, hol_tile t, int max_dist,
                          hol_object obj, hol_tile *out_tile);
/* Remove the game object from t (HOL_EARG if it holds none). */
hol_err hol_world_release(hol_world *w, hol_tile t);

/* Canonical name of corner c of tile t: the least (tile word, corner) pair
 * among the Q tiles around that vertex (Q of t's tiling). */
hol_err hol_world_vertex_canon(hol_tile t, int corner, hol_tile *out_tile,
                               int *out_corner);
/* The tree on corner c of t (pure in seed and vertex). */
hol_err hol_world_tree(uint64_t seed, hol_tile t, int corner, hol_tree *out);

/* Verify every constraint over the whole store: connectors match across
 * every edge between collapsed tiles, logs pair up, creek tiles have legal
 * shapes, every uncollapsed tile still has a completion, biomes valid, the
 * hash table is well formed. HOL_OK, or HOL_ECORRUPT with a one-line
 * description in msg (may be NULL). */
hol_err hol_world_check(const hol_world *w, char *msg, size_t msg_cap);

/* Save: bytes needed, then the image (into buf of at least that size). */
size_t hol_world_save_size(const hol_world *w);
hol_err hol_world_save(const hol_world *w, void *buf, size_t cap,
                       size_t *out_len);
/* Load an image made by hol_world_save: HOL_ECORRUPT (truncated, checksum
 * or structure), HOL_EVERSION (another format version), HOL_ENOMEM (more
 * tiles than 3/4 of the capacity), HOL_EARG (the image was saved with
 * another radius or tiling), with a one-line reason in msg (may be NULL). On error
 * the world is unchanged. On success the seed, the user state and the
 * store come from the image; capacity, allocator and statistics stay. */
hol_err hol_world_load(hol_world *w, const void *buf, size_t len, char *msg,
                       size_t msg_cap);
/* The length a world image promises, from its first HOL_WORLD_IMAGE_HEADER
 * bytes alone (magic, version, record size, record count), so a reader can
 * compare it with the file's size before reading the rest. Errors and msg
 * as hol_world_load (a shorter buffer is HOL_ECORRUPT). */
#define HOL_WORLD_IMAGE_HEADER 64
hol_err hol_world_image_size(const void *header, size_t len, uint64_t *out_len, char *msg,
                             size_t msg_cap);
/* The desc (seed, radius, tiling, a capacity that holds the image) to make a world
 * for an image, after checking its header, length and checksum; errors and
 * msg as hol_world_load. */
hol_err hol_world_image_desc(const void *buf, size_t len,
                             hol_world_desc *out_desc, char *msg,
                             size_t msg_cap);

/* Names for printing ("meadow", "grass", "creek", ...). */
const char *hol_biome_name(int biome);
const char *hol_object_name(int object);
const char *hol_conn_name(int conn); /* "-", "creek", "log" */
char hol_conn_char(int conn);         /* '-', 'c', 'l' */

#endif
