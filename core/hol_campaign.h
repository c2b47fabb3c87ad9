/* hol_campaign.h - levels made from a seed: the level of a mode (`play
 * --mode`) and the default campaign that every platform plays when given
 * no level (the desktop, the headset, Android, the web).
 *
 * Contract
 * - hol_campaign_mode_level makes a level of mode "explore", "tutorial",
 *   "flag" (the flag 5 tiles from the start) or "keys" (3 keys 2..3 tiles
 *   out, the chest at 5), tiles drawn from the seed, named "MODE-SEED"
 *   (decimal). HOL_EARG for another mode.
 * - hol_campaign_default fills levels[0..HOL_CAMPAIGN_LEVELS-1]: the
 *   tutorial, flags at distance 3, 5 and 7 (seeds S, S+1, S+2), then keys
 *   and chest with 2 and 3 keys (chest at 3 and 4; seeds S+3, S+4), named
 *   tutorial, flag-1..3, keys-1..2.
 * - geo (NULL: the default) says the geometry the levels are made for:
 *   zero fields the default ({4,5}, a 3 x 3 room). In {4,5} the tiles are
 *   random canonical addresses at the distance named (as before geometries
 *   came: the same seed, the same levels). In the other tilings each
 *   objective is where a seeded walk of room steps inside the geo's room
 *   first comes to a tile at that distance, so no walk is needed outside
 *   the room; where the room reaches no tile that far (the flat {4,4}: a
 *   room reaches only its own C x R tiles; {4,8}'s folded reach), the
 *   farthest such tile seen, so the level stays playable. The made levels
 *   (not the tutorial, made for {4,5}) then hold the line `tiling 4 Q`,
 *   and `room C R` for a room other than 3 x 3 (the objectives were found
 *   in it); the cell size, and a room for a 3 x 3 geo, are left to the
 *   caller (hol_level_set_geometry: a larger room than 3 x 3 reaches all
 *   that 3 x 3 reaches). HOL_EARG for a geo outside SPEC 7's ranges.
 * - Each level's text is what a level file would hold (hol_level.h), so a
 *   recording carries it and a replay plays the same level.
 * - Pure and deterministic: the same seed, the same levels.
 */
#ifndef HOL_CAMPAIGN_H
#define HOL_CAMPAIGN_H

#include <stdint.h>

#include "hol_err.h"
#include "hol_level.h"

#define HOL_CAMPAIGN_LEVELS 6

/* The geometry levels are made for; zero fields are the defaults. */
typedef struct hol_campaign_geo {
    int q;          /* the tiling {4,q}, 4..8 (0: 5) */
    int cols, rows; /* the room, 3..5 each (0: 3) */
} hol_campaign_geo;

hol_err hol_campaign_mode_level(const char *mode, uint64_t seed, const hol_campaign_geo *geo,
                                hol_level *out);
hol_err hol_campaign_default(uint64_t seed, const hol_campaign_geo *geo,
                             hol_level levels[HOL_CAMPAIGN_LEVELS]);

#endif
