/* hol_sha256.h - SHA-256 (FIPS 180-4), for naming level files in the logs.
 *
 * Contract
 * - hol_sha256 hashes len bytes into 32 bytes; hol_sha256_hex writes the
 *   64 lowercase hex digits and a NUL (65 bytes), as `sha256sum` prints
 *   them, so a researcher can check which file a session played.
 * - Pure: no allocation, no globals; any length (size_t).
 */
#ifndef HOL_SHA256_H
#define HOL_SHA256_H

#include <stddef.h>
#include <stdint.h>

#define HOL_SHA256_HEX 65

void hol_sha256(const void *data, size_t len, uint8_t out[32]);
void hol_sha256_hex(const uint8_t digest[32], char out[HOL_SHA256_HEX]);

#endif
