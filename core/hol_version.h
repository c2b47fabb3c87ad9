/* hol_version.h - the release version of Holonomy. */
#ifndef HOL_VERSION_H
#define HOL_VERSION_H
#define HOL_VERSION "0.1.0"
#endif
