/* hol_shell_build.h - which build this is: the release version, the
 * commit and the build date (docs/logs.md, "Provenance and codebook"), the
 * same on every platform (`holonomy --version`, provenance.csv, a report's
 * build.csv, the web page's and the headset's log folders).
 *
 * Contract
 * - hol_shell_build_version() is HOL_VERSION (core/hol_version.h), the
 *   version the logs' rows carry; hol_shell_build_commit() is `git describe
 *   --always --dirty` of the source built ("unknown" outside a git
 *   checkout); hol_shell_build_date() the build's date, ISO 8601 UTC
 *   (SOURCE_DATE_EPOCH when set, else the commit's date; "unknown" without
 *   either): never the clock, so that two builds of one commit are the same
 *   bytes.
 * - The strings are static, letters, digits and . _ - + : only (no CSV
 *   quoting, no HTML escaping needed).
 * - The values come from hol_build_id.h, made in the build's gen folder by
 *   platform/shell/build_id.sh and rewritten only when they change: only
 *   hol_shell_build.c includes it, so a new commit recompiles one file. A
 *   build whose include path lacks the folder (a unit test) says "unknown".
 */
#ifndef HOL_SHELL_BUILD_H
#define HOL_SHELL_BUILD_H

const char *hol_shell_build_version(void);
const char *hol_shell_build_commit(void);
const char *hol_shell_build_date(void);

#endif
