/* build_info.c - the version, commit and build date (build_info.h). */
#include "build_info.h"

#include "../../core/hol_version.h"
#include "hol_build_id.h"

const char *build_version(void) { return HOL_VERSION; }
const char *build_commit(void) { return HOL_BUILD_COMMIT; }
const char *build_date(void) { return HOL_BUILD_DATE; }
