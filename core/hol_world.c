/* hol_world.c - TEMPORARY stub: every tile is a meadow with grass. */
#include "hol_world.h"

#include <stdlib.h>
#include <string.h>

struct hol_world {
    uint64_t seed;
    int radius;
    hol_room user;
};

size_t hol_world_mem_size(const hol_world_desc *desc)
{
    (void)desc;
    return sizeof(hol_world);
}

hol_err hol_world_init(void *mem, size_t size, const hol_world_desc *desc,
                       hol_world **out_world)
{
    if (!mem || size < sizeof(hol_world) || !desc)
        return HOL_EARG;
    hol_world *w = mem;
    w->seed = desc->seed;
    w->radius = desc->radius ? desc->radius : HOL_WORLD_DEFAULT_RADIUS;
    w->user = hol_room_start();
    *out_world = w;
    return HOL_OK;
}

hol_err hol_world_make(const hol_world_desc *desc, hol_world **out_world)
{
    hol_world *w = malloc(sizeof *w);
    if (!w)
        return HOL_ENOMEM;
    return hol_world_init(w, sizeof *w, desc, out_world);
}

void hol_world_destroy(hol_world *w) { free(w); }
uint64_t hol_world_seed(const hol_world *w) { return w->seed; }
int hol_world_radius(const hol_world *w) { return w->radius; }
hol_room hol_world_user(const hol_world *w) { return w->user; }

void hol_world_get_stats(const hol_world *w, hol_world_stats *out)
{
    memset(out, 0, sizeof *out);
    out->bytes = sizeof *w;
}

hol_err hol_world_update(hol_world *w, const hol_room *room)
{
    w->user = *room;
    return HOL_OK;
}

hol_err hol_world_peek(const hol_world *w, hol_tile t, hol_tile_content *out)
{
    memset(out, 0, sizeof *out);
    out->object = HOL_OBJ_GRASS;
    out->log_partner = -1;
    for (int c = 0; c < 4; c++)
        hol_world_tree(w->seed, t, c, &out->tree[c]);
    return HOL_OK;
}

hol_err hol_world_get(hol_world *w, hol_tile t, hol_tile_content *out)
{
    return hol_world_peek(w, t, out);
}

hol_err hol_world_reserve(hol_world *w, hol_tile t, int max_dist,
                          hol_object obj, hol_tile *out_tile)
{
    (void)w;
    (void)max_dist;
    (void)obj;
    *out_tile = t;
    return HOL_OK;
}

hol_err hol_world_release(hol_world *w, hol_tile t)
{
    (void)w;
    (void)t;
    return HOL_OK;
}

hol_err hol_world_vertex_canon(hol_tile t, int corner, hol_tile *out_tile,
                               int *out_corner)
{
    *out_tile = t;
    *out_corner = corner & 3;
    return HOL_OK;
}

hol_err hol_world_tree(uint64_t seed, hol_tile t, int corner, hol_tree *out)
{
    (void)seed;
    (void)t;
    (void)corner;
    out->kind = HOL_TREE_PINE;
    out->size = 2;
    return HOL_OK;
}

hol_err hol_world_check(const hol_world *w, char *msg, size_t msg_cap)
{
    (void)w;
    if (msg && msg_cap)
        msg[0] = 0;
    return HOL_OK;
}

size_t hol_world_save_size(const hol_world *w)
{
    (void)w;
    return 0;
}

hol_err hol_world_save(const hol_world *w, void *buf, size_t cap,
                       size_t *out_len)
{
    (void)w;
    (void)buf;
    (void)cap;
    *out_len = 0;
    return HOL_EUNSUPPORTED;
}

hol_err hol_world_load(hol_world *w, const void *buf, size_t len, char *msg,
                       size_t msg_cap)
{
    (void)w;
    (void)buf;
    (void)len;
    if (msg && msg_cap)
        msg[0] = 0;
    return HOL_EUNSUPPORTED;
}

const char *hol_biome_name(int biome)
{
    static const char *const n[] = {"meadow", "pine", "wetland", "autumn"};
    return biome >= 0 && biome < HOL_BIOME_COUNT ? n[biome] : "?";
}

const char *hol_object_name(int object)
{
    static const char *const n[] = {"none",  "grass",    "flowers", "log",
                                    "creek", "spring",   "pool",    "rock",
                                    "mushroom", "flag",  "key",     "chest"};
    return object >= 0 && object < HOL_OBJ_COUNT ? n[object] : "?";
}

const char *hol_conn_name(int conn)
{
    static const char *const n[] = {"-", "creek", "log"};
    return conn >= 0 && conn < HOL_CONN_COUNT ? n[conn] : "?";
}

char hol_conn_char(int conn)
{
    return conn >= 0 && conn < HOL_CONN_COUNT ? "-cl"[conn] : '?';
}
