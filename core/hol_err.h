/* hol_err.h - error codes shared by every module.
 *
 * Contract: every fallible function returns a hol_err; HOL_OK is zero, so
 * `if (err)` tests for failure. On failure, outputs are left untouched.
 * hol_err_str gives a short lower-case phrase for a one-line message.
 */
#ifndef HOL_ERR_H
#define HOL_ERR_H

typedef enum hol_err {
    HOL_OK = 0,
    HOL_EPARSE,    /* text that does not follow the grammar */
    HOL_ENOTCANON, /* a valid walk that is not the canonical address */
    HOL_ERANGE,    /* a tile beyond HOL_TILE_MAX_DIST from the origin */
    HOL_EROOM,     /* a step that would leave the room */
    HOL_EARG,      /* an argument out of its documented range */
    HOL_ENOMEM,    /* a fixed-capacity store or arena is full */
    HOL_EIO,       /* reading or writing a file failed */
    HOL_ECORRUPT,  /* a file that fails its checksum or structure checks */
    HOL_EVERSION,  /* a file of an unknown format version */
    HOL_EBUDGET,   /* a search stopped at its node or time budget */
    HOL_EUNSUPPORTED, /* a feature this build or platform does not have */
    HOL_EOPEN,     /* a file that cannot be opened (errno says why) */
    HOL_EUNREACH,  /* no walk inside the room reaches the tile (flat {4,4}) */
    HOL_ERR_COUNT
} hol_err;

const char *hol_err_str(hol_err e);

#endif
