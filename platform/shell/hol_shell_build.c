/* hol_shell_build.c - the version, commit and build date (hol_shell_build.h). */
#include "hol_shell_build.h"

#include "../../core/hol_version.h"

#if defined(__has_include)
#if __has_include("hol_build_id.h")
#include "hol_build_id.h"
#endif
#endif
#ifndef HOL_BUILD_COMMIT
#define HOL_BUILD_COMMIT "unknown"
#define HOL_BUILD_DATE "unknown"
#endif

const char *hol_shell_build_version(void) { return HOL_VERSION; }
const char *hol_shell_build_commit(void) { return HOL_BUILD_COMMIT; }
const char *hol_shell_build_date(void) { return HOL_BUILD_DATE; }
