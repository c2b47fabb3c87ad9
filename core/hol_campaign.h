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

hol_err hol_campaign_mode_level(const char *mode, uint64_t seed, hol_level *out);
hol_err hol_campaign_default(uint64_t seed, hol_level levels[HOL_CAMPAIGN_LEVELS]);

#endif
