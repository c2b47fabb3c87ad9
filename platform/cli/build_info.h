/* build_info.h - which build this is: the release version, the commit and
 * the build date (docs/logs.md, "Provenance").
 *
 * Contract
 * - build_version() is HOL_VERSION (core/hol_version.h), the version the
 *   logs' rows carry; build_commit() is `git describe --always --dirty` of
 *   the source built ("unknown" outside a git checkout); build_date() the
 *   build's date, ISO 8601 UTC (SOURCE_DATE_EPOCH when set, else the
 *   commit's date; "unknown" without either): never the clock, so that two
 *   builds of one commit are the same bytes.
 * - The strings are static, letters, digits and . _ - + : only (no CSV
 *   quoting, no HTML escaping needed).
 * - The values come from $(BUILD)/gen/hol_build_id.h, made by
 *   platform/cli/build_id.sh and rewritten only when they change: only
 *   build_info.c includes it, so a new commit recompiles one file.
 */
#ifndef BUILD_INFO_H
#define BUILD_INFO_H

const char *build_version(void);
const char *build_commit(void);
const char *build_date(void);

#endif
